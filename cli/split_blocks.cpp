// cli/split_blocks.cpp: see split_blocks.hpp.
#include "split_blocks.hpp"

#include <algorithm>
#include <cstddef>
#include <limits>

namespace drange::cli {

Blocks::Blocks(const std::vector<double>& sample, int dim, int count) : dim_(dim) {
  const double inf = std::numeric_limits<double>::infinity();
  const Box all = Box::filled(static_cast<std::size_t>(dim), -inf, inf);
  std::vector<const double*> items;
  for (std::size_t i = 0; i + static_cast<std::size_t>(dim) <= sample.size(); i += static_cast<std::size_t>(dim))
    items.push_back(sample.data() + i);
  boxes_.assign(static_cast<std::size_t>(count), all);
  build(std::move(items), 0, count, all);
}

int Blocks::build(std::vector<const double*> items, int first, int count, Box region) {
  const int at = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  if (count == 1) {
    nodes_[static_cast<std::size_t>(at)].left = first;
    boxes_[static_cast<std::size_t>(first)] = region;
    return at;
  }
  // The widest side of the sample here (axis 0 when it is empty: the blocks are then empty too).
  int axis = 0;
  double widest = -1;
  for (int k = 0; k < dim_; ++k) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const double* p : items) {
      lo = std::min(lo, p[k]);
      hi = std::max(hi, p[k]);
    }
    if (!items.empty() && hi - lo > widest) {
      widest = hi - lo;
      axis = k;
    }
  }
  const int left_count = count / 2;
  const std::size_t cut = items.size() * static_cast<std::size_t>(left_count) / static_cast<std::size_t>(count);
  std::sort(items.begin(), items.end(), [axis](const double* a, const double* b) { return a[axis] < b[axis]; });
  const double split = cut < items.size() ? items[cut][axis] : std::numeric_limits<double>::infinity();
  std::vector<const double*> left, right;
  for (const double* p : items) (p[axis] < split ? left : right).push_back(p);
  Box left_region = region, right_region = region;
  left_region.hi[static_cast<std::size_t>(axis)] = split;
  right_region.lo[static_cast<std::size_t>(axis)] = split;
  const int l = build(std::move(left), first, left_count, left_region);
  const int r = build(std::move(right), first + left_count, count - left_count, right_region);
  Node& node = nodes_[static_cast<std::size_t>(at)];
  node.axis = axis;
  node.split = split;
  node.left = l;
  node.right = r;
  return at;
}

int Blocks::block_of(const double* p) const {
  const Node* node = &nodes_[0];
  while (node->axis >= 0) node = &nodes_[static_cast<std::size_t>(p[node->axis] < node->split ? node->left : node->right)];
  return node->left;
}

std::vector<int> Blocks::meeting(const Box& box) const {
  std::vector<int> found;
  for (std::size_t b = 0; b < boxes_.size(); ++b)
    if (boxes_[b].meets(box)) found.push_back(static_cast<int>(b));
  return found;
}

}  // namespace drange::cli
