// bench/peer_qhull.cpp: Qhull (libqhull_r, Debian libqhull-dev) with the options
// scipy.spatial.Delaunay uses: "Qbb Qc Qz Q12" for d <= 4, "Qbb Qc Qz Qx Q12" for d > 4, and
// "Qt" (always on in scipy), in Delaunay mode ("d"). Simplices are the facets of the lower
// hull of the lifted points (facets that are not upperdelaunay) after triangulation.
// The coordinates are copied to a buffer Qhull may own before the clock; qh_new_qhull (which
// lifts the points, builds the hull and triangulates it) is timed, freeing it is not.
extern "C" {
#include <libqhull_r/qhull_ra.h>
}

#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "peer.hpp"

namespace drange::bench {

PeerResult run_qhull(const PointCloud& points, const RunOptions&) {
  const int d = points.dim;
  std::vector<coordT> coords(points.coords.begin(), points.coords.end());
  std::string flags = d > 4 ? "qhull d Qbb Qc Qz Qx Q12 Qt" : "qhull d Qbb Qc Qz Q12 Qt";
  qhT qh_storage;
  qhT* qh = &qh_storage;
  qh_zero(qh, stderr);
  const auto start = Clock::now();
  const int exitcode = qh_new_qhull(qh, d, static_cast<int>(points.size()), coords.data(), False, flags.data(),
                                    nullptr, stderr);
  const auto stop = Clock::now();
  std::uint64_t count = 0;
  if (exitcode == 0) {
    facetT* facet;
    FORALLfacets {
      if (!facet->upperdelaunay) ++count;
    }
  }
  qh_freeqhull(qh, !qh_ALL);
  int curlong = 0, totlong = 0;
  qh_memfreeshort(qh, &curlong, &totlong);
  if (exitcode != 0) throw std::runtime_error("qh_new_qhull failed with exit code " + std::to_string(exitcode));
  PeerResult r;
  r.simplices = count;
  r.seconds = seconds_between(start, stop);
  r.extra = "qhull_options=" + flags.substr(6);
  for (char& c : r.extra)
    if (c == ' ') c = ',';
  return r;
}

}  // namespace drange::bench
