#!/usr/bin/python3
"""bench/degenerate_families.py: writes the degenerate probe inputs of `bench/run.sh
--degenerate` (its table is in bench/RESULTS.md), in Qhull's format, into a directory.

The probe families: 20 000 points each (5 000 for two_spheres4; 10 000, 3 125, 729 and 1 458
for the 4D to 7D decimal grids; 100 000 for rounded3_dense; 200 000 for ellipsoid_200k) on
curved sets that are not one input sphere (among them smooth surfaces, where the direct search
is weak), a terrain with a flat plateau, and decimal grids and rounded points, whose ties need
the exact stages. They come from one random generator (Python's random module, seed 5).

The surface families (issue 44), each at any size N, in NAME_N.txt:
  square_edges2   uniform on the edges of [-0.5, 0.5]^2, moved inward by up to 1e-10
                  (as Qhull's `rbox N W1e-10 D2`)
  cube_faces3     the same on the faces of the cube (`rbox N W1e-10 D3`)
  cad_part3       the vertices of a mesh of a machined part: a plate with rounded corners and
                  two round holes, flat faces gridded, walls in rings
  cylinder_mesh3  the vertices of a mesh of a cylinder's side, rings staggered by half a step
  torus_mesh3     the vertices of a torus's parameter grid
  bezier_patch3   a bicubic Bezier patch (a freeform surface) evaluated on a parameter grid
  torus4          a 2D torus in R^4 whose tube radius varies (not on one 3-sphere)
The mesh families have exactly N vertices (the grids take a factorisation of N; cad_part3
drops a few seeded random vertices of a slightly finer mesh). Each surface file has a random
generator of its own, seeded by its name and size: one file is the same whether it is written
alone or with the others, and the probe families keep their points.

    bench/degenerate_families.py DIR [--surfaces-only] [--sizes N,...] [--families NAME,...]

  (none)           the probe families and the surface families at 20 000 points (torus4 at
                   5 000): the rows of `bench/run.sh --degenerate`, which also writes
                   cube_faces3 at 200 000 (with --sizes 200000 --families cube_faces3)
  --surfaces-only  no probe families
  --sizes N,...    the surface families at these sizes instead (e.g. 20000,200000,2000000 for
                   the growth comparison of bench/stability.py)
  --families ...   only these surface families

`bench/run.sh --degenerate` writes them into bench/data/families and runs each against CGAL
and Qhull (one table); by hand, per file: drange delaunay DIR/NAME.txt -o /dev/null --stats
--threads 1, and build-bench/bench/drange_bench_run --peer cgal3 (cgal2 in 2D, cgal-dd from 4D,
qhull) --input DIR/NAME.txt. Every file is the same on every run.
"""
import argparse
import itertools
import math
import os
import random
import sys
import zlib

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



# The surface families (issue 44): points on surfaces as scanners and meshers make them, at any
# size, for the growth of the time with the size on one surface.


def boundary_of_box(rng, n, d, width=1e-10):
    """n points uniform on the boundary of [-0.5, 0.5]^d, each moved inward by up to `width` (a
    face of the box chosen uniformly, as all have the same area)."""
    points = []
    for _ in range(n):
        p = [rng.random() - 0.5 for _ in range(d)]
        axis = rng.randrange(d)
        p[axis] = (0.5 - width * rng.random()) * (1 if rng.random() < 0.5 else -1)
        points.append(p)
    return points


