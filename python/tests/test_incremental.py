"""incremental=True and add_points: the result equals a new object on all the points, for
Delaunay, Voronoi, ConvexHull and HalfspaceIntersection; the state's life (close, restart,
copies, pickles) and its errors."""
import copy
import pickle

import numpy as np
import pytest

import scipy.spatial

import drange


def simplex_set(simplices):
    return sorted(tuple(sorted(s)) for s in simplices.tolist())


def grow(cls, points, initial, chunk, **kwargs):
    grown = cls(points[:initial], incremental=True, **kwargs)
    for start in range(initial, len(points), chunk):
        grown.add_points(points[start:start + chunk])
    return grown


@pytest.mark.parametrize("ndim", [2, 3, 4, 5])
@pytest.mark.parametrize("chunk", [1, 5, 1000])
def test_delaunay_grown_equals_fresh(ndim, chunk):
    points = np.random.default_rng(ndim).random((300 if ndim <= 3 else 120, ndim))
    grown = grow(drange.Delaunay, points, ndim + 2, chunk)
    fresh = drange.Delaunay(points)
    assert grown.npoints == len(points)
    assert simplex_set(grown.simplices) == simplex_set(fresh.simplices)
    assert grown.statistics["algorithm"] == "incremental"
    # The derived attributes follow the new simplices (cached ones are dropped).
    assert simplex_set(grown.convex_hull) == simplex_set(fresh.convex_hull)
    queries = np.random.default_rng(9).random((50, ndim))
    inside = grown.find_simplex(queries)
    assert ((inside >= 0) == (fresh.find_simplex(queries) >= 0)).all()
    found = inside >= 0
    transform = grown.transform[inside[found]]
    barycentric = np.einsum("ijk,ik->ij", transform[:, :ndim], queries[found] - transform[:, ndim])
    assert (barycentric >= -1e-9).all() and (barycentric.sum(axis=1) <= 1 + 1e-9).all()


def test_degenerate_and_duplicate_points_added():
    # A grid grown ring by ring: each ring's points are cocircular with the ones inside, and
    # the corners come twice (duplicates).
    rings = [np.array([[i, -r], [i, r], [-r, i], [r, i]], dtype=float)
             for r in range(1, 6) for i in range(-r, r + 1)]
    points = np.concatenate(rings)
    grown = grow(drange.Delaunay, points, 8, 3)
    fresh = drange.Delaunay(points)
    assert simplex_set(grown.simplices) == simplex_set(fresh.simplices)
    assert sorted(grown.coplanar[:, [0, 2]].tolist()) == sorted(fresh.coplanar[:, [0, 2]].tolist())
    assert (grown.vertex_to_simplex >= 0).all()


def test_restart_close_and_errors():
    points = np.random.default_rng(1).random((60, 2))
    restarted = drange.Delaunay(points[:10], incremental=True)
    restarted.add_points(points[10:], restart=True)
    assert simplex_set(restarted.simplices) == simplex_set(drange.Delaunay(points).simplices)
    with pytest.raises(ValueError, match="shape"):
        restarted.add_points(np.zeros((2, 3)))
    with pytest.raises(ValueError, match="point 61, coordinate 0 is NaN"):
        restarted.add_points([[0.5, 0.5], [np.nan, 0.5]])
    assert restarted.npoints == 60  # a refused batch changes nothing
    restarted.add_points(np.empty((0, 2)))
    assert restarted.npoints == 60
    restarted.close()
    with pytest.raises(RuntimeError, match="closed"):
        restarted.add_points(points[:1])
    with pytest.raises(RuntimeError, match="incremental"):
        drange.Delaunay(points).add_points(points[:1])
    with pytest.raises(drange.DegenerateInputError, match="span 2 dimensions"):
        drange.Delaunay([[0, 0], [1, 1], [2, 2]], incremental=True)


