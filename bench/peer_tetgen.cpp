// bench/peer_tetgen.cpp: TetGen (Debian libtet1.5-dev), in 3D only: the Delaunay
// tetrahedralization of the points (switches "Qz": quiet, zero-based indices; no -p, so no
// boundary recovery and no quality refinement). The points are copied into TetGen's input
// structure before the clock; tetrahedralize() is timed.
#include <tetgen.h>

#include <stdexcept>

#include "peer.hpp"

namespace drange::bench {

PeerResult run_tetgen(const PointCloud& points, const RunOptions&) {
  if (points.dim != 3) return not_applicable();
  tetgenio in;
  tetgenio out;
  in.firstnumber = 0;
  in.numberofpoints = static_cast<int>(points.size());
  in.pointlist = new REAL[points.coords.size()];
  for (std::size_t i = 0; i < points.coords.size(); ++i) in.pointlist[i] = points.coords[i];
  tetgenbehavior behavior;
  char switches[] = "Qz";
  if (!behavior.parse_commandline(switches)) throw std::runtime_error("tetgen: bad switches");
  const auto start = Clock::now();
  tetrahedralize(&behavior, &in, &out);
  const auto stop = Clock::now();
  PeerResult r;
  r.simplices = static_cast<std::uint64_t>(out.numberoftetrahedra);
  r.seconds = seconds_between(start, stop);
  r.extra = "tetgen_switches=Qz";
  return r;
}

}  // namespace drange::bench
