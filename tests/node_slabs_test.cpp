// tests/node_slabs_test.cpp: the kd-tree nodes' slabs (delaunay/node_slabs.cpp) and the search
// that prunes with them (search/slab_pruner.hpp, SearchOptions::node_slabs).
//
// A slab must hold every point of its node for exact arithmetic (checked in long double, whose
// 11 extra bits see far below the slab's rounding margin), be thin (kept only when 4 times
// thinner than the node's box across it), and be the same on any thread count; points sampled
// from a surface keep slabs on nearly every small node, uniform points on almost none.
// misses_ball must never drop a point within reach. And the search with slabs must find the
// same triangulation as without, valid by the exact checker, on surfaces where the slabs prune.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "delaunay/node_slabs.hpp"
#include "delaunay/team.hpp"
#include "drange/check.hpp"
#include "drange/delaunay.hpp"
#include "oracle.hpp"
#include "spatial/kdtree.hpp"

namespace {

using drange::PointCloud;
using drange::engine::NodeSlabs;

// n points on the ellipsoid sum (x_k / a_k)^2 = 1 in `dim` dimensions, axes 1, 0.7, 0.4, ...
// (a smooth closed surface that is no sphere: a scan's kind of input).
PointCloud ellipsoid(std::size_t n, int dim, std::uint64_t seed) {
  drange::test::TestRandom random(seed);
  PointCloud points{dim, {}};
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<double> v(static_cast<std::size_t>(dim));
    double norm2 = 0.0;
    for (double& x : v) {
      // Box-Muller: a direction uniform on the sphere.
      x = std::sqrt(-2 * std::log(1 - random.uniform())) * std::cos(2 * M_PI * random.uniform());
      norm2 += x * x;
    }
    for (int k = 0; k < dim; ++k) points.coords.push_back(v[static_cast<std::size_t>(k)] / std::sqrt(norm2) * (1.0 - 0.3 * k));
  }
  return points;
}

struct Built {
  drange::spatial::KdTree tree;
  PointCloud points;  // in tree order
};

Built build(PointCloud points, int leaf_size) {
  Built built{{}, std::move(points)};
  built.tree.build_and_reorder(built.points.coords.data(), static_cast<std::int32_t>(built.points.size()), built.points.dim,
                               leaf_size);
  return built;
}

// Checks every slab against its node's points and box; returns how many nodes keep one.
std::size_t check_slabs(const NodeSlabs& slabs, const Built& built, const std::string& what) {
  const int d = built.points.dim;
  const auto& nodes = built.tree.nodes();
  std::size_t kept = 0;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const double* slab = slabs.slab(static_cast<std::int32_t>(i));
    if (slab == nullptr) continue;
    ++kept;
    long double norm2 = 0.0L, extent = 0.0L;
    const double* lo = built.tree.lower(static_cast<std::int32_t>(i));
    const double* hi = built.tree.upper(static_cast<std::int32_t>(i));
    for (int k = 0; k < d; ++k) {
      norm2 += static_cast<long double>(slab[k]) * slab[k];
      extent += std::fabs(static_cast<long double>(slab[k])) * (static_cast<long double>(hi[k]) - lo[k]);
    }
    EXPECT_NEAR(static_cast<double>(norm2), 1.0, 1e-12) << what << ", node " << i;
    EXPECT_LT(4 * (static_cast<long double>(slab[d + 1]) - slab[d]), extent) << what << ", node " << i << ": not thin";
    for (std::int32_t p = nodes[i].begin; p < nodes[i].end; ++p) {
      long double t = 0.0L;
      for (int k = 0; k < d; ++k) t += static_cast<long double>(slab[k]) * built.points.point(static_cast<std::size_t>(p))[k];
      EXPECT_LE(static_cast<long double>(slab[d]), t) << what << ", node " << i << ", point " << p;
      EXPECT_LE(t, static_cast<long double>(slab[d + 1])) << what << ", node " << i << ", point " << p;
    }
  }
  return kept;
}

TEST(NodeSlabs, HoldEveryPointOfTheirNodeOnSurfacesOnAnyThreadCount) {
  for (const int d : {2, 3, 4})
    for (const int leaf_size : {8, 128}) {
      const std::string what = "ellipsoid d=" + std::to_string(d) + ", leaf size " + std::to_string(leaf_size);
      const Built built = build(ellipsoid(20000, d, static_cast<std::uint64_t>(d * 100 + leaf_size)), leaf_size);
      std::size_t kept_serial = 0;
      std::vector<double> serial;
      for (const int threads : {1, 2}) {
        drange::engine::Team team(threads);
        const NodeSlabs slabs(built.tree, built.points.coords.data(), d, team);
        const std::size_t kept = check_slabs(slabs, built, what);
        // The leaves of a surface sample are flat patches: nearly all keep a slab (in 4D, a
        // leaf of 128 of 20 000 points on a 3-manifold is too curved a patch).
        std::size_t leaves = 0;
        std::vector<double> values;
        for (std::size_t i = 0; i < built.tree.nodes().size(); ++i) {
          leaves += built.tree.nodes()[i].right < 0;
          if (const double* slab = slabs.slab(static_cast<std::int32_t>(i))) values.insert(values.end(), slab, slab + d + 2);
        }
        if (d < 4 || leaf_size == 8) EXPECT_GT(kept, leaves * 9 / 10) << what;
        EXPECT_EQ(slabs.size(), kept) << what;
        if (threads == 1) {
          kept_serial = kept;
          serial = values;
        } else {
          EXPECT_EQ(kept, kept_serial) << what;
          EXPECT_TRUE(values == serial) << what << ": not the same on 2 threads";
        }
      }
    }
}

