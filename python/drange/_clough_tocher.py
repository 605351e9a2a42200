"""drange.interpolate.CloughTocher2DInterpolator: scipy.interpolate's piecewise cubic, C1
interpolant of scattered 2D data, over drange's exact Delaunay.

The mathematics is scipy's, so that both agree to rounding where the triangulations agree:

* Gradients. The gradients g at the points minimise the sum, over the triangulation's edges
  (x_i, x_j), of the integral of the squared second derivative along the edge of the cubic
  Hermite interpolant of f and g there (Nielson's minimum-norm network, as used by Renka and
  Cline). With e = x_j - x_i, L = |e|, a = g_i.e and b = g_j.e, the edge's term is
  (4a^2 + 4ab + 4b^2 - 12(a + b)(f_j - f_i) + 12(f_j - f_i)^2) / L^3, so the best g_i given
  its neighbours' solves the 2x2 system
      sum_j 2 e e^T / L^3 g_i = sum_j (3 (f_j - f_i) - e.g_j) e / L^3.
  Gauss-Seidel sweeps over the points in index order, from g = 0, update each g_i in turn,
  until a sweep moves no gradient by tol or more (relative to its largest component, absolute
  below 1), or maxiter sweeps; each column of the values converges on its own.
* Element. Each triangle (V0, V1, V2) is split at its centroid C into three; on each part the
  interpolant is a cubic in Bernstein-Bezier form. Its control points follow from the values
  and gradients at the vertices, from C1 continuity across the inner edges, and from one
  condition per outer edge: the derivative across the edge, in the direction joining the
  centroids of the two triangles that share it (from C towards the edge's midpoint on the
  hull), is linear along the edge. Both triangles use the same direction, so the interpolant
  is C1; built from barycentric quantities, it commutes with affine maps. With exact
  gradients it reproduces quadratics (their derivatives are linear along any line).
"""
import warnings

import numpy as np

from ._delaunay import Delaunay
from ._scattered import CHUNK_ELEMENTS, ScatteredInterpolator, barycentric


class GradientEstimationWarning(Warning):
    """The Gauss-Seidel sweeps of the gradient estimation stopped at maxiter before tol."""


