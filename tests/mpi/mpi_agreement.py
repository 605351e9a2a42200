"""`mpirun -np P drange delaunay` against one process: the same simplices (as vertex sets) for
P = 1 to 4 on uniform, clustered, grid and sphere inputs in 2D to 4D, in the qhull layout and in
JSON with neighbours (and the same exact copies, in the same order); a larger 3D grid, copies
spread over the file, a CSV file, a .npy file and an input smaller than the processes; --stats
shows that no process holds every point; and the failures: a malformed line (in the last
process's part: the same message and line number as one process), a NaN, a wrong count, a flat
or too small input and a usage error stop every process with one message and one exit code, and
leave no output file.

    python3 tests/mpi/mpi_agreement.py DRANGE MPIRUN

Plain Python 3 (no modules beyond the standard library). Root needs --allow-run-as-root.
"""
import json
import os
import struct
import subprocess
import sys
import tempfile

DRANGE, MPIRUN = sys.argv[1], sys.argv[2]
LAUNCH = [MPIRUN, "--oversubscribe"] + (["--allow-run-as-root"] if os.geteuid() == 0 else [])


def run(command, **kwargs):
    return subprocess.run(command, capture_output=True, text=True, timeout=300, **kwargs)


def simplex_set(path):
    if path.endswith(".json"):
        with open(path) as f:
            rows = json.load(f)["simplices"]
    else:
        with open(path) as f:
            lines = f.read().split("\n")
        rows = [line.split() for line in lines[1:1 + int(lines[0])]]
    keys = [tuple(sorted(int(v) for v in row)) for row in rows]
    assert len(keys) == len(set(keys)), f"{path}: a simplex written twice"
    return set(keys)


def copies(path):
    with open(path) as f:
        return json.load(f)["coplanar"]


def neighbours_consistent(path):
    with open(path) as f:
        data = json.load(f)
    simplices, neighbors = data["simplices"], data["neighbors"]
    for s, row in enumerate(neighbors):
        for k, n in enumerate(row):
            if n < 0:
                continue
            shared = set(simplices[s]) - {simplices[s][k]}
            assert shared <= set(simplices[n]) and s in neighbors[n], f"{path}: neighbour {k} of simplex {s}"


