"""drange.Delaunay against scipy.spatial.Delaunay on inputs in general position (2D to 6D),
where the triangulation is unique: the same simplices, neighbours, hull, vertex neighbours and
find_simplex answers; and the attributes' own meaning (transform, equations, orientation)."""
import numpy as np
import pytest
import scipy.spatial

import drange
from conftest import neighbor_map, sample, simplex_keys

CASES = [("uniform", 3000, 2), ("gaussian", 3000, 2), ("uniform", 1200, 3), ("gaussian", 1200, 3),
         ("uniform", 400, 4), ("uniform", 150, 5), ("gaussian", 70, 6)]


@pytest.fixture(scope="module", params=CASES, ids=[f"{k}-{n}-{d}D" for k, n, d in CASES])
def pair(request):
    kind, n, d = request.param
    points = sample(kind, n, d, seed=n + d)
    return points, drange.Delaunay(points), scipy.spatial.Delaunay(points)


def test_same_simplices(pair):
    points, ours, theirs = pair
    assert ours.nsimplex == theirs.nsimplex
    assert set(simplex_keys(ours.simplices)) == set(simplex_keys(theirs.simplices))


def test_same_neighbors(pair):
    _, ours, theirs = pair
    assert neighbor_map(ours.simplices, ours.neighbors) == neighbor_map(theirs.simplices, theirs.neighbors)


def test_same_convex_hull(pair):
    _, ours, theirs = pair
    assert set(simplex_keys(ours.convex_hull)) == set(simplex_keys(theirs.convex_hull))


def test_same_vertex_neighbor_vertices(pair):
    points, ours, theirs = pair
    (a_ptr, a_idx), (b_ptr, b_idx) = ours.vertex_neighbor_vertices, theirs.vertex_neighbor_vertices
    assert len(a_ptr) == len(points) + 1
    for k in range(len(points)):
        assert set(a_idx[a_ptr[k]:a_ptr[k + 1]]) == set(b_idx[b_ptr[k]:b_ptr[k + 1]])


def test_find_simplex_agrees_away_from_faces(pair):
    points, ours, theirs = pair
    d = points.shape[1]
    low, high = points.min(axis=0), points.max(axis=0)
    queries = np.random.default_rng(d).uniform(low - 0.1 * (high - low), high + 0.1 * (high - low), (2000, d))
    found, expected = ours.find_simplex(queries), theirs.find_simplex(queries)
    assert found.dtype == np.int32 and found.shape == (2000,)
    hull = scipy.spatial.ConvexHull(points)
    outside = (queries @ hull.equations[:, :-1].T + hull.equations[:, -1]).max(axis=1)
    ours_keys, theirs_keys = simplex_keys(ours.simplices), simplex_keys(theirs.simplices)
    compared = 0
    for i, q in enumerate(queries):
        if expected[i] < 0:
            if outside[i] > 1e-9:
                assert found[i] == -1
                compared += 1
            continue
        t = theirs.transform[expected[i]]
        c = t[:d] @ (q - t[d])
        if min(c.min(), 1 - c.sum()) > 1e-9:  # strictly inside, away from every face
            assert ours_keys[found[i]] == theirs_keys[expected[i]]
            compared += 1
    assert compared > 1500


def test_find_simplex_keeps_the_query_shape(pair):
    points, ours, _ = pair
    d = points.shape[1]
    xi = np.broadcast_to(points.mean(axis=0), (3, 4, d))
    assert ours.find_simplex(xi).shape == (3, 4)
    assert ours.find_simplex(points[0]).shape == ()
    assert ours.find_simplex(points[0]) >= 0


def test_transform_gives_barycentric_coordinates(pair):
    points, ours, _ = pair
    d = points.shape[1]
    queries = points[ours.simplices[:50]].mean(axis=1)  # centroids
    s = ours.find_simplex(queries)
    for q, i in zip(queries, s):
        t = ours.transform[i]
        c = t[:d] @ (q - t[d])
        coords = np.append(c, 1 - c.sum())
        assert coords.min() > -1e-9
        assert np.allclose(coords @ points[ours.simplices[i]], q, atol=1e-9)


def test_equations_agree_in_sign_with_scipy(pair):
    points, ours, theirs = pair
    d = points.shape[1]
    assert ours.equations.shape == (ours.nsimplex, d + 2)
    assert np.allclose(np.linalg.norm(ours.equations[:, :-1], axis=1), 1)
    assert (ours.equations[:, d] < 0).all()  # the lower hull: normals point down
    index = {key: i for i, key in enumerate(simplex_keys(theirs.simplices))}
    order = np.array([index[key] for key in simplex_keys(ours.simplices)])
    q = points.mean(axis=0)
    a, b = ours.plane_distance(q), theirs.plane_distance(q)[order]
    clear = (np.abs(a) > 1e-6) & (np.abs(b) > 1e-6)
    assert clear.sum() > 0.9 * len(a)
    assert (np.sign(a[clear]) == np.sign(b[clear])).all()
    # A vertex lies on its simplices' lifted planes.
    v = ours.simplices[0, 0]
    assert abs(ours.plane_distance(points[v])[0]) < 1e-9


