// spatial/kdtree.hpp: the kd-tree of the paper's section 2.4 (after Bentley; de Berg et al.,
// "Computational Geometry", 5.2), built for the shrinking search of the D-Range algorithm.
//
// Layout: the tree owns no coordinates. `build` returns the order in which the points are
// stored; the caller renumbers its points in that order, so every node covers a contiguous
// range [begin, end) of point ids and a leaf's points are contiguous in memory. Nodes are in
// preorder (the left child of node i is i + 1), each with the tight bounding box of its points.
// Leaves hold up to `leaf_size` points ("bucketed"), which keeps the tree shallow and the
// innermost loop a linear scan. Within a leaf larger than kOrderLeafSize, the points are still
// ordered by the same median splits down to kOrderLeafSize, and by index below, so the order
// (the caller's point ids) is the same for every leaf size >= kOrderLeafSize: the engine
// numbers its points in this order, the order of its output follows the ids, and so the leaf
// size, a tuning constant, changes no output byte. (Near points also stay near in memory.)
// Medians are taken in a strict total order (the coordinate, then the index), so the tree and
// the order do not depend on the selection algorithm either.
//
// `search` walks the tree under a query box that the visitor may shrink at any moment (the
// paper's narrowing search region); the visitor also decides which child to enter first
// (2.4.2) and may prune a node for reasons of its own (2.4.1). `search_from` does the same walk
// bottom-up, from the leaf that holds a given point: it visits that leaf, then climbs, visiting
// at each level the sibling subtree, and stops climbing as soon as the query box lies strictly
// inside the box of the subtree visited so far (no point outside it can then be in the box).
#pragma once

#include <cstdint>
#include <vector>

#include "util/uninitialized_vector.hpp"

namespace drange::spatial {

class KdTree {
 public:
  // The finest granularity of the point order (see above): the leaf size drange used first.
  static constexpr int kOrderLeafSize = 8;

  struct Node {
    std::int32_t begin, end;  // point ids [begin, end)
    std::int32_t right;       // index of the right child; -1 for a leaf (left child is this + 1)
    std::int32_t split_axis;
    double split_value;       // points of the left child have coordinate <= split_value
  };

  // Builds the tree over `n` points of dimension `dim` (row-major `coords`). Returns nothing;
  // order() then gives, for each tree position, the index of the point in `coords`.
  void build(const double* coords, std::int32_t n, int dim, int leaf_size = 8);
  // The same, then rewrites `coords` in tree order (row i becomes the point order()[i]), for a
  // caller that renumbers its points (saves it a copy).
  void build_and_reorder(double* coords, std::int32_t n, int dim, int leaf_size = 8, int threads = 1);

  const util::UninitializedVector<std::int32_t>& order() const { return order_; }
  // The leaf that holds tree position `position` (a point id of the caller, after renumbering).
  std::int32_t leaf_of(std::int32_t position) const { return leaf_of_[static_cast<std::size_t>(position)]; }
  std::int32_t parent(std::int32_t node) const { return parent_[static_cast<std::size_t>(node)]; }
  const std::vector<Node>& nodes() const { return nodes_; }
  // The node's box. D > 0: the caller promises dim() == D (the address then needs no
  // multiplication by a run-time value in the walk's hot loop).
  template <int D = 0>
  const double* lower(std::int32_t node) const {
    return &boxes_[static_cast<std::size_t>(node) * 2 * static_cast<std::size_t>(dimension<D>())];
  }
  template <int D = 0>
  const double* upper(std::int32_t node) const { return lower<D>(node) + dimension<D>(); }
  int dim() const { return dim_; }
  std::size_t memory_bytes() const;

  // Visits the nodes whose box meets the query box, depth first. Visitor interface:
  //   const double* query_lower(), query_upper()   the current query box (may shrink)
  //   bool prune(std::int32_t node, bool leaf)      true: skip the node (a leaf or not) and its subtree
  //   bool right_first(const Node& node)            which child to enter first
  //   void leaf(std::int32_t node, std::int32_t begin, std::int32_t end)
  //                                                 scan the points [begin, end) of leaf `node`
  // Returns the number of nodes entered (the search's recursive "calls"). D > 0: the caller
  // promises dim() == D, and the box tests are compiled for that dimension.
  template <int D = 0, class Visitor>
  std::uint64_t search(Visitor& visitor) const {
    return nodes_.empty() ? 0 : walk<D>(visitor, 0);
  }
  // The same set of points (every point in the final query box that no prune excluded), found
  // bottom-up from the leaf `leaf` (leaf_of(id) of a point near the expected answer).
  template <int D = 0, class Visitor>
  std::uint64_t search_from(Visitor& visitor, std::int32_t leaf) const;

