// check/facet_pass.hpp: matching the simplices' facets, and the checks on each facet: shared
// by at most two simplices, from opposite sides, and locally Delaunay.
#pragma once

#include <cstddef>
#include <vector>

#include "check/problem_log.hpp"
#include "check/simplex_table.hpp"
#include "drange/points.hpp"

namespace drange::check {

struct FacetSummary {
  std::size_t interior = 0;           // facets shared by two simplices
  std::size_t boundary = 0;           // facets of one simplex
  std::size_t bad_pairings = 0;       // facets shared three or more times, or from the same side
  std::vector<FacetRef> boundary_facets;  // the boundary facets of usable (non-flat) simplices
};

FacetSummary check_facets(PointsView points, const SimplexTable& table, ProblemLog& log);

}  // namespace drange::check
