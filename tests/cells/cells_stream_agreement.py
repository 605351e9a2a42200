#!/usr/bin/python3
"""The streamed cells of `drange voronoi --cells FILE.txt` against the whole diagram's, and voro++.

Usage: cells_stream_agreement.py DRANGE_EXECUTABLE [--voro]

Without --voro: on uniform, clustered and grid (degenerate) points in 2D and 3D, and on a cloud
with exact duplicates, a point on the box and points outside it, the text cells (with
--cell-vertices) must name the same points as the cells of --cells FILE.json (the whole
diagram's clipped cells), with the same volumes to 1e-9 relative and the same corners to 1e-9
of the box's size; the text must be the same bytes for --threads 1, 2 and 3, and with -o given
too (the diagram computed as well).
With --voro: uniform 3D points in the unit box against voro++ (Debian's voro++, `voro++ -c
'%i %v %w' -o 0 1 0 1 0 1 FILE`): the same number of corners for every cell, and the same
volumes to the digits voro++ prints (its command line writes 6 significant digits, with no
option for more: half a unit of the 6th digit); the 1e-9 agreement is the whole diagram's,
above. When voro++ is not installed it prints "voro++ not installed: not tested" and exits 0
(CTest reads it as a skip).
Exits non-zero with a message naming the case on the first disagreement.
"""
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile

DRANGE = sys.argv[1]
failures = []


def fail(case, message):
    failures.append(f"{case}: {message}")
    print(f"FAIL {case}: {message}", file=sys.stderr)


def run(*args):
    subprocess.run([DRANGE, *args], check=True, stdout=subprocess.DEVNULL)


def write_points(path, points):
    with open(path, "w") as out:
        out.write(f"{len(points[0])}\n{len(points)}\n")
        for p in points:
            out.write(" ".join(repr(x) for x in p) + "\n")


def read_text_cells(path, dim):
    """{point: (volume, [corner, ...])} from a text cells file with --cell-vertices."""
    cells = {}
    with open(path) as text:
        for line in text:
            fields = line.split()
            point, volume, count = int(fields[0]), float(fields[1]), int(fields[2])
            coords = [float(x) for x in fields[3:]]
            if len(coords) != count * dim:
                raise ValueError(f"{path}: line of point {point} has {len(coords)} coordinates, not {count} x {dim}")
            if point in cells:
                raise ValueError(f"{path}: point {point} has two lines")
            cells[point] = (volume, [tuple(coords[i:i + dim]) for i in range(0, len(coords), dim)])
    return cells


def read_json_cells(path):
    clipped = json.load(open(path))["clipped_cells"]
    return {c["point"]: (c["volume"], [tuple(x) for x in c["points"]]) for c in clipped["cells"]}


def compare(case, streamed, whole, box_size):
    if set(streamed) != set(whole):
        fail(case, f"points {sorted(set(streamed) ^ set(whole))[:10]} are in one file only")
        return
    scale = max(box_size) ** len(box_size)
    for point, (volume, corners) in whole.items():
        s_volume, s_corners = streamed[point]
        if abs(s_volume - volume) > 1e-9 * max(abs(volume), 1e-6 * scale):
            fail(case, f"point {point}: volume {s_volume!r}, the whole diagram's {volume!r}")
            return
        if len(s_corners) != len(corners):
            fail(case, f"point {point}: {len(s_corners)} corners, the whole diagram's cell has {len(corners)}")
            return
        tol = 1e-9 * max(box_size)
        for c in s_corners:
            if min(max(abs(a - b) for a, b in zip(c, r)) for r in corners) > tol:
                fail(case, f"point {point}: corner {c} is not a corner of the whole diagram's cell")
                return


def check_case(directory, case, points_path, dim, box=None):
    extra = ["--box", box] if box else []
    whole_path = os.path.join(directory, case + ".json")
    run("voronoi", points_path, "--cells", whole_path, "-o", os.devnull, "-q", *extra)
    texts = []
    for threads in (1, 2, 3):
        path = os.path.join(directory, f"{case}.t{threads}.txt")
        run("voronoi", points_path, "--cells", path, "--cell-vertices", "--threads", str(threads), "-q", *extra)
        texts.append(open(path, "rb").read())
    both = os.path.join(directory, case + ".both.txt")
    run("voronoi", points_path, "--cells", both, "--cell-vertices", "-o", os.path.join(directory, case + ".o.txt"), "-q", *extra)
    texts.append(open(both, "rb").read())
    if any(t != texts[0] for t in texts):
        fail(case, "the text differs between --threads 1, 2, 3 or with -o")
    clipped = json.load(open(whole_path))["clipped_cells"]
    box_size = [u - l for l, u in zip(clipped["box"]["lower"], clipped["box"]["upper"])]
    compare(case, read_text_cells(os.path.join(directory, f"{case}.t1.txt"), dim), read_json_cells(whole_path), box_size)
    print(f"ok {case}: {len(read_json_cells(whole_path))} cells")


