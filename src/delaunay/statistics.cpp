// delaunay/statistics.cpp: the statistics line (the CLI's --stats). scripts/ab_time.sh and
// bench/ parse it: its keys, their order and their formats are fixed.
#include <cstdio>
#include <string>

#include "drange/delaunay.hpp"

namespace drange {

std::string Statistics::summary() const {
  char line[720];
  std::snprintf(line, sizeof line,
                "points=%zu distinct=%zu simplices=%zu hull_facets=%zu calls_per_simplex=%.2f "
                "tested_per_simplex=%.2f candidates_per_simplex=%.2f exact_fallbacks=%zu max_open_facets=%zu "
                "shell_spheres=%zu threads=%zu wasted_searches=%zu "
                "time_kdtree=%.3fs time_first_facet=%.3fs time_search=%.3fs time_total=%.3fs peak_rss=%.1fMiB algorithm=%s time_choice=%.3fs",
                points, distinct_points, simplices, hull_facets, calls_per_simplex(),
                simplices ? double(debug.points_tested) / double(simplices) : 0.0,
                simplices ? double(debug.candidates) / double(simplices) : 0.0,
                debug.exact_fallbacks, debug.max_open_facets, debug.shell_spheres, threads, debug.wasted_searches,
                seconds_kdtree, seconds_first_facet, seconds_search, seconds_total, double(peak_rss_bytes) / (1 << 20), algorithm.c_str(), seconds_choice);
  std::string text = line;
  // The busy times last, a list of any length (scripts read the keys before them by position).
  text += " time_busy=";
  for (std::size_t t = 0; t < seconds_busy.size(); ++t) {
    std::snprintf(line, sizeof line, "%s%.3fs", t ? "," : "", seconds_busy[t]);
    text += line;
  }
  if (seconds_busy.empty()) text += "-";
  std::snprintf(line, sizeof line, " time_critical=%.3fs", seconds_critical_path);
  return text + line;
}

}  // namespace drange
