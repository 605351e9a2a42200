#!/usr/bin/python3
"""tests/families/surface_families_check.py: drange triangulates the surface families of
bench/degenerate_families.py (issue 44) at a few thousand points, 2D to 4D, and `drange check`
validates each output exactly. Two corrupted outputs must be rejected, so that a check that
accepted anything would fail this test.

    surface_families_check.py DRANGE GENERATOR [DRANGE_ARGS...]

DRANGE_ARGS go to `drange delaunay` (e.g. --algorithm incremental). Prints what it ran; exits 1
with the reasons when anything is wrong.
"""
import os
import subprocess
import sys
import tempfile

# (family, size): every surface family, small enough for the whole to run in seconds.
CASES = [("square_edges2", 8000), ("cube_faces3", 6000), ("cad_part3", 6000), ("cylinder_mesh3", 6000),
         ("torus_mesh3", 6000), ("bezier_patch3", 6000), ("torus4", 3000)]


def read_points(path):
    with open(path) as f:
        d, n = int(f.readline()), int(f.readline())
        return [[float(x) for x in f.readline().split()] for _ in range(n)], d


def read_simplices(path):
    with open(path) as f:
        count = int(f.readline())
        return [[int(x) for x in f.readline().split()] for _ in range(count)]


def write_simplices(path, simplices):
    with open(path, "w") as f:
        f.write(f"{len(simplices)}\n" + "".join(" ".join(map(str, s)) + "\n" for s in simplices))


def orient(p, q, r):
    return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0])


def flipped(points, triangles):
    """The triangles with one edge flipped whose quadrilateral is clearly convex (every
    orientation far from zero): a triangulation still, but no longer a Delaunay one."""
    by_edge = {}
    for t, tri in enumerate(triangles):
        for k in range(3):
            edge = tuple(sorted((tri[k], tri[(k + 1) % 3])))
            by_edge.setdefault(edge, []).append((t, tri[(k + 2) % 3]))
    for (a, b), sides in by_edge.items():
        if len(sides) != 2:
            continue
        (t, c), (u, d) = sides
        pa, pb, pc, pd = points[a], points[b], points[c], points[d]
        values = (orient(pa, pb, pc), orient(pa, pb, pd), orient(pc, pd, pa), orient(pc, pd, pb))
        if min(abs(v) for v in values) > 1e-6 and values[0] * values[1] < 0 and values[2] * values[3] < 0:
            result = [tri for k, tri in enumerate(triangles) if k not in (t, u)]
            return result + [[c, d, a], [d, c, b]]
    return None


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    drange, generator, extra = sys.argv[1], sys.argv[2], sys.argv[3:]
    failures = []
    with tempfile.TemporaryDirectory() as work:
        for name, n in CASES:
            subprocess.run([sys.executable, generator, work, "--surfaces-only", "--families", name, "--sizes", str(n)],
                           check=True, stdout=subprocess.DEVNULL)
        outputs = {}
        for name, n in CASES:
            points = os.path.join(work, f"{name}_{n}.txt")
            simplices = os.path.join(work, f"{name}_{n}.simplices")
            run = subprocess.run([drange, "delaunay", points, "-o", simplices, "-q"] + extra,
                                 capture_output=True, text=True)
            if run.returncode != 0:
                failures.append(f"{name} {n}: drange delaunay exited {run.returncode}: {run.stderr.strip()}")
                continue
            check = subprocess.run([drange, "check", points, simplices], capture_output=True, text=True)
            print(f"{name} {n}: {check.stdout.strip().splitlines()[-1] if check.stdout.strip() else check.returncode}")
            if check.returncode != 0 or not check.stdout.startswith("valid: "):
                failures.append(f"{name} {n}: drange check exited {check.returncode}: {check.stdout.strip()[-2000:]}")
            outputs[name] = (points, simplices)

        # The negative controls: one simplex fewer (a hole in the cover, 3D) and one edge flipped
        # (a triangulation that is not Delaunay, 2D).
        corrupt = []
        if "cube_faces3" in outputs:
            points, simplices = outputs["cube_faces3"]
            corrupt.append(("cube_faces3 less one simplex", points, read_simplices(simplices)[:-1]))
        if "square_edges2" in outputs:
            points, simplices = outputs["square_edges2"]
            triangles = flipped(read_points(points)[0], read_simplices(simplices))
            if triangles is None:
                failures.append("square_edges2: no edge to flip found for the negative control")
            else:
                corrupt.append(("square_edges2 with an edge flipped", points, triangles))
        for label, points, simplices in corrupt:
            path = os.path.join(work, "corrupt.simplices")
            write_simplices(path, simplices)
            check = subprocess.run([drange, "check", points, path], capture_output=True, text=True)
            print(f"{label}: drange check exited {check.returncode} ({check.stdout.strip().splitlines()[-1]})")
            if check.returncode != 1:
                failures.append(f"{label}: drange check exited {check.returncode}, not 1 (invalid)")
    if failures:
        print("FAILED:\n  " + "\n  ".join(failures))
        sys.exit(1)
    print("all surface families valid; both corrupted outputs rejected")


if __name__ == "__main__":
    main()