def agreement_with_whole_diagram(directory):
    for dim in (2, 3):
        for dist, n in (("uniform", 3000), ("clustered", 3000), ("grid", 3000 if dim == 2 else 2000)):
            path = os.path.join(directory, f"{dist}{dim}.txt")
            run("generate", dist, str(n), str(dim), "-o", path)
            check_case(directory, f"{dist}{dim}", path, dim)
        # Exact duplicates, a point on the box, points outside it (their cells may miss it).
        path = os.path.join(directory, f"special{dim}.txt")
        run("generate", "uniform", "500", str(dim), "-o", path)
        lines = open(path).read().split("\n")
        points = [tuple(float(x) for x in line.split()) for line in lines[2:] if line.strip()]
        points += [points[3], points[7], points[3]]  # copies
        points.append((0.25,) + (0.5,) * (dim - 1))  # on the face x = 0.25 of the box
        points.append((-0.5,) * dim)  # outside, its cell misses the box
        points.append((0.1,) + (1.2,) * (dim - 1))  # outside, its cell reaches into the box
        write_points(path, points)
        box = ",".join(["0.25"] * dim + ["1"] * dim)
        check_case(directory, f"special{dim}", path, dim, box)


def refusals(directory):
    """Usage errors (exit code 2) naming the problem."""
    path = os.path.join(directory, "u4.txt")
    run("generate", "uniform", "100", "4", "-o", path)
    cases = [
        (["voronoi", path, "--cells", os.path.join(directory, "c.txt")], "2D and 3D"),
        (["voronoi", os.path.join(directory, "uniform2.txt"), "--cells", os.path.join(directory, "c.vtu"),
          "--cell-vertices"], "--cell-vertices"),
    ]
    for args, words in cases:
        done = subprocess.run([DRANGE, *args], capture_output=True, text=True)
        if done.returncode != 2 or words not in done.stderr:
            fail("refusal", f"{' '.join(args[2:])}: exit {done.returncode}, {done.stderr.strip()!r}")


def agreement_with_voro(directory):
    voro = shutil.which("voro++")
    if voro is None:
        print("voro++ not installed: not tested")
        return
    path = os.path.join(directory, "u3.txt")
    run("generate", "uniform", "20000", "3", "-o", path)
    lines = open(path).read().split("\n")
    points = [line for line in lines[2:] if line.strip()]
    voro_input = os.path.join(directory, "voro_in.txt")
    with open(voro_input, "w") as out:
        for i, line in enumerate(points):
            out.write(f"{i} {line}\n")
    subprocess.run([voro, "-c", "%i %v %w", "-o", "0", "1", "0", "1", "0", "1", voro_input], check=True)
    expected = {}
    for line in open(voro_input + ".vol"):
        i, v, w = line.split()
        expected[int(i)] = (v, int(w))
    cells = os.path.join(directory, "u3_cells.txt")
    run("voronoi", path, "--cells", cells, "--cell-vertices", "--box", "0,0,0,1,1,1", "-q")
    got = read_text_cells(cells, 3)
    if set(got) != set(expected):
        fail("voro++", f"points {sorted(set(got) ^ set(expected))[:10]} are in one output only")
        return
    worst = 0
    for i, (printed, corners) in expected.items():
        volume, ours = got[i][0], len(got[i][1])
        if ours != corners:
            fail("voro++", f"point {i}: {ours} corners, voro++ {corners}")
            return
        # voro++ prints %g: 6 significant digits.
        digit = 10 ** (math.floor(math.log10(abs(float(printed)))) - 5)
        worst = max(worst, abs(volume - float(printed)) / digit)
        if abs(volume - float(printed)) > 0.5 * digit * (1 + 1e-9):
            fail("voro++", f"point {i}: volume {volume!r}, voro++ prints {printed}")
            return
    print(f"ok voro++: {len(expected)} cells, the same corner counts; volumes within {worst:.3f} of voro++'s last printed digit")


with tempfile.TemporaryDirectory() as directory:
    if "--voro" in sys.argv[2:]:
        agreement_with_voro(directory)
    else:
        agreement_with_whole_diagram(directory)
        refusals(directory)
if failures:
    sys.exit(f"{len(failures)} disagreement(s)")
