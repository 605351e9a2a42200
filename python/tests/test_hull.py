"""drange.ConvexHull against scipy.spatial.ConvexHull (Qhull) on points in general position, and
its exact properties on degenerate input where Qhull's answer depends on its tolerances."""
import copy
import itertools
import math
import pickle

import numpy as np
import pytest
import scipy.spatial

import drange
from conftest import grid, neighbor_map, sample, simplex_keys


def ball(n, d, seed):
    rng = np.random.default_rng(seed)
    x = rng.standard_normal((n, d))
    x /= np.linalg.norm(x, axis=1)[:, None]
    return x * rng.random(n)[:, None] ** (1 / d)


def sphere(n, d, seed):
    x = np.random.default_rng(seed).standard_normal((n, d))
    return x / np.linalg.norm(x, axis=1)[:, None]


def assert_like_scipy(points):
    ours = drange.ConvexHull(points)
    theirs = scipy.spatial.ConvexHull(points)
    assert sorted(simplex_keys(ours.simplices)) == sorted(simplex_keys(theirs.simplices))
    assert neighbor_map(ours.simplices, ours.neighbors) == neighbor_map(theirs.simplices, theirs.neighbors)
    if points.shape[1] == 2:  # both counter-clockwise, from their own first vertex
        start = list(theirs.vertices).index(ours.vertices[0])
        assert np.array_equal(ours.vertices, np.roll(theirs.vertices, -start))
    else:
        assert np.array_equal(ours.vertices, np.sort(theirs.vertices))
    order = {key: i for i, key in enumerate(simplex_keys(theirs.simplices))}
    matched = theirs.equations[[order[key] for key in simplex_keys(ours.simplices)]]
    np.testing.assert_allclose(ours.equations, matched, rtol=0, atol=1e-12)
    assert ours.area == pytest.approx(theirs.area, rel=1e-12)
    assert ours.volume == pytest.approx(theirs.volume, rel=1e-12)
    assert len(ours.coplanar) == 0 and ours.good is None
    return ours


@pytest.mark.parametrize("d", [2, 3, 4, 5, 6])
@pytest.mark.parametrize("kind", ["uniform", "gaussian"])
def test_random_input_agrees_with_scipy(d, kind):
    for seed, n in [(1, d + 1), (2, d + 3), (3, 60), (4, 400 if d <= 4 else 150)]:
        assert_like_scipy(sample(kind, n, d, seed))


@pytest.mark.parametrize("d", [2, 3, 4, 5])
def test_ball_and_sphere_agree_with_scipy(d):
    assert_like_scipy(ball(3000 if d <= 3 else 600, d, 7))
    hull = assert_like_scipy(sphere(1000 if d <= 3 else 200, d, 8))
    assert len(hull.vertices) == len(hull.points)  # every point of a sphere is extreme


def test_vertices_are_counter_clockwise_in_2d():
    points = np.random.default_rng(1234).random((30, 2))
    hull = drange.ConvexHull(points)
    assert np.array_equal(np.unique(hull.simplices), np.sort(hull.vertices))
    x, y = hull.points[hull.vertices].T
    angle = np.arctan2(y - y.mean(), x - x.mean())
    assert np.all(np.diff(np.unwrap(angle)) > 0)


def exact_sides(points, facet):
    """sign of det[v1 - v0, ..., x - v0] for every point x (the facets' orientation: (-1)^d
    inside). Exact for the small integer coordinates the degenerate tests use: the float
    determinant of such entries is within far less than 1/2 of the integer it must be."""
    assert np.array_equal(points, np.round(points)) and np.abs(points).max() <= 64
    base = points[facet[0]]
    rows = np.broadcast_to(points[facet[1:]] - base, (len(points), len(facet) - 1, points.shape[1]))
    matrices = np.concatenate([rows, (points - base)[:, None, :]], axis=1)
    return np.sign(np.round(np.linalg.det(matrices))).astype(int)


def delaunay_volume(points):
    tri = drange.Delaunay(points)
    corners = points[tri.simplices]
    return np.abs(np.linalg.det(corners[:, 1:] - corners[:, :1])).sum() / math.factorial(points.shape[1])


