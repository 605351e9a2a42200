"""drange: exact Delaunay triangulations, Voronoi diagrams and convex hulls of points in 2 to 11
dimensions.

The classes have the names, attributes and methods of scipy.spatial's, so switching is one
line::

    from drange import Delaunay, Voronoi   # instead of: from scipy.spatial import ...

(and ConvexHull, HalfspaceIntersection.)

drange.interpolate has scipy.interpolate's LinearNDInterpolator, CloughTocher2DInterpolator,
NearestNDInterpolator and griddata over the exact triangulation.

Every decision is exact (no joggling, no tolerance): integer grids, cospherical points and
duplicates give one well-defined triangulation, the same for any input order.
"""
from ._drange import DegenerateInputError, Error, algorithm_names, variant_names
from ._delaunay import Delaunay
from ._hull import ConvexHull
from ._halfspace import HalfspaceIntersection
from ._voronoi import ClippedCells, Voronoi
from ._check import check_triangulation
from ._stars import Stars, delaunay_stars
from ._voronoi_cells import VoronoiCells, voronoi_cells
from . import interpolate

__all__ = ["ConvexHull", "HalfspaceIntersection", "Delaunay", "Voronoi", "ClippedCells", "check_triangulation", "delaunay_stars", "Stars",
           "voronoi_cells", "VoronoiCells", "Error",
           "DegenerateInputError", "variant_names", "algorithm_names", "interpolate"]
__version__ = "0.1.0"
