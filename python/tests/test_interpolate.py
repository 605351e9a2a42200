"""drange.interpolate against scipy.interpolate: the same values where both triangulations agree
(uniform random input, where they are equal), the same calling conventions and errors."""
import numpy as np
import pytest
import scipy.interpolate
import scipy.spatial

import drange
from drange import interpolate
from conftest import sample

SIZES = {2: 2000, 3: 1500, 4: 800, 5: 400}


def smooth(points):
    """Values in [1, 3], so that a relative comparison is meaningful everywhere."""
    return 2.0 + np.sin(3.0 * points.sum(axis=1))


def queries(m, d, seed):
    """Points in a box a little larger than the unit cube: most inside the hull, some outside."""
    return np.random.default_rng(seed).uniform(-0.1, 1.1, (m, d))


def test_the_module_is_reachable_from_the_package():
    import drange as package
    assert package.interpolate.LinearNDInterpolator is interpolate.LinearNDInterpolator


@pytest.mark.parametrize("d", [2, 3, 4, 5])
def test_linear_matches_scipy_inside_and_fills_outside(d):
    points = sample("uniform", SIZES[d], d, seed=100 + d)
    values, xi = smooth(points), queries(4000, d, seed=200 + d)
    ours = interpolate.LinearNDInterpolator(points, values, fill_value=-7.0)(xi)
    theirs = scipy.interpolate.LinearNDInterpolator(points, values, fill_value=-7.0)(xi)
    outside = theirs == -7.0
    assert 0 < outside.sum() < len(xi)
    np.testing.assert_array_equal(ours == -7.0, outside)
    np.testing.assert_allclose(ours[~outside], theirs[~outside], rtol=1e-12, atol=0)


@pytest.mark.parametrize("d", [2, 3, 4])
def test_linear_functions_are_reproduced(d):
    points = sample("gaussian", 500, d, seed=300 + d)
    coefficients = np.arange(1, d + 1) * 0.5
    xi = sample("gaussian", 2000, d, seed=400 + d) * 0.5
    result = interpolate.LinearNDInterpolator(points, points @ coefficients + 4.0)(xi)
    inside = ~np.isnan(result)
    assert inside.sum() > 1000
    np.testing.assert_allclose(result[inside], xi[inside] @ coefficients + 4.0, rtol=1e-12)


def test_default_fill_is_nan_and_a_nan_query_is_outside():
    points = sample("uniform", 200, 2, seed=1)
    ip = interpolate.LinearNDInterpolator(points, smooth(points))
    result = ip(np.array([[5.0, 5.0], [np.nan, 0.5], [0.5, 0.5]]))
    assert np.isnan(result[:2]).all() and np.isfinite(result[2])


@pytest.mark.parametrize("d", [2, 3])
def test_trailing_dimensions_and_complex_values(d):
    points = sample("uniform", 600, d, seed=500 + d)
    rng = np.random.default_rng(d)
    values = 1.0 + rng.random((len(points), 3, 2)) + 1j * (1.0 + rng.random((len(points), 3, 2)))
    xi = queries(1000, d, seed=600 + d)
    ours = interpolate.LinearNDInterpolator(points, values, fill_value=2 + 3j)(xi)
    theirs = scipy.interpolate.LinearNDInterpolator(points, values, fill_value=2 + 3j)(xi)
    assert ours.shape == theirs.shape == (1000, 3, 2) and ours.dtype == np.complex128
    np.testing.assert_allclose(ours, theirs, rtol=1e-12)
    assert (ours == 2 + 3j).any()


def test_integer_values_interpolate_as_floats():
    points = sample("uniform", 300, 2, seed=7)
    values = np.arange(300)
    ours = interpolate.LinearNDInterpolator(points, values)([[0.4, 0.6]])
    theirs = scipy.interpolate.LinearNDInterpolator(points, values)([[0.4, 0.6]])
    assert ours.dtype == np.float64
    np.testing.assert_allclose(ours, theirs, rtol=1e-12)


CALLS = [
    ("one array (m, d)", lambda g: (g.reshape(-1, 2),)),
    ("one array (a, b, d)", lambda g: (g,)),
    ("coordinate arrays", lambda g: (g[..., 0], g[..., 1])),
    ("broadcast coordinates", lambda g: (g[:, :1, 0], g[:1, :, 1])),
    ("a tuple of coordinates", lambda g: ((g[..., 0], g[..., 1]),)),
    ("scalars", lambda g: (0.3, 0.6)),
    ("a tuple of scalars", lambda g: ((0.3, 0.6),)),
    ("a list of one point", lambda g: ([0.3, 0.6],)),
    ("a flat array of points", lambda g: (g.reshape(-1),)),
]


