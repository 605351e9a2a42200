// delaunay/triangulate.hpp: the driver behind drange::delaunay, with the search's switches
// given directly instead of by Options::variant (which it ignores): the tests set single
// switches, and combinations that no named variant has, with it; and Options::algorithm, which
// it ignores too, given as `algorithm` (the incremental kernel, delaunay/incremental/, does not
// read `search`).
#pragma once

#include <cstdint>

#include "delaunay/search_options.hpp"
#include "drange/delaunay.hpp"
#include "drange/points.hpp"

namespace drange::engine {

enum class Algorithm { automatic, direct, incremental };

// `work_budget` (direct search, one thread; 0: none): once the kd-tree nodes entered plus the
// points tested exceed it, the run stops by throwing WorkBudgetExceeded (search_pipeline.hpp).
Triangulation triangulate(PointsView points, const Options& options, const SearchOptions& search,
                          Algorithm algorithm = Algorithm::direct, std::uint64_t work_budget = 0);

}  // namespace drange::engine
