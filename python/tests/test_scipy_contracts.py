"""Where scipy.spatial's contracts say what happens at the edges: empty input, transforms of
simplices too flat for floating point, and the barycentric transform itself against scipy's."""
import numpy as np
import pytest
import scipy.spatial

import drange
from conftest import sample


@pytest.mark.parametrize("cls", [drange.Delaunay, drange.Voronoi, scipy.spatial.Delaunay, scipy.spatial.Voronoi])
def test_empty_input_is_a_value_error(cls):
    with pytest.raises(ValueError, match="No points given"):
        cls(np.empty((0, 2)))


def test_a_simplex_flat_within_rounding_has_a_nan_transform():
    # Not collinear exactly (5/3 is rounded), so drange triangulates it; numpy finds the matrix
    # singular. scipy would give NaN for such a simplex rather than raise.
    tri = drange.Delaunay(np.array([[0.0, 0.0], [3.0, 1.0], [5.0, 5.0 / 3.0]]))
    assert tri.nsimplex == 1
    assert np.isnan(tri.transform).all()
    # A nearly flat but well-conditioned simplex keeps its transform.
    thin = drange.Delaunay(np.array([[0.0, 0.0], [1.0, 0.0], [0.5, 1e-6]]))
    assert np.isfinite(thin.transform).all()


@pytest.mark.parametrize("d", [2, 3, 4])
def test_transform_matches_scipy_on_the_same_simplices(d):
    points = sample("uniform", 300, d, seed=40 + d)
    ours, theirs = drange.Delaunay(points), scipy.spatial.Delaunay(points)
    index = {tuple(sorted(s)): i for i, s in enumerate(theirs.simplices.tolist())}
    checked = 0
    for i, simplex in enumerate(ours.simplices.tolist()):
        j = index.get(tuple(sorted(simplex)))
        if j is None:
            continue
        # The transforms depend on the vertex order; the barycentric coordinates do not.
        x = points[simplex].mean(axis=0)
        mine = ours.transform[i, :d] @ (x - ours.transform[i, d])
        mine = dict(zip(simplex, np.r_[mine, 1 - mine.sum()]))
        other = theirs.transform[j, :d] @ (x - theirs.transform[j, d])
        other = dict(zip(theirs.simplices[j].tolist(), np.r_[other, 1 - other.sum()]))
        for vertex in simplex:
            assert mine[vertex] == pytest.approx(other[vertex], abs=1e-9)
        checked += 1
    assert checked > 0.9 * ours.nsimplex


def test_errors_are_qhull_errors_for_code_written_for_scipy():
    assert issubclass(drange.Error, scipy.spatial.QhullError)
    assert issubclass(drange.DegenerateInputError, scipy.spatial.QhullError)
    collinear = np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 2.0], [3.0, 3.0]])
    for cls in (drange.Delaunay, drange.Voronoi):
        with pytest.raises(scipy.spatial.QhullError, match="hyperplane|distinct"):
            cls(collinear)


@pytest.mark.parametrize("options", ["QJ", "Qbb QJ", b"QJ0.001", "Qc QJn"])
def test_joggling_is_rejected_with_a_reason(options):
    with pytest.raises(ValueError, match="QJ.*exact"):
        drange.Delaunay(sample("uniform", 20, 2, seed=1), qhull_options=options)


def test_other_qhull_options_are_accepted():
    points = sample("uniform", 50, 2, seed=2)
    reference = drange.Delaunay(points).simplices
    np.testing.assert_array_equal(drange.Delaunay(points, qhull_options="Qbb Qc Qz Q12").simplices, reference)