def assert_valid(points, hull, exact=True):
    """Every point inside or on every facet (the equations, and exactly on rationals), every
    ridge in exactly two facets, the neighbours across them, the volume of the triangulation."""
    d = points.shape[1]
    distances = points @ hull.equations[:, :d].T + hull.equations[:, d]
    assert distances.max() <= 1e-12 * max(1.0, np.abs(points).max())
    if exact:
        inside = 1 if d % 2 == 0 else -1
        for facet in hull.simplices.tolist():
            assert np.all(np.isin(exact_sides(points, facet), [0, inside]))
    ridges = {}
    for f, facet in enumerate(hull.simplices.tolist()):
        for k in range(d):
            ridge = tuple(sorted(facet[:k] + facet[k + 1:]))
            ridges.setdefault(ridge, []).append(f)
            assert set(ridge) <= set(hull.simplices[hull.neighbors[f, k]].tolist())
    assert all(len(facets) == 2 for facets in ridges.values())
    assert hull.volume == pytest.approx(delaunay_volume(points), rel=1e-12)


@pytest.mark.parametrize("d,k", [(2, 6), (3, 5), (4, 4), (5, 3)])
def test_grid_is_valid_with_corners_as_vertices(d, k):
    points = grid(k, d)
    hull = drange.ConvexHull(points)
    assert_valid(points, hull)
    extreme = np.isin(points, [0, k - 1])
    assert np.array_equal(np.sort(hull.vertices), np.flatnonzero(extreme.all(axis=1)))
    assert np.array_equal(np.sort(hull.coplanar[:, 0]), np.flatnonzero(extreme.any(axis=1) & ~extreme.all(axis=1)))
    assert hull.volume == pytest.approx((k - 1) ** d, rel=1e-12)
    assert hull.area == pytest.approx(2 * d * (k - 1) ** (d - 1), rel=1e-12)
    # Every facet lies in a face of the cube: its equation is an axis, exactly.
    assert set(np.abs(hull.equations[:, :d]).round(15).ravel().tolist()) == {0.0, 1.0}


def test_points_on_faces_edges_and_copies_are_coplanar():
    corners = np.array(list(itertools.product([0.0, 1.0], repeat=3)))
    faces = np.array([[0.5, 0.5, 0], [0.5, 0.5, 1], [0, 0.5, 0.5], [0.25, 0.75, 1]])
    edges = np.array([[0.5, 0, 0], [1, 0.5, 1]])
    centre = np.array([[0.5, 0.5, 0.5]])
    points = 4 * np.vstack([corners, faces, edges, corners[:3], centre])  # integers: exact_sides
    hull = drange.ConvexHull(points)
    assert_valid(points, hull)
    assert hull.nsimplex == 12 and np.array_equal(hull.vertices, np.arange(8))
    assert np.array_equal(np.sort(hull.coplanar[:, 0]), np.arange(8, 17))  # not the centre
    for point, facet, vertex in hull.coplanar.tolist():
        assert abs(hull.equations[facet, :3] @ points[point] + hull.equations[facet, 3]) < 1e-15
        assert vertex in hull.simplices[facet]


def test_degenerate_input_where_scipy_needs_its_tolerances():
    # Cospherical integer points, collinear points on a big triangle's sides, and a grid's
    # corners repeated: scipy's facets depend on its merging; drange's are exact.
    rng = np.random.default_rng(3)
    circle = np.array([[x, y] for x in range(-25, 26) for y in range(-25, 26) if x * x + y * y == 625], float)
    triangle = np.vstack([[[0, 0], [8, 0], [0, 8]], [[t, 0] for t in range(1, 8)], [[t, 8 - t] for t in range(1, 8)]])
    sides = np.vstack([grid(3, 3), grid(3, 3)])
    square = np.vstack([grid(2, 2) * 16, rng.integers(0, 17, (40, 2))])  # many on the sides
    for points in [circle, triangle.astype(float), sides, square.astype(float)]:
        hull = drange.ConvexHull(points)
        assert_valid(points, hull)
        theirs = scipy.spatial.ConvexHull(points)
        assert hull.volume == pytest.approx(theirs.volume, rel=1e-12)
        assert set(hull.vertices.tolist()) <= set(range(len(points)))


def test_any_order_gives_the_same_facets():
    points = np.vstack([grid(4, 3), grid(4, 3)[:10]])  # with copies
    hull = drange.ConvexHull(points)
    order = np.random.default_rng(5).permutation(len(points))
    permuted = drange.ConvexHull(points[order])
    by_coordinates = lambda h, p: sorted(tuple(sorted(map(tuple, p[f].tolist()))) for f in h.simplices)
    assert by_coordinates(hull, points) == by_coordinates(permuted, points[order])


