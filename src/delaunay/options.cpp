// delaunay/options.cpp: the named search variants and the statistics line.
#include <cstdio>
#include <string>

#include "drange/delaunay.hpp"
#include "drange/errors.hpp"

namespace drange {

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
  throw UsageError("unknown search variant '" + name + "' (expected one of: " + search_variant_names() + ")");
}

const char* search_variant_names() {
  return "full, scan, kdtree, no-prune, no-order, paper, no-bottom-up, no-seed, no-ball, no-shell, no-tie-memory, no-slab, no-hull, fifo, spatial";
}

std::string Statistics::summary() const {
  char line[720];
  std::snprintf(line, sizeof line,
                "points=%zu distinct=%zu simplices=%zu hull_facets=%zu calls_per_simplex=%.2f "
                "tested_per_simplex=%.2f candidates_per_simplex=%.2f exact_fallbacks=%zu max_open_facets=%zu "
                "shell_spheres=%zu threads=%zu wasted_searches=%zu "
                "time_kdtree=%.3fs time_first_facet=%.3fs time_search=%.3fs time_total=%.3fs peak_rss=%.1fMiB",
                points, distinct_points, simplices, hull_facets, calls_per_simplex(),
                simplices ? double(points_tested) / double(simplices) : 0.0,
                simplices ? double(candidates) / double(simplices) : 0.0, exact_fallbacks, max_open_facets, shell_spheres, threads,
                wasted_searches, seconds_kdtree, seconds_first_facet, seconds_search, seconds_total,
                double(peak_rss_bytes) / (1 << 20));
  return line;
}

}  // namespace drange