 private:
  // Builds the subtree of the points [begin, end) and returns its root; with emit false, only
  // orders the points (the part of a leaf below kOrderLeafSize) and returns -1.
  std::int32_t build_node(const double* coords, std::int32_t begin, std::int32_t end, int leaf_size, std::int32_t parent,
                          bool emit);
  // The same construction over points copied next to their index (fixed d: no indirection).
  template <int D>
  void build_fixed(const double* coords, std::int32_t n, int leaf_size, double* reordered, int threads);
  void build_any(const double* coords, std::int32_t n, int dim, int leaf_size, double* reordered, int threads = 1);
  // build_items over up to 2^depth threads: the root's split here, then each half built by a
  // part (a KdTree numbering its own nodes from 0) on a thread of its own, and spliced back in
  // preorder. Every selection sees the same range as in the serial build: the same tree.
  template <class Item>
  void build_items_parallel(Item* items, std::int32_t begin, std::int32_t end, int leaf_size, int depth);
  // Appends `part` (a subtree whose root's parent is `parent`) after the nodes so far; returns
  // the index of its root. Its points are [begin, end).
  std::int32_t splice(const KdTree& part, std::int32_t parent, std::int32_t begin, std::int32_t end);
  template <class Item>
  std::int32_t build_items(Item* items, std::int32_t begin, std::int32_t end, int leaf_size, std::int32_t parent,
                           bool emit);
  // Appends a node (its box to be filled by the caller); returns its index.
  std::int32_t add_node(std::int32_t begin, std::int32_t end, std::int32_t parent);
  // The top-down walk of the subtree rooted at `root`.
  template <int D, class Visitor>
  std::uint64_t walk(Visitor& visitor, std::int32_t root) const;
  template <int D>
  int dimension() const { return D > 0 ? D : dim_; }
  template <int D>
  bool meets(std::int32_t node, const double* lo, const double* hi) const {
    const double* a = lower<D>(node);
    const double* b = upper<D>(node);
    for (int k = 0; k < dimension<D>(); ++k)
      if (b[k] < lo[k] || a[k] > hi[k]) return false;
    return true;
  }
  // True when the query box lies in the open interior of the node's box. A point outside the
  // node's subtree is separated from it by the split of their lowest common ancestor: on that
  // axis it is >= the largest (or <= the smallest) coordinate of the node's box, so it is not
  // in the interior, and hence not in the query box.
  template <int D>
  bool contains_strictly(std::int32_t node, const double* lo, const double* hi) const {
    const double* a = lower<D>(node);
    const double* b = upper<D>(node);
    for (int k = 0; k < dimension<D>(); ++k)
      if (!(a[k] < lo[k] && hi[k] < b[k])) return false;
    return true;
  }
  int dim_ = 0;
  // order_ and leaf_of_ are filled by the build in full (each position lies in one leaf); left
  // uninitialised until then, their pages are first touched by the threads that fill them.
  util::UninitializedVector<std::int32_t> order_;
  std::vector<Node> nodes_;
  std::vector<double> boxes_;
  std::vector<std::int32_t> parent_;   // per node; -1 for the root
  util::UninitializedVector<std::int32_t> leaf_of_;  // per tree position
  // Where the build writes each point's leaf: leaf_of_, or the whole tree's array for a part
  // built in parallel (parts write disjoint ranges, in their own numbering, fixed by splice).
  std::int32_t* leaf_out_ = nullptr;
  std::vector<double> scratch_box_;    // build_node's box when it only orders points
};

template <int D, class Visitor>
std::uint64_t KdTree::walk(Visitor& visitor, std::int32_t root) const {
  std::uint64_t calls = 0;
  // An explicit stack: depth is O(log n) for a median-split tree.
  std::int32_t stack[128];
  int top = 0;
  stack[top++] = root;
  while (top > 0) {
    const std::int32_t i = stack[--top];
    if (!meets<D>(i, visitor.query_lower(), visitor.query_upper())) continue;
    ++calls;
    const Node& node = nodes_[static_cast<std::size_t>(i)];
    if (visitor.prune(i, node.right < 0)) continue;
    if (node.right < 0) {
      visitor.leaf(i, node.begin, node.end);
      continue;
    }
    // Push the child to visit second first. Their boxes are read when they are popped: fetch
    // them now, from 4D on (in 2D and 3D the gain was within the noise, and negative under
    // load).
    if (dimension<D>() >= 4) {
      __builtin_prefetch(lower<D>(i + 1));
      __builtin_prefetch(lower<D>(node.right));
    }
    if (visitor.right_first(node)) {
      stack[top++] = i + 1;
      stack[top++] = node.right;
    } else {
      stack[top++] = node.right;
      stack[top++] = i + 1;
    }
  }
  return calls;
}

template <int D, class Visitor>
std::uint64_t KdTree::search_from(Visitor& visitor, std::int32_t leaf) const {
  // Invariant at the top of the loop: the subtree of `node` has been walked.
  std::uint64_t calls = walk<D>(visitor, leaf);
  for (std::int32_t node = leaf; node != 0;) {
    if (contains_strictly<D>(node, visitor.query_lower(), visitor.query_upper())) break;
    const std::int32_t up = parent_[static_cast<std::size_t>(node)];
    const std::int32_t sibling = node == up + 1 ? nodes_[static_cast<std::size_t>(up)].right : up + 1;
    calls += walk<D>(visitor, sibling);
    node = up;
  }
  return calls;
}

}  // namespace drange::spatial
