// bench/peer_drange.cpp: drange itself, through the public API, with the chosen search variant
// and thread count (1 unless asked: the peers run on one thread).
// The time is the whole of drange::delaunay (input checks, kd-tree, first facet, search,
// neighbours); the statistics add the search phase alone and the paper's calls per simplex.
#include <cstdio>

#include "drange/delaunay.hpp"
#include "peer.hpp"

namespace drange::bench {

PeerResult run_drange(const PointCloud& points, const RunOptions& options) {
  Options o;
  o.variant = options.variant;
  o.threads = options.threads;
  const auto start = Clock::now();
  const Triangulation t = delaunay(points, o);
  const auto stop = Clock::now();
  PeerResult r;
  r.simplices = t.size();
  r.seconds = seconds_between(start, stop);
  const Statistics& s = t.stats;
  const double per = s.simplices ? 1.0 / double(s.simplices) : 0.0;
  char extra[256];
  std::snprintf(extra, sizeof extra,
                "variant=%s calls_per_simplex=%.2f tested_per_simplex=%.2f search_seconds=%.4f exact_fallbacks=%zu",
                options.variant.c_str(), s.calls_per_simplex(), double(s.debug.points_tested) * per, s.seconds_search,
                s.debug.exact_fallbacks);
  r.extra = extra;
  return r;
}

}  // namespace drange::bench
