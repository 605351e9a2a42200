"""Turning what the user passes into what the engine reads; what every class shares."""
import copy
from functools import cached_property

import numpy as np

from . import _drange


def as_points(points):
    """The points as a C-contiguous float64 array of shape (npoints, ndim); copies only if needed."""
    array = np.asarray(points, dtype=np.float64)
    if array.ndim != 2:
        raise ValueError(f"points must be a 2-D array of shape (npoints, ndim); got shape {array.shape}")
    if array.shape[0] == 0:
        raise ValueError("No points given")  # scipy's message and type
    return np.ascontiguousarray(array)


def as_added_points(points, ndim):
    """Points for add_points: as as_points, of the triangulation's dimension; none is allowed."""
    array = np.asarray(points, dtype=np.float64)
    if array.ndim != 2 or array.shape[1] != ndim:
        raise ValueError(f"points to add must be a 2-D array of shape (npoints, {ndim}); got shape {array.shape}")
    return np.ascontiguousarray(array)


def check_scipy_arguments(qhull_options):
    """scipy's qhull_options: accepted where they make sense here."""
    if qhull_options is not None and not isinstance(qhull_options, (str, bytes)):
        raise TypeError(f"qhull_options must be a string or None; got {type(qhull_options).__name__}")
    options = qhull_options.decode() if isinstance(qhull_options, bytes) else (qhull_options or "")
    if any(option.startswith("QJ") for option in options.split()):
        raise ValueError("qhull_options 'QJ' (joggle the input) has no meaning in drange: every decision is "
                         "exact, and degenerate input gives one well-defined triangulation without joggling")
    # Qhull's other options (tolerances, triangulated output, ...) have no effect: every
    # decision is exact and the output is always simplicial.


def as_point_ids(ids):
    """The ids of delaunay_stars and voronoi_cells as an int64 array; ValueError naming a bad one
    (the range and repeats are the engine's to check)."""
    array = np.asarray(ids)
    if array.ndim != 1:
        raise ValueError(f"ids must be a 1-D sequence of point indices; got shape {array.shape}")
    if array.size and not np.issubdtype(array.dtype, np.integer):
        bad = next((x for x in array.tolist() if not (isinstance(x, int) and not isinstance(x, bool))), array[0])
        raise ValueError(f"point id {bad!r} is not an integer index")
    return array.astype(np.int64)


def check_options(variant, threads, algorithm="auto"):
    names = _drange.variant_names
    if not isinstance(variant, str):
        raise TypeError(f"variant must be a string, one of {names}; got {type(variant).__name__}")
    if not isinstance(algorithm, str):
        raise TypeError(f"algorithm must be a string, one of {_drange.algorithm_names}; "
                        f"got {type(algorithm).__name__}")
    if isinstance(threads, bool) or not isinstance(threads, (int, np.integer)):
        raise TypeError(f"threads must be an integer; got {type(threads).__name__}")


def _rebuild(cls, points, arguments):
    """Unpickling: the same class on the same points and arguments gives the same result (the
    engine is exact and deterministic); pickle then restores the original run's figures."""
    return cls(points, **arguments)


class PointSetAttributes:
    """scipy's attributes that depend on the points alone (`self.points` set by the subclass),
    and pickling and copying. A subclass records its keyword arguments in `self._arguments`."""

    def __reduce__(self):
        # The engine's object does not pickle, and need not: the points and the arguments
        # rebuild it, identical, and the pickle holds the points only.
        return _rebuild, (type(self), self.points, self._arguments), {"statistics": self.statistics}

    def __copy__(self):
        result = object.__new__(type(self))
        result.__dict__.update(self.__dict__)
        # The incremental state is the copy's own (sharing it, an add to one would change both).
        if self.__dict__.get("_incremental") is not None:
            result._incremental = result._new_incremental(result.points)
        return result

    def __deepcopy__(self, memo):
        # The engine's object is immutable: shared. Every array and cached attribute is copied.
        result = object.__new__(type(self))
        memo[id(self)] = result
        for name, value in self.__dict__.items():
            if name != "_incremental":
                result.__dict__[name] = value if name == "_core" else copy.deepcopy(value, memo)
        # The incremental state is the copy's own: the same triangulation, built again.
        if self.__dict__.get("_incremental") is not None:
            result._incremental = result._new_incremental(result.points)
        return result

    def _forget_cached(self):
        """Drops every cached attribute, for a class whose points changed (add_points)."""
        for cls in type(self).__mro__:
            for name, member in vars(cls).items():
                if isinstance(member, cached_property):
                    self.__dict__.pop(name, None)

    def _incremental_state(self):
        state = self.__dict__.get("_incremental")
        if state is None:
            raise RuntimeError("incremental mode is not enabled or the object was closed: add_points needs "
                               "incremental=True and no close() before")
        return state

    def add_points(self, points, restart=False):
        """Adds points (incremental=True only): the result is then the one a new object on all
        the points gives (the same simplices, as sets of point indices; their order may differ).
        restart=True builds the state again from all the points; without it only the change is
        computed. Raises RuntimeError without incremental=True or after close()."""
        state = self._incremental_state()
        previous = self.points
        everything = np.concatenate([previous, as_added_points(points, self.ndim)])
        if restart:
            state = self._incremental = self._new_incremental(everything)
        else:
            state.add_points(everything[self.npoints:])
        self.points = everything
        self._forget_cached()
        try:
            self._take_incremental_result()
        except BaseException:
            # A class that computes again on every add (ConvexHull) fails here on bad points:
            # the object goes back to the points before.
            self.points = previous
            self._take_incremental_result()
            raise

    npoints = property(lambda self: self.points.shape[0], doc="Number of input points.")
    ndim = property(lambda self: self.points.shape[1], doc="Dimension of the space.")
    min_bound = property(lambda self: self.points.min(axis=0), doc="Minimum of the points' coordinates.")
    max_bound = property(lambda self: self.points.max(axis=0), doc="Maximum of the points' coordinates.")

    def close(self):
        """Ends incremental mode (scipy's method): frees the state that add_points needs. Without
        incremental=True there is nothing to free."""
        self._incremental = None