def test_copies_and_pickles_keep_their_own_state():
    points = np.random.default_rng(2).random((80, 3))
    original = drange.Delaunay(points[:40], incremental=True)
    deep, shallow = copy.deepcopy(original), copy.copy(original)
    restored = pickle.loads(pickle.dumps(original))
    original.add_points(points[40:60])
    assert deep.npoints == 40 and restored.npoints == 40 and shallow.npoints == 40
    for other in (deep, shallow, restored):
        other.add_points(points[40:])
        assert simplex_set(other.simplices) == simplex_set(drange.Delaunay(points).simplices)
    assert original.npoints == 60


@pytest.mark.parametrize("ndim", [2, 3])
def test_voronoi_grown_equals_fresh(ndim):
    points = np.random.default_rng(5 + ndim).random((200, ndim))
    grown = grow(drange.Voronoi, points, 20, 17)
    fresh = drange.Voronoi(points)
    assert np.array_equal(np.sort(grown.ridge_points, axis=1)[np.lexsort(np.sort(grown.ridge_points, axis=1).T)],
                          np.sort(fresh.ridge_points, axis=1)[np.lexsort(np.sort(fresh.ridge_points, axis=1).T)])
    assert np.allclose(grown.volumes[grown.point_region], fresh.volumes[fresh.point_region])
    assert np.allclose(np.sort(grown.vertices, axis=0), np.sort(fresh.vertices, axis=0))


def test_hull_and_halfspaces_grown_equal_fresh():
    points = np.random.default_rng(3).standard_normal((150, 3))
    grown = grow(drange.ConvexHull, points, 10, 20, qhull_options="QG0")
    fresh = drange.ConvexHull(points, qhull_options="QG0")
    assert simplex_set(grown.simplices) == simplex_set(fresh.simplices)
    assert np.array_equal(grown.vertices, fresh.vertices)
    assert grown.volume == fresh.volume and np.array_equal(grown.good, fresh.good)
    with pytest.raises(ValueError, match="point 150, coordinate 2 is NaN"):
        grown.add_points([[0.0, 0.0, np.nan]])
    assert grown.npoints == 150 and simplex_set(grown.simplices) == simplex_set(fresh.simplices)
    square = np.array([[-1.0, 0, 0], [1, 0, -1], [0, -1, 0], [0, 1, -1]])
    cut = np.array([[1.0, 1, -1.5]])
    grown = drange.HalfspaceIntersection(square, [0.5, 0.5], incremental=True)
    grown.add_halfspaces(cut)
    fresh = drange.HalfspaceIntersection(np.r_[square, cut], [0.5, 0.5])
    assert np.allclose(np.sort(grown.intersections, axis=0), np.sort(fresh.intersections, axis=0))
    assert grown.dual_facets == fresh.dual_facets
    # A refused add (the interior point is outside the new halfspace) leaves the object as it was.
    with pytest.raises(drange.Error):
        grown.add_halfspaces([[1.0, 1.0, -0.5]])
    assert grown.nineq == 5 and np.allclose(np.sort(grown.intersections, axis=0), np.sort(fresh.intersections, axis=0))
    assert len(grown.dual_points) == 5
    with pytest.raises(NotImplementedError, match="furthest_site"):
        drange.Voronoi(points[:, :2], furthest_site=True).clipped_cells()


