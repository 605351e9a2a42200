"""Every error path: bad input is a ValueError (or TypeError for a wrong type) naming the
problem, points without a full-dimensional triangulation a drange.DegenerateInputError."""
import numpy as np
import pytest

import drange
from conftest import sample


def test_exception_hierarchy():
    assert issubclass(drange.DegenerateInputError, drange.Error)
    assert issubclass(drange.Error, RuntimeError)  # like scipy's QhullError


@pytest.mark.parametrize("cls", [drange.Delaunay, drange.Voronoi])
@pytest.mark.parametrize("bad,message", [
    ([[0.0, np.nan], [1, 0], [0, 1]], "point 0, coordinate 1 is NaN"),
    ([[0.0, 0], [np.inf, 0], [0, 1]], "point 1, coordinate 0 is infinite"),
    ([0.0, 1.0, 2.0], r"2-D array of shape \(npoints, ndim\); got shape \(3,\)"),
    (None, r"got shape \(\)"),
    (np.zeros((2, 2, 2)), r"got shape \(2, 2, 2\)"),
    ([[0.0], [1.0]], "dimension 1"),
    (np.eye(13), "dimension 13"),
    ([["a", "b"], ["c", "d"], ["e", "f"]], "could not convert string to float"),
])
def test_bad_input_is_a_value_error(cls, bad, message):
    with pytest.raises(ValueError, match=message):
        cls(bad)


@pytest.mark.parametrize("cls", [drange.Delaunay, drange.Voronoi])
@pytest.mark.parametrize("points,message", [
    ([[0.0, 0.0], [1.0, 1.0]], "2 distinct points"),
    ([[0.0, 0.0], [1.0, 1.0], [2.0, 2.0], [1.0, 1.0]], "affine subspace of dimension 1"),
    (np.c_[np.random.default_rng(0).random((20, 2)), np.zeros(20)], "affine subspace of dimension 2"),
])
def test_degenerate_input(cls, points, message):
    with pytest.raises(drange.DegenerateInputError, match=message):
        cls(points)


@pytest.mark.parametrize("kwargs,error,message", [
    ({"variant": "fast"}, ValueError, "fast"),
    ({"variant": 3}, TypeError, "variant must be a string"),
    ({"algorithm": "quick"}, ValueError, "quick"),
    ({"algorithm": 2}, TypeError, "algorithm must be a string"),
    ({"algorithm": "incremental", "variant": "paper"}, ValueError, "paper"),
    ({"threads": -1}, ValueError, "threads must be 0"),
    ({"threads": "2"}, TypeError, "threads must be an integer"),
    ({"threads": True}, TypeError, "threads must be an integer"),
    ({"qhull_options": 5}, TypeError, "qhull_options"),
])
def test_bad_options(kwargs, error, message):
    points = sample("uniform", 20, 2, seed=1)
    for cls in (drange.Delaunay, drange.Voronoi):
        with pytest.raises(error, match=message):
            cls(points, **kwargs)


def test_find_simplex_with_the_wrong_dimension():
    tri = drange.Delaunay(sample("uniform", 20, 3, seed=1))
    with pytest.raises(ValueError, match="wrong dimensionality in xi"):
        tri.find_simplex([0.5, 0.5])
    with pytest.raises(ValueError, match="wrong dimensionality in xi"):
        tri.find_simplex(0.5)
    with pytest.raises(ValueError, match="shape"):
        tri.plane_distance([0.5, 0.5])


def test_clipping_errors():
    vor4 = drange.Voronoi(sample("uniform", 30, 4, seed=1))
    with pytest.raises(ValueError, match="d = 2 or 3|dimension"):
        vor4.clipped_cells()
    vor = drange.Voronoi(sample("uniform", 30, 2, seed=1))
    with pytest.raises(ValueError, match="empty on axis 0"):
        vor.clipped_cells(box=([1, 0], [0, 1]))
    with pytest.raises(ValueError, match="dimension"):
        vor.clipped_cells(box=([0, 0, 0], [1, 1, 1]))


def test_check_triangulation_errors():
    points = sample("uniform", 10, 2, seed=1)
    with pytest.raises(ValueError, match="3 columns"):
        drange.check_triangulation(points, [[0, 1, 2, 3]])


def test_a_progress_callback_exception_stops_the_run():
    class Stop(Exception):
        pass

    def progress(found):
        raise Stop(found)

    points = sample("uniform", 100000, 2, seed=1)
    with pytest.raises(Stop) as stopped:
        drange.Delaunay(points, progress=progress)
    assert stopped.value.args[0] == 65536  # the first call
