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
#include <set>
#include <string>
#include <vector>

#include "drange/delaunay.hpp"
#include "drange/generate.hpp"

namespace {

using Simplex = std::vector<std::int32_t>;

std::set<Simplex> canonical(const std::vector<std::int32_t>& flat, int d) {
  std::set<Simplex> out;
  for (std::size_t s = 0; s < flat.size(); s += static_cast<std::size_t>(d + 1)) {
    Simplex v(flat.begin() + static_cast<std::ptrdiff_t>(s), flat.begin() + static_cast<std::ptrdiff_t>(s) + d + 1);
    std::sort(v.begin(), v.end());
    out.insert(v);
  }
  return out;
}

std::set<Simplex> cgal_dd(const drange::PointCloud& points) {
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
  std::set<Simplex> out;
  for (auto cell = dt.finite_full_cells_begin(); cell != dt.finite_full_cells_end(); ++cell) {
    Simplex s;
    for (int k = 0; k <= d; ++k) {
      const DT::Point& p = cell->vertex(k)->point();
      s.push_back(index.at(std::vector<double>(p.cartesian_begin(), p.cartesian_end())));
    }
    std::sort(s.begin(), s.end());
    out.insert(s);
  }
  return out;
}

std::set<Simplex> cgal_3(const drange::PointCloud& points) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Vb = CGAL::Triangulation_vertex_base_with_info_3<std::int32_t, K>;
  using Tds = CGAL::Triangulation_data_structure_3<Vb>;
  using DT = CGAL::Delaunay_triangulation_3<K, Tds>;
  std::vector<std::pair<K::Point_3, std::int32_t>> input;
  for (std::size_t i = 0; i < points.size(); ++i)
    input.emplace_back(K::Point_3(points.point(i)[0], points.point(i)[1], points.point(i)[2]), static_cast<std::int32_t>(i));
  DT dt(input.begin(), input.end());
  std::set<Simplex> out;
  for (auto cell = dt.finite_cells_begin(); cell != dt.finite_cells_end(); ++cell) {
    Simplex s;
    for (int k = 0; k < 4; ++k) s.push_back(cell->vertex(k)->info());
    std::sort(s.begin(), s.end());
    out.insert(s);
  }
  return out;
}

struct Case {
  drange::Distribution distribution;
  std::size_t n;
  int d;
};

std::string describe(const Case& c) {
  static const char* const names[] = {"uniform", "ball", "sphere", "gaussian", "clustered", "grid"};
  return std::string(names[static_cast<int>(c.distribution)]) + "_d" + std::to_string(c.d) + "_n" + std::to_string(c.n);
}
std::string case_name(const ::testing::TestParamInfo<Case>& info) { return describe(info.param); }
void PrintTo(const Case& c, std::ostream* os) { *os << describe(c); }

class CgalAgreement : public ::testing::TestWithParam<Case> {};

TEST_P(CgalAgreement, SameSimplicesAsCgalDelaunayTriangulation) {
  const Case c = GetParam();
  const std::uint64_t seed = 2000 + c.n + static_cast<std::uint64_t>(c.d);
  const drange::PointCloud points = drange::generate_points(c.distribution, c.n, c.d, seed);
  const drange::Triangulation ours = drange::delaunay(points);
  EXPECT_EQ(canonical(ours.simplices, c.d), cgal_dd(points)) << "seed " << seed;
  if (c.d == 3) EXPECT_EQ(canonical(ours.simplices, c.d), cgal_3(points)) << "seed " << seed;
}

INSTANTIATE_TEST_SUITE_P(
    RandomInputs, CgalAgreement,
    ::testing::Values(Case{drange::Distribution::Uniform, 4000, 2}, Case{drange::Distribution::Clustered, 4000, 2},
                      Case{drange::Distribution::Uniform, 20000, 3}, Case{drange::Distribution::Gaussian, 3000, 3},
                      Case{drange::Distribution::Uniform, 1000, 4}, Case{drange::Distribution::Ball, 400, 5}),
    case_name);

}  // namespace
