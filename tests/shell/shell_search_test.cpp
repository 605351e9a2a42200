// tests/shell/shell_search_test.cpp: the search with the sphere shell against the search
// without it: the same valid triangulation on spheres, caps, noisy spheres, concentric
// spheres, bubbles and exactly cocircular integer points, on one thread and two; and far less
// work (counters, not times).
#include <gtest/gtest.h>

#include <gmpxx.h>

#include <string>
#include <utility>
#include <vector>

#include "drange/check.hpp"
#include "drange/delaunay.hpp"
#include "shell/shell_inputs.hpp"

namespace {

using drange::Distribution;
using drange::PointCloud;
using namespace drange::test::shell;

std::vector<drange::test::Simplex> canonical(const drange::Triangulation& t) { return drange::test::canonical(t.simplices, t.dim); }

drange::Triangulation triangulate(const PointCloud& points, const char* variant) {
  drange::Options options;
  options.variant = variant;
  options.threads = 1;
  return drange::delaunay(points, options);
}

TEST(SphereShell, SameValidTriangulationWithAndWithoutIt) {
  std::vector<std::pair<std::string, PointCloud>> cases = {
      {"circle", sphere(3000, 2, 21)},
      {"sphere 3D", sphere(1500, 3, 22)},
      {"sphere 4D", sphere(300, 4, 23)},
      // 4D and 5D: the leaf scan's blocks of 32, whose point test bounds its error once per
      // block (search/shell_pruner.hpp, block_terms), and the 5D floating-point form.
      {"noisy sphere 4D", sphere(600, 4, 29, 1.0, 0.0, 1e-9)},
      {"sphere 5D", sphere(120, 5, 30)},
      {"off-centre sphere 3D", sphere(1500, 3, 24, 0.75, 3.0)},
      {"noisy sphere 3D", sphere(1500, 3, 25, 1.0, 0.0, 1e-9)},
      {"noisy circle", sphere(3000, 2, 26, 1.0, 0.0, 1e-7)},
  };
  {
    // A cap: the points of a sphere with z > 0.5.
    const PointCloud all = sphere(4000, 3, 27);
    PointCloud cap{3, {}};
    for (std::size_t i = 0; i < all.size(); ++i)
      if (all.point(i)[2] > 0.5) cap.coords.insert(cap.coords.end(), all.point(i), all.point(i) + 3);
    cases.emplace_back("cap", cap);
  }
  {
    PointCloud c = sphere(1500, 3, 28);  // and its centre
    c.coords.insert(c.coords.end(), {0.0, 0.0, 0.0});
    cases.emplace_back("sphere and centre", c);
  }
  cases.emplace_back("sphere and its bounding cube's corners", with_cube_corners(sphere(1500, 3, 32), 1.0));
  cases.emplace_back("circle and its bounding square's corners", with_cube_corners(sphere(2000, 2, 33), 1.0));
  cases.emplace_back("two concentric circles", concentric(1500, 2, 34, {1.0, 0.5}));
  cases.emplace_back("three concentric spheres 3D", concentric(600, 3, 36, {1.0, 0.7, 0.4}, 0.5));
  cases.emplace_back("two concentric spheres 4D", concentric(200, 4, 40, {1.0, 0.5}));
  // Spheres about several centres: bubbles (leaves straddle two of them), and in a uniform
  // background.
  cases.emplace_back("bubbles 2D", bubbles(10, 300, 2, 80));
  cases.emplace_back("bubbles 3D", bubbles(10, 300, 3, 81));
  cases.emplace_back("bubbles 4D", bubbles(6, 150, 4, 82));
  cases.emplace_back("bubbles in a uniform background 3D", shell_inputs(3)[1]);

  {
    // Every integer point of the circle x^2 + y^2 = 5^4 13^2 (exactly cocircular: ties that
    // only the perturbation breaks).
    PointCloud c{2, {}};
    const long r2 = 625L * 169L;
    for (long x = -325; x <= 325; ++x)
      for (long y = -325; y <= 325; ++y)
        if (x * x + y * y == r2) c.coords.insert(c.coords.end(), {double(x), double(y)});
    cases.emplace_back("integer circle", c);
  }
  for (const auto& [name, points] : cases) {
    const drange::engine::PointStore store = store_of(points);
    EXPECT_TRUE(store.shell.active()) << name;
    const drange::Triangulation with = triangulate(points, "full"), without = triangulate(points, "no-shell");
    EXPECT_EQ(canonical(with), canonical(without)) << name;
    const drange::CheckReport report = drange::check_triangulation(points, with.simplices);
    EXPECT_TRUE(report.valid) << name << ": " << (report.problems.empty() ? "" : report.problems.front());
    // Two threads: the same simplices.
    drange::Options two;
    two.threads = 2;
    EXPECT_EQ(canonical(drange::delaunay(points, two)), canonical(with)) << name;
  }
}

TEST(SphereShell, ConesProveTheHullFacetsOfASphereAroundABall) {
  // 6 400 points on a sphere around 1 600 in its ball: the shell has one sphere, from patches,
  // and the nodes that mix points on it and inside it have no sphere. Their cones about its
  // centre let the search of a hull facet prune them (a sphere's hull facet has no point beyond
  // it, and the boxes of the nodes near it reach across its plane).
  const PointCloud points = sphere_around_ball(6400, 3, 16);
  const auto store = store_of(points);
  ASSERT_TRUE(store.shell.active());
  EXPECT_EQ(store.shell.spheres(), 1);
  const drange::Triangulation with = triangulate(points, "full");
  EXPECT_EQ(canonical(with), canonical(triangulate(points, "no-shell")));
  const drange::CheckReport report = drange::check_triangulation(points, with.simplices);
  EXPECT_TRUE(report.valid) << (report.problems.empty() ? "" : report.problems.front());
  // Nodes entered per simplex (a deterministic work counter, not a time): 12.94 with the cones
  // of the mixed nodes, 18.14 without them.
  EXPECT_LT(with.stats.calls_per_simplex(), 15.0);
}

TEST(SphereShell, CutsTheWorkOnSpheres) {
  // Counters, not times: without the shell every search scans nearly every point, and the
  // double filter cannot decide the points near the candidate's sphere (the double-double
  // stage does, geometry/refined_sign.hpp). With the shell, the leaves' offset order and the
  // nodes' cones leave few points and nodes: on these inputs, 36.6 points tested and 16.9
  // nodes entered per triangle against 1 688 and 96.7, and in 3D 37.1 points per tetrahedron
  // against 1 976.
  for (int d : {2, 3}) {
    const PointCloud points = sphere(d == 2 ? 8000 : 2000, d, 31);
    const drange::Statistics with = triangulate(points, "full").stats, without = triangulate(points, "no-shell").stats;
    EXPECT_LT(with.debug.points_tested * (d == 2 ? 20 : 5), without.debug.points_tested) << "d=" << d;
    if (d == 2) EXPECT_LT(with.search_calls * 4, without.search_calls);
    // Within rounding of one sphere but not exactly on it: GMP is all but never needed, with
    // the shell or without.
    EXPECT_LT(with.debug.exact_fallbacks * 1000, with.debug.points_tested) << "d=" << d;
    EXPECT_LT(without.debug.exact_fallbacks * 1000, without.debug.points_tested) << "d=" << d;
  }
  // Two concentric spheres: the inner one's ball is a cell of cospherical points, as above
  // (points tested with the shell and without: 2D 0.28M and 5.97M, 3D 0.20M and 2.91M).
  for (int d : {2, 3}) {
    const PointCloud points = concentric(d == 2 ? 4000 : 1000, d, 42, {1.0, 0.5});
    const drange::Statistics with = triangulate(points, "full").stats, without = triangulate(points, "no-shell").stats;
    EXPECT_LT(with.debug.points_tested * 3, without.debug.points_tested) << "d=" << d;
  }
  // Bubbles: each bubble's ball is a cell of cospherical points; with a sphere per bubble, as
  // with one sphere (points tested with the shell and without: 2D 0.19M and 1.41M, 3D 0.44M
  // and 4.62M).
  for (int d : {2, 3}) {
    const PointCloud points = bubbles(10, 400, d, 90);
    const drange::Statistics with = triangulate(points, "full").stats, without = triangulate(points, "no-shell").stats;
    EXPECT_LT(with.debug.points_tested * 3, without.debug.points_tested) << "d=" << d;
  }
}

}  // namespace
