// hull/hull_geometry.cpp: the facets' equations, the area and the volume, in floating point;
// and the exact sides of a point.
#include <array>
#include <cmath>
#include <string>

#include "drange/errors.hpp"
#include "drange/hull.hpp"
#include "geometry/minors.hpp"
#include "geometry/predicates.hpp"

namespace drange {
namespace {

void check_hull(PointsView points, const ConvexHull& hull) {
  if (points.dim != hull.dim || points.n != hull.num_points)
    throw UsageError("the points (" + std::to_string(points.n) + " in " + std::to_string(points.dim) +
                     "D) are not those of the hull (" + std::to_string(hull.num_points) + " in " + std::to_string(hull.dim) + "D)");
}

}  // namespace

HullGeometry hull_geometry(PointsView points, const ConvexHull& hull) {
  check_hull(points, hull);
  const int d = hull.dim;
  const std::size_t count = hull.size();
  HullGeometry result;
  result.equations.resize(count * static_cast<std::size_t>(d + 1));
  // A point inside: the vertices' centroid. Each facet's pyramid from it has the volume
  // area * distance / d.
  std::array<double, kMaxDimension> centre{};
  for (const std::int32_t v : hull.vertices)
    for (int k = 0; k < d; ++k) centre[static_cast<std::size_t>(k)] += points.point(static_cast<std::size_t>(v))[k];
  for (int k = 0; k < d; ++k) centre[static_cast<std::size_t>(k)] /= static_cast<double>(hull.vertices.size());
  double factorial = 1.0;  // (d-1)!
  for (int k = 2; k < d; ++k) factorial *= k;
  geometry::MinorTable minors(d);
  std::array<double, geometry::SubsetTable::kMaxColumns> row{};
  const std::uint32_t all = (std::uint32_t{1} << d) - 1;
  // The facets' orientation det[v1 - v0; ...; x - v0] is (-1)^(d+1) outside (hull.hpp).
  const double outward = (d % 2 == 0) ? -1.0 : 1.0;
  for (std::size_t f = 0; f < count; ++f) {
    const std::int32_t* v = hull.facet(f);
    const double* v0 = points.point(static_cast<std::size_t>(v[0]));
    for (int r = 1; r < d; ++r) {
      const double* x = points.point(static_cast<std::size_t>(v[r]));
      for (int k = 0; k < d; ++k) row[static_cast<std::size_t>(k)] = x[k] - v0[k];
      minors.set_row(r - 1, row.data());
    }
    double* equation = result.equations.data() + f * static_cast<std::size_t>(d + 1);
    double norm2 = 0.0;
    for (int j = 0; j < d; ++j) {
      const double sign = ((d - 1 + j) & 1) ? -1.0 : 1.0;
      equation[j] = outward * sign * minors.minor(all & ~(std::uint32_t{1} << j));
      norm2 += equation[j] * equation[j];
    }
    const double norm = std::sqrt(norm2);
    double offset = 0.0, height = 0.0;
    for (int j = 0; j < d; ++j) equation[j] /= norm;
    for (int r = 0; r < d; ++r) {
      const double* x = points.point(static_cast<std::size_t>(v[r]));
      for (int j = 0; j < d; ++j) offset -= equation[j] * x[j];
    }
    offset /= d;
    equation[d] = offset;
    for (int j = 0; j < d; ++j) height -= equation[j] * centre[static_cast<std::size_t>(j)];
    height -= offset;
    const double area = norm / factorial;
    result.area += area;
    result.volume += area * height / d;
  }
  return result;
}

std::vector<std::int8_t> facet_sides(PointsView points, const ConvexHull& hull, const double* x) {
  check_hull(points, hull);
  const int d = hull.dim;
  std::vector<std::int8_t> sides(hull.size());
  std::array<const double*, kMaxDimension> rows{};
  const int outward = (d % 2 == 0) ? -1 : 1;
  for (std::size_t f = 0; f < hull.size(); ++f) {
    const std::int32_t* v = hull.facet(f);
    for (int r = 1; r < d; ++r) rows[static_cast<std::size_t>(r - 1)] = points.point(static_cast<std::size_t>(v[r]));
    rows[static_cast<std::size_t>(d - 1)] = x;
    const geometry::Frame frame{d, d, nullptr, points.point(static_cast<std::size_t>(v[0]))};
    sides[f] = static_cast<std::int8_t>(outward * geometry::orientation(frame, rows.data()));
  }
  return sides;
}

}  // namespace drange
