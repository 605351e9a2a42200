"""drange.interpolate: scipy.interpolate's scattered-data interpolants over drange's Delaunay.

The names, arguments and calling conventions are scipy.interpolate's, so switching is one line::

    from drange.interpolate import LinearNDInterpolator, NearestNDInterpolator, griddata

LinearNDInterpolator locates each query with the exact `Delaunay.find_simplex` (all threads)
and weights the values of the simplex's vertices by the query's barycentric coordinates.
NaturalNeighborInterpolator (drange's own) is Sibson's natural-neighbour interpolant in any
dimension.
"""
import numpy as np

from . import _drange
from ._delaunay import Delaunay

try:  # NearestNDInterpolator's search; a brute-force search stands in without scipy.
    from scipy.spatial import cKDTree as _cKDTree
except ImportError:  # pragma: no cover - scipy is optional
    _cKDTree = None

__all__ = ["LinearNDInterpolator", "NearestNDInterpolator", "NaturalNeighborInterpolator", "griddata"]

# Queries are weighted in chunks so that the gathered transforms and vertex values stay within
# a few MiB whatever the number of queries.
_CHUNK_ELEMENTS = 1 << 20


def _coordinates(args, ndim=None):
    """Points from scipy's conventions: a tuple of broadcastable coordinate arrays (one per
    dimension), or one array of shape (..., ndim); a 1-D array holds whole points in a row."""
    if isinstance(args, tuple) and len(args) == 1:
        args = args[0]  # the argument tuple of __call__(xi)
    if isinstance(args, tuple):
        arrays = np.broadcast_arrays(*args)
        result = np.empty(arrays[0].shape + (len(arrays),), dtype=np.float64)
        for j, array in enumerate(arrays):
            result[..., j] = array
        return result
    result = np.asanyarray(args)
    if result.ndim == 1:
        width = 1 if ndim is None else ndim
        if result.size % width != 0:
            raise ValueError(f"number of dimensions in xi does not match x: {result.size} coordinates "
                             f"do not make whole points of {width}")
        result = result.reshape(-1, width)
    return result


class _ScatteredInterpolator:
    """What both interpolants share: the checks of points and values, rescaling, and the
    shape of the answer. Sets points, values (as given), values_shape, scale, offset, tri."""

    def __init__(self, points, values, rescale):
        self.tri = None
        if _is_triangulation(points):
            if rescale:
                raise ValueError("Rescaling is not supported when passing a Delaunay triangulation as ``points``.")
            self.tri = points
            points = points.points
        points = np.asarray(_coordinates(points), dtype=np.float64)
        if points.ndim != 2:
            raise ValueError(f"invalid shape for input data points: {points.shape}, expected (npoints, ndim)")
        if points.shape[1] < 2:
            raise ValueError("input data must be at least 2-D (for 1-D data use numpy.interp or "
                             "scipy.interpolate.interp1d)")
        values = np.asarray(values)
        if values.ndim == 0 or values.shape[0] != points.shape[0]:
            raise ValueError(f"different number of values and points: {values.shape[0] if values.ndim else 0} "
                             f"values for {points.shape[0]} points")
        self.scale = self.offset = None
        if rescale:
            # scipy's unit cube: centred on the mean, each axis divided by its extent.
            self.offset = points.mean(axis=0)
            self.scale = np.ptp(points, axis=0)
            self.scale[~(self.scale > 0)] = 1.0
            points = (points - self.offset) / self.scale
        self.points = np.ascontiguousarray(points)
        self.values = values
        self.values_shape = values.shape[1:]

    def _queries(self, args):
        """xi as (m, ndim) float64 in the interpolant's coordinates, and the shape of the queries."""
        ndim = self.points.shape[1]
        xi = _coordinates(args, ndim=ndim)
        if xi.ndim == 0 or xi.shape[-1] != ndim:
            raise ValueError(f"number of dimensions in xi does not match x: xi has shape {xi.shape}, "
                             f"the points have {ndim} dimensions")
        shape = xi.shape[:-1]
        xi = np.ascontiguousarray(xi.reshape(-1, ndim), dtype=np.float64)
        if self.scale is not None:
            xi = (xi - self.offset) / self.scale
        return xi, shape


def _is_triangulation(points):
    """drange.Delaunay, or anything with its interface (scipy.spatial.Delaunay)."""
    return isinstance(points, Delaunay) or all(
        hasattr(points, name) for name in ("points", "simplices", "transform", "find_simplex"))


