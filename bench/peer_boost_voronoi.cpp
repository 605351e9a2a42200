// bench/peer_boost_voronoi.cpp: Boost.Polygon's voronoi (Fortune's sweep), the paper's own
// baseline, in 2D only. It takes integer input: the points are scaled from their bounding box
// to the integers in [-2^30, 2^30] and rounded (before the clock), as the paper's baseline
// does; points that round to the same integer pair become one site. The count reported is the
// number of Voronoi vertices: one per Delaunay triangle in general position, fewer where four
// or more sites are cocircular (grids), so it is not comparable with the triangle count there.
#include <boost/polygon/voronoi.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "peer.hpp"

namespace drange::bench {

PeerResult run_boost_voronoi(const PointCloud& points, const RunOptions&) {
  if (points.dim != 2) return not_applicable();
  using Point = boost::polygon::point_data<int>;
  double lo[2] = {points.coords.empty() ? 0 : points.coords[0], points.coords.empty() ? 0 : points.coords[1]};
  double hi[2] = {lo[0], lo[1]};
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int k = 0; k < 2; ++k) {
      lo[k] = std::min(lo[k], points.point(i)[k]);
      hi[k] = std::max(hi[k], points.point(i)[k]);
    }
  const double extent = std::max(hi[0] - lo[0], hi[1] - lo[1]);
  const double scale = extent > 0 ? 2.0 * 1073741824.0 / extent : 1.0;
  std::vector<Point> input;
  input.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double* p = points.point(i);
    input.emplace_back(static_cast<int>(std::lround((p[0] - lo[0]) * scale - 1073741824.0)),
                       static_cast<int>(std::lround((p[1] - lo[1]) * scale - 1073741824.0)));
  }
  const auto start = Clock::now();
  boost::polygon::voronoi_diagram<double> vd;
  boost::polygon::construct_voronoi(input.begin(), input.end(), &vd);
  const auto stop = Clock::now();
  PeerResult r;
  r.simplices = vd.num_vertices();
  r.seconds = seconds_between(start, stop);
  r.extra = "counts=voronoi_vertices input=int32_scaled";
  return r;
}

}  // namespace drange::bench
