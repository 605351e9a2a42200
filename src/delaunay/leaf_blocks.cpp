// delaunay/leaf_blocks.cpp: cutting the leaves into blocks, and filling the blocks.
#include "delaunay/leaf_blocks.hpp"

#include <algorithm>
#include <limits>

#include "delaunay/team.hpp"
#include "util/for_ranges.hpp"

namespace drange::engine {

namespace {
constexpr double kInfinity = std::numeric_limits<double>::infinity();  // empty slots, past a block's points

// The cuts of the points [begin, end) into blocks, as the kd-tree build halves a leaf's range.
void cut(std::int32_t begin, std::int32_t end, std::vector<std::int32_t>& cuts) {
  if (end - begin <= LeafBlocks::kLanes) {
    cuts.push_back(begin);
    return;
  }
  const std::int32_t middle = begin + (end - begin) / 2;  // as KdTree's build
  cut(begin, middle, cuts);
  cut(middle, end, cuts);
}
}  // namespace

LeafBlocks::LeafBlocks(const spatial::KdTree& tree, const double* coords, int dim, Team& team) : d_(dim) {
  const auto& nodes = tree.nodes();
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
      const bool used = slot < blocks;
      begin_.push_back(used ? cuts[static_cast<std::size_t>(slot)] : 0);
      count_.push_back(used ? cuts[static_cast<std::size_t>(slot) + 1] - cuts[static_cast<std::size_t>(slot)] : 0);
    }
  }
  // Every slot writes all of its lanes and its part of its group's boxes (infinity where it has
  // no point), so the arrays need no serial initialisation: the threads first touch them.
  const std::size_t slots = begin_.size();
  boxes_.resize(slots / kLanes * group_size());
  lanes_.resize(slots * block_size());
  util::for_ranges(slots, team, [&](std::size_t, std::size_t from, std::size_t to) {
    for (std::size_t slot = from; slot < to; ++slot) fill(slot, coords);
  }, std::size_t{1} << 12);
}

void LeafBlocks::fill(std::size_t slot, const double* coords) {
  double* lo = &boxes_[slot / kLanes * group_size() + slot % kLanes];
  double* hi = lo + static_cast<std::size_t>(d_) * kLanes;
  double* lanes = &lanes_[slot * block_size()];
  const std::int32_t count = count_[slot];
  for (int k = 0; k < d_; ++k) {
    const std::size_t at = static_cast<std::size_t>(k) * kLanes;
    double low = kInfinity, high = kInfinity;
    for (std::int32_t j = 0; j < kLanes; ++j) {
      const double x = j < count ? coords[static_cast<std::size_t>(begin_[slot] + j) * static_cast<std::size_t>(d_) + static_cast<std::size_t>(k)] : kInfinity;
      lanes[at + static_cast<std::size_t>(j)] = x;
      if (j >= count) continue;
      low = j == 0 ? x : std::min(low, x);
      high = j == 0 ? x : std::max(high, x);
    }
    lo[at] = low;
    hi[at] = high;
  }
}
}  // namespace drange::engine
