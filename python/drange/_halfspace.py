"""drange.HalfspaceIntersection: scipy.spatial.HalfspaceIntersection's interface, by the exact
convex hull of the dual points."""
from fractions import Fraction
from functools import cached_property

import numpy as np

from . import _drange
from ._hull import ConvexHull
from ._points import check_scipy_arguments


def _offsets_at(halfspaces, point):
    """b + A . point for every halfspace, and its exact sign: in floating point, and on
    rationals for the rows whose sign the rounding leaves in doubt (their value is then the
    exact one rounded once)."""
    a, b = halfspaces[:, :-1], halfspaces[:, -1]
    offsets = b + a @ point
    # Each of the d products and d sums rounds once: (2d + 1) u of the absolute terms bounds the
    # error, with room to spare (and underflow covered by the tiny floor).
    bound = (2 * a.shape[1] + 2) * np.finfo(float).eps * (np.abs(b) + np.abs(a) @ np.abs(point)) + 1e-300
    signs = np.sign(offsets)
    for i in np.flatnonzero(np.abs(offsets) <= bound):
        exact = Fraction(b[i]) + sum(Fraction(x) * Fraction(y) for x, y in zip(a[i].tolist(), point.tolist()))
        signs[i] = (exact > 0) - (exact < 0)
        offsets[i] = float(exact)  # correctly rounded where the sum cancelled
    return offsets, signs


def _independent_rows(normals, d, ids):
    """d of the rows, greedily the one farthest from the span of those chosen (unit rows,
    modified Gram-Schmidt): perpendicular planes are preferred to slanted ones through the
    same vertex, whose solution would carry rounding."""
    rows = normals / np.linalg.norm(normals, axis=1)[:, None]
    chosen = []
    for _ in range(d):
        best = int(np.argmax(np.einsum("ij,ij->i", rows, rows)))
        chosen.append(ids[best])
        pivot = rows[best] / np.linalg.norm(rows[best])
        rows = rows - np.outer(rows @ pivot, pivot)
    return chosen


