"""drange.voronoi_cells: the Voronoi cells of given points, from their Delaunay stars alone."""
import numpy as np

from . import _drange
from ._points import as_points, check_options, as_point_ids
from ._voronoi import _rows


class VoronoiCells:
    """Some cells of a Voronoi diagram (drange.voronoi_cells's result), with the names of
    drange.Voronoi, restricted to the cells asked for.

    Attributes
    ----------
    points : ndarray of double, (npoints, ndim)
    ids : ndarray of int64, the point indices asked for, in the order given
    vertices : ndarray of double, (nvertices, ndim)
        The vertices of these cells. Within a cell they are distinct; a vertex shared by two of
        the cells may appear twice when it is the centre of cospherical points whose simplices
        around the two points are not connected through the stars (see docs/algorithm.md).
    ridge_points : ndarray of int32, (nridges, 2)
        The ridges with one of `ids` at one end (the other end may be any point).
    ridge_vertices, regions : list of list of int, -1 for the point at infinity
    point_region : ndarray of int32, (npoints,)
        The region of each point asked for (and of its exact copies); -1 for the others.
    region_point : ndarray of int32, (nregions,)
    volumes : ndarray of double, (nregions,)
        As Voronoi.volumes: inf when unbounded; NaN everywhere if cell_volumes=False.
    """

    def __init__(self, points, ids, core):
        self.points = points
        self.ids = ids
        self._core = core
        self.vertices = core.vertices
        self.ridge_points = core.ridge_points
        self.point_region = core.point_region
        self.region_point = core.region_point
        self.ridge_vertices = _rows(core.ridge_offsets, core.ridge_indices)
        self.regions = _rows(core.region_offsets, core.region_indices)
        volumes = core.volumes
        self.volumes = volumes if len(volumes) == len(self.region_point) else np.full(len(self.region_point), np.nan)

    ndim = property(lambda self: self.points.shape[1])

    def __repr__(self):
        return f"<drange.VoronoiCells: {len(self.regions)} cells of {len(self.points)} points in {self.ndim}D>"


def voronoi_cells(points, ids, *, threads=0, variant="full", cell_volumes=True):
    """The Voronoi cells of the points `ids`, each equal to ``drange.Voronoi(points)``'s cell of
    that point (the same vertices, ridges and volume, up to the last bits of the coordinates),
    read off their Delaunay stars (drange.delaunay_stars) without the rest of the diagram.

    `ids` are zero-based point indices; an id out of range or given twice, or one that is not an
    integer, raises ValueError naming it. Returns a VoronoiCells.

    >>> cells = voronoi_cells(points, [0, 17])
    >>> cells.volumes[cells.point_region[17]]   # the area (volume) of point 17's cell
    """
    points = as_points(points)
    check_options(variant, threads)
    array = as_point_ids(ids)
    core = _drange.voronoi_cells(points, array.tolist(), variant, int(threads), bool(cell_volumes))
    return VoronoiCells(points, array, core)
