// delaunay/search_options.cpp: the named search variants.
#include "delaunay/search_options.hpp"

#include <string>

#include "drange/delaunay.hpp"
#include "drange/errors.hpp"

namespace drange {

const char* variant_names() {
  return "full, scan, kdtree, no-prune, no-order, paper, no-bottom-up, no-seed, no-ball, no-shell, no-tie-memory, no-slab, no-hull, fifo, spatial";
}

namespace engine {

SearchOptions search_variant(const std::string& name) {
  constexpr FacetOrder automatic = FacetOrder::automatic, fifo = FacetOrder::fifo;
  //                                 kdtree prune  order  bottom_up seed  ball   shell  ties   slabs  facet order  hull
  if (name == "full") return SearchOptions{true, true, true, true, true, true, true, true, true, automatic, true};
  if (name == "scan") return SearchOptions{false, false, false, false, false, false, false, false, false, fifo, false};
  if (name == "kdtree") return SearchOptions{true, false, false, false, false, false, false, false, false, fifo, false};
  if (name == "no-prune") return SearchOptions{true, false, true, true, true, true, true, true, true, automatic, true};
  if (name == "no-order") return SearchOptions{true, true, false, true, true, true, true, true, true, automatic, true};
  if (name == "paper") return SearchOptions{true, true, true, false, false, false, false, false, false, fifo, false};
  if (name == "no-bottom-up") return SearchOptions{true, true, true, false, true, true, true, true, true, automatic, true};
  if (name == "no-seed") return SearchOptions{true, true, true, true, false, true, true, true, true, automatic, true};
  if (name == "no-ball") return SearchOptions{true, true, true, true, true, false, true, true, true, automatic, true};
  if (name == "no-shell") return SearchOptions{true, true, true, true, true, true, false, true, true, automatic, true};
  if (name == "no-tie-memory") return SearchOptions{true, true, true, true, true, true, true, false, true, automatic, true};
  if (name == "no-slab") return SearchOptions{true, true, true, true, true, true, true, true, false, automatic, true};
  if (name == "no-hull") return SearchOptions{true, true, true, true, true, true, true, true, true, automatic, false};
  if (name == "fifo") return SearchOptions{true, true, true, true, true, true, true, true, true, fifo, true};
  if (name == "spatial") return SearchOptions{true, true, true, true, true, true, true, true, true, FacetOrder::spatial, true};
  throw UsageError("unknown search variant '" + name + "' (expected one of: " + variant_names() + ")");
}

}  // namespace engine
}  // namespace drange
