"""`mpirun -np P drange delaunay` against one process: the same simplices (as vertex sets) for
P = 1 to 4 on uniform, clustered, grid and sphere inputs in 2D to 4D, in the qhull layout and in
JSON with neighbours; and the failures: a malformed line, a flat input and a usage error stop
every process with one message and one exit code, and leave no output file.

    python3 tests/mpi/mpi_agreement.py DRANGE MPIRUN

Plain Python 3 (no modules beyond the standard library). Root needs --allow-run-as-root.
"""
import json
import os
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


def main():
    failures = 0
    with tempfile.TemporaryDirectory() as tmp:
        inputs = [("uniform", "3000", "2"), ("clustered", "2000", "3"), ("grid", "343", "3"),
                  ("sphere", "1500", "3"), ("uniform", "500", "4")]
        for distribution, count, dim in inputs:
            points = os.path.join(tmp, f"{distribution}{dim}.txt")
            assert run([DRANGE, "generate", distribution, count, dim, "--seed", "3", "-o", points]).returncode == 0
            single = os.path.join(tmp, "single.txt")
            assert run([DRANGE, "delaunay", points, "-o", single]).returncode == 0
            expected = simplex_set(single)
            for processes in (1, 2, 3, 4):
                for name in ("split.txt", "split.json"):
                    out = os.path.join(tmp, name)
                    done = run(LAUNCH + ["-np", str(processes), DRANGE, "delaunay", points, "-o", out, "-q"])
                    label = f"{distribution} {dim}D, {processes} processes, {name}"
                    if done.returncode != 0 or simplex_set(out) != expected:
                        print(f"FAILED {label}: exit {done.returncode} {done.stderr.strip()}")
                        failures += 1
                        continue
                    if name.endswith(".json"):
                        neighbours_consistent(out)
                    print(f"ok {label}: {len(expected)} simplices")
        bad = os.path.join(tmp, "bad.txt")
        with open(bad, "w") as f:
            f.write("2\n4\n0 0\n1 0\n0 x\n1 1\n")
        flat = os.path.join(tmp, "flat.txt")
        with open(flat, "w") as f:
            f.write("2\n4\n0 0\n1 1\n2 2\n3 3\n")
        for command, code, words in ((["delaunay", bad], 3, "not a number"), (["delaunay", flat], 4, "affine subspace"),
                                     (["delaunay", flat, "--only", "1"], 2, "--only"),
                                     (["voronoi", flat], 2, "only drange delaunay")):
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
