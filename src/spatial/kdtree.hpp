// spatial/kdtree.hpp: the kd-tree of the paper's section 2.4 (after Bentley; de Berg et al.,
// "Computational Geometry", 5.2), built for the shrinking search of the D-Range algorithm.
//
// Layout: the tree owns no coordinates. `build` returns the order in which the points are
// stored; the caller renumbers its points in that order, so every node covers a contiguous
// range [begin, end) of point ids and a leaf's points are contiguous in memory. Nodes are in
// preorder (the left child of node i is i + 1), each with the tight bounding box of its points.
// Leaves hold up to `leaf_size` points ("bucketed"), which keeps the tree shallow and the
// innermost loop a linear scan.
//
// `search` walks the tree under a query box that the visitor may shrink at any moment (the
// paper's narrowing search region); the visitor also decides which child to enter first
// (2.4.2) and may prune a node for reasons of its own (2.4.1).
#pragma once

#include <cstdint>
#include <vector>

namespace drange::spatial {

class KdTree {
 public:
  struct Node {
    std::int32_t begin, end;  // point ids [begin, end)
    std::int32_t right;       // index of the right child; -1 for a leaf (left child is this + 1)
    std::int32_t split_axis;
    double split_value;       // points of the left child have coordinate <= split_value
  };

  // Builds the tree over `n` points of dimension `dim` (row-major `coords`). Returns nothing;
  // order() then gives, for each tree position, the index of the point in `coords`. With
  // threads > 1 the two subtrees of the top nodes are built at the same time; the tree is the
  // same for every thread count.
  void build(const double* coords, std::int32_t n, int dim, int leaf_size = 8, int threads = 1);

  const std::vector<std::int32_t>& order() const { return order_; }
  const std::vector<Node>& nodes() const { return nodes_; }
  const double* lower(std::int32_t node) const { return &boxes_[static_cast<std::size_t>(node) * 2 * dim_]; }
  const double* upper(std::int32_t node) const { return lower(node) + dim_; }
  int dim() const { return dim_; }
  std::size_t memory_bytes() const;

  // Visits the nodes whose box meets the query box, depth first. Visitor interface:
  //   const double* query_lower(), query_upper()   the current query box (may shrink)
  //   bool prune(std::int32_t node)                 true: skip the node and its subtree
  //   bool right_first(const Node& node)            which child to enter first
  //   void leaf(std::int32_t begin, std::int32_t end)  scan the points of a leaf
  // Returns the number of nodes entered (the search's recursive "calls").
  template <class Visitor>
  std::uint64_t search(Visitor& visitor) const;

 private:
  // Appends the subtree over [begin, end) to `nodes` and `boxes` (right-child indices relative
  // to those vectors); splits `forks` levels deep into parallel halves.
  std::int32_t build_node(const double* coords, std::int32_t begin, std::int32_t end, int leaf_size, int forks,
                          std::vector<Node>& nodes, std::vector<double>& boxes);
  bool meets(std::int32_t node, const double* lo, const double* hi) const {
    const double* a = lower(node);
    const double* b = upper(node);
    for (int k = 0; k < dim_; ++k)
      if (b[k] < lo[k] || a[k] > hi[k]) return false;
    return true;
  }

  int dim_ = 0;
  std::vector<std::int32_t> order_;
  std::vector<Node> nodes_;
  std::vector<double> boxes_;
};

template <class Visitor>
std::uint64_t KdTree::search(Visitor& visitor) const {
  if (nodes_.empty()) return 0;
  std::uint64_t calls = 0;
  // An explicit stack: depth is O(log n) for a median-split tree.
  std::int32_t stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const std::int32_t i = stack[--top];
    if (!meets(i, visitor.query_lower(), visitor.query_upper())) continue;
    ++calls;
    if (visitor.prune(i)) continue;
    const Node& node = nodes_[static_cast<std::size_t>(i)];
    if (node.right < 0) {
      visitor.leaf(node.begin, node.end);
      continue;
    }
    // Push the child to visit second first.
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

}  // namespace drange::spatial
