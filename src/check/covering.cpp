// check/covering.cpp: the centroid count and the volume identity.
//
// What proves "covered exactly once". Let w(x) be the number of simplices containing x. With
// every interior facet shared by two simplices from opposite sides, w changes only across
// boundary facets; with every boundary facet supporting the hull, those all lie on the hull's
// boundary, so w is one constant k inside the hull (and 0 outside): the simplices cover the
// hull k times. A volume identity cannot tell k = 1 from k = 2: a double covering has twice
// the volume, but it also has twice the boundary, and volumes computed from the boundary
// facets double too. The centroid c of one simplex can: c is interior to that simplex, so in a
// true triangulation no other closed simplex contains it (their interiors would overlap), and
// with k >= 2 at least k closed simplices contain it. So "exactly one simplex contains c"
// is the test, exact because c is rational and each side test is affine in the point: the
// sign of a facet's orientation determinant at c is the sign of the sum of that determinant
// at the d+1 vertices whose average c is.
//
// The volume identity (sum of |volumes| = volume enclosed by the boundary, as cones from a
// fixed point) is kept as an exact cross-check of the facet matching, not as a proof: when
// every interior facet is shared from opposite sides, its two cones cancel and the identity
// holds by algebra, whatever the geometry. It fails exactly when facets are matched wrongly
// (the same-side and triple-sharing checks report those first), so a failure with clean
// facets would expose a bug in the validator itself.
#include "check/covering.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "check/exact_volume.hpp"
#include "check/facet_plane.hpp"
#include "geometry/error_bound.hpp"

