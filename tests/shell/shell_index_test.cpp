// tests/shell/shell_index_test.cpp: the sphere shell's index (delaunay/shell/shell_index.hpp)
// against exact rationals: every point's offset within its stated bound, and every node's
// range, clusters and cones and every block's cone holding its points' exact values; the
// blocks cutting the leaves and listing their points by offset.
#include <gtest/gtest.h>

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "shell/shell_inputs.hpp"

namespace {

using drange::Distribution;
using drange::PointCloud;
using namespace drange::test::shell;

TEST(SphereShell, OffsetsAndNodeRangesBoundTheExactOffsets) {
  // Each point's offset about its own sphere; each node's range, in a node in a sphere.
  for (int d : {2, 3, 5}) {
    for (const PointCloud& points : shell_inputs(d)) {
      const auto store = store_of(points);
      ASSERT_TRUE(store.shell.active());
      const drange::engine::SphereShell& shell = store.shell;
      std::vector<mpq_class> exact(static_cast<std::size_t>(store.size));
      for (std::int32_t id = 0; id < store.size; ++id) {
        const std::int32_t k = shell.point_sphere[static_cast<std::size_t>(id)];
        if (k < 0) continue;
        const double s = shell.offset[static_cast<std::size_t>(id)];
        const drange::engine::ShellSphere sphere = shell.sphere(k);
        exact[static_cast<std::size_t>(id)] = exact_offset(store.point(id), sphere.centre, d, sphere.rho);
        const mpq_class error = abs(exact[static_cast<std::size_t>(id)] - mpq_class(s));
        EXPECT_LE(error, mpq_class(0x1p-53 * std::fabs(s)) + mpq_class(sphere.eta)) << "d=" << d << " id=" << id;
      }
      const auto& nodes = store.tree.nodes();
      std::size_t in_sphere = 0;
      for (std::size_t i = 0; i < nodes.size(); ++i) {
        const std::int32_t k = shell.node_sphere[i];
        if (k < 0) continue;
        ++in_sphere;
        for (std::int32_t id = nodes[i].begin; id < nodes[i].end; ++id) {
          ASSERT_EQ(shell.point_sphere[static_cast<std::size_t>(id)], k) << "node " << i;
          ASSERT_LE(mpq_class(shell.of(static_cast<std::int32_t>(i))[0]), exact[static_cast<std::size_t>(id)]) << "node " << i;
          ASSERT_GE(mpq_class(shell.of(static_cast<std::int32_t>(i))[1]), exact[static_cast<std::size_t>(id)]) << "node " << i;
        }
      }
      EXPECT_GT(in_sphere, nodes.size() / 4) << "d=" << d;
    }
  }
}

TEST(SphereShell, ConcentricClustersBoundTheirPointsExactly) {
  // Each node's two clusters (near the smallest sphere, the rest) hold the exact offset and
  // |y| of each of its points, by the point's side of cluster_split; and nodes that mix the
  // two spheres exist (the case the clusters are for).
  for (int d : {2, 3, 4}) {
    const auto store = store_of(concentric(1500, d, 60 + static_cast<std::uint64_t>(d), {1.0, 0.5}, 0.25));
    const drange::engine::SphereShell& shell = store.shell;
    ASSERT_TRUE(shell.active()) << "d=" << d;
    ASSERT_FALSE(shell.clusters.empty()) << "d=" << d;
    const std::vector<double> g = centre_of(shell);
    std::size_t mixed = 0;
    const auto& nodes = store.tree.nodes();
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      const double* clusters = shell.clusters_of(static_cast<std::int32_t>(i));
      mixed += clusters[0] <= clusters[1] && clusters[4] <= clusters[5];
      for (std::int32_t id = nodes[i].begin; id < nodes[i].end; ++id) {
        const double* cluster = clusters + (shell.offset[static_cast<std::size_t>(id)] < shell.cluster_split ? 0 : 4);
        const mpq_class offset = exact_offset(store.point(id), g.data(), d, shell.rho[0]);
        const mpq_class y2 = offset + mpq_class(shell.rho[0]);
        ASSERT_LE(mpq_class(cluster[0]), offset) << "d=" << d << " node " << i;
        ASSERT_GE(mpq_class(cluster[1]), offset) << "d=" << d << " node " << i;
        ASSERT_LE(mpq_class(cluster[2]) * mpq_class(cluster[2]), y2) << "d=" << d << " node " << i;
        ASSERT_GE(mpq_class(cluster[3]) * mpq_class(cluster[3]), y2) << "d=" << d << " node " << i;
      }
    }
    EXPECT_GT(mixed, 0u) << "d=" << d;
  }
  // One sphere: no clusters.
  EXPECT_TRUE(store_of(sphere(2000, 3, 11)).shell.clusters.empty());
}

