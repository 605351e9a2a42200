"""drange.interpolate.CloughTocher2DInterpolator and griddata(method='cubic') against scipy's, on
random points in general position (where both triangulations are the same), and the
interpolant's own properties: what it reproduces exactly, its errors."""
import warnings

import numpy as np
import pytest
import scipy.interpolate
import scipy.spatial

import drange
from drange import interpolate
from conftest import sample

RTOL = 1e-10


def smooth(points):
    """Values in [1, 3], so that a relative comparison is meaningful everywhere."""
    return 2.0 + np.sin(3.0 * points[:, 0]) * np.cos(2.0 * points[:, 1])


def queries(m, seed):
    """Points in a box a little larger than the unit square: most inside the hull, some outside."""
    return np.random.default_rng(seed).uniform(-0.1, 1.1, (m, 2))


def assert_gradients_match(ours, theirs):
    assert ours.shape == theirs.shape and ours.dtype == theirs.dtype
    np.testing.assert_allclose(ours, theirs, rtol=0, atol=RTOL * np.abs(theirs).max())


def test_the_class_is_exported():
    assert "CloughTocher2DInterpolator" in interpolate.__all__
    assert interpolate.CloughTocher2DInterpolator.__module__ == "drange._clough_tocher"


@pytest.mark.parametrize("n", [40, 2000])
def test_values_and_gradients_match_scipy_and_fill_outside(n):
    points = sample("uniform", n, 2, seed=n)
    values, xi = smooth(points), queries(5000, seed=n + 1)
    ours_ip = interpolate.CloughTocher2DInterpolator(points, values, fill_value=-7.0)
    theirs_ip = scipy.interpolate.CloughTocher2DInterpolator(points, values, fill_value=-7.0)
    assert_gradients_match(ours_ip.grad, theirs_ip.grad)
    ours, theirs = ours_ip(xi), theirs_ip(xi)
    outside = theirs == -7.0
    assert 0 < outside.sum() < len(xi)
    np.testing.assert_array_equal(ours == -7.0, outside)
    np.testing.assert_allclose(ours[~outside], theirs[~outside], rtol=RTOL)
    # A cubic, not the linear interpolant: the two differ inside.
    linear = interpolate.LinearNDInterpolator(points, values)(xi[~outside])
    assert np.abs(linear - ours[~outside]).max() > 1e-4


def test_complex_and_vector_values_match_scipy():
    points = sample("uniform", 700, 2, seed=3)
    rng = np.random.default_rng(4)
    values = 1.0 + rng.random((len(points), 3, 2)) + 1j * (1.0 + rng.random((len(points), 3, 2)))
    xi = queries(1500, seed=5)
    ours_ip = interpolate.CloughTocher2DInterpolator(points, values, fill_value=2 + 3j)
    theirs_ip = scipy.interpolate.CloughTocher2DInterpolator(points, values, fill_value=2 + 3j)
    assert_gradients_match(ours_ip.grad, theirs_ip.grad)  # (npoints, 6, 2), complex
    ours, theirs = ours_ip(xi), theirs_ip(xi)
    assert ours.shape == theirs.shape == (1500, 3, 2) and ours.dtype == np.complex128
    np.testing.assert_allclose(ours, theirs, rtol=RTOL)
    assert (ours == 2 + 3j).any()


def test_each_column_stops_sweeping_when_it_converges_as_in_scipy():
    # The small column's gradients are below 1 and meet the absolute tolerance sweeps before
    # the large one: sweeping it on would make it more accurate than scipy's, not equal.
    points = sample("uniform", 1500, 2, seed=6)
    values = np.stack([100.0 * smooth(points), 0.01 * smooth(points)], axis=1)
    ours = interpolate.CloughTocher2DInterpolator(points, values).grad
    theirs = scipy.interpolate.CloughTocher2DInterpolator(points, values).grad
    for column in range(2):
        assert_gradients_match(ours[:, column], theirs[:, column])


