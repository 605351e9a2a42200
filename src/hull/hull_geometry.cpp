// hull/hull_geometry.cpp: the facets' equations, the area and the volume, in floating point;
// and the exact sides of a point.
#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "drange/errors.hpp"
#include "drange/hull.hpp"
#include "geometry/exact_matrix.hpp"
#include "geometry/minors.hpp"
#include "geometry/predicates.hpp"

namespace drange {
namespace {

void check_hull(PointsView points, const ConvexHull& hull) {
  if (points.dim != hull.dim || points.n != hull.num_points)
    throw UsageError("the points (" + std::to_string(points.n) + " in " + std::to_string(points.dim) +
                     "D) are not those of the hull (" + std::to_string(hull.num_points) + " in " + std::to_string(hull.dim) + "D)");
}

// The facet's normal (its (d-1) x (d-1) minors, signed as in hull_geometry) computed exactly
// and rounded, for a facet whose minors all cancel in floating point: it is not flat (the hull
// is exact), only thinner than the doubles' rounding, and its hyperplane still exists.
void exact_normal(PointsView points, const std::int32_t* v, int d, double outward, double* equation) {
  geometry::IntegerScale scale;
  for (int r = 0; r < d; ++r)
    for (int k = 0; k < d; ++k) scale.include(points.point(static_cast<std::size_t>(v[r]))[k]);
  const double* v0 = points.point(static_cast<std::size_t>(v[0]));
  std::vector<mpz_class> minor;
  std::vector<double> mantissa(static_cast<std::size_t>(d));
  std::vector<long> exponent(static_cast<std::size_t>(d));
  for (int j = 0; j < d; ++j) {
    minor.clear();
    for (int r = 1; r < d; ++r)
      for (int k = 0; k < d; ++k)
        if (k != j) minor.push_back(scale.integer(points.point(static_cast<std::size_t>(v[r]))[k]) - scale.integer(v0[k]));
    const mpz_class value = geometry::bareiss_determinant(minor, d - 1);
    mantissa[static_cast<std::size_t>(j)] = mpz_get_d_2exp(&exponent[static_cast<std::size_t>(j)], value.get_mpz_t());
  }
  // Only the direction counts: every minor over the largest one's power of two, so that none
  // overflows (the zero minors have mantissa 0).
  const long largest = *std::max_element(exponent.begin(), exponent.end());
  for (int j = 0; j < d; ++j) {
    const double sign = ((d - 1 + j) & 1) ? -1.0 : 1.0;
    const auto i = static_cast<std::size_t>(j);
    equation[j] = outward * sign * std::ldexp(mantissa[i], static_cast<int>(std::max(exponent[i] - largest, -2000L)));
  }
}

// A facet whose normal is below this fraction of its edges' product (its Hadamard ratio above
// the inverse) gets its normal from exact minors: a double-precision minor then keeps fewer
// than about 30 correct bits.
constexpr double kThin = 1e-6;

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
    double edges = 1.0;  // the product of the edges from v0: how large the minors could be
    for (int r = 1; r < d; ++r) {
      const double* x = points.point(static_cast<std::size_t>(v[r]));
      double length2 = 0.0;
      for (int k = 0; k < d; ++k) length2 += (x[k] - v0[k]) * (x[k] - v0[k]);
      edges *= std::sqrt(length2);
    }
    double norm2 = 0.0;
    for (int j = 0; j < d; ++j) {
      const double sign = ((d - 1 + j) & 1) ? -1.0 : 1.0;
      equation[j] = outward * sign * minors.minor(all & ~(std::uint32_t{1} << j));
      norm2 += equation[j] * equation[j];
    }
    double norm = std::sqrt(norm2);
    double area = norm / factorial;
    if (!(norm > kThin * edges)) {
      // Thin: the minors cancel, and their rounding may turn the normal anywhere (or to 0).
      // The facet is not flat (the hull is exact): its hyperplane is found exactly.
      exact_normal(points, v, d, outward, equation);
      norm2 = 0.0;
      for (int j = 0; j < d; ++j) norm2 += equation[j] * equation[j];
      norm = std::sqrt(norm2);
    }
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
