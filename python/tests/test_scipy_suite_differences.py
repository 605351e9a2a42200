"""The checks behind scipy_suite/known_differences.txt: where scipy's own test of its Qhull
classes fails against drange, drange's answer is the same as Qhull's up to order ([order]) or
exactly right where Qhull's tolerance decides otherwise ([exact])."""
import os

import numpy as np
import scipy.spatial

import drange

EPS = np.finfo(float).eps
SQUARE = np.array([(0, 0), (0, 1), (1, 1), (1, 0)], dtype=float)


def facet_set(simplices):
    return {frozenset(s) for s in np.asarray(simplices).tolist()}


def test_order_only_delaunay_and_hull():
    # test_2d_square, test_find_simplex, test_convex_hull: Qhull's simplices and hull edges,
    # listed in another order.
    ours, qhull = drange.Delaunay(SQUARE), scipy.spatial.Delaunay(SQUARE)
    assert facet_set(ours.simplices) == facet_set(qhull.simplices)
    assert facet_set(ours.convex_hull) == facet_set(qhull.convex_hull)


def test_order_only_good_facets():
    # test_good2d, test_good2d_incremental_changes, test_good3d: the same facets are good.
    points2 = np.array([[0.2, 0.2], [0.2, 0.4], [0.4, 0.4], [0.4, 0.2], [0.3, 0.6]])
    points3 = np.array([[0.0, 0.0, 0.0], [0.90029516, -0.39187448, 0.18948093],
                        [0.48676420, -0.72627633, 0.48536925], [0.57651530, -0.81179274, -0.09285832],
                        [0.67846893, -0.71119562, 0.18406710]])
    for points, option in [(points2, "QG4"), (points2, "QG-4"), (points3, "QG0"), (points3, "QG-0")]:
        ours = drange.ConvexHull(points, qhull_options=option)
        qhull = scipy.spatial.ConvexHull(points, qhull_options=option)
        assert facet_set(ours.simplices[ours.good]) == facet_set(qhull.simplices[qhull.good]), option
    grown = drange.ConvexHull(points2, incremental=True, qhull_options="QG4")
    grown.add_points([[0.3, 0.8]])
    qhull = scipy.spatial.ConvexHull(np.r_[points2, [[0.3, 0.8]]], qhull_options="QG4")
    assert facet_set(grown.simplices[grown.good]) == facet_set(qhull.simplices[qhull.good])


def test_order_only_voronoi_and_halfspaces():
    # test_simple (Voronoi of a 3 x 3 grid) and the cube's halfspace intersection.
    grid = np.array([(x, y) for x in range(3) for y in range(3)], dtype=float)
    ours, qhull = drange.Voronoi(grid), scipy.spatial.Voronoi(grid)
    assert sorted(map(tuple, ours.vertices.tolist())) == sorted(map(tuple, qhull.vertices.tolist()))
    cube = np.array([[-1.0, 0, 0, 0], [1, 0, 0, -1], [0, -1, 0, 0], [0, 1, 0, -1], [0, 0, -1, 0], [0, 0, 1, -1]])
    ours = drange.HalfspaceIntersection(cube, [0.5, 0.5, 0.5])
    qhull = scipy.spatial.HalfspaceIntersection(cube, np.array([0.5, 0.5, 0.5]))
    assert facet_set(ours.dual_facets) == facet_set(qhull.dual_facets)
    assert sorted(map(tuple, ours.intersections.tolist())) == sorted(map(tuple, qhull.intersections.tolist()))


def test_order_only_furthest_site():
    # test_furthest_site (Delaunay, Voronoi): Qhull's simplices in another order, and its
    # regions as sets of vertices; Qhull lists one region clockwise, drange every one
    # counter-clockwise (the unbounded part first).
    points = np.array([(0, 0), (0, 1), (1, 0), (0.5, 0.5), (1.1, 1.1)])
    ours, qhull = drange.Delaunay(points, furthest_site=True), scipy.spatial.Delaunay(points, furthest_site=True)
    assert facet_set(ours.simplices) == facet_set(qhull.simplices)
    ours, qhull = drange.Voronoi(points, furthest_site=True), scipy.spatial.Voronoi(points, furthest_site=True)
    assert np.array_equal(ours.vertices, qhull.vertices)
    for p in range(len(points)):
        assert set(ours.regions[ours.point_region[p]]) == set(qhull.regions[qhull.point_region[p]])
    # Points 0 and 4 share the ridge from vertex 0 to vertex 1: region 4 lies on its left.
    assert ours.regions[ours.point_region[4]] == [-1, 0, 1] and ours.regions[ours.point_region[0]] == [-1, 1, 0]


def test_exact_where_qhull_rounds():
    # pathological-2: (1, -1 - eps) makes (-1, -1), (0, -1), (1, -1 - eps) a true, very flat
    # triangle, whose circumcentre is about 4.5e15 below: drange keeps it (exactly Delaunay),
    # so the ridge between (-1, -1) and (0, -1) is finite and 4.5e15 long, beyond what the
    # test's nearest-point probe at its midpoint resolves; Qhull merges it away.
    points = np.array([[-1, -1], [-1, 0], [-1, 1], [0, -1], [0, 0], [0, 1], [1, -1 - EPS], [1, 0], [1, 1]])
    tri = drange.Delaunay(points)
    assert drange.check_triangulation(points, tri.simplices)["valid"]
    assert frozenset({0, 3, 6}) in facet_set(tri.simplices)
    ridge = drange.Voronoi(points).ridge_dict[(0, 3)]
    assert min(ridge) >= 0
    # degenerate_pointset.npz: drange's triangulation is exactly Delaunay; its extra NaN
    # transforms are simplices that are true but flat within rounding.
    data = np.load(os.path.join(os.path.dirname(scipy.spatial.__file__), "tests", "data", "degenerate_pointset.npz"))
    points = data["c"]
    tri = drange.Delaunay(points)
    assert drange.check_triangulation(points, tri.simplices)["valid"]
    flat = np.isnan(tri.transform[:, 0, 0])
    corners = tri.points[tri.simplices[flat]]
    volumes = np.abs(np.linalg.det(corners[:, 1:] - corners[:, :1]))
    assert (volumes < np.sqrt(EPS)).all()
