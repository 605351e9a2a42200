// spatial/kdtree.cpp: building the kd-tree by median splits on the widest axis.
#include "spatial/kdtree.hpp"

#include <algorithm>
#include <future>
#include <system_error>
#include <numeric>
#include <vector>

#include "util/select_nth.hpp"
#include "util/uninitialized_vector.hpp"

namespace drange::spatial {

void KdTree::build(const double* coords, std::int32_t n, int dim, int leaf_size) {
  build_any(coords, n, dim, leaf_size, nullptr);
}

void KdTree::build_and_reorder(double* coords, std::int32_t n, int dim, int leaf_size, int threads) {
  build_any(coords, n, dim, leaf_size, coords, threads);
}

void KdTree::build_any(const double* coords, std::int32_t n, int dim, int leaf_size, double* reordered, int threads) {
  dim_ = dim;
  order_.resize(static_cast<std::size_t>(n));
  nodes_.clear();
  boxes_.clear();
  parent_.clear();
  leaf_of_.resize(static_cast<std::size_t>(n));
  leaf_out_ = leaf_of_.data();
  const std::size_t expected_nodes = 2 * static_cast<std::size_t>(n / std::max(1, leaf_size) + 1);
  nodes_.reserve(expected_nodes);
  boxes_.reserve(expected_nodes * 2 * static_cast<std::size_t>(dim));
  parent_.reserve(expected_nodes);
  if (n == 0) return;
  switch (dim) {
    case 2: build_fixed<2>(coords, n, std::max(1, leaf_size), reordered, threads); return;
    case 3: build_fixed<3>(coords, n, std::max(1, leaf_size), reordered, threads); return;
    case 4: build_fixed<4>(coords, n, std::max(1, leaf_size), reordered, threads); return;
    default: break;
  }
  std::iota(order_.begin(), order_.end(), 0);
  scratch_box_.assign(2 * static_cast<std::size_t>(dim), 0.0);
  build_node(coords, 0, n, std::max(1, leaf_size), -1, true);
  if (reordered) {
    const auto d = static_cast<std::size_t>(dim);
    const std::vector<double> copy(coords, coords + static_cast<std::size_t>(n) * d);
    for (std::size_t i = 0; i < order_.size(); ++i)
      std::copy_n(&copy[static_cast<std::size_t>(order_[i]) * d], d, reordered + i * d);
  }
}

std::int32_t KdTree::add_node(std::int32_t begin, std::int32_t end, std::int32_t parent) {
  const std::int32_t index = static_cast<std::int32_t>(nodes_.size());
  nodes_.push_back(Node{begin, end, -1, 0, 0.0});
  parent_.push_back(parent);
  boxes_.resize(boxes_.size() + 2 * static_cast<std::size_t>(dim_));
  return index;
}

namespace {
// Below this many points a thread's start costs more than half the work saves.
constexpr std::int32_t kMinParallel = std::int32_t{1} << 15;

// Runs `first` on the calling thread and `second` on a thread of its own, when one can be
// started (else here too); rethrows second's exception.
template <class First, class Second>
void run_both(const First& first, const Second& second) {
  std::future<void> done;
  try {
    done = std::async(std::launch::async, second);
  } catch (const std::system_error&) {
    second();  // no thread to be had
  }
  first();
  if (done.valid()) done.get();
}

// body(begin, end) over up to 2^depth consecutive ranges of [begin, end), each on a thread.
template <class Body>
void for_halves(std::int32_t begin, std::int32_t end, int depth, const Body& body) {
  if (depth == 0 || end - begin < kMinParallel) {
    body(begin, end);
    return;
  }
  const std::int32_t middle = begin + (end - begin) / 2;
  run_both([&] { for_halves(begin, middle, depth - 1, body); }, [&] { for_halves(middle, end, depth - 1, body); });
}

template <int D>
struct Item {
  double x[D];
  std::int32_t id;
};

// The build's order on an axis: the coordinate, then the index (a strict total order, so the
// median split, and so the tree, is the same whatever the selection algorithm), evaluated
// without branches (util/select_nth.hpp).
inline bool comes_before(double x, std::int32_t i, double y, std::int32_t j) { return (x < y) | ((x == y) & (i < j)); }

template <class Item>
void split_at(Item* first, Item* middle, Item* last, int axis) {
  util::select_nth(first, middle, last,
                   [axis](const Item& a, const Item& b) { return comes_before(a.x[axis], a.id, b.x[axis], b.id); });
}

// A range that is split no further is put in index order: the point order then does not depend
// on how the selection left it.
template <class Item>
void order_by_index(Item* first, Item* last) {
  std::sort(first, last, [](const Item& a, const Item& b) { return a.id < b.id; });
}

// The tight box [lo, hi] of items[begin, end), and its widest axis.
template <class Item>
int box_of(const Item* items, std::int32_t begin, std::int32_t end, double* lo, double* hi) {
  constexpr int kDim = static_cast<int>(sizeof(Item::x) / sizeof(double));
  // Four running boxes over interleaved items, merged at the end: each min and max waits for
  // the previous one of its own box only, so four run at once (min and max are exact, so the
  // box is the same).
  constexpr int kWays = 4;
  double l[kWays][kDim], h[kWays][kDim];
  for (int w = 0; w < kWays; ++w)
    for (int k = 0; k < kDim; ++k) l[w][k] = h[w][k] = items[begin].x[k];
  std::int32_t i = begin + 1;
  for (; i + kWays <= end; i += kWays)
    for (int w = 0; w < kWays; ++w)
      for (int k = 0; k < kDim; ++k) {
        l[w][k] = std::min(l[w][k], items[i + w].x[k]);
        h[w][k] = std::max(h[w][k], items[i + w].x[k]);
      }
  for (; i < end; ++i)
    for (int k = 0; k < kDim; ++k) {
      l[0][k] = std::min(l[0][k], items[i].x[k]);
      h[0][k] = std::max(h[0][k], items[i].x[k]);
    }
  for (int k = 0; k < kDim; ++k) {
    lo[k] = l[0][k];
    hi[k] = h[0][k];
    for (int w = 1; w < kWays; ++w) {
      lo[k] = std::min(lo[k], l[w][k]);
      hi[k] = std::max(hi[k], h[w][k]);
    }
  }
  int axis = 0;
  for (int k = 1; k < kDim; ++k)
    if (hi[k] - lo[k] > hi[axis] - lo[axis]) axis = k;
  return axis;
}
}  // namespace

template <int D>
void KdTree::build_fixed(const double* coords, std::int32_t n, int leaf_size, double* reordered, int threads) {
  int depth = 0;  // 2^depth >= threads
  while ((1 << depth) < threads && depth < 6) ++depth;
  // The copies in and out run on the build's threads too: they are a fair share of the build,
  // most of it the first touch of fresh pages.
  util::UninitializedVector<Item<D>> items(static_cast<std::size_t>(n));
  for_halves(0, n, depth, [&](std::int32_t begin, std::int32_t end) {
    for (std::int32_t i = begin; i < end; ++i) {
      Item<D>& item = items[static_cast<std::size_t>(i)];
      std::copy_n(coords + static_cast<std::size_t>(i) * D, D, item.x);
      item.id = i;
    }
  });
  build_items_parallel(items.data(), 0, n, leaf_size, depth);
  for_halves(0, n, depth, [&](std::int32_t begin, std::int32_t end) {
    for (std::int32_t i = begin; i < end; ++i) {
      const Item<D>& item = items[static_cast<std::size_t>(i)];
      order_[static_cast<std::size_t>(i)] = item.id;
      if (reordered) std::copy_n(item.x, D, reordered + static_cast<std::size_t>(i) * D);
    }
  });
}

// As build_node, step for step (the same total order: the tree is the same).
template <class Item>
std::int32_t KdTree::build_items(Item* items, std::int32_t begin, std::int32_t end, int leaf_size, std::int32_t parent,
                                 bool emit) {
  constexpr int kDim = static_cast<int>(sizeof(Item::x) / sizeof(double));
  const std::int32_t index = emit ? add_node(begin, end, parent) : -1;
  double lo[kDim], hi[kDim];
  const int axis = box_of(items, begin, end, lo, hi);
  const bool leaf = end - begin <= leaf_size || hi[axis] == lo[axis];
  if (emit) {
    std::copy_n(lo, kDim, &boxes_[static_cast<std::size_t>(index) * 2 * kDim]);
    std::copy_n(hi, kDim, &boxes_[static_cast<std::size_t>(index) * 2 * kDim + kDim]);
    if (leaf) std::fill(leaf_out_ + begin, leaf_out_ + end, index);
  }
  if (end - begin <= std::min(leaf_size, kOrderLeafSize) || hi[axis] == lo[axis]) {
    order_by_index(items + begin, items + end);
    return index;
  }
  const std::int32_t middle = begin + (end - begin) / 2;
  split_at(items + begin, items + middle, items + end, axis);
  const bool children = emit && !leaf;  // else only the order is refined (see kOrderLeafSize)
  if (children) {
    nodes_[static_cast<std::size_t>(index)].split_axis = axis;
    nodes_[static_cast<std::size_t>(index)].split_value = items[middle].x[axis];
  }
  build_items(items, begin, middle, leaf_size, index, children);
  const std::int32_t right = build_items(items, middle, end, leaf_size, index, children);
  if (children) nodes_[static_cast<std::size_t>(index)].right = right;
  return index;
}

template <class Item>
void KdTree::build_items_parallel(Item* items, std::int32_t begin, std::int32_t end, int leaf_size, int depth) {
  constexpr int kDim = static_cast<int>(sizeof(Item::x) / sizeof(double));
  if (depth == 0 || end - begin < kMinParallel) {
    build_items(items, begin, end, leaf_size, -1, true);
    return;
  }
  // The root, as build_items makes it.
  double lo[kDim], hi[kDim];
  const int axis = box_of(items, begin, end, lo, hi);
  if (end - begin <= leaf_size || hi[axis] == lo[axis]) {  // a leaf (all points equal): no split to share
    build_items(items, begin, end, leaf_size, -1, true);
    return;
  }
  const std::int32_t index = add_node(begin, end, -1);
  std::copy_n(lo, kDim, &boxes_[static_cast<std::size_t>(index) * 2 * kDim]);
  std::copy_n(hi, kDim, &boxes_[static_cast<std::size_t>(index) * 2 * kDim + kDim]);
  const std::int32_t middle = begin + (end - begin) / 2;
  split_at(items + begin, items + middle, items + end, axis);
  nodes_[static_cast<std::size_t>(index)].split_axis = axis;
  nodes_[static_cast<std::size_t>(index)].split_value = items[middle].x[axis];
  KdTree left, right;
  for (KdTree* part : {&left, &right}) {
    part->dim_ = dim_;
    part->leaf_out_ = leaf_out_;
  }
  run_both([&] { left.build_items_parallel(items, begin, middle, leaf_size, depth - 1); },
           [&] { right.build_items_parallel(items, middle, end, leaf_size, depth - 1); });
  splice(left, index, begin, middle);
  nodes_[static_cast<std::size_t>(index)].right = splice(right, index, middle, end);
}

std::int32_t KdTree::splice(const KdTree& part, std::int32_t parent, std::int32_t begin, std::int32_t end) {
  const auto offset = static_cast<std::int32_t>(nodes_.size());
  for (Node node : part.nodes_) {
    if (node.right >= 0) node.right += offset;
    nodes_.push_back(node);
  }
  for (const std::int32_t up : part.parent_) parent_.push_back(up < 0 ? parent : up + offset);
  boxes_.insert(boxes_.end(), part.boxes_.begin(), part.boxes_.end());
  for (std::int32_t i = begin; i < end; ++i) leaf_out_[i] += offset;
  return offset;
}

std::int32_t KdTree::build_node(const double* coords, std::int32_t begin, std::int32_t end, int leaf_size,
                                std::int32_t parent, bool emit) {
  const std::int32_t index = emit ? add_node(begin, end, parent) : -1;
  // The box is not used once the children are built (they may reallocate boxes_).
  double* lo = emit ? &boxes_[static_cast<std::size_t>(index) * 2 * static_cast<std::size_t>(dim_)] : scratch_box_.data();
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
  const bool leaf = end - begin <= leaf_size || hi[axis] == lo[axis];
  if (emit && leaf) std::fill(leaf_out_ + begin, leaf_out_ + end, index);
  std::int32_t* first = order_.data() + begin;
  if (end - begin <= std::min(leaf_size, kOrderLeafSize) || hi[axis] == lo[axis]) {
    std::sort(first, order_.data() + end);  // by index, as order_by_index
    return index;
  }

  const std::int32_t middle = begin + (end - begin) / 2;
  util::select_nth(first, order_.data() + middle, order_.data() + end, [&](std::int32_t a, std::int32_t b) {
    return comes_before(coords[static_cast<std::size_t>(a) * dim_ + axis], a, coords[static_cast<std::size_t>(b) * dim_ + axis], b);
  });
  const double split = point(middle)[axis];
  // Left: [begin, middle), all <= split after the selection; the boxes are tight, so a
  // coordinate equal to split on both sides is harmless.
  const bool children = emit && !leaf;  // else only the order is refined (see kOrderLeafSize)
  if (children) {
    nodes_[static_cast<std::size_t>(index)].split_axis = axis;
    nodes_[static_cast<std::size_t>(index)].split_value = split;
  }
  build_node(coords, begin, middle, leaf_size, index, children);
  const std::int32_t right = build_node(coords, middle, end, leaf_size, index, children);
  if (children) nodes_[static_cast<std::size_t>(index)].right = right;
  return index;
}

std::size_t KdTree::memory_bytes() const {
  return (order_.capacity() + parent_.capacity() + leaf_of_.capacity()) * sizeof(std::int32_t) +
         nodes_.capacity() * sizeof(Node) + boxes_.capacity() * sizeof(double);
}

}  // namespace drange::spatial
