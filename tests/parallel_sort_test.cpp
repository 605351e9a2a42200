// tests/parallel_sort_test.cpp: util/parallel_sort.hpp against std::sort. Both sorts take a
// strict total order, so each must give std::sort's result exactly, for every thread count and
// whichever way sort_by_key goes: by its buckets (spread-out keys, many equal keys, signed
// zeros) or back to sort_in_parallel (keys all equal, clustered, or too far apart for a
// finite scale).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "delaunay/team.hpp"
#include "util/parallel_sort.hpp"

namespace {

struct Item {
  double key;
  double second;
  std::int32_t index;
};
bool operator==(const Item& a, const Item& b) { return a.key == b.key && a.second == b.second && a.index == b.index; }

// Lexicographic on (key, second), then the index: a strict total order led by the key.
bool less(const Item& a, const Item& b) {
  if (a.key != b.key) return a.key < b.key;
  if (a.second != b.second) return a.second < b.second;
  return a.index < b.index;
}

std::vector<Item> items_of(const std::vector<double>& keys, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> small(0, 3);
  std::vector<Item> items;
  for (std::size_t i = 0; i < keys.size(); ++i) items.push_back(Item{keys[i], double(small(rng)), std::int32_t(i)});
  return items;
}

void expect_sorted_like_std(const std::vector<double>& keys, const char* what) {
  std::vector<Item> expected = items_of(keys, 7);
  std::sort(expected.begin(), expected.end(), less);
  for (int threads = 1; threads <= 3; ++threads) {
    drange::engine::Team team(threads);
    std::vector<Item> by_key = items_of(keys, 7);
    drange::util::sort_by_key(by_key, [](const Item& item) { return item.key; }, less, team);
    EXPECT_TRUE(by_key == expected) << what << ", sort_by_key, " << threads << " threads";
    std::vector<Item> merged = items_of(keys, 7);
    drange::util::sort_in_parallel(merged, less, team);
    EXPECT_TRUE(merged == expected) << what << ", sort_in_parallel, " << threads << " threads";
  }
}

constexpr std::size_t kItems = 100000;  // above sort_by_key's minimum and sort_in_parallel's parts

TEST(ParallelSort, SpreadOutKeysGoThroughTheBuckets) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> uniform(-3.0, 5.0);
  std::vector<double> keys(kItems);
  for (double& k : keys) k = uniform(rng);
  expect_sorted_like_std(keys, "uniform");
  std::normal_distribution<double> normal(0.0, 1.0);
  for (double& k : keys) k = normal(rng);
  expect_sorted_like_std(keys, "gaussian");
}

TEST(ParallelSort, EqualKeysAndSignedZerosShareABucket) {
  // 1000 distinct keys (a grid's column), and -0.0 next to +0.0, which compare equal: the order
  // between them is the second value's and the index's, as in std::sort.
  std::mt19937 rng(2);
  std::vector<double> keys(kItems);
  for (std::size_t i = 0; i < kItems; ++i) keys[i] = double(rng() % 1000) - 500.0;
  for (std::size_t i = 0; i < kItems; i += 3) keys[i] = (rng() & 1) ? 0.0 : -0.0;
  expect_sorted_like_std(keys, "grid with signed zeros");
}

TEST(ParallelSort, KeysWithoutAUsefulScaleFallBack) {
  std::mt19937 rng(3);
  std::vector<double> keys(kItems, 1.5);
  expect_sorted_like_std(keys, "all equal");
  // Farther apart than the largest double: the scale would be zero.
  for (std::size_t i = 0; i < kItems; ++i) keys[i] = (rng() & 1) ? std::numeric_limits<double>::max() * 0.75 : -std::numeric_limits<double>::max() * 0.75;
  keys[5] = 0.0;
  expect_sorted_like_std(keys, "huge spread");
  // One tight cluster and a few far points: a bucket would hold most items.
  std::uniform_real_distribution<double> cluster(1.0, 1.0 + 1e-9);
  for (double& k : keys) k = cluster(rng);
  keys[0] = -1e6;
  keys[1] = 1e6;
  expect_sorted_like_std(keys, "clustered");
  // Subnormal keys: the scale's division by a tiny range overflows.
  for (std::size_t i = 0; i < kItems; ++i) keys[i] = std::numeric_limits<double>::denorm_min() * double(rng() % 4);
  expect_sorted_like_std(keys, "subnormal");
}

TEST(ParallelSort, FewItems) {
  expect_sorted_like_std({}, "empty");
  expect_sorted_like_std({2.0, -1.0, 2.0, 0.5}, "four");
}

}  // namespace
