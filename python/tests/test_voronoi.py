"""drange.Voronoi against scipy.spatial.Voronoi (2D to 5D), and what scipy lacks: exact
merging on grids, cell volumes and cells clipped to a box."""
import numpy as np
import pytest
import scipy.spatial

import drange
from conftest import grid, sample

CASES = [("uniform", 1500, 2), ("gaussian", 600, 3), ("uniform", 200, 4), ("uniform", 80, 5)]


@pytest.fixture(scope="module", params=CASES, ids=[f"{k}-{n}-{d}D" for k, n, d in CASES])
def pair(request):
    kind, n, d = request.param
    points = sample(kind, n, d, seed=n * d)
    return points, drange.Voronoi(points), scipy.spatial.Voronoi(points)


def vertex_set(vor, ids, scale):
    """The coordinates of vertex ids (-1 kept as None), rounded to compare across programs."""
    return {None if v < 0 else tuple(np.round(vor.vertices[v] / scale, 7)) for v in ids}


def test_same_ridges_and_ridge_vertices(pair):
    points, ours, theirs = pair
    scale = np.ptp(points, axis=0).max()
    mine = {tuple(sorted(pq)): rv for pq, rv in zip(ours.ridge_points.tolist(), ours.ridge_vertices)}
    theirs_ridges = {tuple(sorted(pq)): rv for pq, rv in zip(theirs.ridge_points.tolist(), theirs.ridge_vertices)}
    # Qhull leaves out some unbounded ridges with fewer than ndim vertices; drange keeps them.
    assert set(theirs_ridges) <= set(mine)
    for extra in set(mine) - set(theirs_ridges):
        assert -1 in mine[extra] and len(mine[extra]) <= points.shape[1]
    for key, rv in theirs_ridges.items():
        assert vertex_set(ours, mine[key], scale) == vertex_set(theirs, rv, scale)


def test_same_regions(pair):
    points, ours, theirs = pair
    scale = np.ptp(points, axis=0).max()
    for p in range(len(points)):
        a = ours.regions[ours.point_region[p]]
        b = theirs.regions[theirs.point_region[p]]
        assert vertex_set(ours, a, scale) == vertex_set(theirs, b, scale)
        assert ours.region_point[ours.point_region[p]] == p


def test_volumes_equal_the_hull_of_scipys_region(pair):
    points, ours, theirs = pair
    checked = 0
    for p in range(len(points)):
        region = theirs.regions[theirs.point_region[p]]
        volume = ours.volumes[ours.point_region[p]]
        if -1 in region:
            assert volume == np.inf
            continue
        expected = scipy.spatial.ConvexHull(theirs.vertices[region]).volume
        assert volume == pytest.approx(expected, rel=1e-9, abs=1e-12)
        checked += 1
    assert checked > 0


def test_attributes(pair):
    points, ours, _ = pair
    n, d = points.shape
    assert (ours.npoints, ours.ndim) == (n, d)
    assert ours.vertices.shape[1] == d and ours.ridge_points.shape[1] == 2
    assert ours.point_region.shape == (n,)
    assert len(ours.regions) == len(ours.volumes) == len(ours.region_point)
    assert ours.ridge_dict[tuple(ours.ridge_points[0])] == ours.ridge_vertices[0]
    assert ours.statistics["points"] == n
    assert repr(ours).startswith("<drange.Voronoi")


@pytest.mark.parametrize("k,d", [(8, 2), (5, 3)])
def test_grid_cells_are_unit_cubes(k, d):
    points = grid(k, d)
    vor = drange.Voronoi(points)
    assert len(vor.vertices) == (k - 1) ** d  # one vertex per grid cell, merged exactly
    bounded = np.isfinite(vor.volumes)
    assert bounded.sum() == (k - 2) ** d
    assert vor.volumes[bounded] == pytest.approx(1.0, rel=1e-12)


def test_clipped_cells_tile_the_box():
    points = sample("uniform", 300, 2, seed=9)
    vor = drange.Voronoi(points)
    cells = vor.clipped_cells()
    area = np.prod(cells.upper - cells.lower)
    assert len(cells) == len(vor.regions)
    assert cells.volumes.sum() == pytest.approx(area, rel=1e-12)
    for c in range(len(cells)):
        polygon = cells.polygon(c)
        x, y = polygon[:, 0], polygon[:, 1]
        shoelace = 0.5 * np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y)
        assert shoelace == pytest.approx(cells.volumes[c], rel=1e-9)  # counter-clockwise
        if np.isfinite(vor.volumes[c]) and (polygon > cells.lower).all() and (polygon < cells.upper).all():
            assert cells.volumes[c] == pytest.approx(vor.volumes[c], rel=1e-9)


def test_clipped_cells_in_3d_and_a_given_box():
    points = sample("uniform", 200, 3, seed=2)
    vor = drange.Voronoi(points)
    cells = vor.clipped_cells(box=([0.25] * 3, [0.75] * 3))
    assert cells.volumes.sum() == pytest.approx(0.125, rel=1e-12)
    faces = cells.faces(int(np.argmax(cells.volumes)))
    assert len(faces) >= 4 and all(f.shape[1] == 3 for f in faces)
    with pytest.raises(ValueError, match="2D"):
        cells.polygon(0)


def test_without_volumes():
    vor = drange.Voronoi(sample("uniform", 100, 2, seed=1), cell_volumes=False)
    assert np.isnan(vor.volumes).all()


def test_duplicates_share_a_region():
    base = sample("uniform", 100, 2, seed=3)
    vor = drange.Voronoi(np.r_[base, base[:2]])
    assert vor.point_region[100] == vor.point_region[0] and vor.point_region[101] == vor.point_region[1]
