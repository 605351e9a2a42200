"""drange.HalfspaceIntersection against scipy.spatial.HalfspaceIntersection (Qhull's qhalf) on
halfspaces in general position, and exact on degenerate ones (several planes through a vertex)."""
import itertools
import pickle

import numpy as np
import pytest
import scipy.spatial

import drange


def tangent_halfspaces(n, d, seed, redundant=0):
    """n halfspaces tangent to the unit sphere (random normals), plus `redundant` far away."""
    rng = np.random.default_rng(seed)
    normals = rng.standard_normal((n + redundant, d))
    normals /= np.linalg.norm(normals, axis=1)[:, None]
    offsets = -np.ones(n + redundant)
    offsets[n:] = -3.0
    return np.c_[normals, offsets]


def facet_keys(h):
    return [frozenset(f) for f in h.dual_facets]


def assert_like_scipy(halfspaces, interior):
    ours = drange.HalfspaceIntersection(halfspaces, interior)
    theirs = scipy.spatial.HalfspaceIntersection(halfspaces, interior)
    np.testing.assert_allclose(ours.dual_points, theirs.dual_points, rtol=1e-15, atol=0)
    assert sorted(map(sorted, facet_keys(ours))) == sorted(map(sorted, facet_keys(theirs)))
    order = {key: i for i, key in enumerate(facet_keys(theirs))}
    matched = [order[key] for key in facet_keys(ours)]
    scale = np.abs(theirs.intersections).max()
    np.testing.assert_allclose(ours.intersections, theirs.intersections[matched], rtol=0, atol=1e-12 * scale)
    np.testing.assert_allclose(ours.dual_equations, theirs.dual_equations[matched], rtol=0, atol=1e-12)
    assert np.array_equal(ours.dual_vertices, theirs.dual_vertices)
    assert ours.dual_area == pytest.approx(theirs.dual_area, rel=1e-12)
    assert ours.dual_volume == pytest.approx(theirs.dual_volume, rel=1e-12)
    return ours


@pytest.mark.parametrize("d", [2, 3, 4, 5])
def test_tangent_halfspaces_agree_with_scipy(d):
    for seed, n in [(1, 2 * d + 2), (2, 40), (3, 200 if d <= 4 else 80)]:
        ours = assert_like_scipy(tangent_halfspaces(n, d, seed), np.zeros(d))
        # Every vertex is inside every halfspace and on those of its dual facet.
        values = ours.intersections @ ours.halfspaces[:, :-1].T + ours.halfspaces[:, -1]
        assert values.max() <= 1e-12
        for vertex, facet in enumerate(ours.dual_facets):
            assert np.abs(values[vertex, facet]).max() <= 1e-12


@pytest.mark.parametrize("d", [2, 3, 4])
def test_redundant_halfspaces_and_a_shifted_interior_point(d):
    halfspaces = tangent_halfspaces(30, d, 4, redundant=10)
    ours = assert_like_scipy(halfspaces, np.full(d, 0.1))
    assert not set(range(30, 40)) & set(ours.dual_vertices.tolist())  # the far ones bound nothing


def box(d, lower=0.0, upper=1.0):
    """The halfspaces of the box [lower, upper]^d: -x_k + lower <= 0 and x_k - upper <= 0."""
    eye = np.eye(d)
    return np.vstack([np.c_[-eye, np.full(d, lower)], np.c_[eye, np.full(d, -upper)]])