@pytest.mark.parametrize("cls", ["LinearNDInterpolator", "NearestNDInterpolator", "CloughTocher2DInterpolator"])
@pytest.mark.parametrize("name,arguments", CALLS, ids=[name for name, _ in CALLS])
def test_calling_conventions_give_scipys_shapes_and_values(cls, name, arguments):
    points = sample("uniform", 400, 2, seed=11)
    values = smooth(points)
    x, y = np.meshgrid(np.linspace(-0.05, 1.05, 7), np.linspace(0.02, 0.98, 5), indexing="ij")
    args = arguments(np.stack([x, y], axis=-1))
    ours = getattr(interpolate, cls)(points, values)(*args)
    theirs = getattr(scipy.interpolate, cls)(points, values)(*args)
    assert np.shape(ours) == np.shape(theirs)
    np.testing.assert_allclose(ours, theirs, rtol=1e-12)


@pytest.mark.parametrize("name,ndim", [("LinearNDInterpolator", 3), ("CloughTocher2DInterpolator", 2)])
def test_a_delaunay_passed_in_is_used_as_is(name, ndim):
    cls = getattr(interpolate, name)
    points = sample("uniform", 500, ndim, seed=12)
    tri = drange.Delaunay(points)
    values, xi = smooth(points), queries(1000, ndim, seed=13)
    ip = cls(tri, values)
    assert ip.tri is tri
    np.testing.assert_array_equal(ip(xi), cls(points, values)(xi))
    with pytest.raises(ValueError, match="Rescaling is not supported"):
        cls(tri, values, rescale=True)


def test_a_scipy_delaunay_passed_in_is_used_too():
    points = sample("uniform", 300, 2, seed=21)
    values, xi = smooth(points), queries(500, 2, seed=22)
    tri = scipy.spatial.Delaunay(points)
    ip = interpolate.LinearNDInterpolator(tri, values)
    assert ip.tri is tri
    np.testing.assert_allclose(ip(xi), scipy.interpolate.LinearNDInterpolator(points, values)(xi), rtol=1e-12)


def test_rescale_triangulates_in_the_unit_cube_as_scipy():
    points = sample("uniform", 800, 2, seed=14) * np.array([1.0, 1e6]) + np.array([0.0, 5e6])
    values = smooth(points / np.array([1.0, 1e6]))
    xi = np.random.default_rng(15).random((2000, 2)) * np.array([1.0, 1e6]) + np.array([0.0, 5e6])
    ours_ip = interpolate.LinearNDInterpolator(points, values, rescale=True)
    theirs_ip = scipy.interpolate.LinearNDInterpolator(points, values, rescale=True)
    np.testing.assert_array_equal(ours_ip.points, theirs_ip.points)  # the same unit cube
    ours, theirs = ours_ip(xi), theirs_ip(xi)
    np.testing.assert_array_equal(np.isnan(ours), np.isnan(theirs))
    inside = ~np.isnan(ours)
    np.testing.assert_allclose(ours[inside], theirs[inside], rtol=1e-12)
    # Without rescaling the (very anisotropic) triangulation differs, and so do the values.
    plain = interpolate.LinearNDInterpolator(points, values)(xi)
    assert np.abs(plain[inside] - ours[inside]).max() > 1e-6
    near = interpolate.NearestNDInterpolator(points, values, rescale=True)(xi)
    np.testing.assert_array_equal(near, scipy.interpolate.NearestNDInterpolator(points, values, rescale=True)(xi))


def test_duplicate_points_still_interpolate_at_the_originals():
    base = sample("uniform", 300, 2, seed=16)
    points = np.vstack([base, base[:40]])  # 40 exact copies, with the same values
    values = smooth(points)
    ip = interpolate.LinearNDInterpolator(points, values)
    assert len(ip.tri.coplanar) == 40
    np.testing.assert_allclose(ip(base), smooth(base), rtol=1e-12)
    xi = queries(2000, 2, seed=17)
    theirs = scipy.interpolate.LinearNDInterpolator(points, values)(xi)
    np.testing.assert_allclose(ip(xi), theirs, rtol=1e-12)


