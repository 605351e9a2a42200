"""drange.Delaunay: scipy.spatial.Delaunay's interface over the D-Range engine."""
import warnings
from functools import cached_property

import numpy as np

from . import _drange
from ._points import PointSetAttributes, as_points, check_options, check_scipy_arguments


def _inverses(matrices):
    """The inverse of each matrix; NaN for those numpy finds singular."""
    try:
        return np.linalg.inv(matrices)
    except np.linalg.LinAlgError:
        result = np.full(matrices.shape, np.nan)
        for i, matrix in enumerate(matrices):
            try:
                result[i] = np.linalg.inv(matrix)
            except np.linalg.LinAlgError:
                pass
        return result


class Delaunay(PointSetAttributes):
    """Delaunay triangulation in N >= 2 dimensions, exact.

    Parameters
    ----------
    points : array_like, shape (npoints, ndim)
        Coordinates of the points, 2 <= ndim <= 11.
    furthest_site : bool
        The furthest-site triangulation instead: the simplices whose circumspheres hold every
        point (the upper hull of the lifted points), exact under the same perturbation, built
        by insertion as with incremental=True. Only the extreme points are vertices.
    qhull_options
        scipy's argument, accepted so that code switches in one line; it has no effect, since no
        decision needs a tolerance, except that 'QJ' (joggling) raises ValueError.
    incremental : bool
        Allow add_points: the triangulation is kept by insertion (the "incremental"
        algorithm, one thread; `variant` and `algorithm` are then not used), and each call
        removes the simplices whose circumspheres hold a new point and joins it to the cavity's
        boundary: the triangulation's update follows the change, and the result arrays are
        then exported again (linear in their size). close() ends it. `progress` is not called
        and Ctrl-C waits for the end of the call.
    threads : int, keyword only
        Threads for the search and for find_simplex; 0 (default) uses all cores.
    variant : str, keyword only
        An ablation variant of the search, for measurements: "full" (default, the whole
        algorithm), or one with a step left out ("scan", "kdtree", "no-prune",
        "no-order", "paper", ...; every name: drange.variant_names). Every
        variant gives the same simplices; "fifo" and "spatial" fix the order in which
        open facets are taken (the paper's FIFO, or the spatial order that "full" uses
        in 3D to 5D), and "scan", "kdtree" and "paper" use FIFO: these number and list
        the simplices in another order. An unknown name raises ValueError.
    algorithm : str, keyword only
        The construction: "direct" (the D-Range search of each open facet), "incremental"
        (randomized insertion, whose speed does not depend on the points' shape) or "auto"
        (default: the incremental one in 2D and 3D when a probe of the direct search on a
        sample finds it slow, as on surfaces). All give the same simplices, in another
        order. A variant other than "full" measures the direct search. An unknown name, or
        "incremental" with such a variant, raises ValueError.
    progress : callable, keyword only
        Called as progress(simplices_found) every 65536 simplices, and once at the end.

    Attributes
    ----------
    points : ndarray of double, (npoints, ndim)
    simplices : ndarray of int32, (nsimplex, ndim+1)
        Point indices of each simplex, positively oriented.
    neighbors : ndarray of int32, (nsimplex, ndim+1)
        Neighbour k is opposite vertex k; -1 on the hull.
    coplanar : ndarray of int32, (ncoplanar, 3)
        The exact duplicates, left out of the triangulation: point index, a simplex holding
        it, and the index of the point it copies.
    statistics : dict
        The run's figures: points, distinct_points, simplices, hull_facets,
        search_calls, calls_per_simplex, threads, algorithm (the construction that ran),
        seconds_kdtree, seconds_first_facet, seconds_choice,
        seconds_search, seconds_total, peak_rss_bytes, seconds_busy (a list: each
        search thread's busy time), seconds_critical_path; and statistics["debug"], a dict
        of the engine's internal counters (points_tested, candidates, exact_fallbacks,
        max_open_facets, shell_spheres, wasted_searches, unfiltered_tests), whose meaning follows the
        implementation.

    The other attributes (convex_hull, vertex_neighbor_vertices, vertex_to_simplex,
    equations, transform) are computed on first use.
    """

    def __init__(self, points, furthest_site=False, incremental=False, qhull_options=None, *,
                 threads=0, variant="full", algorithm="auto", progress=None):
        check_scipy_arguments(qhull_options)
        check_options(variant, threads, algorithm)
        self.points = as_points(points)
        self.furthest_site = bool(furthest_site)
        self._arguments = {"threads": int(threads), "variant": variant, "algorithm": algorithm,
                           "incremental": bool(incremental), "furthest_site": self.furthest_site}
        self._threads = int(threads)
        if incremental or furthest_site:
            state = self._new_incremental(self.points)
            self._incremental = state if incremental else None
            self._take(state.triangulated(self.points))
        else:
            self._incremental = None
            self._take(_drange.triangulate(self.points, variant, algorithm, int(threads), progress))
        self.paraboloid_scale = 1.0
        self.paraboloid_shift = 0.0

    def _take(self, core):
        self._core = core
        self.simplices = core.simplices
        self.neighbors = core.neighbors
        self.statistics = core.statistics

    def _new_incremental(self, points):
        return _drange.IncrementalDelaunay(points, self.furthest_site)

    def _take_incremental_result(self):
        self._take(self._incremental.triangulated(self.points))

    nsimplex = property(lambda self: self.simplices.shape[0], doc="Number of simplices.")

    @property
    def vertices(self):
        """scipy's deprecated name of `simplices` (scipy 1.10 warns as here; 1.11 removed it)."""
        warnings.warn("Delaunay attribute 'vertices' is deprecated in favour of 'simplices' and will be "
                      "removed in Scipy 1.11.0.", DeprecationWarning, stacklevel=2)
        return self.simplices

    @cached_property
    def vertex_to_simplex(self):
        """For each point, a simplex it is a vertex of; for an exact duplicate, one of the point
        it copies (as scipy gives one for its coplanar points)."""
        result = np.full(self.npoints, -1, dtype=np.int32)
        result[self.simplices.ravel()] = np.repeat(np.arange(self.nsimplex, dtype=np.int32), self.ndim + 1)
        pairs = self._core.duplicates
        result[pairs[:, 0]] = result[pairs[:, 1]]
        return result

    @cached_property
    def coplanar(self):
        """(ncoplanar, 3): each exact duplicate, a simplex that holds it, the point it copies."""
        pairs = self._core.duplicates
        result = np.empty((len(pairs), 3), dtype=np.int32)
        result[:, 0] = pairs[:, 0]
        result[:, 1] = self.vertex_to_simplex[pairs[:, 1]]
        result[:, 2] = pairs[:, 1]
        return result

    @cached_property
    def convex_hull(self):
        """(nfaces, ndim): the hull facets, ordered counter-clockwise in 2D and counter-clockwise
        seen from outside in 3D (in general: det[f1-f0, ..., f(d-1)-f0, x-f0] has the sign
        (-1)^ndim for x inside)."""
        d = self.ndim
        simplex, opposite = np.nonzero(self.neighbors == -1)
        columns = np.arange(d + 1)
        keep = columns[None, :] != opposite[:, None]
        facets = self.simplices[simplex][keep].reshape(-1, d)
        # Removing vertex k from a positive simplex leaves a facet oriented by (-1)^(d-k); one
        # transposition where k is odd gives every facet the orientation (-1)^d.
        odd = (opposite % 2) == 1
        facets[odd, :2] = facets[odd, 1::-1]
        return facets

    @cached_property
    def vertex_neighbor_vertices(self):
        """(indptr, indices): the neighbours of point k are indices[indptr[k]:indptr[k+1]]."""
        d, n = self.ndim, self.npoints
        first, second = np.triu_indices(d + 1, 1)
        a = self.simplices[:, first].ravel().astype(np.int64)
        b = self.simplices[:, second].ravel().astype(np.int64)
        edges = np.unique(np.concatenate([a * n + b, b * n + a]))
        source, target = np.divmod(edges, n)
        indptr = np.searchsorted(source, np.arange(n + 1)).astype(np.int32)
        return indptr, target.astype(np.int32)

    @cached_property
    def transform(self):
        """(nsimplex, ndim+1, ndim): barycentric transforms, as scipy's. For simplex i,
        c = transform[i, :ndim] @ (x - transform[i, ndim]) gives the first ndim barycentric
        coordinates of x; the last is 1 - sum(c). As scipy's, a simplex too flat for floating
        point (reciprocal condition number, 1-norm, below 1000 eps) has a row of NaN: drange's
        simplices are never flat exactly, but can be within rounding."""
        d = self.ndim
        corners = self.points[self.simplices]  # (nsimplex, d+1, d)
        origin = corners[:, d, :]
        columns = (corners[:, :d, :] - origin[:, None, :]).transpose(0, 2, 1)
        inverse = _inverses(columns)
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            norms = np.abs(columns).sum(axis=1).max(axis=1) * np.abs(inverse).sum(axis=1).max(axis=1)
            too_flat = ~(1.0 / norms >= 1000 * np.finfo(np.float64).eps)  # NaN counts as too flat
        result = np.empty((self.nsimplex, d + 1, d))
        result[:, :d, :] = inverse
        result[:, d, :] = origin
        result[too_flat] = np.nan
        return result

    @cached_property
    def equations(self):
        """(nsimplex, ndim+2): the hyperplane [normal, offset] of each simplex lifted to the
        paraboloid x -> (x, |x|^2), with a unit normal pointing out of the lifted hull: down, so
        that the distance of a lifted point is positive inside the simplex's circumsphere; up
        for the furthest site (positive outside)."""
        d = self.ndim
        corners = self.points[self.simplices]
        base = corners[:, 0, :]
        edges = corners[:, 1:, :] - base[:, None, :]
        # Circumcentre c = base + y with 2 (v_i - base) . y = |v_i - base|^2.
        y = np.linalg.solve(2 * edges, np.einsum("ijk,ijk->ij", edges, edges)[..., None])[..., 0]
        centre = base + y
        radius2 = np.einsum("ij,ij->i", y, y)
        # On the sphere |x|^2 = 2 c.x - |c|^2 + r^2; the plane z - 2 c.x + |c|^2 - r^2 = 0.
        result = np.empty((self.nsimplex, d + 2))
        result[:, :d] = 2 * centre
        result[:, d] = -1.0
        result[:, d + 1] = radius2 - np.einsum("ij,ij->i", centre, centre)
        result /= np.linalg.norm(result[:, :d + 1], axis=1)[:, None]
        return -result if self.furthest_site else result

    def lift_points(self, x):
        """Lifts points to the paraboloid: (x, |x|^2 * paraboloid_scale + paraboloid_shift)."""
        x = np.asarray(x, dtype=np.float64)
        z = np.sum(x * x, axis=-1) * self.paraboloid_scale + self.paraboloid_shift
        return np.concatenate([x, z[..., None]], axis=-1)

    def plane_distance(self, xi):
        """Distances of the lifted point xi (shape (ndim,)) to every simplex's lifted plane."""
        xi = np.asarray(xi, dtype=np.float64)
        if xi.shape != (self.ndim,):
            raise ValueError(f"xi must have shape ({self.ndim},); got {xi.shape}")
        return self.equations[:, :-1] @ self.lift_points(xi) + self.equations[:, -1]

    def find_simplex(self, xi, bruteforce=False, tol=None):
        """The simplex containing each point of xi (shape (..., ndim)), -1 outside the hull.

        Exact: a point on a shared face, a vertex or the hull boundary is found in one of the
        simplices that hold it, a point one rounding error outside is outside, and NaN gives -1.
        The queries are shared among the `threads` given to the constructor; the answers do
        not depend on the count. `bruteforce` and `tol` are scipy's and have no effect here.
        """
        xi = np.asarray(xi, dtype=np.float64)
        if xi.ndim == 0 or xi.shape[-1] != self.ndim:
            raise ValueError(f"wrong dimensionality in xi: shape {xi.shape}, expected (..., {self.ndim})")
        found = self._core.find_simplex(np.ascontiguousarray(xi.reshape(-1, self.ndim)), self._threads)
        return found.reshape(xi.shape[:-1])

    def __repr__(self):
        return f"<drange.Delaunay: {self.npoints} points in {self.ndim}D, {self.nsimplex} simplices>"
