// delaunay/triangulate.hpp: the driver behind drange::delaunay, with the search's switches
// given directly instead of by Options::variant (which it ignores): the tests set single
// switches, and combinations that no named variant has, with it.
#pragma once

#include "delaunay/search_options.hpp"
#include "drange/delaunay.hpp"
#include "drange/points.hpp"

namespace drange::engine {

Triangulation triangulate(PointsView points, const Options& options, const SearchOptions& search);

}  // namespace drange::engine
