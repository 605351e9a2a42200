"""A pytest plugin: scipy.spatial's Delaunay, Voronoi, ConvexHull and HalfspaceIntersection
replaced by drange's before scipy's own test file is imported, so that its test bodies run
unchanged against drange. Loaded by run_scipy_suite.py (pytest -p drange_in_place)."""
import scipy.spatial
import scipy.spatial._qhull

import drange

for _name in ("Delaunay", "Voronoi", "ConvexHull", "HalfspaceIntersection"):
    setattr(scipy.spatial._qhull, _name, getattr(drange, _name))
    setattr(scipy.spatial, _name, getattr(drange, _name))
