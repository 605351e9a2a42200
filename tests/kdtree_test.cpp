// tests/kdtree_test.cpp: the kd-tree's two walks against brute force, on random points and on
// integer grids (many coordinates equal to a split value), with fixed and shrinking boxes.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "drange/generate.hpp"
#include "spatial/kdtree.hpp"

namespace {

using drange::spatial::KdTree;

struct Cloud {
  int dim;
  std::vector<double> coords;
  std::int32_t size() const { return static_cast<std::int32_t>(coords.size() / static_cast<std::size_t>(dim)); }
};

Cloud random_cloud(int dim, int n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Cloud c{dim, {}};
  for (int i = 0; i < n * dim; ++i) c.coords.push_back(u(rng));
  return c;
}

// The integer grid {0..side-1}^dim.
Cloud grid_cloud(int dim, int side) {
  std::size_t total = 1;
  for (int k = 0; k < dim; ++k) total *= static_cast<std::size_t>(side);
  return Cloud{dim, drange::generate_points(drange::Distribution::Grid, total, dim, 1).coords};
}

// Reports every point of the visited leaves that lies in the box, and the leaves as the walk
// handed them over (node, begin, end). With `shrink`, the box shrinks towards its centre after
// every leaf, as the search's candidate sphere does.
class BoxVisitor {
 public:
  BoxVisitor(const std::vector<double>& points, int dim, std::vector<double> lo, std::vector<double> hi, bool shrink)
      : points_(points), dim_(dim), lo_(std::move(lo)), hi_(std::move(hi)), shrink_(shrink) {}
  const double* query_lower() const { return lo_.data(); }
  const double* query_upper() const { return hi_.data(); }
  bool prune(std::int32_t, bool) const { return false; }
  bool right_first(const KdTree::Node&) const { return false; }
  void leaf(std::int32_t node, std::int32_t begin, std::int32_t end) {
    leaves.push_back({node, begin, end});
    for (std::int32_t id = begin; id < end; ++id)
      if (inside(id)) found.insert(id);
    if (!shrink_) return;
    for (int k = 0; k < dim_; ++k) {
      const double c = (lo_[static_cast<std::size_t>(k)] + hi_[static_cast<std::size_t>(k)]) / 2;
      lo_[static_cast<std::size_t>(k)] = (lo_[static_cast<std::size_t>(k)] + c) / 2;
      hi_[static_cast<std::size_t>(k)] = (hi_[static_cast<std::size_t>(k)] + c) / 2;
    }
  }
  bool inside(std::int32_t id) const {
    const double* x = &points_[static_cast<std::size_t>(id) * static_cast<std::size_t>(dim_)];
    for (int k = 0; k < dim_; ++k)
      if (x[k] < lo_[static_cast<std::size_t>(k)] || x[k] > hi_[static_cast<std::size_t>(k)]) return false;
    return true;
  }
  std::set<std::int32_t> found;
  std::vector<std::array<std::int32_t, 3>> leaves;

