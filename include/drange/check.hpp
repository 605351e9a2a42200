// drange/check.hpp: an exact validator for a Delaunay triangulation, ours or anyone's.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "drange/points.hpp"

namespace drange {

struct CheckReport {
  bool valid = true;
  std::vector<std::string> problems;  // one human-readable line per problem found (capped)
  std::size_t problem_count = 0;      // all problems, also those beyond the cap
  std::size_t simplices = 0;
  std::size_t interior_facets = 0;
  std::size_t boundary_facets = 0;
};

// Checks, with exact arithmetic, that `simplices` (m rows of d+1 zero-based indices, any
// orientation) is a Delaunay triangulation of `points`:
//   - indices in range, no repeated vertex, nonzero volume;
//   - every facet shared by at most two simplices, and then from opposite sides;
//   - every boundary facet supports the convex hull (no point strictly beyond it);
//   - the simplices cover the hull exactly once: proved by the boundary forming a closed,
//     locally convex surface around an interior point that lies in exactly one simplex (after
//     Mehlhorn et al., "Checking geometric programs", 1999); the exact total volume is also
//     compared with the volume enclosed by the boundary facets, as a cross-check of the facet
//     matching;
//   - every distinct point is a vertex (exact duplicates may be left out);
//   - no point strictly inside any circumsphere (locally, across every interior facet,
//     which for a triangulation is equivalent to the global condition).
// Never throws on a bad triangulation; throws UsageError on mismatched dimensions.
CheckReport check_triangulation(PointsView points, const std::vector<std::int32_t>& simplices,
                                std::size_t max_problems = 20);

}  // namespace drange
