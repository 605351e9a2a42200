// delaunay/leaf_blocks.hpp: the points of every kd-tree leaf copied in blocks of 8, coordinates
// and bounding boxes transposed, so that the search (facet_search.cpp) tests eight block boxes,
// then the eight points of a block, at once with vector instructions (4D and up). The layout
// only: the arithmetic on the lanes belongs to the search's kernel, which owns the ball.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "delaunay/point_store.hpp"
#include "spatial/kdtree.hpp"

namespace drange::engine {

// The points of each kd-tree leaf in blocks of at most kLanes consecutive ids, cut the way
// the build orders a leaf's points (halving its range down to KdTree::kOrderLeafSize: each
// block is a subtree of that order, near points). A leaf's blocks come in groups of kLanes
// (a leaf of up to kLanes^2 points has one group), each group with the bounding boxes of its
// blocks transposed (lower k of its j-th block at k * kLanes + j, then the upper bounds; an
// empty slot's box is at +infinity), each block with its points' coordinates transposed
// likewise (+infinity past its points). The leaf scan then tests the ball against a group's
// boxes together and, in the blocks that meet the ball, the distances of the block's points
// together: straight-line loops over kLanes doubles (vector instructions). A copy of the
// coordinates, O(n d) doubles, built once per search object.
//
// From d = 4 on (kMinBlockDimension). Below, the balls are small against a leaf, the scan of a
// leaf is short already and building the blocks costs more than they save (2D 1M points,
// time_search 0.87 -> 1.02 s; 3D 200k 1.39 -> 1.47 s).
constexpr int kMinBlockDimension = 4;
class LeafBlocks {
 public:
  static constexpr int kLanes = spatial::KdTree::kOrderLeafSize;

  LeafBlocks() = default;
  LeafBlocks(const PointStore& points, bool enabled) {
    if (!enabled || points.size == 0) return;
    d_ = points.dim;
    const auto& nodes = points.tree.nodes();
    first_.assign(nodes.size(), {-1, 0});
    std::vector<std::int32_t> cuts;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      if (nodes[i].right >= 0) continue;
      cuts.clear();
      cut(nodes[i].begin, nodes[i].end, cuts);
      cuts.push_back(nodes[i].end);
      const auto blocks = static_cast<std::int32_t>(cuts.size() - 1);
      const std::int32_t groups = (blocks + kLanes - 1) / kLanes;
      first_[i] = {static_cast<std::int32_t>(begin_.size() / kLanes), groups};
      for (std::int32_t slot = 0; slot < groups * kLanes; ++slot) {
        begin_.push_back(slot < blocks ? cuts[static_cast<std::size_t>(slot)] : 0);
        count_.push_back(slot < blocks ? cuts[static_cast<std::size_t>(slot) + 1] - cuts[static_cast<std::size_t>(slot)] : 0);
      }
    }
    const std::size_t slots = begin_.size();
    boxes_.assign(slots / kLanes * group_size(), kInfinity);
    lanes_.assign(slots * block_size(), kInfinity);
    for (std::size_t block = 0; block < slots; ++block) {
      double* lo = &boxes_[block / kLanes * group_size() + block % kLanes];
      double* hi = lo + static_cast<std::size_t>(d_) * kLanes;
      double* lanes = &lanes_[block * block_size()];
      for (std::int32_t j = 0; j < count_[block]; ++j) {
        const double* x = points.point(begin_[block] + j);
        for (int k = 0; k < d_; ++k) {
          const std::size_t at = static_cast<std::size_t>(k) * kLanes;
          lo[at] = j == 0 ? x[k] : std::min(lo[at], x[k]);
          hi[at] = j == 0 ? x[k] : std::max(hi[at], x[k]);
          lanes[at + static_cast<std::size_t>(j)] = x[k];
        }
      }
    }
  }
  bool enabled() const { return !begin_.empty(); }
  // A leaf's groups: the first one's index and their number.
  struct Groups {
    std::int32_t first, count;
  };
  Groups groups(std::int32_t leaf) const { return first_[static_cast<std::size_t>(leaf)]; }
  const double* boxes(std::int32_t group) const { return &boxes_[static_cast<std::size_t>(group) * group_size()]; }
  // Block `slot` of `group`: its first point, its point count (0: an empty slot), its points.
  std::int32_t begin(std::int32_t group, int slot) const { return begin_[index(group, slot)]; }
  std::int32_t count(std::int32_t group, int slot) const { return count_[index(group, slot)]; }
  const double* lanes(std::int32_t group, int slot) const { return &lanes_[index(group, slot) * block_size()]; }

 private:
  static constexpr double kInfinity = std::numeric_limits<double>::infinity();  // empty slots, past a block's points
  static std::size_t index(std::int32_t group, int slot) { return static_cast<std::size_t>(group) * kLanes + static_cast<std::size_t>(slot); }
  std::size_t group_size() const { return 2 * static_cast<std::size_t>(d_) * kLanes; }
  std::size_t block_size() const { return static_cast<std::size_t>(d_) * kLanes; }
  static void cut(std::int32_t begin, std::int32_t end, std::vector<std::int32_t>& cuts) {
    if (end - begin <= kLanes) {
      cuts.push_back(begin);
      return;
    }
    const std::int32_t middle = begin + (end - begin) / 2;  // as KdTree's build
    cut(begin, middle, cuts);
    cut(middle, end, cuts);
  }
  int d_ = 0;
  std::vector<Groups> first_;         // per tree node (leaves only)
  std::vector<std::int32_t> begin_;   // per block slot
  std::vector<std::int32_t> count_;   // per block slot
  std::vector<double> boxes_;         // per group
  std::vector<double> lanes_;         // per block slot
};

}  // namespace drange::engine
