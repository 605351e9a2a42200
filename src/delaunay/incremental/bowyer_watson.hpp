// delaunay/incremental/bowyer_watson.hpp: the incremental kernel. The points are inserted one
// by one in a biased randomized order (insertion_order.hpp); each is located by a walk, the
// cells in conflict with it (cell_predicates.hpp) are removed, and the cavity they leave is
// filled with the new point joined to its boundary facets (Bowyer; Watson).
//
// It computes the same triangulation as the direct search: the Delaunay triangulation of the
// points under the same symbolic perturbation, which is unique, so any correct construction
// gives the same set of simplices; only their order and numbering differ. Its work does not
// depend on the points' shape: with the randomized order each insertion removes and creates
// O(1) cells in expectation, and the walk from the previous point, which the kd-tree order of
// each round keeps near, is short.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "delaunay/first_facet.hpp"
#include "delaunay/incremental/insertion.hpp"
#include "delaunay/point_store.hpp"
#include "drange/delaunay.hpp"

namespace drange::engine {


// Fills result.simplices (positively oriented, in `points`' ids), result.neighbors (when
// `record_neighbors`; -1 on the hull) and result.stats.hull_facets. `first`: a hull facet of
// the points (find_first_facet), the start of the first simplex. `order`: every point id once,
// insertion_order(points). `progress` as in Options.
IncrementalCounters triangulate_incrementally(const PointStore& points, const FirstFacet& first,
                                              const std::vector<std::int32_t>& order, Triangulation& result,
                                              bool record_neighbors, const std::function<void(std::size_t)>& progress);

}  // namespace drange::engine
