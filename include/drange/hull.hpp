// drange/hull.hpp: the convex hull of points in E^d, exact, its facets triangulated.
//
// The hull is that of the points under a symbolic perturbation that moves every point outward
// from an interior point by an amount that grows with its squared distance from it (then, for
// the ties that leaves, by amounts ordered by the points' lexicographic ranks). Its facets are
// therefore simplices whose vertices are exactly the extreme points of the input: a point in a
// face's relative interior, or on an edge between two corners, never becomes a vertex, and is
// listed among the coplanar points instead. Every facet of the true hull (a square of a cube, a
// side of a grid) is triangulated by its own corners, consistently across shared faces, and the
// same points in any order give the same facets.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "drange/points.hpp"

namespace drange {

// The result, in flat arrays like scipy.spatial.ConvexHull (with Qhull's option Qt):
//   simplices[f*d + k]  vertex k of facet f (zero-based input index). Each facet is oriented as
//                       Triangulation's hull facets are: det[v1-v0, ..., v(d-1)-v0, x-v0] has the
//                       sign (-1)^d for x inside (counter-clockwise in 2D, counter-clockwise seen
//                       from outside in 3D);
//   neighbors[f*d + k]  the facet across the ridge opposite vertex k of facet f;
//   vertices            the extreme points, increasing;
//   coplanar[c*3 + 0..2] a point on the hull's boundary that is not a vertex (inside a face, on
//                       an edge, or an exact copy of a vertex), a facet whose hyperplane holds
//                       it, and that facet's vertex nearest to it (scipy's columns); ordered by
//                       facet, then by point.
struct ConvexHull {
  int dim = 0;
  std::size_t num_points = 0;
  std::vector<std::int32_t> simplices;
  std::vector<std::int32_t> neighbors;
  std::vector<std::int32_t> vertices;
  std::vector<std::int32_t> coplanar;

  std::size_t size() const { return dim > 0 ? simplices.size() / static_cast<std::size_t>(dim) : 0; }
  const std::int32_t* facet(std::size_t f) const { return simplices.data() + f * static_cast<std::size_t>(dim); }
};

// Computes the convex hull by Quickhull (Barber, Dobkin and Huhdanpaa) with exact orientations.
// Throws InputError (NaN/infinite coordinate, a dimension outside 2..11, 2^31 points or more)
// or DegenerateInputError (fewer than d+1 distinct points, or all points in one hyperplane);
// InternalError when an invariant of the construction fails (a bug).
ConvexHull convex_hull(PointsView points);

// The facets' hyperplanes and the hull's measures, in floating point from the input coordinates:
//   equations[f*(d+1) + k]  the unit outward normal (k < d) and the offset (k = d) of facet f:
//                           normal . x + offset is negative inside, as scipy's equations;
//   area                    the total (d-1)-volume of the facets (the perimeter in 2D);
//   volume                  the d-volume inside.
struct HullGeometry {
  std::vector<double> equations;
  double area = 0.0;
  double volume = 0.0;
};
HullGeometry hull_geometry(PointsView points, const ConvexHull& hull);

// For each facet, the exact side of the point x (d coordinates) of its hyperplane: 1 outside
// (x sees the facet), 0 on it, -1 inside. Not perturbed: Qhull's "visible", which neither
// coplanarity nor degeneracy counts as.
std::vector<std::int8_t> facet_sides(PointsView points, const ConvexHull& hull, const double* x);

// For the hull of the dual points of halfspaces A_i x + b_i <= 0 (`halfspaces`: the rows
// [A_i, b_i], d+1 numbers each; dual point i is A_i / -(b_i + A_i . c) for a point c strictly
// inside them all), the facets grouped by the vertex of the intersection they stand for: for
// each facet, the least index among the facets connected to it across ridges whose halfspaces
// meet in one point. Exact on the halfspaces themselves, whatever rounding the dual points
// carry: neighbours are merged when the extra halfspace of one passes through the other's
// vertex (a (d+1) x (d+1) determinant of the rows is zero).
std::vector<std::int32_t> vertex_groups(PointsView halfspaces, const ConvexHull& dual);

}  // namespace drange