namespace drange::check {
namespace {

// The centroid in floating point, with a per-coordinate bound on its error.
struct ApproximateCentroid {
  std::vector<double> value, error;
};

ApproximateCentroid approximate_centroid(PointsView points, const std::int32_t* row, int d) {
  ApproximateCentroid c{std::vector<double>(static_cast<std::size_t>(d), 0.0), std::vector<double>(static_cast<std::size_t>(d), 0.0)};
  for (int k = 0; k < d; ++k) {
    double sum = 0.0, abs_sum = 0.0;
    for (int i = 0; i <= d; ++i) {
      const double x = points.point(static_cast<std::size_t>(row[i]))[k];
      sum += x;
      abs_sum += std::fabs(x);
    }
    c.value[static_cast<std::size_t>(k)] = sum / (d + 1);
    // d roundings in the sum, one in the division; doubled for the comparisons that use it.
    c.error[static_cast<std::size_t>(k)] = 2.0 * geometry::gamma_bound(d + 1) * abs_sum / (d + 1);
  }
  return c;
}

// False if the filter proves the centroid outside the simplex's bounding box.
bool box_may_contain(PointsView points, const std::int32_t* row, int d, const ApproximateCentroid& c) {
  for (int k = 0; k < d; ++k) {
    double lo = points.point(static_cast<std::size_t>(row[0]))[k], hi = lo;
    for (int i = 1; i <= d; ++i) {
      const double x = points.point(static_cast<std::size_t>(row[i]))[k];
      lo = std::min(lo, x);
      hi = std::max(hi, x);
    }
    const std::size_t kk = static_cast<std::size_t>(k);
    if (c.value[kk] + c.error[kk] < lo || c.value[kk] - c.error[kk] > hi) return false;
  }
  return true;
}

// Exact: is the centroid of `centre` in the closed simplex t? For each facet of t, the
// centroid must not be strictly on the side away from t.
bool contains_centroid(PointsView points, const SimplexTable& table, std::size_t t,
                       const std::vector<const double*>& centre, FacetPlane& plane) {
  const int d = table.dim;
  std::vector<const double*> corners(static_cast<std::size_t>(d));
  for (int omit = 0; omit <= d; ++omit) {
    const FacetRef f{static_cast<std::int32_t>(t), omit};
    for (int i = 0; i < d; ++i) corners[static_cast<std::size_t>(i)] = points.point(static_cast<std::size_t>(facet_vertex(table, f, i)));
    plane.set(corners.data());
    if (plane.side_of_average(centre.data(), d + 1) == -inner_side(table, f)) return false;
  }
  return true;
}

}  // namespace

CentroidCover check_centroid_cover(PointsView points, const SimplexTable& table, ProblemLog& log) {
  CentroidCover result;
  for (std::size_t s = 0; s < table.count && result.centre_simplex < 0; ++s)
    if (table.usable(s)) result.centre_simplex = static_cast<std::int32_t>(s);
  if (result.centre_simplex < 0) return result;

  const int d = table.dim;
  const std::int32_t* centre_row = table.row(static_cast<std::size_t>(result.centre_simplex));
  std::vector<const double*> centre(static_cast<std::size_t>(d) + 1);
  for (int i = 0; i <= d; ++i) centre[static_cast<std::size_t>(i)] = points.point(static_cast<std::size_t>(centre_row[i]));
  const ApproximateCentroid approx = approximate_centroid(points, centre_row, d);

  FacetPlane plane(d);
  std::vector<std::int32_t> holders;
  for (std::size_t t = 0; t < table.count; ++t) {
    if (!table.usable(t) || !box_may_contain(points, table.row(t), d, approx)) continue;
    if (contains_centroid(points, table, t, centre, plane)) holders.push_back(static_cast<std::int32_t>(t));
  }
  result.containing = holders.size();
  if (holders.size() != 1) {
    log.report([&] {
      const int shown = static_cast<int>(std::min<std::size_t>(holders.size(), 8));
      std::string line = "the centroid of simplex " + std::to_string(result.centre_simplex) + " lies in " +
                         std::to_string(holders.size()) + " simplices " + format_ids(holders.data(), shown);
      if (holders.size() > 8) line.insert(line.size() - 1, " ...");
      return line + (holders.empty() ? ": internal inconsistency, please report this input"
                                     : ": the simplices overlap, covering the hull more than once");
    });
  }
  return result;
}

void check_volume_identity(PointsView points, const SimplexTable& table, const std::vector<FacetRef>& boundary,
                           ProblemLog& log) {
  const int d = table.dim;
  // The vertices, and the origin of the cones: the lexicographically smallest vertex (a hull
  // vertex, so the cones over the facets around it vanish).
  std::vector<char> is_vertex(points.n, 0);
  std::vector<std::int32_t> vertices;
  std::int32_t origin = -1;
  for (std::size_t s = 0; s < table.count; ++s) {
    if (!table.usable(s)) continue;
    for (int k = 0; k <= d; ++k) {
      const std::int32_t v = table.row(s)[k];
      if (is_vertex[static_cast<std::size_t>(v)]) continue;
      is_vertex[static_cast<std::size_t>(v)] = 1;
      vertices.push_back(v);
      const double* p = points.point(static_cast<std::size_t>(v));
      if (origin < 0 || std::lexicographical_compare(p, p + d, points.point(static_cast<std::size_t>(origin)),
                                                    points.point(static_cast<std::size_t>(origin)) + d))
        origin = v;
    }
  }
  if (origin < 0) return;
  const IntegerPoints integers(points.coords, points.n, d, vertices);

  // Sum of |det| over the simplices: d! times their total volume.
  DeterminantSum simplices_total(integers, d);
  for (std::size_t s = 0; s < table.count; ++s)
    if (table.usable(s)) simplices_total.add(table.row(s), table.sign[s]);
  // The cone over each boundary facet from the origin, positive when the origin is on the
  // facet's inner side: inner_side(F) * D_F(origin).
  DeterminantSum enclosed(integers, d);
  std::vector<std::int32_t> cone(static_cast<std::size_t>(d) + 1);
  for (const FacetRef f : boundary) {
    for (int i = 0; i < d; ++i) cone[static_cast<std::size_t>(i)] = facet_vertex(table, f, i);
    cone[static_cast<std::size_t>(d)] = origin;
    enclosed.add(cone.data(), inner_side(table, f));
  }
  if (simplices_total.total() != enclosed.total()) {
    log.report([&] {
      // Back from integers in units of 2^(d * shift) to volumes, for the message only.
      auto volume = [&](const mpz_class& z) {
        long exponent = 0;
        double v = mpz_get_d_2exp(&exponent, z.get_mpz_t());
        for (int k = 2; k <= d; ++k) v /= k;
        return std::ldexp(v, static_cast<int>(exponent + d * integers.shift()));
      };
      return "the simplices' total volume " + format_number(volume(simplices_total.total())) +
             " differs from the volume " + format_number(volume(enclosed.total())) + " enclosed by the boundary facets";
    });
  }
}

}  // namespace drange::check