 private:
  const std::vector<double>& points_;
  int dim_;
  std::vector<double> lo_, hi_;
  bool shrink_;
};

// The points in tree order, as the engine renumbers them.
std::vector<double> in_tree_order(const Cloud& c, const KdTree& tree) {
  std::vector<double> out;
  for (std::int32_t i : tree.order()) out.insert(out.end(), c.coords.begin() + i * c.dim, c.coords.begin() + (i + 1) * c.dim);
  return out;
}

void check_walks(const Cloud& cloud, unsigned seed, bool integer, int leaf_size = 8) {
  KdTree tree;
  tree.build(cloud.coords.data(), cloud.size(), cloud.dim, leaf_size);
  const std::vector<double> points = in_tree_order(cloud, tree);
  // Structure: every point's leaf holds it; parent links match the preorder layout.
  for (std::int32_t id = 0; id < cloud.size(); ++id) {
    const KdTree::Node& leaf = tree.nodes()[static_cast<std::size_t>(tree.leaf_of(id))];
    ASSERT_LT(leaf.right, 0);
    ASSERT_TRUE(leaf.begin <= id && id < leaf.end);
  }
  for (std::size_t i = 0; i < tree.nodes().size(); ++i) {
    const KdTree::Node& node = tree.nodes()[i];
    if (node.right < 0) continue;
    ASSERT_EQ(tree.parent(static_cast<std::int32_t>(i) + 1), static_cast<std::int32_t>(i));
    ASSERT_EQ(tree.parent(node.right), static_cast<std::int32_t>(i));
  }
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<std::int32_t> pick(0, cloud.size() - 1);
  std::uniform_real_distribution<double> radius(0.0, 3.0);
  for (int query = 0; query < 200; ++query) {
    // Boxes centred on a point (on a grid: faces exactly on grid lines and split values).
    const std::int32_t centre = pick(rng);
    const double r = integer ? std::floor(radius(rng)) : radius(rng) / 20;
    std::vector<double> lo, hi;
    for (int k = 0; k < cloud.dim; ++k) {
      lo.push_back(points[static_cast<std::size_t>(centre) * static_cast<std::size_t>(cloud.dim) + static_cast<std::size_t>(k)] - r);
      hi.push_back(points[static_cast<std::size_t>(centre) * static_cast<std::size_t>(cloud.dim) + static_cast<std::size_t>(k)] + r);
    }
    for (bool shrink : {false, true}) {
      BoxVisitor top_down(points, cloud.dim, lo, hi, shrink), bottom_up(points, cloud.dim, lo, hi, shrink);
      tree.search(top_down);
      tree.search_from(bottom_up, tree.leaf_of(pick(rng)));
      // Each leaf came with its own node (the search's scans index their blocks by it).
      for (const BoxVisitor* v : {&top_down, &bottom_up})
        for (const auto& [node, begin, end] : v->leaves) {
          const KdTree::Node& n = tree.nodes()[static_cast<std::size_t>(node)];
          ASSERT_LT(n.right, 0) << "node " << node << " is not a leaf";
          ASSERT_EQ(n.begin, begin);
          ASSERT_EQ(n.end, end);
        }
      // Every point in the final box was in every earlier box: it must have been reported.
      for (BoxVisitor* v : {&top_down, &bottom_up})
        for (std::int32_t id = 0; id < cloud.size(); ++id)
          if (v->inside(id)) ASSERT_TRUE(v->found.count(id)) << "d=" << cloud.dim << " point " << id << " missed";
      if (!shrink) EXPECT_EQ(top_down.found, bottom_up.found);
    }
  }
}

TEST(KdTree, WalksFindEveryPointInTheBoxOnRandomPoints) {
  for (int d : {2, 3, 4, 5}) check_walks(random_cloud(d, 3000, 40u + static_cast<unsigned>(d)), 7u, false);
}

TEST(KdTree, WalksFindEveryPointInTheBoxWithLargeLeaves) {
  for (int d : {2, 3, 5}) check_walks(random_cloud(d, 3000, 50u + static_cast<unsigned>(d)), 12u, false, 48);
  check_walks(grid_cloud(3, 12), 13u, true, 48);
}

// The point order (the engine's point ids, hence its output order) is that of the leaf size 8
// tree for every leaf size from kOrderLeafSize up; only the number of nodes changes.
TEST(KdTree, TheOrderDoesNotDependOnTheLeafSize) {
  for (const Cloud& cloud : {random_cloud(2, 5000, 1u), random_cloud(3, 4000, 2u), random_cloud(5, 3000, 3u),
                             grid_cloud(2, 30), grid_cloud(3, 10), grid_cloud(5, 4)}) {
    KdTree fine;
    fine.build(cloud.coords.data(), cloud.size(), cloud.dim, KdTree::kOrderLeafSize);
    for (int leaf_size : {16, 37, 64, 200}) {
      KdTree coarse;
      coarse.build(cloud.coords.data(), cloud.size(), cloud.dim, leaf_size);
      EXPECT_EQ(coarse.order(), fine.order()) << "d=" << cloud.dim << " leaf size " << leaf_size;
      EXPECT_LT(coarse.nodes().size(), fine.nodes().size());
      for (const KdTree::Node& node : coarse.nodes())
        if (node.right < 0) EXPECT_LE(node.end - node.begin, leaf_size);
    }
  }
}

// build_and_reorder splits the build between threads (the two halves of the root, and so on
// down): the tree must be the serial one, node for node. The inputs are large enough for
// three levels of splits; the last one has thousands of copies of each of 9 points, whose
// subtrees end in leaves of equal points.
TEST(KdTree, TheTreeDoesNotDependOnTheThreadCount) {
  Cloud copies{2, {}};
  std::mt19937_64 rng(9);
  for (int i = 0; i < 150000; ++i)
    for (int k = 0; k < 2; ++k) copies.coords.push_back(static_cast<double>(rng() % 3));
  for (const Cloud& cloud : {random_cloud(2, 300000, 4u), random_cloud(3, 200000, 5u), random_cloud(4, 150000, 6u),
                             grid_cloud(2, 400), copies}) {
    for (int leaf_size : {8, 32, 64}) {
      std::vector<double> serial_coords = cloud.coords;
      KdTree serial;
      serial.build_and_reorder(serial_coords.data(), cloud.size(), cloud.dim, leaf_size, 1);
      for (int threads : {2, 3, 4, 8}) {
        SCOPED_TRACE("d=" + std::to_string(cloud.dim) + " n=" + std::to_string(cloud.size()) + " leaf size " +
                     std::to_string(leaf_size) + " threads " + std::to_string(threads));
        std::vector<double> coords = cloud.coords;
        KdTree tree;
        tree.build_and_reorder(coords.data(), cloud.size(), cloud.dim, leaf_size, threads);
        EXPECT_EQ(coords, serial_coords);
        EXPECT_EQ(tree.order(), serial.order());
        ASSERT_EQ(tree.nodes().size(), serial.nodes().size());
        for (std::int32_t i = 0; i < static_cast<std::int32_t>(tree.nodes().size()); ++i) {
          const KdTree::Node& a = tree.nodes()[static_cast<std::size_t>(i)];
          const KdTree::Node& b = serial.nodes()[static_cast<std::size_t>(i)];
          ASSERT_TRUE(a.begin == b.begin && a.end == b.end && a.right == b.right && a.split_axis == b.split_axis &&
                      a.split_value == b.split_value)
              << "node " << i;
          ASSERT_EQ(tree.parent(i), serial.parent(i)) << "node " << i;
          for (int k = 0; k < cloud.dim; ++k) {
            ASSERT_EQ(tree.lower(i)[k], serial.lower(i)[k]) << "node " << i;
            ASSERT_EQ(tree.upper(i)[k], serial.upper(i)[k]) << "node " << i;
          }
        }
        for (std::int32_t p = 0; p < cloud.size(); ++p) ASSERT_EQ(tree.leaf_of(p), serial.leaf_of(p)) << "point " << p;
      }
    }
  }
}

TEST(KdTree, WalksFindEveryPointInTheBoxOnGrids) {
  check_walks(grid_cloud(2, 40), 8u, true);
  check_walks(grid_cloud(3, 12), 9u, true);
  check_walks(grid_cloud(4, 6), 10u, true);
  check_walks(grid_cloud(5, 4), 11u, true);
}

}  // namespace
