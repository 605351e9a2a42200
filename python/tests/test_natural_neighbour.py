"""drange.interpolate.NaturalNeighborInterpolator and the engine's natural-neighbour
coordinates: against the definition (the volumes the query's Voronoi cell takes from its
neighbours' cells, from drange.Voronoi's volumes before and after adding it), linear precision,
the data at the points, outside the hull, errors."""
import numpy as np
import pytest

import drange
from drange.interpolate import NaturalNeighborInterpolator


@pytest.mark.parametrize("ndim,n", [(2, 300), (3, 300), (4, 200)])
def test_weights_are_the_stolen_volumes(ndim, n):
    rng = np.random.default_rng(ndim)
    points = rng.random((n, ndim))
    queries = 0.45 + 0.1 * rng.random((3, ndim))  # near the middle: every neighbour's cell is bounded
    interpolant = NaturalNeighborInterpolator(points, np.zeros(n))
    offsets, ids, weights = interpolant.coordinates(queries)
    before = drange.Voronoi(points)
    old = before.volumes[before.point_region]
    for q, x in enumerate(queries):
        after = drange.Voronoi(np.vstack([points, x]))
        cell = after.volumes[after.point_region[n]]  # x's cell, bounded: x is inside the hull
        with np.errstate(invalid="ignore"):  # inf - inf for the cells of the hull's points
            stolen = old - after.volumes[after.point_region][:n]
        # Where the cells are bounded and not huge, the difference of their volumes is
        # accurate to far below the weights' scale: it must be what x takes.
        measurable = np.isfinite(old) & (old < 1e3)
        mine = np.zeros(n)
        mine[ids[offsets[q]:offsets[q + 1]]] = weights[offsets[q]:offsets[q + 1]]
        assert np.allclose(mine[measurable], stolen[measurable] / cell, atol=1e-8)
        assert np.isclose(weights[offsets[q]:offsets[q + 1]].sum(), 1.0)


@pytest.mark.parametrize("ndim", [2, 3, 5])
def test_linear_precision_data_and_outside(ndim):
    rng = np.random.default_rng(10 + ndim)
    points = rng.random((60 * ndim, ndim))
    slope = np.arange(1.0, ndim + 1)
    values = np.c_[points @ slope + 2.0, -(points @ slope)]  # two columns, both linear
    interpolant = NaturalNeighborInterpolator(points, values)
    inside = 0.3 + 0.4 * rng.random((20, ndim))
    assert np.allclose(interpolant(inside), np.c_[inside @ slope + 2.0, -(inside @ slope)], atol=1e-10)
    assert np.array_equal(interpolant(points[:5]), values[:5])  # the data at the points, exactly
    assert np.isnan(interpolant(np.full((1, ndim), 3.0))).all()
    assert interpolant(points[:2] + 0.0).shape == (2, 2)


def test_grid_ties_and_complex_values():
    # Cospherical grid points: the perturbation fixes the triangulation; the weights are still
    # the geometric ones, by symmetry equal for the four around a cell's centre.
    grid = np.array([(x, y) for x in range(6) for y in range(6)], dtype=float)
    interpolant = NaturalNeighborInterpolator(grid, grid[:, 0] + 1j * grid[:, 1], fill_value=-1)
    offsets, ids, weights = interpolant.coordinates([[2.5, 2.5]])
    assert sorted(ids.tolist()) == [14, 15, 20, 21] and np.allclose(weights, 0.25)
    assert np.isclose(interpolant([2.5, 2.5]), 2.5 + 2.5j)
    assert interpolant([[0.0, 2.5]]) == -1  # on the hull: the cell is unbounded
    tri = drange.Delaunay(grid)
    assert np.isclose(NaturalNeighborInterpolator(tri, grid[:, 0])([1.25, 3.5]), 1.25)


def test_errors():
    points = np.random.default_rng(1).random((20, 2))
    interpolant = NaturalNeighborInterpolator(points, np.ones(20))
    with pytest.raises(ValueError, match="dimensions"):
        interpolant(np.zeros((2, 3)))
    assert np.isnan(interpolant([[np.nan, 0.5], [0.5, np.inf]])).all()  # fill_value, as LinearND's
    with pytest.raises(ValueError, match="NaN"):
        interpolant.coordinates([[np.nan, 0.5]])
    with pytest.raises(ValueError, match="values"):
        NaturalNeighborInterpolator(points, np.ones(19))