def grid_shape(n, aspect):
    """(a, b) with a * b == n and a / b nearest to `aspect`: the sides of a parameter grid of
    exactly n vertices."""
    best = None
    for b in range(1, math.isqrt(n) + 1):
        if n % b:
            continue
        for a, bb in ((n // b, b), (b, n // b)):
            score = abs(math.log(a / bb / aspect))
            if min(a, bb) >= 3 and (best is None or score < best[0]):
                best = (score, a, bb)
    if best is None:
        raise ValueError(f"{n} points cannot make a parameter grid of at least 3 x 3: choose a size with divisors")
    return best[1], best[2]


def torus_mesh(n):
    """The parameter grid of the torus of radii 1 and 0.3 (quads nearly square: a / b = 1 / 0.3)."""
    a, b = grid_shape(n, 1 / 0.3)
    points = []
    for i in range(a):
        u = 2 * math.pi * i / a
        for j in range(b):
            v = 2 * math.pi * j / b
            points.append([(1 + 0.3 * math.cos(v)) * math.cos(u), (1 + 0.3 * math.cos(v)) * math.sin(u),
                           0.3 * math.sin(v)])
    return points


def cylinder_mesh(n):
    """The side of the cylinder of radius 1 and height 2, in rings of m vertices, every other ring
    turned by half a step: the vertices of a mesh of nearly equilateral triangles (a ring's
    distance (2 pi / m) sqrt(3) / 2 gives m / rings = pi sqrt(3) / 2)."""
    m, rings = grid_shape(n, math.pi * math.sqrt(3) / 2)
    points = []
    for i in range(rings):
        z = -1 + 2 * i / (rings - 1)
        for j in range(m):
            t = 2 * math.pi * (j + 0.5 * (i % 2)) / m
            points.append([math.cos(t), math.sin(t), z])
    return points


# A bicubic Bezier patch over the unit square: the control points' x and y are moved off the
# regular 4 x 4 net (else x = u and y = v, a height field over a grid) and their heights make
# two bumps and a saddle.
BEZIER_NET = [[(0.0, 0.0, 0.0), (0.05, 0.33, 0.3), (-0.05, 0.67, -0.2), (0.0, 1.0, 0.1)],
              [(0.33, -0.1, 0.4), (0.45, 0.3, -0.6), (0.25, 0.7, 0.7), (0.4, 1.1, 0.0)],
              [(0.67, 0.1, -0.3), (0.6, 0.4, 0.8), (0.8, 0.6, -0.5), (0.6, 0.9, 0.2)],
              [(1.0, 0.0, 0.1), (1.1, 0.33, -0.2), (0.9, 0.67, 0.3), (1.0, 1.0, 0.0)]]


def bezier_patch(n):
    a, b = grid_shape(n, 1.0)

    def bernstein(t):
        s = 1 - t
        return (s * s * s, 3 * t * s * s, 3 * t * t * s, t * t * t)

    points = []
    for i in range(a):
        bu = bernstein(i / (a - 1))
        for j in range(b):
            bv = bernstein(j / (b - 1))
            points.append([sum(bu[k] * bv[m] * BEZIER_NET[k][m][c] for k in range(4) for m in range(4))
                           for c in range(3)])
    return points


# The machined part of cad_part3: a plate [0, 4] x [0, 2] x [0, 1] with corners rounded to a
# radius of 0.4, pierced by two round holes along z.
PLATE = (4.0, 2.0, 1.0, 0.4)
HOLES = ((1.0, 1.0, 0.5), (3.0, 1.0, 0.3))


def plate_outline(h):
    """Points along the plate's rounded outline, at spacing about h (each straight edge and each
    quarter circle divided evenly: a mesher puts vertices on the curves of the model)."""
    length, width, _, radius = PLATE
    corners = ((length - radius, radius, -0.5 * math.pi), (length - radius, width - radius, 0.0),
               (radius, width - radius, 0.5 * math.pi), (radius, radius, math.pi))
    points = []
    for k, (cx, cy, start) in enumerate(corners):
        # The straight edge from the previous corner's arc to this one's, then this arc.
        px, py, pstart = corners[k - 1]
        x0, y0 = px + radius * math.cos(pstart + 0.5 * math.pi), py + radius * math.sin(pstart + 0.5 * math.pi)
        x1, y1 = cx + radius * math.cos(start), cy + radius * math.sin(start)
        steps = max(1, round(math.hypot(x1 - x0, y1 - y0) / h))
        points += [(x0 + (x1 - x0) * s / steps, y0 + (y1 - y0) * s / steps) for s in range(steps)]
        steps = max(2, round(0.5 * math.pi * radius / h))
        points += [(cx + radius * math.cos(start + 0.5 * math.pi * s / steps),
                    cy + radius * math.sin(start + 0.5 * math.pi * s / steps)) for s in range(steps)]
    return points


def inside_plate(x, y, margin):
    """True when (x, y) is inside the plate's outline and outside its holes by at least margin."""
    length, width, _, radius = PLATE
    qx = abs(x - 0.5 * length) - (0.5 * length - radius)
    qy = abs(y - 0.5 * width) - (0.5 * width - radius)
    outside = math.hypot(max(qx, 0.0), max(qy, 0.0)) + min(max(qx, qy), 0.0) - radius
    return outside <= -margin and all(math.hypot(x - cx, y - cy) >= r + margin for cx, cy, r in HOLES)


def cad_mesh(h):
    """The vertices of a mesh of the part at spacing about h: the outline and the holes' circles
    at every level of the walls, and on the top and bottom faces a square grid kept h / 2 away
    from the edges."""
    length, width, height, _ = PLATE
    curves = plate_outline(h)
    for cx, cy, r in HOLES:
        steps = max(8, round(2 * math.pi * r / h))
        curves += [(cx + r * math.cos(2 * math.pi * s / steps), cy + r * math.sin(2 * math.pi * s / steps))
                   for s in range(steps)]
    levels = max(1, round(height / h))
    points = [[x, y, height * k / levels] for k in range(levels + 1) for x, y in curves]
    face = [(i * h, j * h) for i in range(1, int(length / h) + 1) for j in range(1, int(width / h) + 1)
            if inside_plate(i * h, j * h, 0.5 * h)]
    points += [[x, y, z] for z in (0.0, height) for x, y in face]
    return points


def cad_part(rng, n):
    """Exactly n vertices of the part: the mesh whose spacing gives n or a few more, less
    seeded random vertices."""
    length, width, height, _ = PLATE
    area = 2 * length * width + 2 * (length + width) * height + sum(2 * math.pi * r * height for _, _, r in HOLES)
    h = math.sqrt(area / n)
    points = cad_mesh(h)
    for _ in range(50):
        if n <= len(points) <= n * 1.02 + 10:
            break
        h *= math.sqrt(len(points) / (n * 1.01))
        points = cad_mesh(h)
    while len(points) < n:
        h *= 0.995
        points = cad_mesh(h)
    dropped = set(rng.sample(range(len(points)), len(points) - n))
    return [p for i, p in enumerate(points) if i not in dropped]


def torus4(rng, n):
    """n points on the torus (cos a, sin a, r cos b, r sin b) in R^4 with r = 0.5 + 0.2 cos 3a,
    a and b uniform: a surface in R^4 that is not on one 3-sphere (|p|^2 = 1 + r^2 varies)."""
    points = []
    for _ in range(n):
        a, b = 2 * math.pi * rng.random(), 2 * math.pi * rng.random()
        r = 0.5 + 0.2 * math.cos(3 * a)
        points.append([math.cos(a), math.sin(a), r * math.cos(b), r * math.sin(b)])
    return points


# name: (dimension, maker(rng, n)).
SURFACES = {
    "square_edges2": (2, lambda rng, n: boundary_of_box(rng, n, 2)),
    "cube_faces3": (3, lambda rng, n: boundary_of_box(rng, n, 3)),
    "cad_part3": (3, cad_part),
    "cylinder_mesh3": (3, lambda rng, n: cylinder_mesh(n)),
    "torus_mesh3": (3, lambda rng, n: torus_mesh(n)),
    "bezier_patch3": (3, lambda rng, n: bezier_patch(n)),
    "torus4": (4, torus4),
}
# The surface files written by default: every family at 20 000 points (torus4 at 5 000, as the
# 4D probes). Larger ones only when asked (--sizes): scripts/same_output.sh runs every default
# file four times.
DEFAULT_SURFACE_ROWS = [(name, 5000 if dim == 4 else 20000) for name, (dim, _) in SURFACES.items()]


def surface_file_name(name, n):
    return f"{name}_{n}"


def surface(name, n):
    """The points of surface family `name` at size n, from a generator seeded by both."""
    make = SURFACES[name][1]
    return make(random.Random(zlib.crc32(f"{name}:{n}".encode())), n)


def write(directory, name, points):
    with open(os.path.join(directory, name + ".txt"), "w") as out:
        out.write(f"{len(points[0])}\n{len(points)}\n")
        for p in points:
            out.write(" ".join(repr(x) for x in p) + "\n")
    print(name, len(points))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("directory")
    ap.add_argument("--surfaces-only", action="store_true", help="no probe families")
    ap.add_argument("--sizes", default="", help="the surface families at these sizes (N,N,...)")
    ap.add_argument("--families", default="", help="only these surface families (NAME,NAME,...)")
    args = ap.parse_args()
    try:
        sizes = [int(x) for x in args.sizes.split(",")] if args.sizes else []
    except ValueError:
        ap.error(f"--sizes: '{args.sizes}' is not a list of integers")
    if any(n < 10 for n in sizes):
        ap.error("--sizes: every size must be at least 10")
    names = args.families.split(",") if args.families else list(SURFACES)
    unknown = [name for name in names if name not in SURFACES]
    if unknown:
        ap.error(f"--families: unknown {', '.join(unknown)} (known: {', '.join(SURFACES)})")
    rows = [(name, n) for name in names for n in sizes] if sizes else \
        [(name, n) for name, n in DEFAULT_SURFACE_ROWS if name in names]
    os.makedirs(args.directory, exist_ok=True)
    if not args.surfaces_only:
        for name, points in families(random.Random(5)):
            write(args.directory, name, points)
    for name, n in rows:
        try:
            points = surface(name, n)
        except ValueError as e:
            sys.exit(f"bench/degenerate_families.py: {name} at {n}: {e}")
        write(args.directory, surface_file_name(name, n), points)


if __name__ == "__main__":
    main()