def test_a_duplicate_with_another_value_takes_the_value_of_the_point_it_copies():
    base = sample("uniform", 100, 2, seed=18)
    points = np.vstack([base, base[5:6]])
    values = np.append(smooth(base), 100.0)
    ip = interpolate.LinearNDInterpolator(points, values)
    copy, original = ip.tri.coplanar[0, 0], ip.tri.coplanar[0, 2]
    assert {copy, original} == {5, 100}
    assert ip(base[5:6])[0] == pytest.approx(values[original], rel=1e-12)


def test_a_simplex_flat_within_rounding_is_interpolated_by_least_squares():
    # Not collinear exactly (5/3 is rounded): one simplex, with a NaN transform row.
    points = np.array([[0.0, 0.0], [3.0, 1.0], [5.0, 5.0 / 3.0]])
    ip = interpolate.LinearNDInterpolator(points, 2.0 * points[:, 0] - points[:, 1] + 1.0)
    assert np.isnan(ip.tri.transform).all()
    np.testing.assert_allclose(ip(points), 2.0 * points[:, 0] - points[:, 1] + 1.0, rtol=1e-12)


@pytest.mark.parametrize("d", [2, 4])
def test_nearest_matches_scipy_with_its_dtype_and_trailing_dimensions(d):
    points = sample("uniform", 700, d, seed=700 + d)
    values = np.arange(len(points) * 2).reshape(-1, 2)
    xi = queries(1500, d, seed=800 + d)
    ours = interpolate.NearestNDInterpolator(points, values)(xi)
    theirs = scipy.interpolate.NearestNDInterpolator(points, values)(xi)
    assert ours.dtype == theirs.dtype and ours.shape == (1500, 2)
    np.testing.assert_array_equal(ours, theirs)


@pytest.mark.parametrize("d", [2, 3])
def test_nearest_without_scipy_scans_and_finds_the_same_points(d, monkeypatch):
    points = sample("gaussian", 3000, d, seed=900 + d)
    values = np.arange(len(points))
    xi = sample("gaussian", 1000, d, seed=1000 + d)
    expected = scipy.interpolate.NearestNDInterpolator(points, values)(xi)
    monkeypatch.setattr(interpolate, "_cKDTree", None)
    ip = interpolate.NearestNDInterpolator(points, values, tree_options={"leafsize": 4})
    assert ip.tree is None
    np.testing.assert_array_equal(ip(xi), expected)


@pytest.mark.parametrize("method", ["linear", "nearest"])
@pytest.mark.parametrize("d", [2, 3])
def test_griddata_matches_scipy(method, d):
    points = sample("uniform", 500, d, seed=1100 + d)
    values = smooth(points)
    grid = np.meshgrid(*[np.linspace(-0.05, 1.05, 9)] * d, indexing="ij")
    for xi in (tuple(grid), np.stack(grid, axis=-1).reshape(-1, d)):
        ours = interpolate.griddata(points, values, xi, method=method, fill_value=-1.0)
        theirs = scipy.interpolate.griddata(points, values, xi, method=method, fill_value=-1.0)
        assert ours.shape == theirs.shape
        np.testing.assert_allclose(ours, theirs, rtol=1e-12)
    columns = tuple(points.T)  # points as a tuple of coordinate arrays
    np.testing.assert_allclose(interpolate.griddata(columns, values, points[:10], method=method),
                               values[:10], rtol=1e-12)


def test_griddata_unknown_methods_are_refused():
    points = sample("uniform", 50, 2, seed=19)
    with pytest.raises(ValueError, match="Unknown interpolation method 'spline'"):
        interpolate.griddata(points, smooth(points), points, method="spline")


@pytest.mark.parametrize("cls", [interpolate.LinearNDInterpolator, interpolate.NearestNDInterpolator])
def test_bad_input_is_a_value_error(cls):
    points = sample("uniform", 50, 3, seed=20)
    with pytest.raises(ValueError, match="different number of values and points"):
        cls(points, np.ones(49))
    with pytest.raises(ValueError, match="different number of values and points"):
        cls(points, 1.0)
    with pytest.raises(ValueError, match="at least 2-D"):
        cls(points[:, :1], np.ones(50))
    with pytest.raises(ValueError, match="invalid shape"):
        cls(points.reshape(5, 10, 3), np.ones(5))
    ip = cls(points, np.ones(50))
    for xi in [(np.ones((4, 2)),), (np.ones((4, 4)),), (0.5, 0.5), (np.ones(4),), (np.ones(3), np.ones(3))]:
        with pytest.raises(ValueError, match="number of dimensions in xi"):
            ip(*xi)
