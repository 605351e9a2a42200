// bench/peer_cgal.cpp: CGAL's Delaunay_triangulation_2 and _3 (Epick), sequential and, for 3D,
// the parallel mode (Parallel_tag, TBB, a spatial lock grid over the bounding box). The points
// are converted to CGAL's point type before the clock; the range insertion spatially sorts
// them, which is part of CGAL's construction and is timed.
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_3.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <algorithm>
#include <string>
#include <vector>

#include "peer.hpp"

namespace drange::bench {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

PeerResult run_cgal2(const PointCloud& points, const RunOptions&) {
  if (points.dim != 2) return not_applicable();
  std::vector<K::Point_2> input;
  input.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) input.emplace_back(points.point(i)[0], points.point(i)[1]);
  const auto start = Clock::now();
  CGAL::Delaunay_triangulation_2<K> dt;
  dt.insert(input.begin(), input.end());
  const auto stop = Clock::now();
  PeerResult r;
  r.simplices = dt.number_of_faces();
  r.seconds = seconds_between(start, stop);
  return r;
}

static std::vector<K::Point_3> points_3(const PointCloud& points) {
  std::vector<K::Point_3> input;
  input.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double* p = points.point(i);
    input.emplace_back(p[0], p[1], p[2]);
  }
  return input;
}

PeerResult run_cgal3(const PointCloud& points, const RunOptions&) {
  if (points.dim != 3) return not_applicable();
  const std::vector<K::Point_3> input = points_3(points);
  const auto start = Clock::now();
  CGAL::Delaunay_triangulation_3<K> dt(input.begin(), input.end());
  const auto stop = Clock::now();
  PeerResult r;
  r.simplices = dt.number_of_finite_cells();
  r.seconds = seconds_between(start, stop);
  return r;
}

#ifdef CGAL_LINKED_WITH_TBB
PeerResult run_cgal3_parallel(const PointCloud& points, const RunOptions& options) {
  if (points.dim != 3) return not_applicable();
  using Tds = CGAL::Triangulation_data_structure_3<CGAL::Triangulation_vertex_base_3<K>,
                                                   CGAL::Delaunay_triangulation_cell_base_3<K>, CGAL::Parallel_tag>;
  using DT = CGAL::Delaunay_triangulation_3<K, Tds>;
  const std::vector<K::Point_3> input = points_3(points);
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(options.threads));
  const auto start = Clock::now();
  CGAL::Bbox_3 box = input.empty() ? CGAL::Bbox_3() : input.front().bbox();
  for (const K::Point_3& p : input) box += p.bbox();
  DT::Lock_data_structure locks(box, 50);
  DT dt(input.begin(), input.end(), &locks);
  const auto stop = Clock::now();
  PeerResult r;
  r.simplices = dt.number_of_finite_cells();
  r.seconds = seconds_between(start, stop);
  r.extra = "tbb=yes threads=" + std::to_string(options.threads);
  return r;
}
#endif

}  // namespace drange::bench
