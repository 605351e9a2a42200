"""drange.Voronoi: scipy.spatial.Voronoi's interface, plus cell volumes and clipped cells."""
from functools import cached_property

import numpy as np

from . import _drange
from ._points import PointSetAttributes, as_points, check_options, check_scipy_arguments


def _rows(offsets, values):
    """Ragged rows (offsets, values) as a list of lists of int."""
    flat = values.tolist()
    bounds = offsets.tolist()
    return [flat[bounds[r]:bounds[r + 1]] for r in range(len(bounds) - 1)]


class Voronoi(PointSetAttributes):
    """Voronoi diagram in N >= 2 dimensions, read off the exact Delaunay triangulation.

    Parameters are scipy's (see drange.Delaunay for furthest_site, incremental (add_points),
    qhull_options, threads, variant, algorithm and progress), plus:

    With furthest_site=True the furthest-site diagram: each point's region is where it is the
    farthest point; every region is unbounded (volume inf) and a point that is not extreme has
    an empty one (volume 0).

    cell_volumes : bool, keyword only
        Compute the volume of every bounded cell (default True).

    Attributes
    ----------
    points : ndarray of double, (npoints, ndim)
    vertices : ndarray of double, (nvertices, ndim)
        The Voronoi vertices: circumcentres of the Delaunay simplices. Cospherical simplices
        (every cell of an integer grid) share one vertex, decided exactly.
    ridge_points : ndarray of int32, (nridges, 2)
        The pairs of points whose cells share a (ndim-1)-face.
    ridge_vertices : list of list of int
        The vertices of each ridge, -1 for the point at infinity (3D: in cyclic order).
    regions : list of list of int
        Each cell's vertices, -1 when unbounded (2D: counter-clockwise). With the option 'Qz'
        in qhull_options, one more region first, empty (Qhull's point at infinity, which scipy
        has by default, at a place of Qhull's choosing): no point's region; its volume is NaN
        and its region_point -1. Clipped cells keep the numbering without it.
    point_region : ndarray of int32, (npoints,)
        Each point's region; an exact duplicate shares the region of the point it copies.
    volumes : ndarray of double, (nregions,)
        Each region's volume (area in 2D), inf when unbounded; per point:
        ``volumes[point_region]``. NaN everywhere if cell_volumes=False.
    region_point : ndarray of int32, (nregions,)
        The point of each region.
    statistics : dict
        The triangulation's figures, as drange.Delaunay.statistics.
    """

    def __init__(self, points, furthest_site=False, incremental=False, qhull_options=None, *,
                 threads=0, variant="full", algorithm="auto", cell_volumes=True, progress=None):
        check_scipy_arguments(qhull_options)
        check_options(variant, threads, algorithm)
        self.points = as_points(points)
        self.furthest_site = bool(furthest_site)
        self._arguments = {"threads": int(threads), "variant": variant, "algorithm": algorithm,
                           "cell_volumes": bool(cell_volumes), "incremental": bool(incremental),
                           "qhull_options": qhull_options, "furthest_site": self.furthest_site}
        options = qhull_options.decode() if isinstance(qhull_options, bytes) else (qhull_options or "")
        self._region_at_infinity = "Qz" in options.split()
        if incremental or furthest_site:
            state = self._new_incremental(self.points)
            self._incremental = state if incremental else None
            self._take(state.diagram(self.points, bool(cell_volumes)))
        else:
            self._incremental = None
            self._take(_drange.voronoi(self.points, variant, algorithm, int(threads), bool(cell_volumes), progress))

    def _take(self, core):
        self._core = core
        self.vertices = core.vertices
        self.ridge_points = core.ridge_points
        self.point_region = core.point_region
        self.region_point = core.region_point
        self.simplex_vertex = core.simplex_vertex
        self.statistics = core.statistics
        volumes = core.volumes
        self.volumes = volumes if len(volumes) == len(self.region_point) else np.full(len(self.region_point), np.nan)
        # The furthest site: a point that is not extreme is no simplex's vertex and has no
        # region in the engine's diagram; as in scipy, it gets one of its own, empty.
        self._empty_regions = 0
        if self.furthest_site:
            inner = np.flatnonzero(self.point_region < 0).astype(np.int32)
            self._empty_regions = len(inner)
            self.point_region = self.point_region.copy()
            self.point_region[inner] = len(self.region_point) + np.arange(len(inner), dtype=np.int32)
            self.region_point = np.r_[self.region_point, inner]
            self.volumes = np.r_[self.volumes, np.zeros(len(inner))]
        if self._region_at_infinity:
            self.point_region = self.point_region + 1
            self.region_point = np.r_[np.int32(-1), self.region_point]
            self.volumes = np.r_[np.nan, self.volumes]

    def _new_incremental(self, points):
        return _drange.IncrementalDelaunay(points, self.furthest_site)

    def _take_incremental_result(self):
        self._take(self._incremental.diagram(self.points, self._arguments["cell_volumes"]))

    @cached_property
    def ridge_vertices(self):
        return _rows(self._core.ridge_offsets, self._core.ridge_indices)

    @cached_property
    def regions(self):
        regions = _rows(self._core.region_offsets, self._core.region_indices) + [[] for _ in range(self._empty_regions)]
        # Qhull's option Qz adds a point at infinity, whose region is empty and no point's.
        return [[]] + regions if self._region_at_infinity else regions

    @property
    def ridge_dict(self):
        """{(p, q): ridge vertices}, as scipy's."""
        return {(int(p), int(q)): v for (p, q), v in zip(self.ridge_points.tolist(), self.ridge_vertices)}

    def clipped_cells(self, box=None, margin=0.1):
        """Every cell intersected with an axis-aligned box (2D and 3D).

        box : (lower, upper), each of ndim values; default: the points' bounding box enlarged
        by `margin` times its extent on every side. Returns a ClippedCells; the cells tile the box.
        """
        if self.furthest_site:
            raise NotImplementedError("clipped cells are the nearest-site diagram's; not available with furthest_site=True")
        if box is None:
            lower, upper = _drange.default_clip_box(self.points, float(margin))
        else:
            lower, upper = (np.asarray(b, dtype=np.float64).ravel() for b in box)
        return ClippedCells(self._core.clip(lower.tolist(), upper.tolist()), self.ndim, self._core.region_point)

    def __repr__(self):
        return (f"<drange.Voronoi: {self.npoints} points in {self.ndim}D, {len(self.vertices)} vertices, "
                f"{len(self.ridge_points)} ridges>")