def test_every_simplex_positive_and_hull_oriented(pair):
    points, ours, _ = pair
    d = points.shape[1]
    corners = points[ours.simplices]
    assert (np.linalg.det(corners[:, 1:] - corners[:, :1]) > 0).all()
    inside = points.mean(axis=0)
    facets = points[ours.convex_hull]
    rows = np.concatenate([facets[:, 1:] - facets[:, :1], (inside - facets[:, 0])[:, None, :]], axis=1)
    assert (np.sign(np.linalg.det(rows)) == (-1) ** d).all()


def test_attributes(pair):
    points, ours, _ = pair
    n, d = points.shape
    assert (ours.npoints, ours.ndim) == (n, d)
    assert ours.simplices.dtype == np.int32 and ours.simplices.shape == (ours.nsimplex, d + 1)
    assert ours.neighbors.dtype == np.int32 and ours.neighbors.shape == ours.simplices.shape
    assert ours.coplanar.shape == (0, 3)
    assert (ours.min_bound == points.min(axis=0)).all() and (ours.max_bound == points.max(axis=0)).all()
    assert not ours.furthest_site
    v2s = ours.vertex_to_simplex
    assert all(k in ours.simplices[v2s[k]] for k in range(n))
    stats = ours.statistics
    assert stats["simplices"] == ours.nsimplex and stats["points"] == n
    # The engine's internal counters are apart, in stats["debug"].
    assert stats["debug"]["points_tested"] > 0 and "points_tested" not in stats
    # One busy time per search thread, none above the critical path.
    assert len(stats["seconds_busy"]) >= 1
    assert all(0 <= busy <= stats["seconds_critical_path"] + 1e-9 for busy in stats["seconds_busy"])
    assert ours.lift_points(points[:2]).shape == (2, d + 1)
    assert repr(ours).startswith("<drange.Delaunay")


def test_result_arrays_are_views_and_points_are_not_copied():
    points = sample("uniform", 500, 3, seed=1)
    tri = drange.Delaunay(points)
    assert np.shares_memory(tri.points, points)
    assert not tri.simplices.flags.owndata and tri.simplices.base is not None
    # Input that is not C-contiguous float64 is converted.
    for converted in (points.astype(np.float32), np.asfortranarray(points), points.tolist()):
        again = drange.Delaunay(converted)
        assert again.points.dtype == np.float64 and again.points.flags.c_contiguous


def test_result_does_not_depend_on_input_order():
    points = sample("gaussian", 2000, 3, seed=5)
    order = np.random.default_rng(5).permutation(len(points))
    a = drange.Delaunay(points)
    b = drange.Delaunay(points[order])
    assert set(simplex_keys(a.simplices)) == set(simplex_keys(order[b.simplices]))


def test_variants_give_the_same_simplices():
    points = sample("uniform", 1000, 2, seed=3)
    reference = set(simplex_keys(drange.Delaunay(points).simplices))
    for variant in ("no-prune", "no-order", "kdtree", "scan", "fifo", "spatial"):
        assert set(simplex_keys(drange.Delaunay(points, variant=variant).simplices)) == reference


def test_algorithms_give_the_same_simplices():
    # Points on a cylinder (where "auto" picks the incremental kernel) and uniform points
    # (where it keeps the direct search): every algorithm, the same simplices and neighbours.
    rng = np.random.default_rng(4)
    angle = rng.uniform(0, 2 * np.pi, 10000)
    cylinder = np.c_[np.cos(angle), np.sin(angle), rng.uniform(-1, 1, 10000)]
    for points, automatic in ((cylinder, "incremental"), (sample("uniform", 6000, 3, seed=4), "direct")):
        direct = drange.Delaunay(points, algorithm="direct")
        reference = set(simplex_keys(direct.simplices))
        assert direct.statistics["algorithm"] == "direct"
        for algorithm in ("incremental", "auto"):
            tri = drange.Delaunay(points, algorithm=algorithm)
            assert set(simplex_keys(tri.simplices)) == reference
            assert neighbor_map(tri.simplices, tri.neighbors) == neighbor_map(direct.simplices, direct.neighbors)
            assert tri.statistics["algorithm"] == (automatic if algorithm == "auto" else algorithm)
        vor = drange.Voronoi(points, algorithm="incremental")
        assert vor.statistics["algorithm"] == "incremental"
        assert len(vor.vertices) == len(drange.Voronoi(points, algorithm="direct").vertices)
    assert "incremental" in drange.algorithm_names


def test_scipy_arguments_are_accepted():
    points = sample("uniform", 100, 2, seed=2)
    tri = drange.Delaunay(points, furthest_site=False, incremental=False, qhull_options="Qt Qbb")
    tri.close()
    assert tri.find_simplex(points[0], bruteforce=True, tol=1e-3) >= 0
