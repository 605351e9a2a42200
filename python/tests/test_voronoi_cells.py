"""drange.voronoi_cells: each cell asked for equals drange.Voronoi's cell of that point."""
import itertools

import numpy as np
import pytest

import drange


def close(a, b):
    return len(a) == len(b) and np.allclose(np.array(a, float).reshape(len(a), -1),
                                            np.array(b, float).reshape(len(b), -1), rtol=1e-9, atol=1e-9)


def cell(v, p):
    r = v.point_region[p]
    ids = v.regions[r]
    ridges = {}
    for (a, b), rv in zip(v.ridge_points.tolist(), v.ridge_vertices):
        if p in (a, b):
            ridges[b if a == p else a] = (-1 in rv, sorted(v.vertices[x].tolist() for x in rv if x >= 0))
    return -1 in ids, sorted(v.vertices[x].tolist() for x in ids if x >= 0), v.volumes[r], ridges


def expect_cells(points, ids):
    full = drange.Voronoi(points)
    part = drange.voronoi_cells(points, ids)
    asked = {int(i) for i in ids}
    assert len(part.regions) == len({int(full.point_region[i]) for i in asked})
    for p in range(len(points)):
        if full.point_region[p] not in {full.point_region[i] for i in asked}:
            assert part.point_region[p] == -1, p
            continue
        owner = int(full.region_point[full.point_region[p]])
        f_open, f_vertices, f_volume, f_ridges = cell(full, owner)
        g_open, g_vertices, g_volume, g_ridges = cell(part, owner)
        assert f_open == g_open, p
        assert close(f_vertices, g_vertices), (p, f_vertices, g_vertices)
        assert (np.isinf(f_volume) and np.isinf(g_volume)) or abs(f_volume - g_volume) <= 1e-9 * f_volume, p
        assert f_ridges.keys() == g_ridges.keys(), p
        for q, (unbounded, vertices) in f_ridges.items():
            assert g_ridges[q][0] == unbounded and close(vertices, g_ridges[q][1]), (p, q)


@pytest.mark.parametrize("ndim,npoints", [(2, 500), (3, 300), (4, 120)])
def test_uniform(ndim, npoints):
    points = np.random.default_rng(ndim).random((npoints, ndim))
    expect_cells(points, [npoints - 1, 3, 17, 42])


@pytest.mark.parametrize("ndim,k", [(2, 9), (3, 5), (4, 3)])
def test_integer_grids(ndim, k):
    points = np.array(list(itertools.product(range(k), repeat=ndim)), dtype=float)
    expect_cells(points, [0, 1, len(points) // 2, len(points) - 1])


def test_cospherical_integer_points():
    points = np.array([p for p in itertools.product(range(-7, 8), repeat=3) if sum(c * c for c in p) == 50], float)
    points = np.vstack([points, [[0.0, 0.0, 0.0]]])  # the centre: one bounded cell among unbounded ones
    expect_cells(points, [0, 5, len(points) - 1])


def test_duplicates_answer_for_the_point_they_copy():
    points = np.random.default_rng(3).random((100, 2))
    points = np.vstack([points, points[7:8]])
    expect_cells(points, [100])
    cells = drange.voronoi_cells(points, [100])
    assert cells.point_region[7] == cells.point_region[100] == 0


@pytest.mark.parametrize("ids,message", [([3, 3], "point id 3 is given twice"), ([50], "point id 50 is out of range"),
                                         ([1.5], "point id 1.5 is not")])
def test_bad_ids_are_named(ids, message):
    points = np.random.default_rng(1).random((50, 2))
    with pytest.raises(ValueError, match=message):
        drange.voronoi_cells(points, ids)
