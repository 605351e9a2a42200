// spatial/kdtree.cpp: building the kd-tree by median splits on the widest axis.
#include "spatial/kdtree.hpp"

#include <algorithm>
#include <future>
#include <numeric>
#include <system_error>

namespace drange::spatial {

namespace {
// Subtrees smaller than this are built on the thread that reaches them.
constexpr std::int32_t kParallelPoints = std::int32_t{1} << 15;
std::size_t expected_nodes(std::int32_t n, int leaf_size) { return 2 * static_cast<std::size_t>(n / leaf_size + 1); }
}  // namespace

void KdTree::build(const double* coords, std::int32_t n, int dim, int leaf_size, int threads) {
  dim_ = dim;
  leaf_size = std::max(1, leaf_size);
  order_.resize(static_cast<std::size_t>(n));
  std::iota(order_.begin(), order_.end(), 0);
  nodes_.clear();
  boxes_.clear();
  nodes_.reserve(expected_nodes(n, leaf_size));
  boxes_.reserve(expected_nodes(n, leaf_size) * 2 * static_cast<std::size_t>(dim));
  int forks = 0;  // ceil(log2(threads)) levels of parallel halves
  while (forks < 16 && (1 << forks) < threads) ++forks;
  if (n > 0) build_node(coords, 0, n, leaf_size, forks, nodes_, boxes_);
}

std::int32_t KdTree::build_node(const double* coords, std::int32_t begin, std::int32_t end, int leaf_size, int forks,
                                std::vector<Node>& nodes, std::vector<double>& boxes) {
  const std::int32_t index = static_cast<std::int32_t>(nodes.size());
  nodes.push_back(Node{begin, end, -1, 0, 0.0});
  const std::size_t box = boxes.size();
  boxes.resize(box + 2 * static_cast<std::size_t>(dim_));
  double* lo = &boxes[box];
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
  if (end - begin <= leaf_size || hi[axis] == lo[axis]) return index;

  const std::int32_t middle = begin + (end - begin) / 2;
  auto first = order_.begin() + begin;
  std::nth_element(first, order_.begin() + middle, order_.begin() + end, [&](std::int32_t a, std::int32_t b) {
    return coords[static_cast<std::size_t>(a) * dim_ + axis] < coords[static_cast<std::size_t>(b) * dim_ + axis];
  });
  const double split = point(middle)[axis];
  // Left: [begin, middle), all <= split after nth_element; the boxes are tight, so a
  // coordinate equal to split on both sides is harmless.
  nodes[static_cast<std::size_t>(index)].split_axis = axis;
  nodes[static_cast<std::size_t>(index)].split_value = split;
  if (forks == 0 || end - begin < kParallelPoints) {
    build_node(coords, begin, middle, leaf_size, 0, nodes, boxes);
    const std::int32_t right = build_node(coords, middle, end, leaf_size, 0, nodes, boxes);
    nodes[static_cast<std::size_t>(index)].right = right;
    return index;
  }
  // The halves own disjoint ranges of order_: build them at the same time into vectors of their
  // own, then append them in preorder (left, then right, whose child indices move by its offset).
  std::vector<Node> left_nodes, right_nodes;
  std::vector<double> left_boxes, right_boxes;
  auto build_left = [&] {
    left_nodes.reserve(expected_nodes(middle - begin, leaf_size));
    left_boxes.reserve(expected_nodes(middle - begin, leaf_size) * 2 * static_cast<std::size_t>(dim_));
    build_node(coords, begin, middle, leaf_size, forks - 1, left_nodes, left_boxes);
  };
  std::future<void> left;
  try {
    left = std::async(std::launch::async, build_left);
  } catch (const std::system_error&) {
    build_left();  // no thread to spare: one after the other
  }
  right_nodes.reserve(expected_nodes(end - middle, leaf_size));
  right_boxes.reserve(expected_nodes(end - middle, leaf_size) * 2 * static_cast<std::size_t>(dim_));
  build_node(coords, middle, end, leaf_size, forks - 1, right_nodes, right_boxes);
  if (left.valid()) left.get();  // rethrows the left half's exception
  for (const std::vector<Node>* part : {&left_nodes, &right_nodes}) {
    const auto offset = static_cast<std::int32_t>(nodes.size());
    if (part == &right_nodes) nodes[static_cast<std::size_t>(index)].right = offset;
    for (Node node : *part) {
      if (node.right >= 0) node.right += offset;
      nodes.push_back(node);
    }
  }
  boxes.insert(boxes.end(), left_boxes.begin(), left_boxes.end());
  boxes.insert(boxes.end(), right_boxes.begin(), right_boxes.end());
  return index;
}

std::size_t KdTree::memory_bytes() const {
  return order_.capacity() * sizeof(std::int32_t) + nodes_.capacity() * sizeof(Node) + boxes_.capacity() * sizeof(double);
}

}  // namespace drange::spatial
