// check/validator.cpp: drange::check_triangulation (drange/check.hpp), the exact validator of
// a Delaunay triangulation, ours or anyone's (`qdelaunay i`, either orientation).
//
// The checks, in the order their problems are reported:
//   1. coordinates finite; per simplex: indices in range, distinct, nonzero volume
//      (simplex_table.cpp);
//   2. per facet: shared by at most two simplices, from opposite sides; across every interior
//      facet, locally Delaunay (facet_pass.cpp);
//   3. every distinct point used (point_usage.cpp);
//   4. the hull covered once: the centroid of one simplex lies in exactly one (covering.cpp);
//   5. every boundary facet supports the hull (hull_support.cpp);
//   6. cross-check: total volume equals the volume the boundary encloses (covering.cpp).
// Together, 1-5 are exactly "a triangulation of the convex hull of the points whose vertices
// are all the distinct points, with empty circumspheres": 1, 2 and 5 make the simplices cover
// the hull a constant number of times, 4 makes that number one (see covering.cpp), and the
// local Delaunay test of 2 is then equivalent to the global one (facet_pass.cpp).
// Every decision is an exact sign (geometry/predicates.hpp, filtered, GMP when needed).
// Cost for n points and m simplices: O(m) predicate calls and exact determinants, sorting
// only within small buckets (key_groups.hpp; no hashing), and, for a sound triangulation, a
// linear-time hull certificate (hull_support.cpp). A million uniform points check in seconds,
// reading the files included.
#include <climits>
#include <cstdint>
#include <string>
#include <vector>

#include "check/covering.hpp"
#include "check/facet_pass.hpp"
#include "check/hull_support.hpp"
#include "check/point_usage.hpp"
#include "check/problem_log.hpp"
#include "check/simplex_table.hpp"
#include "drange/check.hpp"
#include "drange/errors.hpp"

namespace drange {
namespace {

void check_arguments(PointsView points, const std::vector<std::int32_t>& simplices) {
  if (points.dim < 2) {
    throw UsageError("check_triangulation: the dimension must be at least 2, got " + std::to_string(points.dim));
  }
  if (points.n > 0 && points.coords == nullptr) throw UsageError("check_triangulation: no coordinates for " + std::to_string(points.n) + " points");
  if (points.n > static_cast<std::size_t>(INT32_MAX)) {
    throw UsageError("check_triangulation: " + std::to_string(points.n) + " points exceed the 32-bit index range");
  }
  const std::size_t width = static_cast<std::size_t>(points.dim) + 1;
  if (simplices.size() % width != 0) {
    throw UsageError("check_triangulation: " + std::to_string(simplices.size()) + " vertex indices are not a multiple of d+1 = " +
                     std::to_string(width) + " (the points are " + std::to_string(points.dim) + "-dimensional)");
  }
}

bool all_usable(const check::SimplexTable& table) {
  for (std::size_t s = 0; s < table.count; ++s)
    if (!table.usable(s)) return false;
  return true;
}

CheckReport finish(CheckReport report, check::ProblemLog& log) {
  report.problem_count = log.count();
  report.valid = log.count() == 0;
  report.problems = log.take_lines();
  return report;
}

}  // namespace

CheckReport check_triangulation(PointsView points, const std::vector<std::int32_t>& simplices, std::size_t max_problems) {
  check_arguments(points, simplices);
  check::ProblemLog log(max_problems);
  CheckReport report;

  const bool finite = check::check_coordinates(points, log);
  const check::SimplexTable table = check::build_simplex_table(points, simplices, finite, log);
  report.simplices = table.count;
  if (table.count == 0) {
    if (points.n > 0) log.add("the triangulation has no simplices (" + std::to_string(points.n) + " points)");
    return finish(report, log);
  }
  if (!finite) return finish(report, log);  // no geometric decision is possible

  check::FacetSummary facets = check::check_facets(points, table, log);
  report.interior_facets = facets.interior;
  report.boundary_facets = facets.boundary;
  const std::vector<std::int32_t> stray = check::check_point_usage(points, table, log);
  const check::CentroidCover cover = check::check_centroid_cover(points, table, log);

  const bool facets_sound = all_usable(table) && facets.bad_pairings == 0;
  check::check_support({points, table, facets.boundary_facets, facets_sound && cover.containing == 1,
                        cover.centre_simplex, stray},
                       log);
  if (facets_sound) check::check_volume_identity(points, table, facets.boundary_facets, log);
  return finish(report, log);
}

}  // namespace drange
