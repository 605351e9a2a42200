"""What drange.interpolate's scattered-data interpolants share: scipy's conventions for the
points, values and queries, rescaling, and barycentric coordinates from `Delaunay.transform`."""
import numpy as np

from ._delaunay import Delaunay

# Queries are weighted in chunks so that the gathered transforms and vertex values stay within
# a few MiB whatever the number of queries.
CHUNK_ELEMENTS = 1 << 20


def coordinates(args, ndim=None):
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


def is_triangulation(points):
    """drange.Delaunay, or anything with its interface (scipy.spatial.Delaunay)."""
    return isinstance(points, Delaunay) or all(
        hasattr(points, name) for name in ("points", "simplices", "transform", "find_simplex"))


class ScatteredInterpolator:
    """What the interpolants share: the checks of points and values, rescaling, and the
    shape of the answer. Sets points, values (as given), values_shape, scale, offset, tri."""

    def __init__(self, points, values, rescale):
        self.tri = None
        if is_triangulation(points):
            if rescale:
                raise ValueError("Rescaling is not supported when passing a Delaunay triangulation as ``points``.")
            self.tri = points
            points = points.points
        points = np.asarray(coordinates(points), dtype=np.float64)
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

    def _flat_values(self, fill_value):
        """scipy's types: values as float64 or complex128, flattened to (npoints, k), and
        fill_value of the same kind."""
        self.is_complex = np.iscomplexobj(self.values)
        dtype = np.complex128 if self.is_complex else np.float64
        self.values = np.ascontiguousarray(self.values.reshape(len(self.values), -1), dtype=dtype)
        self.fill_value = complex(fill_value) if self.is_complex else float(fill_value)

    def _queries(self, args):
        """xi as (m, ndim) float64 in the interpolant's coordinates, and the shape of the queries."""
        ndim = self.points.shape[1]
        xi = coordinates(args, ndim=ndim)
        if xi.ndim == 0 or xi.shape[-1] != ndim:
            raise ValueError(f"number of dimensions in xi does not match x: xi has shape {xi.shape}, "
                             f"the points have {ndim} dimensions")
        shape = xi.shape[:-1]
        xi = np.ascontiguousarray(xi.reshape(-1, ndim), dtype=np.float64)
        if self.scale is not None:
            xi = (xi - self.offset) / self.scale
        return xi, shape


def barycentric(tri, points, simplices, xi):
    """Barycentric coordinates (m, d+1) of each xi in its simplex of tri (points: tri's points,
    as the interpolant holds them), in the simplex's vertex order."""
    d = xi.shape[1]
    transform = tri.transform[simplices]
    weights = np.empty((len(xi), d + 1))
    weights[:, :d] = np.einsum("ijk,ik->ij", transform[:, :d, :], xi - transform[:, d, :])
    weights[:, d] = 1.0 - weights[:, :d].sum(axis=1)
    # A NaN transform (a simplex flat within rounding): weights w with sum(w v_j) = x and
    # sum(w) = 1 in the least-squares sense; any such w reproduces linear functions.
    for i in np.flatnonzero(np.isnan(transform[:, 0, 0])):
        corners = points[tri.simplices[simplices[i]]]  # (d+1, d)
        system = np.vstack([corners.T, np.ones(d + 1)])
        weights[i] = np.linalg.lstsq(system, np.append(xi[i], 1.0), rcond=None)[0]
    return weights