TEST(SphereShell, ConesHoldTheirPointsExactly) {
  // For every node and block with a cone: each point's exact y = x - g has m . y >= cos_lo |y| and
  // r_lo <= |y| <= r_hi, and sin_hi^2 >= 1 - cos_lo^2 / |m|^2 (the rim's sine for m as stored).
  // With one sphere, every node's cone is about its centre, over the points off it too.
  for (int d : {2, 3, 5}) {
    for (const PointCloud& points : {sphere(2000, d, 13), sphere(2000, d, 14, 2.0, -0.5, 1e-12), shell_inputs(d)[1],
                                     sphere_around_ball(2000, d, 15)}) {
      const auto store = store_of(points);
      ASSERT_TRUE(store.shell.active());
      const drange::engine::SphereShell& shell = store.shell;
      const auto& nodes = store.tree.nodes();
      const bool one_sphere = shell.spheres() == 1;
      // Whether the cone holds the points [begin, end) (true for a cone too wide to be used),
      // about their sphere's centre.
      const auto holds = [&](const double* cone, std::int32_t begin, std::int32_t end) {
        const double cos_lo = cone[d], sin_hi = cone[d + 1], r_lo = cone[d + 2], r_hi = cone[d + 3];
        if (!(cos_lo > 0.0)) return true;
        mpq_class m2 = 0;
        for (int k = 0; k < d; ++k) m2 += mpq_class(cone[k]) * mpq_class(cone[k]);
        EXPECT_LT(abs(m2 - 1), mpq_class(1e-12));
        EXPECT_GE(mpq_class(sin_hi) * mpq_class(sin_hi), 1 - mpq_class(cos_lo) * mpq_class(cos_lo) / m2);
        for (std::int32_t id = begin; id < end; ++id) {
          const std::int32_t sphere_of_id = shell.point_sphere[static_cast<std::size_t>(id)];
          if (!one_sphere && (sphere_of_id != shell.point_sphere[static_cast<std::size_t>(begin)] || sphere_of_id < 0)) {
            ADD_FAILURE() << "d=" << d << ": a cone over points of several spheres, or of none";
            return false;
          }
          const std::vector<double> g = centre_of(shell, one_sphere ? 0 : sphere_of_id);
          mpq_class dot = 0, y2 = 0;
          for (int k = 0; k < d; ++k) {
            const mpq_class y = mpq_class(store.point(id)[k]) - mpq_class(g[static_cast<std::size_t>(k)]);
            dot += mpq_class(cone[k]) * y;
            y2 += y * y;
          }
          if (dot < 0 || dot * dot < mpq_class(cos_lo) * mpq_class(cos_lo) * y2 || mpq_class(r_lo) * mpq_class(r_lo) > y2 ||
              mpq_class(r_hi) * mpq_class(r_hi) < y2) {
            ADD_FAILURE() << "d=" << d << ": point " << id << " is outside its cone";
            return false;
          }
        }
        return !::testing::Test::HasFailure();
      };
      std::size_t leaves = 0, leaf_cones = 0;
      for (std::size_t i = 0; i < nodes.size(); ++i) {
        const double* cone = shell.cone_of(static_cast<std::int32_t>(i));
        const double cos_lo = cone[d];
        if (nodes[i].right < 0) ++leaves;
        if (!(cos_lo > 0.0)) continue;
        if (nodes[i].right < 0) ++leaf_cones;
        ASSERT_TRUE(holds(cone, nodes[i].begin, nodes[i].end)) << "node " << i;
      }
      // (Around a ball, a leaf inside it may hold points in every direction.)
      const bool all_on_it = std::count(shell.point_sphere.begin(), shell.point_sphere.end(), -1) == 0;
      if (d <= 3 && one_sphere && all_on_it) EXPECT_EQ(leaf_cones, leaves) << "d=" << d << ": a leaf holds a small cap of the sphere";
      std::size_t block_cones = 0, blocks_in_spheres = 0;
      for (std::size_t b = 0; b + 1 < shell.block_start.size(); ++b) {
        if (shell.block_sphere[b] < 0) continue;
        ++blocks_in_spheres;
        const double* cone = shell.block_cone_of(static_cast<std::int32_t>(b));
        if (!holds(cone, shell.block_start[b], shell.block_start[b + 1])) return;
        block_cones += cone[d] > 0.0;
      }
      // (In the background of bubbles, a point in a bubble's patch may lie in any direction.)
      if (one_sphere) EXPECT_EQ(block_cones, blocks_in_spheres) << "d=" << d << ": a block holds a few near points";
    }
  }
}

