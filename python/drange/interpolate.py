"""drange.interpolate: scipy.interpolate's scattered-data interpolants over drange's Delaunay.

The names, arguments and calling conventions are scipy.interpolate's, so switching is one line::

    from drange.interpolate import (CloughTocher2DInterpolator, LinearNDInterpolator,
                                    NearestNDInterpolator, griddata)

LinearNDInterpolator locates each query with the exact `Delaunay.find_simplex` (all threads)
and weights the values of the simplex's vertices by the query's barycentric coordinates.
CloughTocher2DInterpolator (2D, in _clough_tocher.py) locates queries the same way and
evaluates a piecewise cubic, C1 interpolant with gradients estimated as scipy's.
NaturalNeighborInterpolator (drange's own) is Sibson's natural-neighbour interpolant in any
dimension.
"""
import numpy as np

from . import _drange
from ._clough_tocher import CloughTocher2DInterpolator, GradientEstimationWarning
from ._delaunay import Delaunay
from ._scattered import CHUNK_ELEMENTS, ScatteredInterpolator, barycentric

try:  # NearestNDInterpolator's search; a brute-force search stands in without scipy.
    from scipy.spatial import cKDTree as _cKDTree
except ImportError:  # pragma: no cover - scipy is optional
    _cKDTree = None

__all__ = ["CloughTocher2DInterpolator", "GradientEstimationWarning", "LinearNDInterpolator",
           "NaturalNeighborInterpolator", "NearestNDInterpolator", "griddata"]


class LinearNDInterpolator(ScatteredInterpolator):
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
        self._flat_values(fill_value)
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
        chunk = max(1, CHUNK_ELEMENTS // ((d + 1) * max(d, self.values.shape[1])))
        for start in range(0, len(inside), chunk):
            rows = inside[start:start + chunk]
            weights = self._weights(simplex[rows], xi[rows])
            corners = self.values[self.tri.simplices[simplex[rows]]]  # (rows, d+1, k)
            result[rows] = np.einsum("ij,ijk->ik", weights, corners)
        return result.reshape(shape + self.values_shape)

    def _weights(self, simplices, xi):
        """Barycentric coordinates (m, d+1) of each xi in its simplex, in the simplex's vertex order."""
        return barycentric(self.tri, self.points, simplices, xi)


class NearestNDInterpolator(ScatteredInterpolator):
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


class NaturalNeighborInterpolator(ScatteredInterpolator):
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
        """The interpolant at xi, shaped as LinearNDInterpolator's answer (fill_value where xi
        is outside the hull or not finite, as there)."""
        xi, shape = self._queries(args)
        finite = np.flatnonzero(np.isfinite(xi).all(axis=1))
        offsets, ids, weights = self._state.natural_neighbours(np.ascontiguousarray(xi[finite]))
        result = np.full((len(xi), self.values.shape[1]), self.fill_value, dtype=self.values.dtype)
        inside = np.flatnonzero(offsets[1:] > offsets[:-1])
        if len(inside):
            # Empty queries hold no entries, so each kept start runs to the next kept one.
            result[finite[inside]] = np.add.reduceat(weights[:, None] * self.values[ids], offsets[inside], axis=0)
        return result.reshape(shape + self.values_shape)


def _nearest_by_scan(points, xi):
    """Index of the nearest point to each query, by comparing every pair (chunked so that one
    chunk's differences take a few MiB); ties go to the lowest index."""
    n, d = points.shape
    result = np.empty(len(xi), dtype=np.intp)
    chunk = max(1, CHUNK_ELEMENTS // (n * d))
    for start in range(0, len(xi), chunk):
        queries = xi[start:start + chunk]
        distances = ((queries[:, None, :] - points[None, :, :]) ** 2).sum(axis=2)
        result[start:start + chunk] = np.argmin(distances, axis=1)
    return result


def griddata(points, values, xi, method="linear", fill_value=np.nan, rescale=False):
    """Interpolates scattered data at xi, as scipy.interpolate.griddata, in 2 or more dimensions.

    method is 'linear' (LinearNDInterpolator), 'nearest' (NearestNDInterpolator; fill_value
    has no effect) or 'cubic' (CloughTocher2DInterpolator, 2D only).
    """
    if method == "nearest":
        return NearestNDInterpolator(points, values, rescale=rescale)(xi)
    if method == "linear":
        return LinearNDInterpolator(points, values, fill_value=fill_value, rescale=rescale)(xi)
    if method == "cubic":
        return CloughTocher2DInterpolator(points, values, fill_value=fill_value, rescale=rescale)(xi)
    raise ValueError(f"Unknown interpolation method {method!r}: use 'linear', 'nearest' or 'cubic'")