TEST(NodeSlabs, UniformPointsKeepAlmostNone) {
  for (const int d : {2, 3, 5}) {
    const Built built = build(drange::test::random_points(50000, d, static_cast<std::uint64_t>(d)), 64);
    drange::engine::Team team(1);
    const NodeSlabs slabs(built.tree, built.points.coords.data(), d, team);
    check_slabs(slabs, built, "uniform d=" + std::to_string(d));
    EXPECT_LE(slabs.size(), built.tree.nodes().size() / 100) << "d=" << d;
  }
}

TEST(NodeSlabs, MissesBallOnlyWhenNoPointOfTheSlabIsInReach) {
  drange::engine::Team team(1);
  const Built built = build(drange::test::random_points(100, 3, 1), 8);
  const NodeSlabs slabs(built.tree, built.points.coords.data(), 3, team);
  // The slab 1 <= x <= 1.5 (normal (1, 0, 0)): its nearest point to the origin is at 1.
  const double slab[] = {1.0, 0.0, 0.0, 1.0, 1.5};
  const double origin[] = {0.0, 0.0, 0.0}, beyond[] = {3.0, 5.0, -2.0};
  EXPECT_TRUE(slabs.misses_ball<3>(slab, origin, 0.999));
  EXPECT_FALSE(slabs.misses_ball<3>(slab, origin, 1.0));    // touches it
  EXPECT_FALSE(slabs.misses_ball<3>(slab, origin, 1.0 - 1e-15));  // within its rounding margin
  EXPECT_TRUE(slabs.misses_ball(slab, beyond, 1.4));        // the run-time d agrees
  EXPECT_FALSE(slabs.misses_ball(slab, beyond, 1.5));
  EXPECT_FALSE(slabs.misses_ball<3>(slab, std::vector<double>{1.2, 7.0, 7.0}.data(), 0.0));  // the centre in the slab
}

TEST(NodeSlabs, ABallThatMissesASlabHoldsNoPointOfItsNode) {
  // Balls about random centres, with radii up to the nearest point of each node: whenever
  // misses_ball says so, every point of the node is farther than the reach (long double).
  const Built built = build(ellipsoid(5000, 3, 7), 32);
  drange::engine::Team team(1);
  const NodeSlabs slabs(built.tree, built.points.coords.data(), 3, team);
  drange::test::TestRandom random(3);
  std::size_t missed = 0;
  for (std::size_t i = 0; i < built.tree.nodes().size(); ++i) {
    const double* slab = slabs.slab(static_cast<std::int32_t>(i));
    if (slab == nullptr) continue;
    const auto& node = built.tree.nodes()[i];
    for (int trial = 0; trial < 20; ++trial) {
      double centre[3];
      for (double& c : centre) c = 2.4 * random.uniform() - 1.2;
      long double nearest = 1e300L;
      for (std::int32_t p = node.begin; p < node.end; ++p) {
        long double d2 = 0.0L;
        for (int k = 0; k < 3; ++k) {
          const long double delta = static_cast<long double>(built.points.point(static_cast<std::size_t>(p))[k]) - centre[k];
          d2 += delta * delta;
        }
        nearest = std::min(nearest, std::sqrt(d2));
      }
      const double reach = static_cast<double>(nearest) * (trial % 2 == 0 ? random.uniform() : 1.0);
      if (!slabs.misses_ball<3>(slab, centre, reach)) continue;
      ++missed;
      EXPECT_GT(nearest, static_cast<long double>(reach)) << "node " << i;
    }
  }
  EXPECT_GT(missed, 100u);  // the test saw slabs missing balls
}

drange::Triangulation triangulate(const PointCloud& points, const char* variant) {
  drange::Options options;
  options.variant = variant;
  options.threads = 1;  // the work counted is then the same on every run
  return drange::delaunay(points, options);
}

TEST(NodeSlabs, TheSearchFindsTheSameValidTriangulationWithLessWorkOnSurfaces) {
  struct Case {
    std::string name;
    PointCloud points;
    bool pruned;  // the slabs save work there (fewer nodes entered with them than without)
  };
  std::vector<Case> cases = {{"ellipse 2D", ellipsoid(20000, 2, 41), true},
                             {"ellipsoid 3D", ellipsoid(20000, 3, 42), true},
                             {"ellipsoid 4D", ellipsoid(3000, 4, 43), false}};  // few slabs at this size
  {
    // A cylinder (its balls touch it along circles, where the slabs stop being tried).
    drange::test::TestRandom random(44);
    PointCloud c{3, {}};
    for (int i = 0; i < 8000; ++i) {
      const double t = 2 * M_PI * random.uniform();
      c.coords.insert(c.coords.end(), {std::cos(t), std::sin(t), 2 * random.uniform() - 1});
    }
    cases.push_back({"cylinder", c, false});
  }
  for (const Case& c : cases) {
    const drange::Triangulation with = triangulate(c.points, "full"), without = triangulate(c.points, "no-slab");
    EXPECT_EQ(drange::test::canonical(with.simplices, with.dim), drange::test::canonical(without.simplices, without.dim)) << c.name;
    const drange::CheckReport report = drange::check_triangulation(c.points, with.simplices);
    EXPECT_TRUE(report.valid) << c.name << ": " << (report.problems.empty() ? "" : report.problems.front());
    if (c.pruned) EXPECT_LT(with.stats.search_calls, without.stats.search_calls * 9 / 10) << c.name;
  }
}

}  // namespace
