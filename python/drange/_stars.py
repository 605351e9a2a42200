"""drange.delaunay_stars: the simplices around given points, without the whole triangulation."""
import numpy as np

from . import _drange
from ._points import as_points, check_options, as_point_ids


class Stars:
    """The stars of some points of a Delaunay triangulation (drange.delaunay_stars's result).

    Attributes
    ----------
    points : ndarray of double, (npoints, ndim)
    ids : ndarray of int64, the point indices asked for, in the order given
    simplices : ndarray of int32, (nsimplex, ndim+1)
        Every simplex of ``drange.Delaunay(points)`` with a vertex in ``ids``, each once and
        positively oriented: the same vertex sets as there, in another order and numbering.
    neighbors : ndarray of int32, (nsimplex, ndim+1)
        Neighbour k is the returned simplex opposite vertex k; -1 on the hull or where that
        simplex is not returned.
    duplicates : ndarray of int64, (nduplicates, 2)
        Every exact copy among the points and the point it copies, as Delaunay's ``coplanar``
        lists them; a copy's id gives the star of the point it copies.
    statistics : dict
        The run's figures, as Delaunay.statistics.
    """

    def __init__(self, points, ids, core):
        self.points = points
        self.ids = ids
        self._core = core

    simplices = property(lambda self: self._core.simplices)
    neighbors = property(lambda self: self._core.neighbors)
    duplicates = property(lambda self: self._core.duplicates)
    statistics = property(lambda self: self._core.statistics)
    ndim = property(lambda self: self.points.shape[1])


def delaunay_stars(points, ids, *, threads=0, variant="full"):
    """The stars of the points `ids`: every simplex of the Delaunay triangulation incident to
    one of them, exactly as ``drange.Delaunay(points)`` has it, found without the rest of the
    triangulation (a walk to each point, then its facets wrapped one by one), at a cost that
    grows with the stars, not with the points, once the points are sorted into the kd-tree.

    `ids` are zero-based point indices; an id out of range or given twice, or one that is not
    an integer, raises ValueError naming it. `threads` speeds up the preparation only;
    `variant` as Delaunay's. Returns a Stars.

    >>> stars = delaunay_stars(points, [0, 17])
    >>> stars.simplices          # the triangles (tetrahedra, ...) touching point 0 or 17
    """
    points = as_points(points)
    check_options(variant, threads)
    array = as_point_ids(ids)
    core = _drange.stars(points, array.tolist(), variant, int(threads))
    return Stars(points, array, core)
