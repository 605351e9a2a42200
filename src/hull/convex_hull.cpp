// hull/convex_hull.cpp: drange::convex_hull, from the caller's points to the scipy-shaped arrays.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "drange/errors.hpp"
#include "util/check_points.hpp"
#include "drange/hull.hpp"
#include "hull/initial_simplex.hpp"
#include "hull/quickhull.hpp"

namespace drange {
namespace {

// A copy of the coordinates scaled by a power of two so that the largest magnitude is below 1:
// exact, and orientations keep their signs. The filters' error bound then holds (no underflow
// escapes it, geometry/error_bound.hpp). False when the scaling would lose the smallest
// magnitude (inputs spanning more than 2^1022): the copy is left unscaled, and only the exact
// stages decide.
bool scaled_copy(PointsView input, std::vector<double>& coords) {
  coords.assign(input.coords, input.coords + input.n * static_cast<std::size_t>(input.dim));
  double largest = 0.0, smallest = std::numeric_limits<double>::infinity();
  for (const double x : coords) {
    if (x == 0.0) continue;
    largest = std::max(largest, std::fabs(x));
    smallest = std::min(smallest, std::fabs(x));
  }
  if (largest == 0.0) return true;
  int exponent = 0;
  std::frexp(largest, &exponent);
  if (std::ldexp(smallest, -exponent) < std::numeric_limits<double>::min()) return false;
  for (double& x : coords) x = std::ldexp(x, -exponent);
  return true;
}

}  // namespace

ConvexHull convex_hull(PointsView points) {
  util::check_points(points, "computes hulls");
  const int d = points.dim;
  std::vector<double> coords;
  const bool filters = scaled_copy(points, coords);
  const PointsView scaled(coords.data(), points.n, d);
  hull::Quickhull quickhull(coords.data(), static_cast<std::int32_t>(points.n), d, filters, hull::initial_simplex(scaled));
  hull::HullFacets facets = quickhull.run();

  ConvexHull result;
  result.dim = d;
  result.num_points = points.n;
  result.simplices = std::move(facets.vertices);
  result.neighbors = std::move(facets.neighbors);
  const std::size_t count = result.size();
  // The construction's facets have O(x) > 0 outside, so sign -1 = (-1)^d inside in odd d; in
  // even d one transposition gives Triangulation's convention.
  if (d % 2 == 0)
    for (std::size_t f = 0; f < count; ++f) {
      std::swap(result.simplices[f * static_cast<std::size_t>(d)], result.simplices[f * static_cast<std::size_t>(d) + 1]);
      std::swap(result.neighbors[f * static_cast<std::size_t>(d)], result.neighbors[f * static_cast<std::size_t>(d) + 1]);
    }
  result.vertices = result.simplices;
  std::sort(result.vertices.begin(), result.vertices.end());
  result.vertices.erase(std::unique(result.vertices.begin(), result.vertices.end()), result.vertices.end());
  for (std::size_t f = 0; f < count; ++f) {
    std::vector<std::int32_t>& on = facets.coplanar[f];
    std::sort(on.begin(), on.end());
    const std::int32_t* v = result.facet(f);
    for (const std::int32_t x : on) {
      // The nearest of the facet's vertices (the scaled distances order them as the input's).
      std::int32_t nearest = v[0];
      double best = std::numeric_limits<double>::infinity();
      for (int k = 0; k < d; ++k) {
        double distance = 0.0;
        for (int j = 0; j < d; ++j) {
          const double delta = scaled.point(static_cast<std::size_t>(x))[j] - scaled.point(static_cast<std::size_t>(v[k]))[j];
          distance += delta * delta;
        }
        if (distance < best) {
          best = distance;
          nearest = v[k];
        }
      }
      result.coplanar.insert(result.coplanar.end(), {x, static_cast<std::int32_t>(f), nearest});
    }
  }
  return result;
}

}  // namespace drange
