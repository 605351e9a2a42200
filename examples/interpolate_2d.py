"""Triangulate scattered samples with drange, draw the triangulation and the Voronoi cells,
and interpolate the samples linearly on a grid.

Notebook-style: each "# %%" starts a cell (VS Code, Jupyter's jupytext, Spyder run them one by
one); as a script it writes one picture:

    PYTHONPATH=build/python /usr/bin/python3 examples/interpolate_2d.py [OUTPUT.png]
"""
# %% Samples of a smooth function at scattered points
import sys

import matplotlib

matplotlib.use("Agg")  # write files; remove this line in a notebook to see the figure inline
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.collections import PolyCollection

import drange
from drange.interpolate import LinearNDInterpolator


def f(x, y):
    return np.sin(3 * x) * np.cos(2 * y)


rng = np.random.default_rng(7)
points = rng.random((400, 2))
values = f(points[:, 0], points[:, 1])

# %% The Delaunay triangulation and the Voronoi diagram (same call shapes as scipy.spatial)
tri = drange.Delaunay(points)
vor = drange.Voronoi(points)
cells = vor.clipped_cells(box=([0, 0], [1, 1]))  # every cell cut to the unit square
print(f"{tri.nsimplex} triangles, {len(vor.vertices)} Voronoi vertices; "
      f"the clipped cells cover {cells.volumes.sum():.6f} of the unit square")

# %% Linear interpolation on the triangulation (scipy.interpolate's interface): each grid point's
# triangle found exactly, its value weighted by barycentric coordinates; NaN outside the hull
side = np.linspace(0, 1, 200)
gx, gy = np.meshgrid(side, side)
queries = np.c_[gx.ravel(), gy.ravel()]
interpolated = LinearNDInterpolator(tri, values)(queries)
inside = ~np.isnan(interpolated)
error = np.abs(interpolated[inside] - f(queries[inside, 0], queries[inside, 1]))
print(f"{inside.sum()} of {len(queries)} grid points inside the hull; "
      f"interpolation error: max {error.max():.4f}, mean {error.mean():.5f}")

# %% The picture: triangulation and cells on the left, the interpolant on the right
figure, (left, right) = plt.subplots(1, 2, figsize=(11, 5.2))
area = cells.volumes / cells.volumes.max()
left.add_collection(PolyCollection([cells.polygon(c) for c in range(len(cells))], array=area,
                                   cmap="Blues", edgecolors="white", linewidths=0.6))
left.triplot(points[:, 0], points[:, 1], tri.simplices, color="0.25", linewidth=0.5)
left.plot(points[:, 0], points[:, 1], "o", color="crimson", markersize=2)
left.set(title="Delaunay triangles over Voronoi cells (shade: cell area)", xlim=(0, 1), ylim=(0, 1), aspect="equal")
image = right.imshow(interpolated.reshape(gx.shape), origin="lower", extent=(0, 1, 0, 1), cmap="viridis")
right.plot(points[:, 0], points[:, 1], "k.", markersize=2)
right.set(title="Linear interpolation of sin(3x) cos(2y)", aspect="equal")
figure.colorbar(image, ax=right, shrink=0.8)
figure.tight_layout()
output = sys.argv[1] if len(sys.argv) > 1 else "interpolate_2d.png"
figure.savefig(output, dpi=80)
print(f"wrote {output}")
