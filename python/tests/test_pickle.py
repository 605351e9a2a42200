"""Pickling and copying drange.Delaunay and drange.Voronoi: the same arrays, the same answers,
the original run's statistics, and copies independent of the original."""
import copy
import pickle

import numpy as np
import pytest

import drange
from conftest import sample

CASES = [("uniform", 800, 2), ("gaussian", 300, 3), ("uniform", 120, 4)]


@pytest.mark.parametrize("kind,n,d", CASES)
def test_delaunay_round_trip(kind, n, d):
    points = sample(kind, n, d, seed=n + d)
    tri = drange.Delaunay(points, threads=1, variant="fifo")
    _ = tri.transform  # a cached attribute, recomputed after unpickling
    blob = pickle.dumps(tri)
    assert len(blob) < points.nbytes + 4096  # the points, not the triangulation
    back = pickle.loads(blob)
    assert type(back) is drange.Delaunay
    np.testing.assert_array_equal(back.points, tri.points)
    np.testing.assert_array_equal(back.simplices, tri.simplices)
    np.testing.assert_array_equal(back.neighbors, tri.neighbors)
    np.testing.assert_array_equal(back.coplanar, tri.coplanar)
    assert back.statistics == tri.statistics
    queries = sample("uniform", 200, d, seed=7) * 1.2
    np.testing.assert_array_equal(back.find_simplex(queries), tri.find_simplex(queries))
    np.testing.assert_array_equal(back.transform, tri.transform)


@pytest.mark.parametrize("kind,n,d", CASES)
def test_voronoi_round_trip(kind, n, d):
    points = sample(kind, n, d, seed=3 * n + d)
    vor = drange.Voronoi(points, cell_volumes=(d != 4))
    back = pickle.loads(pickle.dumps(vor, protocol=pickle.HIGHEST_PROTOCOL))
    np.testing.assert_array_equal(back.vertices, vor.vertices)
    np.testing.assert_array_equal(back.ridge_points, vor.ridge_points)
    assert back.ridge_vertices == vor.ridge_vertices
    assert back.regions == vor.regions
    np.testing.assert_array_equal(back.point_region, vor.point_region)
    np.testing.assert_array_equal(back.volumes, vor.volumes)  # NaN where volumes were not asked
    assert back.statistics == vor.statistics


def test_duplicates_survive_pickling():
    points = np.array([[0, 0], [1, 0], [0, 1], [1, 1], [1, 0], [0.5, 0.5]], dtype=float)
    tri = drange.Delaunay(points)
    back = pickle.loads(pickle.dumps(tri))
    np.testing.assert_array_equal(back.coplanar, tri.coplanar)
    assert back.coplanar.shape == (1, 3)


@pytest.mark.parametrize("cls", [drange.Delaunay, drange.Voronoi])
def test_copies(cls):
    points = sample("uniform", 400, 3, seed=11)
    original = cls(points)
    shallow = copy.copy(original)
    deep = copy.deepcopy(original)
    for other in (shallow, deep):
        assert type(other) is cls
        np.testing.assert_array_equal(other.points, original.points)
    assert shallow.points is original.points
    assert deep.points is not original.points
    deep.points[0, 0] = 99.0  # the deep copy owns its arrays
    assert original.points[0, 0] != 99.0
    if cls is drange.Delaunay:
        queries = sample("uniform", 50, 3, seed=12)
        np.testing.assert_array_equal(deep.find_simplex(queries), original.find_simplex(queries))
        np.testing.assert_array_equal(deep.simplices, original.simplices)
    else:
        assert deep.regions == original.regions
