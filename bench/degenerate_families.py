#!/usr/bin/python3
"""bench/degenerate_families.py: writes the degenerate probe inputs of `bench/run.sh
--degenerate` (its table is in bench/RESULTS.md): 20 000 points each (5 000 for two_spheres4;
10 000, 3 125, 729 and 1 458 for the 4D to 7D decimal grids; 100 000 for rounded3_dense;
200 000 for ellipsoid_200k) on curved sets that are not one input sphere (among them smooth
surfaces, where the direct search is weak), a terrain with a flat plateau, and decimal grids and
rounded points, whose ties need the exact stages, in Qhull's format, into a directory.

    bench/degenerate_families.py DIR

`bench/run.sh --degenerate` writes them into bench/data/families and runs each against CGAL
and Qhull (one table); by hand, per file: drange delaunay DIR/NAME.txt -o /dev/null --stats
--threads 1, and build-bench/bench/drange_bench_run --peer cgal3 (cgal2 in 2D, cgal-dd from 4D,
qhull) --input DIR/NAME.txt. The points come from Python's random module with a fixed
seed: the same files on every run.
"""
import itertools
import math
import os
import random
import sys

N = 20000


def on_sphere(rng, d):
    v = [rng.gauss(0, 1) for _ in range(d)]
    s = math.sqrt(sum(x * x for x in v))
    return [x / s for x in v]