def test_large_degenerate_input_is_valid():
    points = grid(30, 3)  # 27 000 points, 5 048 on the boundary
    hull = drange.ConvexHull(points)
    assert_valid(points, hull, exact=False)
    assert len(hull.vertices) == 8 and len(hull.coplanar) == 30 ** 3 - 28 ** 3 - 8


SQUARE_AND_ONE = np.array([[0.2, 0.2], [0.2, 0.4], [0.4, 0.4], [0.4, 0.2], [0.3, 0.6]])


@pytest.mark.parametrize("points,option", [
    (SQUARE_AND_ONE, "QG4"), (SQUARE_AND_ONE, "QG-4"), (SQUARE_AND_ONE, "QG0"),
    (np.vstack([SQUARE_AND_ONE[:4], [[0.3, 0.3]]]), "QG4"),
    (np.array([[0.0, 0.0, 0.0], [0.90029516, -0.39187448, 0.18948093], [0.48676420, -0.72627633, 0.48536925],
               [0.57651530, -0.81179274, -0.09285832], [0.67846893, -0.71119562, 0.18406710]]), "QG0"),
    (sample("uniform", 40, 4, 9), "QG7"), (sample("uniform", 40, 3, 9) * 2 - 0.5, "QG-3")])
def test_good_facets_as_scipy(points, option):
    ours = drange.ConvexHull(points, qhull_options=option)
    theirs = scipy.spatial.ConvexHull(points, qhull_options=option)
    assert sorted(simplex_keys(ours.simplices)) == sorted(simplex_keys(theirs.simplices))
    good = lambda h: sorted(key for key, g in zip(simplex_keys(h.simplices), h.good) if g)
    assert good(ours) == good(theirs)
    n = int(option.lstrip("QG-"))
    assert n not in ours.vertices and n not in ours.simplices


def test_good_is_strict_visibility():
    # Point 4 on the square's top side: on a facet's hyperplane, it sees none.
    points = np.vstack([SQUARE_AND_ONE[:4], [[0.3, 0.4]]])
    assert not drange.ConvexHull(points, qhull_options="QG4").good.any()
    assert drange.ConvexHull(points, qhull_options="QG-4").good.all()


def test_errors():
    with pytest.raises(ValueError, match="NaN"):
        drange.ConvexHull([[0, 0], [1, 1], [2, np.nan]])
    with pytest.raises(drange.DegenerateInputError, match="dimension 1") as error:
        drange.ConvexHull([[0, 0], [1, 1], [2, 2]])
    assert isinstance(error.value, scipy.spatial.QhullError)
    with pytest.raises(drange.DegenerateInputError):
        drange.ConvexHull([[0, 0, 0], [1, 0, 0], [0, 1, 0]])  # too few points
    with pytest.raises(ValueError, match="No points"):
        drange.ConvexHull(np.empty((0, 3)))
    with pytest.raises(ValueError, match="2-D"):
        drange.ConvexHull([0.0, 1.0, 2.0])
    with pytest.raises(ValueError, match="dimension 1"):
        drange.ConvexHull([[0.0], [1.0]])
    with pytest.raises(ValueError, match="QJ"):
        drange.ConvexHull(np.eye(3), qhull_options="QJ")
    with pytest.raises(ValueError, match="QG"):
        drange.ConvexHull(np.eye(3), qhull_options="QGx")
    with pytest.raises(ValueError, match="does not exist"):
        drange.ConvexHull(np.eye(3), qhull_options="QG5")
    with pytest.raises(drange.DegenerateInputError):
        drange.ConvexHull(np.eye(3), incremental=True)
    with pytest.raises(RuntimeError, match="incremental"):
        drange.ConvexHull(np.vstack([np.eye(3), np.zeros(3)])).add_points([[1, 1, 1]])


def test_pickle_and_copy():
    points = sample("uniform", 50, 3, 4)
    hull = drange.ConvexHull(points, qhull_options="QG2")
    hull.area  # a cached value
    for other in [pickle.loads(pickle.dumps(hull)), copy.copy(hull), copy.deepcopy(hull)]:
        assert np.array_equal(other.simplices, hull.simplices) and np.array_equal(other.good, hull.good)
        assert other.area == hull.area and other.volume == hull.volume
        assert np.array_equal(other.equations, hull.equations)
    assert drange.ConvexHull(points).nsimplex == scipy.spatial.ConvexHull(points).nsimplex
    hull.close()