def extra_inputs(tmp):
    """A larger 3D grid (ties everywhere), copies spread over the file, CSV with a header row, a
    .npy file, and 6 points for 4 processes."""
    grid = os.path.join(tmp, "grid3_big.txt")
    assert run([DRANGE, "generate", "grid", "1000", "3", "--seed", "3", "-o", grid]).returncode == 0
    base = os.path.join(tmp, "base2.txt")
    assert run([DRANGE, "generate", "uniform", "1200", "2", "--seed", "4", "-o", base]).returncode == 0
    with open(base) as f:
        rows = f.read().split("\n")[2:2 + 1200]
    spread = [rows[i] for i in range(1200)]
    for k in range(150):  # a copy of an earlier or later row, every eighth row
        spread.insert(8 * k + 3, rows[(k * 397) % 1200])
    copies_path = os.path.join(tmp, "copies2.txt")
    with open(copies_path, "w") as f:
        f.write(f"2\n{len(spread)}\n" + "\n".join(spread) + "\n")
    csv = os.path.join(tmp, "points.csv")
    with open(csv, "w") as f:
        f.write("x,y,z\n" + "\n".join(",".join(r.split()) for r in rows[:300]
                                       for r in [r + " " + str(len(r) % 7)]) + "\n")
    clustered = os.path.join(tmp, "clustered_npy.txt")
    assert run([DRANGE, "generate", "clustered", "800", "3", "--seed", "6", "-o", clustered]).returncode == 0
    with open(clustered) as f:
        values = [float(v) for line in f.read().split("\n")[2:] for v in line.split()]
    npy = os.path.join(tmp, "points.npy")
    header = "{'descr': '<f8', 'fortran_order': False, 'shape': (%d, 3), }" % (len(values) // 3)
    header += " " * (63 - (10 + len(header)) % 64) + "\n"
    with open(npy, "wb") as f:
        f.write(b"\x93NUMPY\x01\x00" + struct.pack("<H", len(header)) + header.encode() + struct.pack(f"<{len(values)}d", *values))
    tiny = os.path.join(tmp, "tiny3.txt")
    with open(tiny, "w") as f:
        f.write("3\n6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1\n0.2 0.3 0.1\n")
    return [("grid 3D 1000", grid, (2, 4)), ("copies 2D", copies_path, (2, 3)), ("csv 3D", csv, (3,)),
            ("npy 3D", npy, (2,)), ("6 points 3D", tiny, (4,))]


def check_no_process_holds_everything(tmp):
    points = os.path.join(tmp, "uniform_stats.txt")
    assert run([DRANGE, "generate", "uniform", "20000", "3", "--seed", "7", "-o", points]).returncode == 0
    done = run(LAUNCH + ["-np", "3", DRANGE, "delaunay", points, "-o", os.path.join(tmp, "stats.txt"), "-q", "--stats"])
    ranks = [dict(field.split("=", 1) for field in line.split()) for line in done.stderr.splitlines()
             if line.startswith("rank=")]
    summary = [line for line in done.stderr.splitlines() if line.startswith("ranks=")]
    held = [int(r["points_owned"]) + int(r["ghost_points"]) for r in ranks]
    owned = sum(int(r["points_owned"]) for r in ranks)
    if done.returncode != 0 or len(ranks) != 3 or owned != 20000 or max(held) >= 20000 or len(summary) != 1 \
            or "balance=" not in summary[0] or "exchange_bytes=" not in summary[0]:
        print(f"FAILED --stats: exit {done.returncode}, held {held}, owned {owned}: {done.stderr.strip()}")
        return 1
    print(f"ok --stats, 3 processes: points held {held} of 20000")
    return 0


def main():
    failures = 0
    with tempfile.TemporaryDirectory() as tmp:
        inputs = [("uniform", "3000", "2"), ("clustered", "2000", "3"), ("grid", "343", "3"),
                  ("sphere", "1500", "3"), ("uniform", "500", "4")]
        paths = []
        for distribution, count, dim in inputs:
            points = os.path.join(tmp, f"{distribution}{dim}.txt")
            assert run([DRANGE, "generate", distribution, count, dim, "--seed", "3", "-o", points]).returncode == 0
            paths.append((f"{distribution} {dim}D", points, (1, 2, 3, 4)))
        paths += extra_inputs(tmp)
        for label, points, counts in paths:
            single = os.path.join(tmp, "single.json")
            assert run([DRANGE, "delaunay", points, "-o", single, "-q"]).returncode == 0
            expected, expected_copies = simplex_set(single), copies(single)
            for processes in counts:
                for name in ("split.txt", "split.json"):
                    out = os.path.join(tmp, name)
                    done = run(LAUNCH + ["-np", str(processes), DRANGE, "delaunay", points, "-o", out, "-q"])
                    case = f"{label}, {processes} processes, {name}"
                    if done.returncode != 0 or simplex_set(out) != expected or (
                            name.endswith(".json") and copies(out) != expected_copies):
                        print(f"FAILED {case}: exit {done.returncode} {done.stderr.strip()}")
                        failures += 1
                        continue
                    if name.endswith(".json"):
                        neighbours_consistent(out)
                    print(f"ok {case}: {len(expected)} simplices, {len(expected_copies)} copies")
        failures += check_no_process_holds_everything(tmp)
        bad = os.path.join(tmp, "bad.txt")
        with open(bad, "w") as f:
            f.write("2\n4\n0 0\n1 0\n0 x\n1 1\n")
        flat = os.path.join(tmp, "flat.txt")
        with open(flat, "w") as f:
            f.write("2\n4\n0 0\n1 1\n2 2\n3 3\n")
        cases = [(["delaunay", bad], 3, "not a number"), (["delaunay", flat], 4, "affine subspace"),
                 (["delaunay", flat, "--only", "1"], 2, "--only"), (["voronoi", flat], 2, "only drange delaunay")]
        # Damaged copies of a 400-point file: in the last quarter (the last process's part), a
        # wrong count in the header, and fewer points than a triangulation needs.
        good = os.path.join(tmp, "good.txt")
        assert run([DRANGE, "generate", "uniform", "400", "3", "--seed", "5", "-o", good]).returncode == 0
        with open(good) as f:
            lines = f.read().split("\n")
        for name, line, text in (("late.txt", 2 + 370, "0.5 abc 0.1"), ("nan.txt", 2 + 390, "0.5 nan 0.1"),
                                 ("short.txt", 2 + 395, "0.5 0.1"), ("count.txt", 1, "401")):
            damaged = lines[:]
            damaged[line] = text
            with open(os.path.join(tmp, name), "w") as f:
                f.write("\n".join(damaged))
        with open(os.path.join(tmp, "tiny.txt"), "w") as f:
            f.write("3\n3\n0 0 0\n1 0 0\n0 1 0\n")
        for name in ("late.txt", "nan.txt", "short.txt", "count.txt", "tiny.txt"):
            path = os.path.join(tmp, name)
            alone = run([DRANGE, "delaunay", path, "-o", os.path.join(tmp, "never1.txt")])
            message = [line for line in alone.stderr.splitlines() if line.startswith("drange:")]
            assert alone.returncode != 0 and len(message) == 1, alone.stderr
            cases.append((["delaunay", path], alone.returncode, message[0][len("drange: "):]))
        for command, code, words in cases:
            out = os.path.join(tmp, "never.txt")
            done = run(LAUNCH + ["-np", "3", DRANGE] + command + ["-o", out])
            messages = [line for line in done.stderr.splitlines() if line.startswith("drange:")]
            if done.returncode != code or len(messages) != 1 or words not in messages[0] or os.path.exists(out):
                print(f"FAILED error case {words!r}: exit {done.returncode}, messages {messages}")
                failures += 1
            else:
                print(f"ok error case {words!r}: exit {code}, one message, no file")
    print("all agree" if failures == 0 else f"{failures} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
