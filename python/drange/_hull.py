"""drange.ConvexHull: scipy.spatial.ConvexHull's interface over drange's exact Quickhull."""
from functools import cached_property

import numpy as np

from . import _drange
from ._points import PointSetAttributes, as_points, check_scipy_arguments


def _good_option(qhull_options, npoints):
    """Qhull's 'QGn' / 'QG-n' in qhull_options: (n, True for visible) or None."""
    options = qhull_options.decode() if isinstance(qhull_options, bytes) else (qhull_options or "")
    found = None
    for option in options.split():
        if not option.startswith("QG"):
            continue
        try:
            n = int(option[2:])
        except ValueError:
            raise ValueError(f"qhull_options {option!r}: QG needs a point index, as in 'QG4' or 'QG-4'") from None
        visible = not option[2:].startswith("-")
        n = abs(n)
        if n >= npoints:
            raise ValueError(f"qhull_options {option!r}: point {n} does not exist ({npoints} points)")
        found = (n, visible)
    return found


def _counter_clockwise(simplices):
    """The 2D hull's vertices in counter-clockwise order: every facet [a, b] has the inside on
    its left (drange's facet orientation), so the boundary runs a -> b."""
    following = dict(zip(simplices[:, 0].tolist(), simplices[:, 1].tolist()))
    start = min(following)
    order = [start]
    while following[order[-1]] != start:
        order.append(following[order[-1]])
    return np.array(order, dtype=np.int32)


class _Rebuilt:
    """ConvexHull's incremental state: none, since each add_points computes the hull again."""

    def add_points(self, points):
        pass


class ConvexHull(PointSetAttributes):
    """Convex hull in N >= 2 dimensions, exact, its facets triangulated.

    Parameters
    ----------
    points : array_like, shape (npoints, ndim)
        Coordinates of the points, 2 <= ndim <= 11.
    incremental : bool
        Allow add_points (scipy's argument); each call computes the hull of all the points
        again (Quickhull from scratch: exact, and the same facets as a new ConvexHull). close()
        ends it.
    qhull_options : str
        scipy's options. 'QGn' and 'QG-n' are honoured as in scipy: point n is left out of
        the hull, and `good` marks the facets that point n sees (or, with '-', does not see);
        seeing is strict, exactly: a point on a facet's hyperplane does not see it. 'QJ'
        (joggling) raises ValueError; the other options have no effect: no decision needs a
        tolerance, and the facets are always triangulated (Qhull's 'Qt').

    Attributes
    ----------
    points : ndarray of double, (npoints, ndim)
    simplices : ndarray of int32, (nfacet, ndim)
        The facets. Each is oriented as drange.Delaunay's convex_hull (counter-clockwise in 2D
        and seen from outside in 3D). Only extreme points are vertices: a true facet with more
        corners (a square of a cube) is split into simplices between its corners.
    neighbors : ndarray of int32, (nfacet, ndim)
        Neighbour k of a facet is the facet across the ridge opposite its vertex k.
    vertices : ndarray of int32, (nvertices,)
        The extreme points: counter-clockwise in 2D, increasing otherwise.
    coplanar : ndarray of int32, (ncoplanar, 3)
        Every point on the hull's boundary that is not a vertex (inside a facet or on an edge,
        or an exact copy of a vertex): its index, a facet whose hyperplane holds it and that
        facet's vertex nearest to it. (scipy lists such points only with the option 'Qc'.)
    equations : ndarray of double, (nfacet, ndim+1)
        [normal, offset] of each facet, the normal of unit length and outward: normal . x +
        offset is negative inside.
    area, volume : float
        The (ndim-1)-volume of the boundary (the perimeter in 2D) and the ndim-volume inside.
    good : ndarray of bool, (nfacet,), or None
        With 'QGn' / 'QG-n' (above); None otherwise.
    """

    def __init__(self, points, incremental=False, qhull_options=None):
        check_scipy_arguments(qhull_options)
        self.points = as_points(points)
        self._arguments = {"qhull_options": qhull_options}
        self._incremental = _Rebuilt() if incremental else None
        self._build()

    def _build(self):
        good = _good_option(self._arguments["qhull_options"], self.npoints)
        self.good = None
        if good is None:
            self._core = _drange.convex_hull(self.points)
            self.simplices = self._core.simplices
            self.neighbors = self._core.neighbors
            self.coplanar = self._core.coplanar
            vertices = self._core.vertices
        else:
            # Point n is not part of the hull (scipy's QGn): the hull of the others, renumbered.
            # A bad coordinate is named here, by its index among all the points.
            bad = np.argwhere(~np.isfinite(self.points))
            if len(bad):
                i, k = bad[0]
                raise ValueError(f"point {i}, coordinate {k} is {'NaN' if np.isnan(self.points[i, k]) else 'infinite'}")
            n, visible = good
            kept = np.delete(np.arange(self.npoints, dtype=np.int32), n)
            self._core = _drange.convex_hull(np.ascontiguousarray(self.points[kept]))
            self.simplices = kept[self._core.simplices]
            self.neighbors = self._core.neighbors
            coplanar = self._core.coplanar.copy()
            coplanar[:, 0] = kept[coplanar[:, 0]]
            coplanar[:, 2] = kept[coplanar[:, 2]]
            self.coplanar = coplanar
            vertices = kept[self._core.vertices]
            sides = self._core.facet_sides(self.points[n])
            self.good = sides > 0 if visible else sides <= 0
        self.vertices = _counter_clockwise(self.simplices) if self.ndim == 2 else vertices

    @staticmethod
    def _new_incremental(points):
        return _Rebuilt()

    def _take_incremental_result(self):
        self._build()

    nsimplex = property(lambda self: self.simplices.shape[0], doc="Number of facets.")

    @cached_property
    def _geometry(self):
        return self._core.geometry()

    @property
    def equations(self):
        """(nfacet, ndim+1): each facet's unit outward normal and offset."""
        return self._geometry[0]

    @property
    def area(self):
        """The (ndim-1)-volume of the hull's boundary (the perimeter in 2D)."""
        return self._geometry[1]

    @property
    def volume(self):
        """The ndim-volume of the hull."""
        return self._geometry[2]

    def __reduce__(self):
        # The points and the options rebuild the identical hull.
        return type(self), (self.points, self._incremental is not None, self._arguments["qhull_options"])

    def __repr__(self):
        return f"<drange.ConvexHull: {self.npoints} points in {self.ndim}D, {self.nsimplex} facets>"
