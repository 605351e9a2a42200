// tests/leaf_blocks_test.cpp: the leaves' blocks (delaunay/leaf_blocks.cpp) against the kd-tree
// and the coordinates they copy, for every thread count.
//
// Every leaf's blocks hold exactly its points, in order, with at most LeafBlocks::kLanes per
// block; each block's lanes are its points' coordinates (+infinity past them), each box the
// exact bounds of its block's points (+infinity for an empty slot); and the blocks built on
// several threads are the ones built on one. Leaf sizes from below one block to several groups
// of blocks, in d = 2, 3 and 5; enough points (70 000: over 8 192 blocks) that the fill is cut
// into ranges for the threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "delaunay/leaf_blocks.hpp"
#include "delaunay/team.hpp"
#include "oracle.hpp"
#include "spatial/kdtree.hpp"

namespace {

using drange::engine::LeafBlocks;
constexpr int kLanes = LeafBlocks::kLanes;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Every value the blocks hold, leaf by leaf, in a flat list (for comparing two builds), after
// checking each against the tree and the coordinates.
std::vector<double> check_blocks(const LeafBlocks& blocks, const drange::spatial::KdTree& tree, const double* coords, int d,
                                 const std::string& what) {
  std::vector<double> values;
  const auto& nodes = tree.nodes();
  for (std::size_t leaf = 0; leaf < nodes.size(); ++leaf) {
    if (nodes[leaf].right >= 0) continue;
    const LeafBlocks::Groups groups = blocks.groups(static_cast<std::int32_t>(leaf));
    std::int32_t next = nodes[leaf].begin;  // the leaf's next point not yet met in a block
    for (std::int32_t group = groups.first; group < groups.first + groups.count; ++group) {
      const double* boxes = blocks.boxes(group);
      for (int slot = 0; slot < kLanes; ++slot) {
        const std::int32_t count = blocks.count(group, slot);
        EXPECT_LE(count, kLanes) << what;
        if (count > 0) {
          EXPECT_EQ(blocks.begin(group, slot), next) << what << ", leaf " << leaf;
          next += count;
        }
        const double* lanes = blocks.lanes(group, slot);
        for (int k = 0; k < d; ++k) {
          double lo = kInfinity, hi = -kInfinity;
          for (int j = 0; j < kLanes; ++j) {
            const double lane = lanes[k * kLanes + j];
            values.push_back(lane);
            if (j >= count) {
              EXPECT_EQ(lane, kInfinity) << what;
              continue;
            }
            const double x = coords[static_cast<std::size_t>(blocks.begin(group, slot) + j) * static_cast<std::size_t>(d) + static_cast<std::size_t>(k)];
            EXPECT_EQ(lane, x) << what;
            lo = std::min(lo, x);
            hi = std::max(hi, x);
          }
          if (count == 0) lo = hi = kInfinity;
          EXPECT_EQ(boxes[k * kLanes + slot], lo) << what << ", leaf " << leaf << ", slot " << slot << ", axis " << k;
          EXPECT_EQ(boxes[(d + k) * kLanes + slot], hi) << what << ", leaf " << leaf << ", slot " << slot << ", axis " << k;
          values.push_back(boxes[k * kLanes + slot]);
          values.push_back(boxes[(d + k) * kLanes + slot]);
        }
      }
    }
    EXPECT_EQ(next, nodes[leaf].end) << what << ", leaf " << leaf;
  }
  return values;
}

TEST(LeafBlocks, HoldEveryLeafsPointsWithExactBoxesOnAnyThreadCount) {
  for (const int d : {2, 3, 5})
    for (const int leaf_size : {5, 8, 29, 200}) {
      const std::string what = "d=" + std::to_string(d) + ", leaf size " + std::to_string(leaf_size);
      drange::PointCloud points = drange::test::random_points(70000, d, static_cast<std::uint64_t>(d * 1000 + leaf_size));
      drange::spatial::KdTree tree;
      tree.build_and_reorder(points.coords.data(), static_cast<std::int32_t>(points.size()), d, leaf_size);
      std::vector<double> serial;
      for (const int threads : {1, 2, 3}) {
        drange::engine::Team team(threads);
        const LeafBlocks blocks(tree, points.coords.data(), d, team);
        const std::vector<double> values = check_blocks(blocks, tree, points.coords.data(), d, what + ", threads=" + std::to_string(threads));
        if (threads == 1)
          serial = values;
        else
          EXPECT_TRUE(values == serial) << what << ", threads=" << threads;
      }
    }
}

}  // namespace
