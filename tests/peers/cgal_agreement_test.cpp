// Agreement with CGAL (Debian's libcgal-dev) on random points in general position, where the
// Delaunay triangulation is unique: CGAL's dD Delaunay_triangulation (d = 2..5) and its
// Delaunay_triangulation_3 give the same simplices as drange, as sets of input indices.
// Built only when CMake finds CGAL (test.sh installs it).
#include <CGAL/Delaunay_triangulation.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Epick_d.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "drange/delaunay.hpp"
#include "oracle.hpp"
#include "peers/peer_case.hpp"
#include "drange/generate.hpp"

namespace drange {
namespace {

// CGAL's simplices as a flat array of input indices.
std::vector<std::int32_t> cgal_dd(const PointCloud& points) {
  using Kernel = CGAL::Epick_d<CGAL::Dynamic_dimension_tag>;
  using DT = CGAL::Delaunay_triangulation<Kernel>;
  const int d = points.dim;
  std::map<std::vector<double>, std::int32_t> index;
  std::vector<DT::Point> input;
  for (std::size_t i = 0; i < points.size(); ++i) {
    std::vector<double> c(points.point(i), points.point(i) + d);
    index[c] = static_cast<std::int32_t>(i);
    input.emplace_back(d, c.begin(), c.end());
  }
  DT dt(d);
  dt.insert(input.begin(), input.end());
  std::vector<std::int32_t> out;
  for (auto cell = dt.finite_full_cells_begin(); cell != dt.finite_full_cells_end(); ++cell) {
    std::vector<std::int32_t> s;
    for (int k = 0; k <= d; ++k) {
      const DT::Point& p = cell->vertex(k)->point();
      s.push_back(index.at(std::vector<double>(p.cartesian_begin(), p.cartesian_end())));
    }
    out.insert(out.end(), s.begin(), s.end());
  }
  return out;
}

std::vector<std::int32_t> cgal_3(const PointCloud& points) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Vb = CGAL::Triangulation_vertex_base_with_info_3<std::int32_t, K>;
  using Tds = CGAL::Triangulation_data_structure_3<Vb>;
  using DT = CGAL::Delaunay_triangulation_3<K, Tds>;
  std::vector<std::pair<K::Point_3, std::int32_t>> input;
  for (std::size_t i = 0; i < points.size(); ++i)
    input.emplace_back(K::Point_3(points.point(i)[0], points.point(i)[1], points.point(i)[2]), static_cast<std::int32_t>(i));
  DT dt(input.begin(), input.end());
  std::vector<std::int32_t> out;
  for (auto cell = dt.finite_cells_begin(); cell != dt.finite_cells_end(); ++cell) {
    std::vector<std::int32_t> s;
    for (int k = 0; k < 4; ++k) s.push_back(cell->vertex(k)->info());
    out.insert(out.end(), s.begin(), s.end());
  }
  return out;
}

class CgalAgreement : public ::testing::TestWithParam<test::PeerCase> {};

TEST_P(CgalAgreement, SameSimplicesAsCgalDelaunayTriangulation) {
  const test::PeerCase c = GetParam();
  const std::uint64_t seed = 2000 + c.n + static_cast<std::uint64_t>(c.d);
  const PointCloud points = generate_points(c.distribution, c.n, c.d, seed);
  const Triangulation ours = delaunay(points);
  EXPECT_EQ(test::canonical(ours.simplices, c.d), test::canonical(cgal_dd(points), c.d)) << "seed " << seed;
  if (c.d == 3) EXPECT_EQ(test::canonical(ours.simplices, c.d), test::canonical(cgal_3(points), c.d)) << "seed " << seed;
}

INSTANTIATE_TEST_SUITE_P(
    RandomInputs, CgalAgreement,
    ::testing::Values(test::PeerCase{Distribution::Uniform, 4000, 2}, test::PeerCase{Distribution::Clustered, 4000, 2},
                      test::PeerCase{Distribution::Uniform, 20000, 3}, test::PeerCase{Distribution::Gaussian, 3000, 3},
                      test::PeerCase{Distribution::Uniform, 1000, 4}, test::PeerCase{Distribution::Ball, 400, 5}),
    test::case_name);

}  // namespace
}  // namespace drange
