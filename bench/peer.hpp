// bench/peer.hpp: what every peer of the benchmark runner (run_one.cpp) provides.
//
// A peer builds one triangulation of the points it is given and times the construction only:
// the points arrive already read (file I/O is not timed), and converting them to the peer's
// own point type happens before the clock starts unless the peer needs it as part of its
// algorithm (then the peer's file says so).
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

#include "drange/points.hpp"

namespace drange::bench {

struct RunOptions {
  int threads = 1;                // drange and CGAL's parallel 3D; every other peer is sequential
  std::string variant = "full";   // drange's search variant (drange::Options::variant)
};

struct PeerResult {
  bool applicable = true;        // false: the peer does not handle this dimension ("n/a")
  std::uint64_t simplices = 0;   // finite d-simplices (Fortune: Voronoi vertices, see its file)
  double seconds = 0;            // construction only
  std::string extra;             // more "key=value" pairs for the machine-readable line
};

using Clock = std::chrono::steady_clock;
inline double seconds_between(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

inline PeerResult not_applicable() {
  PeerResult r;
  r.applicable = false;
  return r;
}

PeerResult run_drange(const PointCloud& points, const RunOptions& options);
PeerResult run_cgal2(const PointCloud& points, const RunOptions& options);
PeerResult run_cgal3(const PointCloud& points, const RunOptions& options);
PeerResult run_cgal3_parallel(const PointCloud& points, const RunOptions& options);
PeerResult run_cgal_dd_static(const PointCloud& points, const RunOptions& options);
PeerResult run_cgal_dd_dynamic(const PointCloud& points, const RunOptions& options);
PeerResult run_qhull(const PointCloud& points, const RunOptions& options);
PeerResult run_boost_voronoi(const PointCloud& points, const RunOptions& options);
PeerResult run_tetgen(const PointCloud& points, const RunOptions& options);

}  // namespace drange::bench
