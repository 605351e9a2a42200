"""drange's Python classes against scipy.spatial's, side by side in one run, as a user sees
them: wall time of the call (conversion and result arrays included), best of `--repeat`.

    PYTHONPATH=build/python /usr/bin/python3 bench/python_vs_scipy.py [--quick] [--repeat N] [--only PREFIX] [-o FILE]

Prints one Markdown table: time of each, and the ratio drange/scipy (below 1: drange faster).
ConvexHull rows read `volume` from both (scipy computes it in the constructor, drange on first
use); add_points rows add one point to an incremental triangulation per repetition. `--only
ConvexHull` runs those rows alone.
"""
import argparse
import os
import platform
import sys
import time

import numpy as np
import scipy
import scipy.spatial

import drange


def best_time(function, repeat):
    best = float("inf")
    for _ in range(repeat):
        start = time.perf_counter()
        function()
        best = min(best, time.perf_counter() - start)
    return best


def cases(quick):
    rng = np.random.default_rng(1)
    sizes = {2: 100000 if quick else 1000000, 3: 30000 if quick else 200000, 4: 5000 if quick else 50000,
             5: 2000 if quick else 10000, 6: 500 if quick else 2000}
    for d, n in sizes.items():
        points = rng.random((n, d))
        yield f"Delaunay uniform {d}D {n}", (lambda p=points: drange.Delaunay(p, threads=1)), \
            (lambda p=points: scipy.spatial.Delaunay(p))
    side = 300 if quick else 1000
    grid = np.array(np.meshgrid(np.arange(side), np.arange(side))).reshape(2, -1).T.astype(float)
    yield f"Delaunay grid {side}x{side}", (lambda: drange.Delaunay(grid, threads=1)), \
        (lambda: scipy.spatial.Delaunay(grid))
    for d, n in ((2, 100000 if quick else 500000), (3, 20000 if quick else 100000)):
        points = rng.random((n, d))
        yield f"Voronoi uniform {d}D {n} (drange with volumes)", (lambda p=points: drange.Voronoi(p, threads=1)), \
            (lambda p=points: scipy.spatial.Voronoi(p))
    n = 100000 if quick else 1000000
    points = rng.random((100000, 2))
    queries = rng.random((n, 2))
    ours, theirs = drange.Delaunay(points, threads=1), scipy.spatial.Delaunay(points)
    ours.find_simplex(queries[:10])  # builds the locator outside the timing, as scipy's is built with the triangulation
    yield f"find_simplex {n} queries, 100000 points 2D", (lambda: ours.find_simplex(queries)), \
        (lambda: theirs.find_simplex(queries))
    yield from add_points_cases(rng, quick)
    yield from hull_cases(rng, quick)


def add_points_cases(rng, quick):
    """add_points of one point to a triangulation of n (incremental=True): each repetition adds
    the next point of a list, the triangulations built outside the timing."""
    for d, n in ((2, 100000 if quick else 1000000), (3, 30000 if quick else 200000)):
        points, extra = rng.random((n, d)), rng.random((1000, d))
        ours, theirs = drange.Delaunay(points, incremental=True), scipy.spatial.Delaunay(points, incremental=True)
        ours_next, theirs_next = iter(extra), iter(extra)
        yield f"Delaunay add_points 1 point to {d}D {n}", (lambda: ours.add_points(next(ours_next)[None])), \
            (lambda: theirs.add_points(next(theirs_next)[None]))


def hull_cases(rng, quick):
    def ball(n, d):
        x = rng.standard_normal((n, d))
        x /= np.linalg.norm(x, axis=1)[:, None]
        return x * rng.random(n)[:, None] ** (1 / d)

    def sphere(n, d):
        x = rng.standard_normal((n, d))
        return x / np.linalg.norm(x, axis=1)[:, None]

    scale = 10 if quick else 1
    inputs = [(f"uniform {d}D", rng.random((n // scale, d))) for d, n in
              ((2, 1000000), (3, 1000000), (4, 1000000), (5, 100000), (6, 20000))]
    inputs += [("ball 3D", ball(1000000 // scale, 3)), ("sphere 2D", sphere(1000000 // scale, 2)),
               ("sphere 3D", sphere(1000000 // scale, 3)), ("sphere 4D", sphere(20000 // scale, 4))]
    for name, points in inputs:
        yield f"ConvexHull {name} {len(points)}", (lambda p=points: drange.ConvexHull(p).volume), \
            (lambda p=points: scipy.spatial.ConvexHull(p).volume)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="small inputs (about 30 s)")
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--only", default="", help="only the cases whose name starts with this (e.g. ConvexHull)")
    parser.add_argument("-o", "--output", help="also write the table to this file")
    args = parser.parse_args()
    lines = [f"drange {drange.__version__} vs scipy {scipy.__version__} (Qhull), one thread, best of {args.repeat}; "
             f"{platform.processor() or platform.machine()}, {os.cpu_count()} cores, load {os.getloadavg()[0]:.2f}",
             "", "| case | drange | scipy | drange/scipy |", "|---|---|---|---|"]
    print("\n".join(lines), flush=True)
    for name, ours, theirs in cases(args.quick):
        if not name.startswith(args.only):
            continue
        a, b = best_time(ours, args.repeat), best_time(theirs, args.repeat)
        line = f"| {name} | {a:.3f} s | {b:.3f} s | {a / b:.2f} |"
        print(line, flush=True)
        lines.append(line)
    lines.append("")
    lines.append(f"Command: `PYTHONPATH=build/python /usr/bin/python3 bench/python_vs_scipy.py {' '.join(sys.argv[1:])}`")
    if args.output:
        with open(args.output, "w") as out:
            out.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
