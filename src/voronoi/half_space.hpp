// voronoi/half_space.hpp: what the clipped polygon (2D) and polyhedron (3D) of clip_cells
// share: the side of a clipping line or plane each corner lies on, and the point where an
// edge crosses it.
//
// A clip keeps the half-space  normal . x <= offset  (normal a unit vector), so the signed
// distance of a corner x to the boundary is  normal . x - offset. A corner within the
// tolerance `tol` of the boundary is On it (clip_cells.cpp says how tol is chosen): it is
// kept as it is and no crossing point is made next to it. A bisector through a corner, as
// every bisector of an integer grid, therefore leaves the shape unchanged instead of adding
// a copy of that corner.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <tuple>
#include <vector>

namespace drange::cells {

enum class Side : signed char { Inside, On, Outside };

// What one clip did to a shape.
enum class ClipResult { Unchanged, Cut, Empty };

// Which sides occur among the corners.
struct SidesPresent {
  bool inside = false;
  bool outside = false;
};

// Fills the signed distance and the side of every corner: entries 0 .. corners.size() - 1 (the
// arrays only grow, so that their sizes need no call per clip).
template <class Corners>
SidesPresent classify(const Corners& corners, const double* normal, double offset, double tol,
                      std::vector<double>& distance, std::vector<Side>& side) {
  constexpr std::size_t D = std::tuple_size<typename Corners::value_type>::value;
  if (distance.size() < corners.size()) {
    distance.resize(corners.size());
    side.resize(corners.size());
  }
  SidesPresent present;
  for (std::size_t v = 0; v < corners.size(); ++v) {
    double dot = 0;
    for (std::size_t k = 0; k < D; ++k) dot += normal[k] * corners[v][k];
    distance[v] = dot - offset;
    side[v] = distance[v] < -tol ? Side::Inside : distance[v] > tol ? Side::Outside : Side::On;
    present.inside |= side[v] == Side::Inside;
    present.outside |= side[v] == Side::Outside;
  }
  return present;
}

// Whether the edge between corners on sides a and b crosses the boundary strictly (an On end
// is itself the crossing).
inline bool crosses(Side a, Side b) {
  return (a == Side::Inside && b == Side::Outside) || (a == Side::Outside && b == Side::Inside);
}

// The point where the edge from `in` (distance d_in < 0) to `out` (d_out > 0) meets the
// boundary. Always computed from the inside end, so it does not depend on the edge's direction.
template <std::size_t D>
std::array<double, D> crossing_point(const std::array<double, D>& in, double d_in, const std::array<double, D>& out,
                                     double d_out) {
  const double t = d_in / (d_in - d_out);
  std::array<double, D> x;
  for (std::size_t k = 0; k < D; ++k) x[k] = in[k] + t * (out[k] - in[k]);
  return x;
}

// The largest distance of a corner from the origin (the cell's point): a boundary farther
// away than this cannot cut the shape.
template <class Corners>
double max_norm(const Corners& corners) {
  constexpr std::size_t D = std::tuple_size<typename Corners::value_type>::value;
  double largest = 0;
  for (const auto& x : corners) {
    double sum = 0;
    for (std::size_t k = 0; k < D; ++k) sum += x[k] * x[k];
    if (sum > largest) largest = sum;  // not std::fmax: a library call here, in the clip's inner loop
  }
  return std::sqrt(largest);
}

template <std::size_t D>
double distance(const std::array<double, D>& a, const std::array<double, D>& b) {
  double sum = 0;
  for (std::size_t k = 0; k < D; ++k) sum += (a[k] - b[k]) * (a[k] - b[k]);
  return std::sqrt(sum);
}

}  // namespace drange::cells
