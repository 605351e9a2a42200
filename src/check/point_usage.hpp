// check/point_usage.hpp: the checks on the points themselves: finite coordinates, and every
// distinct point a vertex of some simplex.
#pragma once

#include <cstdint>
#include <vector>

#include "check/problem_log.hpp"
#include "check/simplex_table.hpp"
#include "drange/points.hpp"

namespace drange::check {

// Reports every point with a NaN or infinite coordinate; true if there is none.
bool check_coordinates(PointsView points, ProblemLog& log);

// Reports every point that is in no simplex and is not an exact copy (same coordinates) of a
// point that is. Returns those points, in increasing order.
std::vector<std::int32_t> check_point_usage(PointsView points, const SimplexTable& table, ProblemLog& log);

}  // namespace drange::check