class LinearNDInterpolator(_ScatteredInterpolator):
    """Piecewise linear interpolant on the Delaunay triangulation, as scipy.interpolate's.

    Parameters
    ----------
    points : ndarray of floats, shape (npoints, ndim), or a drange.Delaunay
        The sample points (2 <= ndim <= 11), or their triangulation (a scipy.spatial.Delaunay
        is used too, with its own find_simplex).
    values : ndarray of float or complex, shape (npoints, ...)
        The values at the points; trailing dimensions are interpolated independently.
    fill_value : float, optional
        The value outside the convex hull; NaN by default.
    rescale : bool, optional
        Rescale the points (and the queries) to the unit cube before triangulating.

    The location is exact: a query on a shared face is interpolated in one of the simplices
    holding it (the value is the same), a query a rounding error outside the hull gets
    fill_value. An exact duplicate point is left out of the triangulation, so its value is
    ignored in favour of the point it copies. A simplex too flat for floating point has a NaN
    `transform` row; the barycentric coordinates of a query in it are then solved by least
    squares, which still reproduces a linear function.
    """

    def __init__(self, points, values, fill_value=np.nan, rescale=False):
        super().__init__(points, values, rescale)
        # scipy's types: float64 or complex128 values, flattened to (npoints, k).
        self.is_complex = np.iscomplexobj(self.values)
        dtype = np.complex128 if self.is_complex else np.float64
        self.values = np.ascontiguousarray(self.values.reshape(len(self.values), -1), dtype=dtype)
        self.fill_value = complex(fill_value) if self.is_complex else float(fill_value)
        if self.tri is None:
            self.tri = Delaunay(self.points)

    def __call__(self, *args):
        """The interpolant at xi: one array of shape (..., ndim), or ndim broadcastable arrays
        of coordinates. Returns shape xi.shape[:-1] + values.shape[1:]."""
        xi, shape = self._queries(args)
        result = np.full((len(xi), self.values.shape[1]), self.fill_value, dtype=self.values.dtype)
        simplex = np.asarray(self.tri.find_simplex(xi))
        inside = np.flatnonzero(simplex >= 0)
        d = self.points.shape[1]
        chunk = max(1, _CHUNK_ELEMENTS // ((d + 1) * max(d, self.values.shape[1])))
        for start in range(0, len(inside), chunk):
            rows = inside[start:start + chunk]
            weights = self._weights(simplex[rows], xi[rows])
            corners = self.values[self.tri.simplices[simplex[rows]]]  # (rows, d+1, k)
            result[rows] = np.einsum("ij,ijk->ik", weights, corners)
        return result.reshape(shape + self.values_shape)

    def _weights(self, simplices, xi):
        """Barycentric coordinates (m, d+1) of each xi in its simplex, in the simplex's vertex order."""
        d = xi.shape[1]
        transform = self.tri.transform[simplices]
        weights = np.empty((len(xi), d + 1))
        weights[:, :d] = np.einsum("ijk,ik->ij", transform[:, :d, :], xi - transform[:, d, :])
        weights[:, d] = 1.0 - weights[:, :d].sum(axis=1)
        # A NaN transform (a simplex flat within rounding): weights w with sum(w v_j) = x and
        # sum(w) = 1 in the least-squares sense; any such w reproduces linear functions.
        for i in np.flatnonzero(np.isnan(transform[:, 0, 0])):
            corners = self.points[self.tri.simplices[simplices[i]]]  # (d+1, d)
            system = np.vstack([corners.T, np.ones(d + 1)])
            weights[i] = np.linalg.lstsq(system, np.append(xi[i], 1.0), rcond=None)[0]
        return weights


class NearestNDInterpolator(_ScatteredInterpolator):
    """The value of the nearest sample point, as scipy.interpolate's.

    Parameters
    ----------
    x : ndarray of floats, shape (npoints, ndim)
    y : ndarray, shape (npoints, ...)
        Returned as given (no conversion) at the nearest point.
    rescale : bool, optional
        Rescale the points (and the queries) to the unit cube before searching.
    tree_options : dict, optional
        Passed to scipy.spatial.cKDTree. Without scipy the search is a brute-force scan, and
        tree_options has no effect.
    """

    def __init__(self, x, y, rescale=False, tree_options=None):
        super().__init__(x, y, rescale)  # values as given: scipy returns y's entries, dtype and all
        self.tree = _cKDTree(self.points, **(tree_options or {})) if _cKDTree is not None else None

    def __call__(self, *args):
        """The nearest sample's value at xi: one array of shape (..., ndim), or ndim
        broadcastable coordinate arrays. Returns shape xi.shape[:-1] + y.shape[1:]."""
        xi, shape = self._queries(args)
        if self.tree is not None:
            nearest = self.tree.query(xi)[1]
        else:
            nearest = _nearest_by_scan(self.points, xi)
        return self.values[nearest].reshape(shape + self.values.shape[1:])


class NaturalNeighborInterpolator(_ScatteredInterpolator):
    """Sibson's natural-neighbour interpolant, in any dimension (drange's own; scipy has none).

    The value at x weights the values of x's natural neighbours by the volumes x's Voronoi cell
    would take from theirs if x were added (Sibson's coordinates): continuous, equal to the data
    at the points, exact on linear functions, smooth away from the points. Same parameters as
    LinearNDInterpolator; fill_value outside the convex hull and on its boundary (where x's cell
    is unbounded). `coordinates(xi)` gives the neighbours and weights themselves. The cells'
    combinatorics are exact (drange.Delaunay's perturbed triangulation); the volumes are computed
    in floating point (C++: drange::IncrementalDelaunay::natural_neighbours). One thread.
    """

    def __init__(self, points, values, fill_value=np.nan, rescale=False):
        super().__init__(points, values, rescale)
        self.is_complex = np.iscomplexobj(self.values)
        dtype = np.complex128 if self.is_complex else np.float64
        self.values = np.ascontiguousarray(self.values.reshape(len(self.values), -1), dtype=dtype)
        self.fill_value = complex(fill_value) if self.is_complex else float(fill_value)
        self._state = _drange.IncrementalDelaunay(self.points)

    def coordinates(self, *args):
        """(offsets, ids, weights) for the queries xi flattened to (m, ndim): query q's natural
        neighbours are ids[offsets[q]:offsets[q+1]] with those weights (summing to 1); none
        outside the hull."""
        xi, _ = self._queries(args)
        return self._state.natural_neighbours(xi)

    def __call__(self, *args):
        """The interpolant at xi, shaped as LinearNDInterpolator's answer."""
        xi, shape = self._queries(args)
        offsets, ids, weights = self._state.natural_neighbours(xi)
        result = np.full((len(xi), self.values.shape[1]), self.fill_value, dtype=self.values.dtype)
        inside = np.flatnonzero(offsets[1:] > offsets[:-1])
        if len(inside):
            # Empty queries hold no entries, so each kept start runs to the next kept one.
            result[inside] = np.add.reduceat(weights[:, None] * self.values[ids], offsets[inside], axis=0)
        return result.reshape(shape + self.values_shape)


def _nearest_by_scan(points, xi):
    """Index of the nearest point to each query, by comparing every pair (chunked so that one
    chunk's differences take a few MiB); ties go to the lowest index."""
    n, d = points.shape
    result = np.empty(len(xi), dtype=np.intp)
    chunk = max(1, _CHUNK_ELEMENTS // (n * d))
    for start in range(0, len(xi), chunk):
        queries = xi[start:start + chunk]
        distances = ((queries[:, None, :] - points[None, :, :]) ** 2).sum(axis=2)
        result[start:start + chunk] = np.argmin(distances, axis=1)
    return result


def griddata(points, values, xi, method="linear", fill_value=np.nan, rescale=False):
    """Interpolates scattered data at xi, as scipy.interpolate.griddata, in 2 or more dimensions.

    method is 'linear' (LinearNDInterpolator) or 'nearest' (NearestNDInterpolator; fill_value
    has no effect). 'cubic' (scipy's CloughTocher2DInterpolator, 2D only) is not implemented.
    """
    if method == "nearest":
        return NearestNDInterpolator(points, values, rescale=rescale)(xi)
    if method == "linear":
        return LinearNDInterpolator(points, values, fill_value=fill_value, rescale=rescale)(xi)
    if method == "cubic":
        raise NotImplementedError("griddata(method='cubic') (a Clough-Tocher interpolant, 2D only) is not "
                                  "implemented in drange; use scipy.interpolate.griddata(..., method='cubic')")
    raise ValueError(f"Unknown interpolation method {method!r}: use 'linear' or 'nearest'")
