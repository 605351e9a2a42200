"""Shared helpers for the drange Python tests (run by CTest with PYTHONPATH=<build>/python)."""
import numpy as np
import pytest


def simplex_keys(simplices):
    """Each simplex as a sorted tuple of point indices."""
    return [tuple(row) for row in np.sort(np.asarray(simplices), axis=1).tolist()]


def neighbor_map(simplices, neighbors):
    """{(simplex key, vertex): key of the simplex across the facet opposite that vertex, or None}."""
    keys = simplex_keys(simplices)
    result = {}
    for s, row in enumerate(np.asarray(simplices).tolist()):
        for k, vertex in enumerate(row):
            n = int(neighbors[s][k])
            result[(keys[s], vertex)] = keys[n] if n >= 0 else None
    return result


def sample(kind, n, d, seed):
    rng = np.random.default_rng(seed)
    if kind == "uniform":
        return rng.random((n, d))
    if kind == "gaussian":
        return rng.standard_normal((n, d))
    raise ValueError(kind)


def grid(k, d):
    """The integer grid {0..k-1}^d as floats."""
    return np.array(np.meshgrid(*[np.arange(k)] * d, indexing="ij")).reshape(d, -1).T.astype(float)


@pytest.fixture
def rng():
    return np.random.default_rng(12345)