@pytest.mark.parametrize("order", ["random", "sorted by x"])
def test_the_sweeps_are_gauss_seidel_in_index_order(order):
    # Stopped after 3 sweeps, far from converged: only the same order of updates gives the
    # same gradients. Points sorted along x make a long chain of lower-numbered neighbours.
    points = sample("uniform", 1000, 2, seed=7)
    if order == "sorted by x":
        points = points[np.argsort(points[:, 0])]
    values = smooth(points)
    with pytest.warns(interpolate.GradientEstimationWarning, match="maxiter=3"):
        ours = interpolate.CloughTocher2DInterpolator(points, values, maxiter=3).grad
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        theirs = scipy.interpolate.CloughTocher2DInterpolator(points, values, maxiter=3).grad
        converged = scipy.interpolate.CloughTocher2DInterpolator(points, values).grad
    assert np.abs(theirs - converged).max() > 1e-3  # three sweeps are far from the answer
    assert_gradients_match(ours, theirs)


def test_a_scipy_delaunay_passed_in_is_used_too():
    points = sample("uniform", 300, 2, seed=10)
    values, xi = smooth(points), queries(500, seed=11)
    ip = interpolate.CloughTocher2DInterpolator(scipy.spatial.Delaunay(points), values)
    np.testing.assert_allclose(ip(xi), scipy.interpolate.CloughTocher2DInterpolator(points, values)(xi), rtol=RTOL)


def test_rescale_matches_scipy():
    points = sample("uniform", 800, 2, seed=12) * np.array([1.0, 1e6]) + np.array([0.0, 5e6])
    values = smooth(points / np.array([1.0, 1e6]))
    xi = np.random.default_rng(13).random((2000, 2)) * np.array([1.0, 1e6]) + np.array([0.0, 5e6])
    ours_ip = interpolate.CloughTocher2DInterpolator(points, values, rescale=True)
    theirs_ip = scipy.interpolate.CloughTocher2DInterpolator(points, values, rescale=True)
    assert_gradients_match(ours_ip.grad, theirs_ip.grad)
    ours, theirs = ours_ip(xi), theirs_ip(xi)
    np.testing.assert_array_equal(np.isnan(ours), np.isnan(theirs))
    inside = ~np.isnan(ours)
    np.testing.assert_allclose(ours[inside], theirs[inside], rtol=RTOL)
    plain = interpolate.CloughTocher2DInterpolator(points, values)(xi)
    assert np.nanmax(np.abs(plain - ours)) > 1e-6


def test_griddata_cubic_matches_scipy():
    points = sample("uniform", 500, 2, seed=14)
    values = smooth(points)
    grid = np.meshgrid(np.linspace(-0.05, 1.05, 21), np.linspace(-0.05, 1.05, 17), indexing="ij")
    for xi in (tuple(grid), np.stack(grid, axis=-1).reshape(-1, 2)):
        ours = interpolate.griddata(points, values, xi, method="cubic", fill_value=-1.0)
        theirs = scipy.interpolate.griddata(points, values, xi, method="cubic", fill_value=-1.0)
        assert ours.shape == theirs.shape
        np.testing.assert_allclose(ours, theirs, rtol=RTOL)
        assert (ours == -1.0).any()
    stretched, xi = points * np.array([1.0, 1e3]), np.stack(grid, axis=-1) * np.array([1.0, 1e3])
    ours = interpolate.griddata(stretched, values, xi, method="cubic", rescale=True)
    theirs = scipy.interpolate.griddata(stretched, values, xi, method="cubic", rescale=True)
    assert ours.shape == (21, 17)
    np.testing.assert_allclose(ours, theirs, rtol=RTOL)


