// delaunay/incremental/insertion_order.cpp: the rounds of the biased randomized insertion order.
#include "delaunay/incremental/insertion_order.hpp"

#include <array>

namespace drange::engine {
namespace {

// The last rounds are the large ones; beyond this many, a round would hold a handful of points.
constexpr int kRounds = 24;

// splitmix64's finaliser: a fixed bijection of 64-bit words whose low bits are independent
// enough to draw rounds from.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// Round 0 is the first inserted; a point's round is kRounds - 1 minus its hash's trailing
// zeros, so that half the points are in the last round.
int round_of(std::int64_t key) {
  const std::uint64_t h = mix(static_cast<std::uint64_t>(key));
  int zeros = 0;
  while (zeros < kRounds - 1 && ((h >> zeros) & 1u) == 0) ++zeros;
  return kRounds - 1 - zeros;
}

// The kd-tree's leaves in a continuous order: at each node the children are visited in the
// direction that `reversed` holds for its split axis, and the second child with every other
// axis reversed, so that it starts next to where the first ended (in 2D, Hilbert's U at each
// level). Consecutive leaves are then neighbours in space, which the left-first order of the
// ids is not at every level.
void leaves_in_snake_order(const spatial::KdTree& tree, std::int32_t node, std::uint32_t reversed,
                           std::vector<std::int32_t>& leaves) {
  const spatial::KdTree::Node& n = tree.nodes()[static_cast<std::size_t>(node)];
  if (n.right < 0) {
    leaves.push_back(node);
    return;
  }
  const std::uint32_t axis = std::uint32_t{1} << (n.split_axis & 31);
  const bool right_first = (reversed & axis) != 0;
  leaves_in_snake_order(tree, right_first ? n.right : node + 1, reversed, leaves);
  leaves_in_snake_order(tree, right_first ? node + 1 : n.right, reversed ^ ~axis, leaves);
}

// Positions [0, n) of `tree`'s points: by round (round_of(key(position))), then along the
// leaves' snake path; within a leaf, by position.
template <class Key>
std::vector<std::int32_t> order_by_rounds(const spatial::KdTree& tree, std::int32_t n, const Key& key) {
  // A counting sort by round.
  std::array<std::size_t, kRounds + 1> start{};
  std::vector<std::uint8_t> round(static_cast<std::size_t>(n));
  for (std::int32_t id = 0; id < n; ++id) {
    const int r = round_of(key(id));
    round[static_cast<std::size_t>(id)] = static_cast<std::uint8_t>(r);
    ++start[static_cast<std::size_t>(r) + 1];
  }
  for (int r = 0; r < kRounds; ++r) start[static_cast<std::size_t>(r) + 1] += start[static_cast<std::size_t>(r)];
  std::vector<std::int32_t> order(static_cast<std::size_t>(n));
  std::vector<std::int32_t> leaves;
  if (!tree.nodes().empty()) leaves_in_snake_order(tree, 0, 0, leaves);
  for (const std::int32_t leaf : leaves) {
    const spatial::KdTree::Node& node = tree.nodes()[static_cast<std::size_t>(leaf)];
    for (std::int32_t id = node.begin; id < node.end; ++id) order[start[round[static_cast<std::size_t>(id)]]++] = id;
  }
  return order;
}

}  // namespace

std::vector<std::int32_t> insertion_order(const PointStore& points) {
  // The store's ids are tree positions already.
  return order_by_rounds(points.tree, points.size, [&](std::int32_t id) { return points.rank(id); });
}

std::vector<std::int32_t> insertion_order(const double* coords, const std::int64_t* keys, std::int32_t n, int dim) {
  spatial::KdTree tree;
  tree.build(coords, n, dim);
  const auto& row = tree.order();  // tree position -> row
  std::vector<std::int32_t> order = order_by_rounds(tree, n, [&](std::int32_t position) { return keys[row[static_cast<std::size_t>(position)]]; });
  for (std::int32_t& position : order) position = row[static_cast<std::size_t>(position)];
  return order;
}

}  // namespace drange::engine
