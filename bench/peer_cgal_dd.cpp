// bench/peer_cgal_dd.cpp: CGAL's dD Delaunay_triangulation with Epick_d, the dimension fixed at
// compile time (Dimension_tag<D>, instantiated for D = 2..8) or at run time
// (Dynamic_dimension_tag). Points converted before the clock; the range insertion (which
// spatially sorts) is timed.
#include <CGAL/Delaunay_triangulation.h>
#include <CGAL/Epick_d.h>

#include <vector>

#include "peer.hpp"

namespace drange::bench {
namespace {

template <class Kernel>
PeerResult build(const PointCloud& points, int dim_argument) {
  using DT = CGAL::Delaunay_triangulation<Kernel>;
  using Point = typename DT::Point;
  const int d = points.dim;
  std::vector<Point> input;
  input.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) input.emplace_back(d, points.point(i), points.point(i) + d);
  const auto start = Clock::now();
  DT dt(dim_argument);
  dt.insert(input.begin(), input.end());
  const auto stop = Clock::now();
  PeerResult r;
  r.simplices = dt.number_of_finite_full_cells();
  r.seconds = seconds_between(start, stop);
  return r;
}

template <int D>
PeerResult build_static(const PointCloud& points) {
  return build<CGAL::Epick_d<CGAL::Dimension_tag<D>>>(points, D);
}

}  // namespace

PeerResult run_cgal_dd_static(const PointCloud& points, const RunOptions&) {
  switch (points.dim) {
    case 2: return build_static<2>(points);
    case 3: return build_static<3>(points);
    case 4: return build_static<4>(points);
    case 5: return build_static<5>(points);
    case 6: return build_static<6>(points);
    case 7: return build_static<7>(points);
    case 8: return build_static<8>(points);
    default: return not_applicable();
  }
}

PeerResult run_cgal_dd_dynamic(const PointCloud& points, const RunOptions&) {
  return build<CGAL::Epick_d<CGAL::Dynamic_dimension_tag>>(points, points.dim);
}

}  // namespace drange::bench
