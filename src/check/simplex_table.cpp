// check/simplex_table.cpp: sorting the simplices' rows and the per-simplex checks (indices in
// range, distinct vertices, nonzero volume by the exact orientation predicate).
#include "check/simplex_table.hpp"

#include <algorithm>
#include <string>

#include "geometry/predicates.hpp"

namespace drange::check {
namespace {

std::string simplex_text(const std::vector<std::int32_t>& simplices, std::size_t s, int dim) {
  return "simplex " + std::to_string(s) + " " + format_ids(&simplices[s * static_cast<std::size_t>(dim + 1)], dim + 1);
}

// Reports the row's index problems; true if the row is combinatorially valid.
bool check_indices(const std::vector<std::int32_t>& simplices, std::size_t s, int dim, std::size_t n,
                   const std::int32_t* sorted_row, ProblemLog& log) {
  const std::int32_t* row = &simplices[s * static_cast<std::size_t>(dim + 1)];
  bool ok = true;
  for (int k = 0; k <= dim; ++k) {
    if (row[k] < 0 || static_cast<std::size_t>(row[k]) >= n) {
      log.report([&] {
        return simplex_text(simplices, s, dim) + ": vertex index " + std::to_string(row[k]) + " is out of range (" +
               std::to_string(n) + " points)";
      });
      ok = false;
    }
  }
  for (int k = 0; k < dim; ++k) {
    if (sorted_row[k] == sorted_row[k + 1] && (k == 0 || sorted_row[k - 1] != sorted_row[k])) {
      log.report([&] { return simplex_text(simplices, s, dim) + ": vertex " + std::to_string(sorted_row[k]) + " is repeated"; });
      ok = false;
    }
  }
  return ok;
}

}  // namespace

SimplexTable build_simplex_table(PointsView points, const std::vector<std::int32_t>& simplices, bool geometry,
                                 ProblemLog& log) {
  SimplexTable t;
  t.dim = points.dim;
  const std::size_t width = static_cast<std::size_t>(points.dim + 1);
  t.count = simplices.size() / width;
  t.sorted = simplices;
  t.sign.assign(t.count, kFlat);
  std::vector<const double*> corners(width);
  for (std::size_t s = 0; s < t.count; ++s) {
    std::int32_t* row = &t.sorted[s * width];
    std::sort(row, row + width);
    if (!check_indices(simplices, s, points.dim, points.n, row, log)) {
      t.sign[s] = kBroken;
      continue;
    }
    if (!geometry) continue;
    for (std::size_t k = 0; k < width; ++k) corners[k] = points.point(static_cast<std::size_t>(row[k]));
    t.sign[s] = static_cast<std::int8_t>(geometry::simplex_orientation(points.dim, corners.data()));
    if (t.sign[s] == kFlat) {
      log.report([&] { return simplex_text(simplices, s, points.dim) + ": flat (zero volume)"; });
    }
  }
  return t;
}

std::vector<std::int32_t> facet_ids(const SimplexTable& t, FacetRef f) {
  std::vector<std::int32_t> ids(static_cast<std::size_t>(t.dim));
  for (int i = 0; i < t.dim; ++i) ids[static_cast<std::size_t>(i)] = facet_vertex(t, f, i);
  return ids;
}

}  // namespace drange::check
