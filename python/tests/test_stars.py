"""drange.delaunay_stars: the stars equal the full triangulation's simplices at the given points."""
import itertools

import numpy as np
import pytest

import drange


def vertex_sets(simplices, ids=None):
    rows = {tuple(sorted(row)) for row in np.asarray(simplices).tolist()}
    return rows if ids is None else {row for row in rows if set(row) & set(ids)}


def expect_stars(points, ids):
    full = drange.Delaunay(points)
    stars = drange.delaunay_stars(points, ids)
    kept = {int(i) for i in ids}
    for index, _, original in full.coplanar.tolist():
        if index in kept:
            kept.add(original)
    assert vertex_sets(stars.simplices) == vertex_sets(full.simplices, kept)
    assert len(vertex_sets(stars.simplices)) == len(stars.simplices)  # none twice
    assert stars.neighbors.shape == stars.simplices.shape
    # Neighbours: the returned simplex across each facet, or -1.
    facets = {}
    for s, row in enumerate(stars.simplices.tolist()):
        for k in range(len(row)):
            facets.setdefault(tuple(sorted(row[:k] + row[k + 1:])), []).append(s)
    for s, row in enumerate(stars.simplices.tolist()):
        for k in range(len(row)):
            others = [t for t in facets[tuple(sorted(row[:k] + row[k + 1:]))] if t != s]
            assert stars.neighbors[s, k] == (others[0] if others else -1)


@pytest.mark.parametrize("ndim,npoints", [(2, 500), (3, 400), (4, 150), (5, 80)])
def test_uniform(ndim, npoints):
    points = np.random.default_rng(ndim).random((npoints, ndim))
    expect_stars(points, [0])
    expect_stars(points, [npoints - 1, 3, 17, 42])
    expect_stars(points, list(range(npoints)))


@pytest.mark.parametrize("ndim,k", [(2, 9), (3, 5), (4, 3)])
def test_integer_grids(ndim, k):
    points = np.array(list(itertools.product(range(k), repeat=ndim)), dtype=float)
    expect_stars(points, [0, len(points) // 2, len(points) - 1])


def test_cospherical_integer_points():
    points = np.array([p for p in itertools.product(range(-7, 8), repeat=3) if sum(c * c for c in p) == 50], float)
    expect_stars(points, [0, 5, len(points) - 1])


def test_duplicates_answer_for_the_point_they_copy():
    points = np.random.default_rng(3).random((100, 2))
    points = np.vstack([points, points[7:8]])
    expect_stars(points, [100])
    assert drange.delaunay_stars(points, [100]).duplicates.tolist() == [[100, 7]]


@pytest.mark.parametrize("ids,message", [([3, 3], "point id 3 is given twice"), ([50], "point id 50 is out of range"),
                                         ([-2], "point id -2 is out of range"), ([1.5], "point id 1.5 is not"),
                                         (["a"], "point id 'a' is not")])
def test_bad_ids_are_named(ids, message):
    points = np.random.default_rng(1).random((50, 2))
    with pytest.raises(ValueError, match=message):
        drange.delaunay_stars(points, ids)
