// delaunay/leaf_blocks.hpp: the points of every kd-tree leaf copied in blocks of 8, coordinates
// and bounding boxes transposed, so that the search (search/search_kernel.hpp) tests eight block boxes,
// then the eight points of a block, at once with vector instructions. The layout only: the
// arithmetic on the lanes belongs to the search's kernel, which owns the ball.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "spatial/kdtree.hpp"
#include "util/uninitialized_vector.hpp"

namespace drange::engine {

class Team;

// The points of each kd-tree leaf in blocks of at most kLanes consecutive ids, cut the way
// the build orders a leaf's points (halving its range down to KdTree::kOrderLeafSize: each
// block is a subtree of that order, near points). A leaf's blocks come in groups of kLanes
// (a leaf of up to kLanes^2 points has one group), each group with the bounding boxes of its
// blocks transposed (lower k of its j-th block at k * kLanes + j, then the upper bounds; the
// empty slots, past the leaf's last block in its last group, have their box at +infinity),
// each block with its points' coordinates transposed likewise (+infinity past its points).
// The leaf scan then tests the ball against a group's boxes together and, in the blocks that
// meet the ball, the distances of the block's points together: straight-line loops over kLanes
// doubles (vector instructions) that give bit masks. A copy of the coordinates, O(n d)
// doubles, built once (prepare_points) and shared by every search thread.
//
// In every dimension, because the lane tests give masks (search/search_kernel.hpp, scan_blocks): with a
// branch per lane, the blocks lose in 2D and 3D, where the balls are small against a leaf.
class LeafBlocks {
 public:
  static constexpr int kLanes = spatial::KdTree::kOrderLeafSize;

  LeafBlocks() = default;
  // The blocks of every leaf of `tree`, over its points' coordinates `coords` (tree order,
  // `dim` per point); the blocks are filled on the team's threads.
  LeafBlocks(const spatial::KdTree& tree, const double* coords, int dim, Team& team);

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
  static std::size_t index(std::int32_t group, int slot) { return static_cast<std::size_t>(group) * kLanes + static_cast<std::size_t>(slot); }
  std::size_t group_size() const { return 2 * static_cast<std::size_t>(d_) * kLanes; }
  std::size_t block_size() const { return static_cast<std::size_t>(d_) * kLanes; }
  // Block `slot`'s coordinates and its part of its group's boxes.
  void fill(std::size_t slot, const double* coords);

  int d_ = 0;
  std::vector<Groups> first_;                  // per tree node (leaves only)
  std::vector<std::int32_t> begin_;            // per block slot
  std::vector<std::int32_t> count_;            // per block slot
  util::UninitializedVector<double> boxes_;    // per group
  util::UninitializedVector<double> lanes_;    // per block slot
};

}  // namespace drange::engine