@pytest.mark.parametrize("ndim", [2, 3, 4])
def test_furthest_site_agrees_with_scipy(ndim):
    # Random points: the furthest-site triangulation is unique, so Qhull's is the same.
    points = np.random.default_rng(20 + ndim).random((60, ndim))
    ours = tri = drange.Delaunay(points, furthest_site=True)
    theirs = scipy.spatial.Delaunay(points, furthest_site=True)
    assert ours.furthest_site and simplex_set(ours.simplices) == simplex_set(theirs.simplices)
    assert simplex_set(ours.convex_hull) == simplex_set(theirs.convex_hull)
    inner = np.setdiff1d(np.arange(len(points)), ours.simplices)
    assert (ours.vertex_to_simplex[inner] == -1).all()
    grown = grow(drange.Delaunay, points, 20, 7, furthest_site=True)
    assert simplex_set(grown.simplices) == simplex_set(ours.simplices)
    if ndim <= 3:
        ours, theirs = drange.Voronoi(points, furthest_site=True), scipy.spatial.Voronoi(points, furthest_site=True)
        assert ours.furthest_site
        assert np.allclose(np.sort(ours.vertices, axis=0), np.sort(theirs.vertices, axis=0))
        # scipy leaves out a ridge with one finite vertex (an edge in a single tetrahedron,
        # docs/formats.md); drange keeps it.
        extra = set(simplex_set(ours.ridge_points)) - set(simplex_set(theirs.ridge_points))
        assert set(simplex_set(theirs.ridge_points)) <= set(simplex_set(ours.ridge_points))
        assert all(sorted(ours.ridge_dict.get(k, ours.ridge_dict.get(k[::-1])))[0] == -1 and
                   len(ours.ridge_dict.get(k, ours.ridge_dict.get(k[::-1]))) == 2 for k in extra)
        assert ndim == 3 or not extra
        # Each point's region: the same vertices (as coordinates); empty for inner points.
        for p in range(len(points)):
            a = ours.regions[ours.point_region[p]]
            b = theirs.regions[theirs.point_region[p]]
            assert (-1 in a) == (-1 in b) and len(a) == len(b), p
        assert np.isinf(ours.volumes[ours.point_region[tri.simplices.ravel()]]).all()
        assert (ours.volumes[ours.point_region[inner]] == 0).all()


def test_furthest_site_degenerate():
    # A grid: its furthest-site triangulation uses the four corners alone, two triangles
    # whose circumcircle is the one through all four (a tie the perturbation breaks).
    grid = np.array([(x, y) for x in range(5) for y in range(5)], dtype=float)
    tri = drange.Delaunay(grid, furthest_site=True)
    assert tri.nsimplex == 2 and set(tri.simplices.ravel().tolist()) == {0, 4, 20, 24}
    assert drange.Voronoi(grid, furthest_site=True).vertices.tolist() == [[2.0, 2.0]]


def test_furthest_site_equations_point_out_of_the_lifted_hull():
    points = np.random.default_rng(4).random((40, 2))
    tri = drange.Delaunay(points, furthest_site=True)
    lifted = tri.lift_points(points)
    distances = lifted @ tri.equations[:, :-1].T + tri.equations[:, -1]
    assert (distances <= 1e-12).all()  # every point on or beneath every upper facet


def test_furthest_site_pickles_and_copies():
    points = np.random.default_rng(8).random((50, 3))
    for original in (drange.Delaunay(points, furthest_site=True), drange.Voronoi(points, furthest_site=True)):
        for other in (pickle.loads(pickle.dumps(original)), copy.deepcopy(original)):
            assert other.furthest_site
            assert np.array_equal(other.point_region if hasattr(other, "point_region") else other.simplices,
                                  original.point_region if hasattr(original, "point_region") else original.simplices)


def test_threads_share_an_object_safely():
    # The engine runs without the GIL under the object's lock: calls from several Python
    # threads on one interpolant, and adds to several objects at once, give the serial answers.
    from concurrent.futures import ThreadPoolExecutor
    from drange.interpolate import NaturalNeighborInterpolator
    rng = np.random.default_rng(11)
    points, queries = rng.random((3000, 2)), 0.2 + 0.6 * rng.random((8, 200, 2))
    interpolant = NaturalNeighborInterpolator(points, points[:, 0] * points[:, 1])
    serial = [interpolant(q) for q in queries]
    with ThreadPoolExecutor(4) as pool:
        assert all(np.array_equal(a, b) for a, b in zip(pool.map(interpolant, queries), serial))
        grown = list(pool.map(lambda seed: grow(drange.Delaunay, np.random.default_rng(seed).random((400, 3)), 50, 30),
                              range(4)))
    for seed, tri in enumerate(grown):
        fresh = drange.Delaunay(np.random.default_rng(seed).random((400, 3)))
        assert simplex_set(tri.simplices) == simplex_set(fresh.simplices)