TEST(SphereShell, BlocksCutTheLeavesAndListTheirPointsByOffset) {
  for (int d : {2, 3, 4}) {
   for (const PointCloud& points : {sphere(3000, d, 15, 1.0, 0.0, 1e-10), shell_inputs(d)[1]}) {
    const auto store = store_of(points);
    const drange::engine::SphereShell& shell = store.shell;
    ASSERT_TRUE(shell.active());
    const auto& nodes = store.tree.nodes();
    ASSERT_EQ(shell.block_start.back(), store.size);
    for (std::size_t leaf = 0; leaf < nodes.size(); ++leaf) {
      if (nodes[leaf].right >= 0) continue;
      if (shell.first_block[leaf] < 0) {  // a leaf in no sphere
        ASSERT_EQ(shell.node_sphere[leaf], -1);
        continue;
      }
      // The leaf's blocks: consecutive, of 1 to 8 points in 3D, 32 from 4D (a whole run of one
      // sphere's points in 2D), from its first point to its last.
      auto block = static_cast<std::size_t>(shell.first_block[leaf]);
      ASSERT_EQ(shell.block_start[block], nodes[leaf].begin);
      for (; shell.block_start[block] < nodes[leaf].end; ++block) {
        const std::int32_t begin = shell.block_start[block], end = shell.block_start[block + 1];
        ASSERT_GE(end - begin, 1);
        if (d > 2 && shell.block_sphere[block] >= 0) ASSERT_LE(end - begin, d == 3 ? 8 : 32);
        std::vector<std::int32_t> ids(shell.block_ids.begin() + begin, shell.block_ids.begin() + end);
        for (std::int32_t id : ids) ASSERT_EQ(shell.point_sphere[static_cast<std::size_t>(id)], shell.block_sphere[block]);
        for (std::int32_t i = begin; i < end; ++i) {
          const auto at = static_cast<std::size_t>(i);
          EXPECT_EQ(shell.block_offsets[at], shell.offset[static_cast<std::size_t>(shell.block_ids[at])]);
          if (i > begin) EXPECT_LE(shell.block_offsets[at - 1], shell.block_offsets[at]);
        }
        std::sort(ids.begin(), ids.end());
        for (std::size_t j = 0; j < ids.size(); ++j) ASSERT_EQ(ids[j], begin + static_cast<std::int32_t>(j));
      }
      ASSERT_EQ(shell.block_start[block], nodes[leaf].end);
    }
   }
  }
}

}  // namespace
