"""Degenerate inputs, where scipy (Qhull) rejects the points, joggles them, or returns a
triangulation that the exact validator refuses: drange returns a valid Delaunay triangulation.
Each case also records what scipy does, so that a change in scipy is noticed, not assumed."""
from fractions import Fraction

import numpy as np
import pytest
import scipy.spatial

import drange
from conftest import grid, simplex_keys


def exact_volume_sum(points, simplices):
    """Sum of the simplices' volumes times d!, exactly (integer or dyadic coordinates)."""
    total = Fraction(0)
    for row in simplices:
        corners = [[Fraction(x) for x in points[v]] for v in row]
        m = [[a - b for a, b in zip(c, corners[0])] for c in corners[1:]]
        total += abs(determinant(m))
    return total


def determinant(m):
    m = [row[:] for row in m]
    n, sign, result = len(m), 1, Fraction(1)
    for c in range(n):
        pivot = next((r for r in range(c, n) if m[r][c] != 0), None)
        if pivot is None:
            return Fraction(0)
        if pivot != c:
            m[c], m[pivot] = m[pivot], m[c]
            sign = -sign
        result *= m[c][c]
        for r in range(c + 1, n):
            f = m[r][c] / m[c][c]
            m[r] = [a - f * b for a, b in zip(m[r], m[c])]
    return sign * result


def scipy_outcome(points):
    """'rejected', 'invalid' or 'valid': what scipy.spatial.Delaunay does with the points."""
    try:
        simplices = scipy.spatial.Delaunay(points).simplices
    except Exception:  # scipy.spatial.QhullError
        return "rejected"
    return "valid" if drange.check_triangulation(points, simplices)["valid"] else "invalid"


def degenerate_cases():
    rng = np.random.default_rng(7)
    flat = rng.random((50, 3))
    flat[:, 2] *= 1e-13
    plane = rng.random((50, 3))
    plane[:, 2] = 0
    plane[0, 2] = 1e-10
    angles = np.linspace(0, 2 * np.pi, 64, endpoint=False)
    return {
        # what scipy 1.10 returns: flat simplices
        "grid 4D 4^4": grid(4, 4),
        "grid 5D 3^5": grid(3, 5),
        "plane plus one point 1e-10 off": plane,
        # overlapping simplices
        "3D points 1e-13 thin": flat,
        # two triangles
        "grid 10x10 at 1e12": 1e12 + grid(10, 2),
        # depending on the sample, "initial simplex is flat" or an invalid triangulation
        "cluster 1e-6 wide at 1e8": 1e8 + rng.random((200, 2)) * 1e-6,
        # not Delaunay: a point inside a circumcircle
        "64 points on a circle": np.c_[np.cos(angles), np.sin(angles)],
    }


CASES = degenerate_cases()


@pytest.mark.parametrize("name", list(CASES))
def test_valid_where_scipy_fails(name):
    points = CASES[name]
    tri = drange.Delaunay(points)
    report = drange.check_triangulation(points, tri.simplices)
    assert report["valid"], report["problems"]
    assert scipy_outcome(points) in ("rejected", "invalid")


@pytest.mark.parametrize("k,d", [(30, 2), (6, 3), (4, 4)])
def test_grid_volume_is_exact(k, d):
    points = grid(k, d)
    tri = drange.Delaunay(points)
    # The cube [0, k-1]^d has volume (k-1)^d: the simplices' d!-scaled volumes sum to d! (k-1)^d.
    factorial = int(np.prod(np.arange(1, d + 1)))
    assert exact_volume_sum(points, tri.simplices) == factorial * (k - 1) ** d
    assert tri.nsimplex == factorial * (k - 1) ** d  # every simplex of the grid has volume 1/d!


def test_cospherical_points_are_independent_of_input_order():
    x = np.array([[a, b] for a in range(-5, 6) for b in range(-5, 6) if a * a + b * b == 25], float)
    points = np.r_[x, [[0.0, 0.0]]]
    reference = None
    for seed in range(5):
        order = np.random.default_rng(seed).permutation(len(points))
        tri = drange.Delaunay(points[order])
        coords = {tuple(sorted(map(tuple, points[order][row].tolist()))) for row in tri.simplices}
        reference = reference or coords
        assert coords == reference


def test_duplicates_are_reported_as_coplanar():
    rng = np.random.default_rng(4)
    base = rng.random((200, 2))
    points = np.r_[base, base[[3, 5, 5]]]
    tri = drange.Delaunay(points)
    assert tri.coplanar.tolist() == [[200, tri.vertex_to_simplex[3], 3],
                                     [201, tri.vertex_to_simplex[5], 5],
                                     [202, tri.vertex_to_simplex[5], 5]]
    # As scipy's: a duplicate's vertex_to_simplex is a simplex of the point it copies.
    for copy, original in [(200, 3), (201, 5), (202, 5)]:
        assert tri.vertex_to_simplex[copy] == tri.vertex_to_simplex[original]
        assert original in tri.simplices[tri.vertex_to_simplex[copy]]
    assert set(simplex_keys(tri.simplices)) == set(simplex_keys(drange.Delaunay(base).simplices))
    # A duplicate is found in a simplex that holds its original.
    assert 3 in tri.simplices[tri.find_simplex(points[200])]


def contains_exactly(points, simplex, q):
    """Whether the closed simplex holds q, in rationals."""
    corners = [[Fraction(x) for x in points[v]] for v in simplex]
    q = [Fraction(x) for x in q]
    d = len(q)
    for k in range(d + 1):
        rows = [q if i == k else corners[i] for i in range(d + 1)]
        if determinant([[a - b for a, b in zip(r, rows[0])] for r in rows[1:]]) < 0:
            return False
    return True


@pytest.mark.parametrize("k,d", [(5, 2), (3, 3)])
def test_find_simplex_is_exact_on_faces_and_hull(k, d):
    points = grid(k, d)
    tri = drange.Delaunay(points)
    # Every point of the half-integer lattice lies on a vertex, a shared face or the hull.
    queries = grid(2 * k - 1, d) / 2
    found = tri.find_simplex(queries)
    assert (found >= 0).all()
    for q, s in zip(queries, found):
        assert contains_exactly(points, tri.simplices[s], q)
    # One ulp outside the hull is outside.
    outside = np.full(d, 1.0)
    outside[0] = np.nextafter(0.0, -1.0)
    assert tri.find_simplex(outside) == -1
    assert tri.find_simplex(np.full(d, np.nan)) == -1


def test_check_triangulation_reports_problems():
    points = grid(3, 2)
    good = drange.Delaunay(points).simplices
    report = drange.check_triangulation(points, good)
    assert report["valid"] and report["problem_count"] == 0 and report["simplices"] == len(good)
    bad = good[:-1]
    report = drange.check_triangulation(points, bad)
    assert not report["valid"] and report["problems"]
