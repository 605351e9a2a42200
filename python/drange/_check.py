"""The exact validator, for anyone's triangulation (scipy's included)."""
import numpy as np

from . import _drange
from ._points import as_points


def check_triangulation(points, simplices, max_problems=20):
    """Checks exactly that `simplices` is a Delaunay triangulation of `points`.

    `simplices` has ndim+1 point indices per row, in either orientation (scipy's and Qhull's
    output are accepted). Checked: nonzero volumes; every facet shared by at most two simplices,
    from opposite sides; boundary facets supporting the convex hull; the hull covered exactly
    once; every distinct point used; no point strictly inside a circumsphere.

    Returns a dict: ``valid`` (bool), ``problems`` (a message per problem, at most
    `max_problems`), ``problem_count``, ``simplices``, ``interior_facets``, ``boundary_facets``.
    """
    points = as_points(points)
    simplices = np.ascontiguousarray(simplices, dtype=np.int32)
    return _drange.check_triangulation(points, simplices, int(max_problems))
