// delaunay/prepare_points.hpp: from the caller's points to the engine's PointStore.
#pragma once

#include <vector>

#include "delaunay/point_store.hpp"
#include "delaunay/search_options.hpp"
#include "delaunay/team.hpp"
#include "drange/delaunay.hpp"

namespace drange::engine {

// Checks the input (dimension, finite coordinates; throws InputError/UsageError), finds exact
// duplicates (reported, left out), ranks the distinct points lexicographically and stores them
// in kd-tree order. Throws DegenerateInputError with fewer than d+1 distinct points. The sort
// and the kd-tree use the team's threads; the result is the same for every thread count.
// `accelerators`: the search options whose accelerators (sphere shell, known hull facets) are
// built; the others are left empty, which the search reads as off.
PointStore prepare_points(PointsView input, int leaf_size, std::vector<Duplicate>& duplicates, Team& team,
                          const SearchOptions& accelerators = SearchOptions{});

}  // namespace drange::engine
