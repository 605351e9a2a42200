// check/hull_support.hpp: the boundary facets must support the convex hull: no input point
// strictly beyond any of them.
#pragma once

#include <cstdint>
#include <vector>

#include "check/problem_log.hpp"
#include "check/simplex_table.hpp"
#include "drange/points.hpp"

namespace drange::check {

struct SupportInput {
  PointsView points;
  const SimplexTable& table;
  const std::vector<FacetRef>& boundary;  // boundary facets of usable simplices
  // Everything the certificate relies on already holds: no broken or flat simplex, every
  // facet shared at most twice and then from opposite sides, and the centroid of simplex
  // `centre_simplex` lies in exactly one (closed) simplex.
  bool premises_hold;
  std::int32_t centre_simplex;
  // Points in no simplex that are not exact copies of a used point (see point_usage.hpp).
  const std::vector<std::int32_t>& stray_points;
};

// Reports every boundary facet (one per group of coplanar adjacent boundary facets) beyond
// which some point lies, and every boundary ridge not shared by exactly two boundary facets.
void check_support(const SupportInput& input, ProblemLog& log);

}  // namespace drange::check