def families(rng):
    yield "two_circles", [[x * r for x in on_sphere(rng, 2)] for r in (1, 0.5) for _ in range(N // 2)]
    yield "two_spheres3", [[x * r for x in on_sphere(rng, 3)] for r in (1, 0.5) for _ in range(N // 2)]
    for d in (2, 3):
        centres = [[rng.uniform(-1, 1) for _ in range(d)] for _ in range(20)]
        yield f"bubbles{d}", [[c[k] + 0.05 * x[k] for k in range(d)] for c in centres
                              for x in (on_sphere(rng, d) for _ in range(N // 20))]
    yield "cylinder", [[math.cos(t), math.sin(t), rng.uniform(-1, 1)]
                       for t in (rng.uniform(0, 2 * math.pi) for _ in range(N))]
    yield "cylinder_rings", [[math.cos(2 * math.pi * j / 200), math.sin(2 * math.pi * j / 200), i / 50.0]
                             for i in range(100) for j in range(200)]
    yield "circle_in_3d", [on_sphere(rng, 2) + [0.0] for _ in range(N)] + [[0.0, 0.0, 1.0], [0.0, 0.0, -1.0]]
    yield "hemisphere", [[x[0], x[1], abs(x[2])] for x in (on_sphere(rng, 3) for _ in range(N))]
    torus = []
    for _ in range(N):
        a, b = rng.uniform(0, 2 * math.pi), rng.uniform(0, 2 * math.pi)
        torus.append([(1 + 0.3 * math.cos(b)) * math.cos(a), (1 + 0.3 * math.cos(b)) * math.sin(a), 0.3 * math.sin(b)])
    yield "torus", torus
    yield "sphere_in_ball", ([on_sphere(rng, 3) for _ in range(N * 4 // 5)] +
                             [[x * rng.random() ** (1 / 3) for x in on_sphere(rng, 3)] for _ in range(N // 5)])
    # Concentric spheres: five in 3D, two in 4D, and the eight layers of a spherical grid (the
    # same 2 500 Fibonacci points at each radius, as in Earth models).
    yield "five_spheres3", [[x * r for x in on_sphere(rng, 3)] for r in (1, 0.8, 0.6, 0.4, 0.2) for _ in range(N // 5)]
    yield "two_spheres4", [[x * r for x in on_sphere(rng, 4)] for r in (1, 0.5) for _ in range(N // 8)]
    fibonacci = []
    for i in range(N // 8):
        z = 1 - 2 * (i + 0.5) / (N // 8)
        angle = math.pi * (3 - math.sqrt(5)) * i
        fibonacci.append([math.sqrt(1 - z * z) * math.cos(angle), math.sqrt(1 - z * z) * math.sin(angle), z])
    yield "layers3", [[x * (6371 - 300 * k) for x in p] for k in range(8) for p in fibonacci]
    yield "polar_grid", [[r / 50 * math.cos(2 * math.pi * j / 400), r / 50 * math.sin(2 * math.pi * j / 400)]
                         for r in range(1, 51) for j in range(400)]
    # A terrain (2.5D): half the points on a flat plateau at z = 0.3 (a coordinate no power of
    # two divides), the rest on a wavy slope.
    plateau = []
    for _ in range(N):
        x, y = rng.random(), rng.random()
        plateau.append([x, y, 0.3 if x < 0.5 else 0.3 + 0.2 * (x - 0.5) * math.sin(7 * y)])
    yield "plateau", plateau
    # Decimal data: grids of 0.1 k and 0.01 k (as numpy.arange makes them: no power of two
    # divides the coordinates, so every tie is for the exact stages), and uniform points rounded
    # to two decimals (distinct), as in CSV files.
    yield "decimal_grid3", [[0.1 * i, 0.1 * j, 0.1 * k] for i in range(27) for j in range(27) for k in range(27)]
    yield "decimal_grid2", [[0.01 * i, 0.01 * j] for i in range(200) for j in range(100)]
    rounded = {}
    while len(rounded) < N:
        p = tuple(round(rng.random(), 2) for _ in range(3))
        rounded[p] = None
    yield "rounded3", [list(p) for p in rounded]
    # Denser decimal data: 100 000 distinct points rounded to 0.01 in 3D (a tenth of the
    # lattice's sites taken: four points of a lattice plane on one circle abound), and 20 000
    # rounded to 0.05 in 4D.
    rounded = {}
    while len(rounded) < 100000:
        rounded[tuple(round(rng.random(), 2) for _ in range(3))] = None
    yield "rounded3_dense", [list(p) for p in rounded]
    rounded = {}
    while len(rounded) < N:
        rounded[tuple(round(rng.random() * 20) / 20 for _ in range(4))] = None
    yield "rounded4", [list(p) for p in rounded]
    # Decimal grids in 4D and 5D: 10^4 and 5^5 points of 0.1 k, whose ties go to the exact
    # integer stages.
    yield "decimal_grid4", [[0.1 * i, 0.1 * j, 0.1 * k, 0.1 * m] for i in range(10) for j in range(10)
                            for k in range(10) for m in range(10)]
    yield "decimal_grid5", [[0.1 * i, 0.1 * j, 0.1 * k, 0.1 * m, 0.1 * q] for i in range(5) for j in range(5)
                            for k in range(5) for m in range(5) for q in range(5)]
    # And in 6D and 7D: {0, .1, .2}^6 and {0, .1, .2}^6 x {0, .1}.
    yield "decimal_grid6", [[0.1 * x for x in p] for p in itertools.product(range(3), repeat=6)]
    yield "decimal_grid7", [[0.1 * x for x in p + (z,)] for p in itertools.product(range(3), repeat=6) for z in range(2)]
    # Smooth surfaces that are no sphere, as a scan samples an object: an ellipse in the plane,
    # an ellipsoid of axes 1, 0.7 and 0.4 (20 000 and 200 000 points), and a sphere with waves
    # of a fifth of its radius. (Last, so that the families above keep their points: they share
    # one random generator.)
    yield "ellipse", [[x[0], 0.6 * x[1]] for x in (on_sphere(rng, 2) for _ in range(N))]
    for name, count in (("ellipsoid", N), ("ellipsoid_200k", 10 * N)):
        yield name, [[x[0], 0.7 * x[1], 0.4 * x[2]] for x in (on_sphere(rng, 3) for _ in range(count))]
    wavy = []
    for _ in range(N):
        x = on_sphere(rng, 3)
        polar, azimuth = math.acos(max(-1.0, min(1.0, x[2]))), math.atan2(x[1], x[0])
        r = 1 + 0.2 * math.sin(3 * polar) * math.cos(2 * azimuth)
        wavy.append([r * c for c in x])
    yield "wavy_sphere", wavy


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    directory = sys.argv[1]
    os.makedirs(directory, exist_ok=True)
    rng = random.Random(5)
    for name, points in families(rng):
        with open(os.path.join(directory, name + ".txt"), "w") as out:
            out.write(f"{len(points[0])}\n{len(points)}\n")
            for p in points:
                out.write(" ".join(repr(x) for x in p) + "\n")
        print(name, len(points))


if __name__ == "__main__":
    main()
