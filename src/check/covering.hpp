// check/covering.hpp: the simplices cover the hull exactly once.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "check/problem_log.hpp"
#include "check/simplex_table.hpp"
#include "drange/points.hpp"

namespace drange::check {

struct CentroidCover {
  std::int32_t centre_simplex = -1;  // the first usable simplex; -1 if there is none
  std::size_t containing = 0;        // usable simplices whose closed region holds its centroid
};

// Counts the simplices that contain the centroid of the first usable simplex (exactly: the
// centroid is rational) and reports a count other than one.
CentroidCover check_centroid_cover(PointsView points, const SimplexTable& table, ProblemLog& log);

// Cross-check: the sum of the simplices' |volumes| equals the volume enclosed by the boundary
// facets (cones from a fixed point, each facet oriented outward), exactly. Only meaningful when
// every facet pairs up correctly; see covering.cpp for what it does and does not prove.
void check_volume_identity(PointsView points, const SimplexTable& table, const std::vector<FacetRef>& boundary,
                           ProblemLog& log);

}  // namespace drange::check