def test_the_data_are_interpolated_and_copies_have_no_gradient():
    base = sample("uniform", 300, 2, seed=15)
    points = np.vstack([base, base[:20]])  # 20 exact copies, with the same values
    ip = interpolate.CloughTocher2DInterpolator(points, smooth(points))
    np.testing.assert_allclose(ip(base), smooth(base), rtol=1e-13)
    assert np.isnan(ip.grad[300:]).all() and np.isfinite(ip.grad[:300]).all()


def test_a_linear_function_is_reproduced_once_the_gradients_converge():
    points = sample("gaussian", 300, 2, seed=16)
    linear = lambda x: 1.5 * x[..., 0] - 2.0 * x[..., 1] + 4.0
    xi = sample("gaussian", 2000, 2, seed=17) * 0.5
    ip = interpolate.CloughTocher2DInterpolator(points, linear(points), tol=1e-13, maxiter=10000)
    np.testing.assert_allclose(ip.grad[:, 0], np.tile([1.5, -2.0], (300, 1)), rtol=1e-11)
    result = ip(xi)
    inside = ~np.isnan(result)
    assert inside.sum() > 1900
    np.testing.assert_allclose(result[inside], linear(xi[inside]), rtol=1e-11)


def test_with_exact_gradients_quadratics_are_reproduced_but_not_cubics():
    points = sample("uniform", 400, 2, seed=18)
    xi = np.random.default_rng(19).uniform(0.1, 0.9, (3000, 2))
    quadratic = lambda x, y: 1.0 + 2.0 * x - y + 3.0 * x * x - 2.0 * x * y + 0.5 * y * y
    quadratic_grad = lambda x, y: np.stack([2.0 + 6.0 * x - 2.0 * y, -1.0 - 2.0 * x + y], axis=-1)
    cubic = lambda x, y: x ** 3 - 2.0 * x * y * y
    cubic_grad = lambda x, y: np.stack([3.0 * x * x - 2.0 * y * y, -4.0 * x * y], axis=-1)
    errors = []
    for f, grad in ((quadratic, quadratic_grad), (cubic, cubic_grad)):
        ip = interpolate.CloughTocher2DInterpolator(points, f(*points.T))
        ip.grad = grad(*points.T)[:, None, :]  # the estimate replaced by the exact gradients
        errors.append(np.abs(ip(xi) - f(*xi.T)).max())
    assert errors[0] < 1e-13 and errors[1] > 1e-5


@pytest.mark.parametrize("name,arguments", [("3-D points", lambda p: (np.hstack([p, p[:, :1]]), smooth(p))),
                                            ("a 3-D triangulation", lambda p: (drange.Delaunay(np.hstack([p, p[:, :1] ** 2])), smooth(p)))])
def test_other_dimensions_are_a_value_error(name, arguments):
    points = sample("uniform", 50, 2, seed=20)
    with pytest.raises(ValueError, match="2-D only: the points have 3 dimensions"):
        interpolate.CloughTocher2DInterpolator(*arguments(points))
    if name == "3-D points":
        with pytest.raises(ValueError, match="2-D only"):
            interpolate.griddata(*arguments(points), points[:3], method="cubic")


def test_bad_values_and_queries_are_value_errors():
    points = sample("uniform", 50, 2, seed=21)
    with pytest.raises(ValueError, match="different number of values and points"):
        interpolate.CloughTocher2DInterpolator(points, np.ones(49))
    with pytest.raises(ValueError, match="different number of values and points"):
        interpolate.CloughTocher2DInterpolator(points, np.ones((2, 50)))
    with pytest.raises(ValueError, match="at least 2-D"):
        interpolate.CloughTocher2DInterpolator(points[:, :1], np.ones(50))
    ip = interpolate.CloughTocher2DInterpolator(points, np.arange(50))
    assert ip(points[:2]).dtype == np.float64
    for xi in [(np.ones((4, 3)),), (0.5, 0.5, 0.5), (np.ones(3),)]:
        with pytest.raises(ValueError, match="number of dimensions in xi"):
            ip(*xi)
