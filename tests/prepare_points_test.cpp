// tests/prepare_points_test.cpp: the engine's point store (delaunay/prepare_points.cpp) against
// a direct computation, for every thread count.
//
// The ranks are the lexicographic order of the distinct points, each duplicate is reported
// with the first input index of its coordinates, and the store (ids, coordinates, ranks, input
// indices, kd-tree order) is the same for 1 to 7 threads. The inputs are large enough for the
// parallel sort and its merges cut into pieces (more than 2^16 points), with many duplicates,
// in d = 2 and 4 (the fixed-d sort of points) and d = 5 (the sort of indices).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "delaunay/prepare_points.hpp"
#include "delaunay/search_options.hpp"
#include "delaunay/team.hpp"
#include "drange/delaunay.hpp"
#include "drange/generate.hpp"

namespace {

using drange::Duplicate;
using drange::PointCloud;

// `distinct` random points, each copied a random number of times (0 to 3), shuffled; small
// integer coordinates in the first axis make many points share a prefix.
PointCloud points_with_copies(int d, std::size_t distinct, unsigned seed) {
  const PointCloud base = drange::generate_points(drange::Distribution::Uniform, distinct, d, seed);
  std::mt19937_64 rng(seed);
  std::vector<std::size_t> picks;
  for (std::size_t i = 0; i < distinct; ++i) picks.insert(picks.end(), 1 + rng() % 4, i);
  std::shuffle(picks.begin(), picks.end(), rng);
  PointCloud points{d, {}};
  for (const std::size_t i : picks) {
    const double* p = base.point(i);
    points.coords.push_back(std::floor(p[0] * 8));  // ties on the first coordinate
    points.coords.insert(points.coords.end(), p + 1, p + d);
  }
  return points;
}

// The distinct points' input indices in lexicographic order (ties: the lower index), and the
// duplicates, computed directly.
void reference(const PointCloud& points, std::vector<std::int64_t>& ranked, std::vector<Duplicate>& duplicates) {
  const int d = points.dim;
  std::vector<std::int64_t> order(points.size());
  std::iota(order.begin(), order.end(), 0);
  const auto less = [&](std::int64_t a, std::int64_t b) {
    const double* p = points.point(static_cast<std::size_t>(a));
    const double* q = points.point(static_cast<std::size_t>(b));
    if (!std::equal(p, p + d, q)) return std::lexicographical_compare(p, p + d, q, q + d);
    return a < b;
  };
  std::sort(order.begin(), order.end(), less);
  ranked.clear();
  duplicates.clear();
  for (const std::int64_t i : order) {
    const double* p = points.point(static_cast<std::size_t>(i));
    if (!ranked.empty() && std::equal(p, p + d, points.point(static_cast<std::size_t>(ranked.back())))) {
      duplicates.push_back(Duplicate{i, ranked.back()});
    } else {
      ranked.push_back(i);
    }
  }
  std::sort(duplicates.begin(), duplicates.end(), [](const Duplicate& a, const Duplicate& b) { return a.index < b.index; });
}

void expect_store_matches_reference(const PointCloud& points, const std::string& what) {
  std::vector<std::int64_t> ranked;
  std::vector<Duplicate> expected_duplicates;
  reference(points, ranked, expected_duplicates);
  ASSERT_GT(expected_duplicates.size(), points.size() / 3) << what;
  const int d = points.dim;
  // The store scales by the power of two that brings the largest magnitude into [0.5, 1).
  int exponent = 0;
  std::frexp(*std::max_element(points.coords.begin(), points.coords.end(), [](double a, double b) { return std::fabs(a) < std::fabs(b); }), &exponent);
  drange::engine::PointStore serial;
  for (const int threads : {1, 2, 3, 4, 7}) {
    const std::string at = what + ", threads=" + std::to_string(threads);
    drange::engine::Team team(threads);
    std::vector<Duplicate> duplicates;
    drange::engine::PointStore store = drange::engine::prepare_points(points, 32, duplicates, team);
    ASSERT_EQ(duplicates.size(), expected_duplicates.size()) << at;
    for (std::size_t i = 0; i < duplicates.size(); ++i) {
      ASSERT_EQ(duplicates[i].index, expected_duplicates[i].index) << at;
      ASSERT_EQ(duplicates[i].original, expected_duplicates[i].original) << at;
    }
    ASSERT_EQ(static_cast<std::size_t>(store.size), ranked.size()) << at;
    for (std::int32_t id = 0; id < store.size; ++id) {
      const auto r = static_cast<std::size_t>(store.rank(id));
      ASSERT_EQ(store.input_index[static_cast<std::size_t>(id)], ranked[r]) << at << ", id " << id;
      const double* input = points.point(static_cast<std::size_t>(ranked[r]));
      for (int k = 0; k < d; ++k) ASSERT_EQ(std::ldexp(input[k], -exponent), store.point(id)[k]) << at << ", id " << id;
    }
    if (threads == 1) {
      serial = std::move(store);
      continue;
    }
    EXPECT_TRUE(store.coords == serial.coords) << at;
    EXPECT_TRUE(store.input_index == serial.input_index) << at;
    EXPECT_TRUE(store.tree.order() == serial.tree.order()) << at;
  }
}

TEST(PreparePoints, RanksAndDuplicatesInTwoDimensions) {
  expect_store_matches_reference(points_with_copies(2, 40000, 1), "2D");
}

TEST(PreparePoints, RanksAndDuplicatesInFourDimensions) {
  expect_store_matches_reference(points_with_copies(4, 30000, 2), "4D");
}

TEST(PreparePoints, RanksAndDuplicatesInFiveDimensions) {
  expect_store_matches_reference(points_with_copies(5, 30000, 3), "5D");
}

// The search's accelerators are built only when the options use them: on a sphere (3D: the
// shell, the hull's facets) each is there with the full search and absent with its switch off,
// the other unchanged.
TEST(PreparePoints, BuildsOnlyTheAcceleratorsTheOptionsUse) {
  const PointCloud points = drange::generate_points(drange::Distribution::Sphere, 4000, 3, 5);
  const auto store_for = [&](const char* variant) {
    drange::engine::Team team(1);
    std::vector<Duplicate> duplicates;
    return drange::engine::prepare_points(points, 64, duplicates, team, drange::engine::search_variant(variant));
  };
  const drange::engine::PointStore full = store_for("full");
  ASSERT_TRUE(full.shell.active());
  ASSERT_TRUE(full.hull.active());
  const drange::engine::PointStore no_shell = store_for("no-shell"), no_hull = store_for("no-hull");
  EXPECT_FALSE(no_shell.shell.active());
  EXPECT_TRUE(no_shell.hull.active());
  EXPECT_FALSE(no_hull.hull.active());
  EXPECT_TRUE(no_hull.shell.active());
  EXPECT_FALSE(store_for("scan").shell.active());  // the shell prunes kd-tree nodes: no tree, no shell
}

}  // namespace