class CloughTocher2DInterpolator(ScatteredInterpolator):
    """Piecewise cubic, C1, curvature-minimising interpolant in 2D, as scipy.interpolate's.

    Parameters
    ----------
    points : ndarray of floats, shape (npoints, 2), or a drange.Delaunay
        The sample points, or their 2D triangulation (a scipy.spatial.Delaunay is used too).
    values : ndarray of float or complex, shape (npoints, ...)
        The values at the points; trailing dimensions are interpolated independently.
    fill_value : float, optional
        The value outside the convex hull; NaN by default.
    tol : float, optional
        The gradient estimation stops when a sweep changes no gradient by tol or more
        (relative to the gradient's largest component when that exceeds 1).
    maxiter : int, optional
        The most sweeps of the gradient estimation; stopping there warns with
        GradientEstimationWarning.
    rescale : bool, optional
        Rescale the points (and the queries) to the unit square before triangulating.

    Attributes
    ----------
    grad : ndarray, shape (npoints, k, 2)
        The estimated gradients (k values per point, float or complex as the values), in the
        rescaled coordinates when rescale is True; NaN at a point in no triangle (an exact
        duplicate).

    A query is located exactly (`Delaunay.find_simplex`): one a rounding error outside the
    hull gets fill_value. Each Gauss-Seidel sweep is vectorised by levels (see
    `_sweep_levels`); it costs more when the points are numbered along a long chain of
    neighbours, as a grid in row order, than in random order.
    """

    def __init__(self, points, values, fill_value=np.nan, tol=1e-6, maxiter=400, rescale=False):
        super().__init__(points, values, rescale)
        if self.points.shape[1] != 2:
            raise ValueError(f"CloughTocher2DInterpolator is 2-D only: the points have "
                             f"{self.points.shape[1]} dimensions")
        self._flat_values(fill_value)
        if self.tri is None:
            self.tri = Delaunay(self.points)
        indptr, indices = self.tri.vertex_neighbor_vertices
        real = self.values.view(np.float64)  # complex: real and imaginary parts as columns
        grad = _estimate_gradients(self.points, indptr, indices, real, float(tol), int(maxiter))
        if self.is_complex:
            pairs = grad.reshape(len(grad), -1, 2, 2)  # (point, value, real/imaginary, x/y)
            grad = pairs[:, :, 0, :] + 1j * pairs[:, :, 1, :]
        self.grad = grad

    def __call__(self, *args):
        """The interpolant at xi: one array of shape (..., 2), or 2 broadcastable arrays of
        coordinates. Returns shape xi.shape[:-1] + values.shape[1:]."""
        xi, shape = self._queries(args)
        k = self.values.shape[1]
        result = np.full((len(xi), k), self.fill_value, dtype=self.values.dtype)
        simplex = np.asarray(self.tri.find_simplex(xi))
        inside = np.flatnonzero(simplex >= 0)
        chunk = max(1, CHUNK_ELEMENTS // (32 * k))
        for start in range(0, len(inside), chunk):
            rows = inside[start:start + chunk]
            result[rows] = self._element(simplex[rows], xi[rows])
        return result.reshape(shape + self.values_shape)

    def _cross_directions(self, simplices):
        """For each simplex and each edge k (opposite vertex k, from vertex k+1 to k+2 cyclically),
        the ratio delta_{k+2} / delta_C of the cross direction's coordinates in the part
        (V_{k+1}, V_{k+2}, C); it is all that the edge's condition needs."""
        neighbours = self.tri.neighbors[simplices]  # (m, 3)
        across = np.maximum(neighbours, 0)
        centroids = self.points[self.tri.simplices[across]].sum(axis=2) / 3.0  # (m, 3, 2)
        c = barycentric(self.tri, self.points, np.repeat(simplices, 3), centroids.reshape(-1, 2))
        c = c.reshape(-1, 3, 3)  # (m, edge k, coordinate)
        k = np.arange(3)
        opposite, second = c[:, k, k], c[:, k, (k + 2) % 3]
        # From C = (1/3, 1/3, 1/3) to the neighbour's centroid c, in the part's coordinates
        # (V_{k+1}, V_{k+2}, C): delta = (c_{k+1} - c_k, c_{k+2} - c_k, 3 c_k - 1).
        with np.errstate(divide="ignore", invalid="ignore"):  # the hull's edges are replaced below
            ratio = (second - opposite) / (3.0 * opposite - 1.0)
        # On the hull: towards the edge's midpoint, delta = (1/2, 1/2, -1).
        return np.where(neighbours >= 0, ratio, -0.5)

    def _element(self, simplices, xi):
        """The interpolant (m, k) at xi, each in its simplex."""
        m = len(xi)
        b = barycentric(self.tri, self.points, simplices, xi)  # (m, 3)
        rows = np.arange(m)[:, None]
        # Rotate each triangle so that the query lies in the part (P0, P1, C): the part opposite
        # the vertex of smallest barycentric coordinate, which becomes P2.
        low = np.argmin(b, axis=1)[:, None]
        turn = (low + np.array([1, 2, 0])) % 3
        ratio = self._cross_directions(simplices)[rows, (low + np.arange(3)) % 3]  # edges P0P1, P1P2, P2P0
        b = b[rows, turn]
        u, v, w = b[:, 0:1] - b[:, 2:3], b[:, 1:2] - b[:, 2:3], 3.0 * b[:, 2:3]  # in (P0, P1, C)
        vertices = self.tri.simplices[simplices][rows, turn]
        p = self.points[vertices]  # (m, 3, 2)
        f = self.values[vertices]  # (m, 3, k)
        g = self.grad[vertices]  # (m, 3, k, 2)
        # Edge derivatives: from vertex i along the whole edge to vertex j, g_i . (P_j - P_i).
        dd = {}
        for i, j in ((0, 1), (1, 2), (2, 0)):
            edge = p[:, j] - p[:, i]
            dd[i, j] = np.einsum("mkx,mx->mk", g[:, i], edge)
            dd[j, i] = -np.einsum("mkx,mx->mk", g[:, j], edge)
        f = [f[:, 0], f[:, 1], f[:, 2]]
        # Control points next to vertex i: towards vertex j, and towards C.
        near = {key: f[key[0]] + d / 3.0 for key, d in dd.items()}
        inner = [(f[i] + near[i, (i + 1) % 3] + near[i, (i + 2) % 3]) / 3.0 for i in range(3)]
        # The control point of part (P_i, P_j, C) between the edge and C, from the edge's
        # condition: the cross derivative's quadratic along the edge has no curvature.
        middle = []
        for e, (i, j) in enumerate(((0, 1), (1, 2), (2, 0))):
            flat = f[i] - 2.0 * near[i, j] + near[j, i]
            cubic = -f[i] + 3.0 * near[i, j] - 3.0 * near[j, i] + f[j]
            middle.append((inner[i] + inner[j] - flat + ratio[:, e:e + 1] * cubic) / 2.0)
        # C1 across the inner edges, C being the centroid: each point one step from C's side
        # is the mean of its three neighbours one step further out.
        spoke = [(middle[i] + middle[(i + 2) % 3] + inner[i]) / 3.0 for i in range(3)]
        centre = (spoke[0] + spoke[1] + spoke[2]) / 3.0
        return (u ** 3 * f[0] + v ** 3 * f[1] + w ** 3 * centre
                + 3.0 * (u * u * v * near[0, 1] + u * v * v * near[1, 0] + u * u * w * inner[0]
                         + v * v * w * inner[1] + u * w * w * spoke[0] + v * w * w * spoke[1])
                + 6.0 * u * v * w * middle[0])


def _edge_rows(indptr, rows):
    """The positions in the neighbour lists of the neighbours of rows, row after row."""
    starts = indptr[rows].astype(np.int64)
    counts = indptr[rows + 1] - starts
    ends = np.cumsum(counts)
    return np.repeat(starts - ends + counts, counts) + np.arange(ends[-1] if len(ends) else 0)


def _sweep_levels(indptr, indices):
    """The level of each point for a vectorised Gauss-Seidel sweep in index order.

    The sweep updates point i from the new gradients of its lower-numbered neighbours and
    the old ones of its higher-numbered ones. A point's level is 0 without lower-numbered
    neighbours, else one more than the highest level among them; updating level after level,
    all the points of a level at once, then reads exactly what the sequential sweep reads
    (a higher-numbered neighbour is always in a later level)."""
    n = len(indptr) - 1
    source = np.repeat(np.arange(n), np.diff(indptr))
    waiting = np.bincount(indices[indices > source], minlength=n)  # lower-numbered neighbours
    level = np.zeros(n, dtype=np.int64)
    frontier, depth = np.flatnonzero(waiting == 0), 0
    while len(frontier):
        level[frontier] = depth
        edges = _edge_rows(indptr, frontier)
        targets = indices[edges]
        targets, counts = np.unique(targets[targets > np.repeat(frontier, np.diff(indptr)[frontier])],
                                    return_counts=True)
        waiting[targets] -= counts
        frontier, depth = targets[waiting[targets] == 0], depth + 1
    return level


def _estimate_gradients(points, indptr, indices, values, tol, maxiter):
    """The gradients (n, k, 2) of the k columns of values (n, k) at the points, by Gauss-Seidel
    sweeps in index order (see the module's docstring); NaN at a point without neighbours."""
    n, k = values.shape
    indptr = np.asarray(indptr, dtype=np.int64)
    indices = np.asarray(indices, dtype=np.int64)
    result = np.full((n, k, 2), np.nan)
    counts = np.diff(indptr)
    level = _sweep_levels(indptr, indices)
    order = np.flatnonzero(counts > 0)
    order = order[np.argsort(level[order], kind="stable")]
    if len(order) == 0 or k == 0:
        return result
    position = np.empty(n, dtype=np.int64)
    position[order] = np.arange(len(order))
    edges = _edge_rows(indptr, order)
    source = np.repeat(np.arange(len(order)), counts[order])  # positions, in sweep order
    target = position[indices[edges]]
    segments = np.concatenate([[0], np.cumsum(counts[order])[:-1]])

    # M = e e^T / L^3 per edge, and the 2x2 systems' inverses and right-hand sides per point.
    e = points[indices[edges]] - points[order][source]
    length = np.sqrt(e[:, 0] ** 2 + e[:, 1] ** 2)
    e_l3 = e / (length * length * length)[:, None]
    mxx, mxy, myy = e_l3[:, 0] * e[:, 0], e_l3[:, 0] * e[:, 1], e_l3[:, 1] * e[:, 1]
    qxx, qxy, qyy = (2.0 * np.add.reduceat(m, segments) for m in (mxx, mxy, myy))
    det = qxx * qyy - qxy * qxy
    ixx, ixy, iyy = (qyy / det)[:, None], (-qxy / det)[:, None], (qxx / det)[:, None]
    f = values[order]
    jump = 3.0 * (f[target] - f[source])  # (edges, k)
    cx = np.add.reduceat(jump * e_l3[:, 0:1], segments, axis=0)
    cy = np.add.reduceat(jump * e_l3[:, 1:2], segments, axis=0)
    mxx, mxy, myy = mxx[:, None], mxy[:, None], myy[:, None]

    # The levels as blocks of consecutive positions, with their edges and segment starts.
    cuts = np.concatenate([[0], np.flatnonzero(np.diff(level[order])) + 1, [len(order)]])
    blocks = []
    for v0, v1 in zip(cuts[:-1], cuts[1:]):
        e0 = segments[v0]
        e1 = segments[v1] if v1 < len(order) else len(edges)
        blocks.append((v0, v1, e0, e1, segments[v0:v1] - e0))

    columns = np.arange(k)  # the columns still sweeping
    gx, gy = np.zeros((len(order), k)), np.zeros((len(order), k))
    for _ in range(maxiter):
        old_x, old_y = gx.copy(), gy.copy()
        for v0, v1, e0, e1, starts in blocks:
            hx, hy = gx[target[e0:e1]], gy[target[e0:e1]]
            rx = cx[v0:v1] - np.add.reduceat(mxx[e0:e1] * hx + mxy[e0:e1] * hy, starts, axis=0)
            ry = cy[v0:v1] - np.add.reduceat(mxy[e0:e1] * hx + myy[e0:e1] * hy, starts, axis=0)
            gx[v0:v1] = ixx[v0:v1] * rx + ixy[v0:v1] * ry
            gy[v0:v1] = ixy[v0:v1] * rx + iyy[v0:v1] * ry
        change = np.maximum(np.abs(gx - old_x), np.abs(gy - old_y))
        change /= np.maximum(1.0, np.maximum(np.abs(gx), np.abs(gy)))
        done = np.nanmax(change, axis=0, initial=0.0) < tol  # NaN data: as scipy, not counted
        if done.any():
            result[order[:, None], columns[done], 0] = gx[:, done]
            result[order[:, None], columns[done], 1] = gy[:, done]
            keep = ~done
            columns, gx, gy, cx, cy = columns[keep], gx[:, keep], gy[:, keep], cx[:, keep], cy[:, keep]
            if len(columns) == 0:
                return result
    result[order[:, None], columns, 0] = gx
    result[order[:, None], columns, 1] = gy
    warnings.warn(f"the gradient estimation did not reach tol={tol:g} in maxiter={maxiter} sweeps for "
                  f"{len(columns)} of {k} value columns; the interpolant may be inaccurate",
                  GradientEstimationWarning, stacklevel=3)
    return result
