// delaunay/triangulate.hpp: the driver behind drange::delaunay, with the search's switches
// given directly instead of by Options::variant (which it ignores): the tests set single
// switches, and combinations that no named variant has, with it. `incremental`: the
// incremental kernel (delaunay/incremental/) instead of the direct search, which `search` then
// does not concern (Options::algorithm, which it ignores too, resolved).
#pragma once

#include "delaunay/search_options.hpp"
#include "drange/delaunay.hpp"
#include "drange/points.hpp"

namespace drange::engine {

Triangulation triangulate(PointsView points, const Options& options, const SearchOptions& search, bool incremental = false);

}  // namespace drange::engine