class ClippedCells:
    """Voronoi cells clipped to a box: cell c is region c of the diagram, cut by the box.

    Attributes
    ----------
    lower, upper : ndarray (ndim,)  the box
    volumes : ndarray (ncells,)     area (2D) or volume (3D) of each clipped cell
    region_point : ndarray (ncells,)  the input point of each cell
    points : ndarray (ncorners, ndim)   the corners, each cell with its own
    face_offsets, face_indices : the boundary loops (2D: one polygon per cell, counter-clockwise;
        3D: one loop per face, counter-clockwise seen from outside); loop f is
        points[face_indices[face_offsets[f]:face_offsets[f+1]]]
    cell_faces : ndarray (ncells+1,)  cell c owns loops cell_faces[c] to cell_faces[c+1]-1
    """

    def __init__(self, parts, ndim, region_point):
        self.ndim = ndim
        self.lower = parts["lower"]
        self.upper = parts["upper"]
        self.points = parts["points"]
        self.face_offsets = parts["face_offsets"]
        self.face_indices = parts["face_indices"]
        self.cell_faces = parts["cell_faces"]
        self.volumes = parts["volumes"]
        self.region_point = region_point

    def __len__(self):
        return len(self.volumes)

    def faces(self, cell):
        """The boundary loops of a cell, each as an array of corner coordinates."""
        loops = range(self.cell_faces[cell], self.cell_faces[cell + 1])
        return [self.points[self.face_indices[self.face_offsets[f]:self.face_offsets[f + 1]]] for f in loops]

    def polygon(self, cell):
        """2D: the cell's polygon, counter-clockwise, shape (ncorners, 2); empty if it misses the box."""
        if self.ndim != 2:
            raise ValueError(f"polygon() is for 2D cells; these are {self.ndim}D (use faces())")
        loops = self.faces(cell)
        return loops[0] if loops else np.empty((0, 2))
