// spatial/kdtree.cpp: building the kd-tree by median splits on the widest axis.
#include "spatial/kdtree.hpp"

#include <algorithm>
#include <numeric>

namespace drange::spatial {

void KdTree::build(const double* coords, std::int32_t n, int dim, int leaf_size) {
  dim_ = dim;
  order_.resize(static_cast<std::size_t>(n));
  std::iota(order_.begin(), order_.end(), 0);
  nodes_.clear();
  boxes_.clear();
  parent_.clear();
  leaf_of_.assign(static_cast<std::size_t>(n), -1);
  const std::size_t expected_nodes = 2 * static_cast<std::size_t>(n / std::max(1, leaf_size) + 1);
  nodes_.reserve(expected_nodes);
  boxes_.reserve(expected_nodes * 2 * static_cast<std::size_t>(dim));
  parent_.reserve(expected_nodes);
  if (n > 0) build_node(coords, 0, n, std::max(1, leaf_size), -1);
}

std::int32_t KdTree::build_node(const double* coords, std::int32_t begin, std::int32_t end, int leaf_size,
                                std::int32_t parent) {
  const std::int32_t index = static_cast<std::int32_t>(nodes_.size());
  nodes_.push_back(Node{begin, end, -1, 0, 0.0});
  parent_.push_back(parent);
  const std::size_t box = boxes_.size();
  boxes_.resize(box + 2 * static_cast<std::size_t>(dim_));
  double* lo = &boxes_[box];
  double* hi = lo + dim_;
  auto point = [&](std::int32_t i) { return coords + static_cast<std::size_t>(order_[static_cast<std::size_t>(i)]) * dim_; };
  for (int k = 0; k < dim_; ++k) lo[k] = hi[k] = point(begin)[k];
  for (std::int32_t i = begin + 1; i < end; ++i)
    for (int k = 0; k < dim_; ++k) {
      lo[k] = std::min(lo[k], point(i)[k]);
      hi[k] = std::max(hi[k], point(i)[k]);
    }
  int axis = 0;
  for (int k = 1; k < dim_; ++k)
    if (hi[k] - lo[k] > hi[axis] - lo[axis]) axis = k;
  if (end - begin <= leaf_size || hi[axis] == lo[axis]) {
    std::fill(leaf_of_.begin() + begin, leaf_of_.begin() + end, index);
    return index;
  }

  const std::int32_t middle = begin + (end - begin) / 2;
  auto first = order_.begin() + begin;
  std::nth_element(first, order_.begin() + middle, order_.begin() + end, [&](std::int32_t a, std::int32_t b) {
    return coords[static_cast<std::size_t>(a) * dim_ + axis] < coords[static_cast<std::size_t>(b) * dim_ + axis];
  });
  const double split = point(middle)[axis];
  // Left: [begin, middle), all <= split after nth_element; the boxes are tight, so a
  // coordinate equal to split on both sides is harmless.
  nodes_[static_cast<std::size_t>(index)].split_axis = axis;
  nodes_[static_cast<std::size_t>(index)].split_value = split;
  build_node(coords, begin, middle, leaf_size, index);
  const std::int32_t right = build_node(coords, middle, end, leaf_size, index);
  nodes_[static_cast<std::size_t>(index)].right = right;
  return index;
}

std::size_t KdTree::memory_bytes() const {
  return (order_.capacity() + parent_.capacity() + leaf_of_.capacity()) * sizeof(std::int32_t) +
         nodes_.capacity() * sizeof(Node) + boxes_.capacity() * sizeof(double);
}

}  // namespace drange::spatial