class HalfspaceIntersection:
    """Intersection of halfspaces A x + b <= 0 in N >= 2 dimensions, by the exact convex hull of
    their dual points (Qhull's "qhalf").

    Parameters
    ----------
    halfspaces : array_like, shape (nineq, ndim+1)
        The inequalities, stacked as [A; b].
    interior_point : array_like, shape (ndim,)
        A point strictly inside every halfspace (checked exactly).
    incremental : bool
        Allow add_halfspaces (scipy's argument); each call computes the intersection of all
        the halfspaces again. close() ends it.
    qhull_options
        scipy's argument: 'QJ' raises ValueError; the other options have no effect.

    Attributes
    ----------
    halfspaces, interior_point : the input, as float64 arrays.
    intersections : ndarray of double, (ninter, ndim)
        The vertices of the intersection: one per facet of the dual hull, each the solution of
        the equations of d of the halfspaces through it.
    dual_points : ndarray of double, (nineq, ndim)
        Each halfspace's dual point, A_i / -(b_i + A_i . interior_point).
    dual_facets : list of list of int
        For each intersection, the halfspaces through it: the vertices of the facets of the
        dual hull that stand for it, merged exactly (the apex of a square pyramid has one facet
        of four), in increasing order. The dual hull is exact on the dual points as rounded to
        doubles (as Qhull's, without its tolerance): a redundant halfspace that only touches a
        vertex is listed or not as the rounding of its dual point decides.
    dual_vertices : ndarray of int32
        The halfspaces in dual_facets, increasing (as scipy's, whatever its docstring says of
        2D): those that bound the intersection, and touching ones as above.
    dual_equations : ndarray of double, (ninter, ndim+1)
        [normal, offset] of each dual facet, as ConvexHull.equations.
    dual_area, dual_volume : float
        The dual hull's area and volume.

    An unbounded intersection (the interior point not strictly inside the dual hull) raises
    drange.Error, a scipy.spatial.QhullError when scipy is installed; so does an interior
    point that is not strictly inside every halfspace.
    """

    def __init__(self, halfspaces, interior_point, incremental=False, qhull_options=None):
        check_scipy_arguments(qhull_options)
        halfspaces = np.ascontiguousarray(np.asarray(halfspaces, dtype=np.float64))
        if halfspaces.ndim != 2 or halfspaces.shape[1] < 3:
            raise ValueError(f"halfspaces must be a 2-D array of shape (nineq, ndim+1) with ndim >= 2; got shape {halfspaces.shape}")
        d = halfspaces.shape[1] - 1
        interior_point = np.array(interior_point, dtype=np.float64)
        if interior_point.shape != (d,):
            raise ValueError(f"interior_point must have shape ({d},); got {interior_point.shape}")
        if not (np.isfinite(halfspaces).all() and np.isfinite(interior_point).all()):
            raise ValueError("halfspaces and interior_point must be finite (no NaN or infinity)")
        self.interior_point = interior_point
        self._qhull_options = qhull_options
        self._incremental = bool(incremental)
        self._build(halfspaces)

    def _build(self, halfspaces):
        """The intersection of `halfspaces` around self.interior_point (checked above)."""
        d = halfspaces.shape[1] - 1
        interior_point = self.interior_point
        self.halfspaces = halfspaces
        self.__dict__.pop("intersections", None)
        offsets, signs = _offsets_at(halfspaces, interior_point)
        outside = np.flatnonzero(signs >= 0)
        if len(outside):
            raise _drange.Error(f"the interior point is not strictly inside halfspace {outside[0]} "
                                f"({'on its boundary' if signs[outside[0]] == 0 else 'outside it'})")
        self.dual_points = halfspaces[:, :-1] / -offsets[:, None]
        self._dual = ConvexHull(self.dual_points)
        # Bounded exactly when the dual hull holds its origin (the interior point) strictly.
        if (self._dual._core.facet_sides(np.zeros(d)) >= 0).any():
            raise _drange.Error("the intersection of the halfspaces is unbounded: the interior point is not "
                                "strictly inside the convex hull of their dual points")
        groups = self._dual._core.vertex_groups(halfspaces)
        representatives, members = np.unique(groups, return_inverse=True)
        facets = [set() for _ in representatives]
        for facet, group in zip(self._dual.simplices.tolist(), members.tolist()):
            facets[group].update(facet)
        self.dual_facets = [sorted(facet) for facet in facets]
        self._representatives = representatives
        # The d halfspaces each vertex is solved from: a simplex of its dual facet, or, where
        # more halfspaces meet there, d of them chosen to be as independent as possible.
        self._solved = self._dual.simplices[representatives].copy()
        for group, facet in enumerate(self.dual_facets):
            if len(facet) > d:
                self._solved[group] = _independent_rows(halfspaces[facet, :-1], d, facet)
        self.dual_vertices = np.sort(self._dual.vertices)

    ndim = property(lambda self: self.halfspaces.shape[1] - 1, doc="Dimension of the space.")
    nineq = property(lambda self: self.halfspaces.shape[0], doc="Number of halfspaces.")
    npoints = property(lambda self: self.halfspaces.shape[0], doc="Number of dual points (scipy's name).")
    min_bound = property(lambda self: self.dual_points.min(axis=0), doc="Minimum of the dual points.")
    max_bound = property(lambda self: self.dual_points.max(axis=0), doc="Maximum of the dual points.")
    dual_area = property(lambda self: self._dual.area, doc="Area of the dual hull.")
    dual_volume = property(lambda self: self._dual.volume, doc="Volume of the dual hull.")
    dual_equations = property(lambda self: self._dual.equations[self._representatives],
                              doc="[normal, offset] of each dual facet.")

    @cached_property
    def intersections(self):
        """(ninter, ndim): each vertex solves the equations of d halfspaces through it (those of
        one simplex of its dual facet: linearly independent; the best conditioned of them)."""
        chosen = self._solved
        a = self.halfspaces[chosen][:, :, :-1]
        b = self.halfspaces[chosen][:, :, -1]
        return np.linalg.solve(a, -b[..., None])[..., 0] + 0.0  # + 0.0: no negative zeros

    def __reduce__(self):
        return type(self), (self.halfspaces, self.interior_point, self._incremental, self._qhull_options)

    def add_halfspaces(self, halfspaces, restart=False):
        """Adds halfspaces (incremental=True only; scipy's method): the intersection of all of
        them is computed again. Raises RuntimeError without incremental=True or after close()."""
        if not self._incremental:
            raise RuntimeError("incremental mode is not enabled or the object was closed: add_halfspaces "
                               "needs incremental=True and no close() before")
        added = np.asarray(halfspaces, dtype=np.float64)
        if added.ndim != 2 or added.shape[1] != self.ndim + 1:
            raise ValueError(f"halfspaces to add must be a 2-D array of shape (nineq, {self.ndim + 1}); "
                             f"got shape {added.shape}")
        if not np.isfinite(added).all():
            raise ValueError("halfspaces must be finite (no NaN or infinity)")
        before = self.halfspaces
        try:
            self._build(np.ascontiguousarray(np.concatenate([before, added])))
        except BaseException:
            self._build(before)  # refused (an unbounded intersection ...): as it was
            raise

    def close(self):
        """Ends incremental mode (scipy's method)."""
        self._incremental = False

    def __repr__(self):
        return f"<drange.HalfspaceIntersection: {self.nineq} halfspaces in {self.ndim}D, {len(self.dual_facets)} vertices>"