@pytest.mark.parametrize("d", [2, 3, 4])
def test_box_with_planes_through_a_corner_is_exact(d):
    # The box, a copy of one of its sides, and planes through its corner (1, ..., 1) that cut
    # nothing off: 2^d vertices, exactly (no vertex split in two by the rounding of the dual
    # points, none off by a rounding), each with the box's sides through it.
    touching = [np.r_[np.ones(d), -d], np.r_[np.arange(1.0, d + 1), -np.arange(1.0, d + 1).sum()]]
    halfspaces = np.vstack([box(d), box(d)[:1], touching])
    hull = drange.HalfspaceIntersection(halfspaces, np.full(d, 0.25))
    corners = np.array(list(itertools.product([0.0, 1.0], repeat=d)))
    assert sorted(map(tuple, hull.intersections.tolist())) == sorted(map(tuple, corners.tolist()))
    assert len(hull.dual_facets) == 2 ** d
    values = hull.intersections @ halfspaces[:, :-1].T + halfspaces[:, -1]
    assert values.max() == 0.0
    sides = set(range(1, 2 * d))  # the box's sides but side 0, which has a copy (2d)
    for vertex, facet in enumerate(hull.dual_facets):
        tight = set(np.flatnonzero(values[vertex] == 0).tolist())
        # Every side through the vertex bounds it; a plane that only touches it (or the copy
        # of side 0) may be listed too, as the rounding of its dual point decides.
        assert tight & sides <= set(facet) <= tight
        assert len(set(facet) & {0, 2 * d}) == int(hull.intersections[vertex, 0] == 0)  # one of the copies
    assert sides <= set(hull.dual_vertices.tolist())


def test_octahedron_gives_the_cube_dual():
    normals = np.array(list(itertools.product([-1.0, 1.0], repeat=3)))
    ours = assert_like_scipy(np.c_[normals, -np.ones(8)], np.zeros(3))
    assert len(ours.dual_facets) == 6 and all(len(f) == 4 for f in ours.dual_facets)


def test_errors():
    square = box(2)
    with pytest.raises(drange.Error, match="not strictly inside halfspace 0 .on its boundary"):
        drange.HalfspaceIntersection(square, [0.0, 0.5])
    with pytest.raises(drange.Error, match="outside"):
        drange.HalfspaceIntersection(square, [2.0, 0.5])
    with pytest.raises(drange.Error, match="unbounded") as error:
        drange.HalfspaceIntersection(square[:3], [0.5, 0.5])
    assert isinstance(error.value, scipy.spatial.QhullError)
    # x - y - 1 <= 0 at (1, 2^-60): floating point says 0 (on it), exactly it is -2^-60 (inside);
    # x + y - 1 at the same point is +2^-60 (outside).
    tilted = np.vstack([box(2, -1.0, 2.0), [[1.0, -1.0, -1.0]]])
    inside = drange.HalfspaceIntersection(tilted, [1.0, 2.0 ** -60])
    assert inside.dual_points[4].tolist() == [2.0 ** 60, -(2.0 ** 60)]
    with pytest.raises(drange.Error, match="halfspace 4 .outside"):
        drange.HalfspaceIntersection(np.vstack([box(2, -1.0, 2.0), [[1.0, 1.0, -1.0]]]), [1.0, 2.0 ** -60])
    with pytest.raises(ValueError, match="finite"):
        drange.HalfspaceIntersection(np.r_[square, [[np.nan, 0, 0]]], [0.5, 0.5])
    with pytest.raises(ValueError, match="shape"):
        drange.HalfspaceIntersection(square, [0.5, 0.5, 0.5])
    with pytest.raises(ValueError, match="ndim"):
        drange.HalfspaceIntersection([[1.0, 2.0]], [0.5])
    with pytest.raises(ValueError, match="QJ"):
        drange.HalfspaceIntersection(square, [0.5, 0.5], qhull_options="QJ")
    with pytest.raises(RuntimeError, match="incremental"):
        drange.HalfspaceIntersection(square, [0.5, 0.5]).add_halfspaces(square)
    closed = drange.HalfspaceIntersection(square, [0.5, 0.5], incremental=True)
    with pytest.raises(ValueError, match="shape"):
        closed.add_halfspaces([[1.0, 0.0]])
    closed.close()
    with pytest.raises(RuntimeError, match="closed"):
        closed.add_halfspaces(square)


def test_pickle_and_attributes():
    hull = drange.HalfspaceIntersection(tangent_halfspaces(20, 3, 6), np.zeros(3))
    other = pickle.loads(pickle.dumps(hull))
    assert np.array_equal(other.intersections, hull.intersections) and other.dual_facets == hull.dual_facets
    assert hull.ndim == 3 and hull.nineq == 20 and hull.npoints == 20
    assert np.array_equal(hull.min_bound, hull.dual_points.min(axis=0))
    hull.close()
