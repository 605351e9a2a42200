// Tests of the seed memory (delaunay/seed_memory.hpp): how many seeds a point keeps per
// dimension, and that remembering keeps them most recent first and distinct.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "delaunay/seed_memory.hpp"

namespace {

using drange::engine::SeedMemory;

std::vector<std::int32_t> seeds_of(const SeedMemory& memory, std::int32_t id) {
  std::vector<std::int32_t> seeds;
  for (int i = 0; i < memory.seeds_per_point(); ++i) seeds.push_back(memory.seed(id, i));
  return seeds;
}

// However many seeds a dimension keeps (a tuning choice), a point's seeds are its most recent
// distinct apexes, newest first, and the search kernel compiled for d reads that many.
TEST(SeedMemory, KeepsItsCountOfMostRecentApexesInEveryDimension) {
  for (int d = 2; d <= 8; ++d) {
    SeedMemory memory(4, d);
    const int k = memory.seeds_per_point();
    ASSERT_EQ(k, SeedMemory::per_point_in(d)) << "d = " << d;
    ASSERT_GE(k, 1) << "d = " << d;
    for (std::int32_t apex = 10; apex < 10 + k + 2; ++apex) memory.remember(2, apex);
    std::vector<std::int32_t> newest;
    for (int i = 0; i < k; ++i) newest.push_back(10 + k + 1 - i);
    EXPECT_EQ(seeds_of(memory, 2), newest) << "d = " << d;
  }
}

TEST(SeedMemory, StartsWithoutSeeds) {
  const SeedMemory memory(3, 3);
  for (std::int32_t id = 0; id < 3; ++id) EXPECT_EQ(seeds_of(memory, id), (std::vector<std::int32_t>{-1, -1}));
}

TEST(SeedMemory, KeepsTheMostRecentApexFirst) {
  SeedMemory memory(3, 3);
  memory.remember(1, 5);
  EXPECT_EQ(seeds_of(memory, 1), (std::vector<std::int32_t>{5, -1}));
  memory.remember(1, 7);
  EXPECT_EQ(seeds_of(memory, 1), (std::vector<std::int32_t>{7, 5}));
  memory.remember(1, 9);
  EXPECT_EQ(seeds_of(memory, 1), (std::vector<std::int32_t>{9, 7}));
  EXPECT_EQ(seeds_of(memory, 0), (std::vector<std::int32_t>{-1, -1}));  // other points untouched
  EXPECT_EQ(seeds_of(memory, 2), (std::vector<std::int32_t>{-1, -1}));
}

// The same apex found again must not push out the other seed (shifting it in again would often
// leave a point's two seeds one apex twice).
TEST(SeedMemory, KeepsItsSeedsDistinct) {
  SeedMemory memory(2, 4);
  memory.remember(0, 5);
  memory.remember(0, 7);
  memory.remember(0, 7);
  EXPECT_EQ(seeds_of(memory, 0), (std::vector<std::int32_t>{7, 5}));
  memory.remember(0, 5);  // a seed found again moves to the front
  EXPECT_EQ(seeds_of(memory, 0), (std::vector<std::int32_t>{5, 7}));
  memory.remember(0, 5);
  EXPECT_EQ(seeds_of(memory, 0), (std::vector<std::int32_t>{5, 7}));
}

TEST(SeedMemory, TheCompiledCountReadsTheSameSeeds) {
  SeedMemory memory(2, 3);
  memory.remember<2>(1, 4);
  memory.remember<2>(1, 6);
  memory.remember<2>(1, 6);
  EXPECT_EQ(memory.seed<2>(1, 0), 6);
  EXPECT_EQ(memory.seed<2>(1, 1), 4);
  EXPECT_EQ(seeds_of(memory, 1), (std::vector<std::int32_t>{6, 4}));
}

}  // namespace
