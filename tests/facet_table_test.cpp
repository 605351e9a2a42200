// Tests of the facet table (delaunay/facet_table.hpp) against std::map: random opens and closes
// through growth, with removals in the middle of probe runs (the backward shift reads each
// entry's stored hash), and hashes squeezed into a few home slots so that runs are long.
#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <random>
#include <vector>

#include "delaunay/facet_table.hpp"

namespace {

using drange::engine::FacetOwner;
using drange::engine::FacetTable;

void exercise(int d, bool crowded, std::uint32_t seed) {
  std::mt19937 rng(seed);
  FacetTable table(d);
  std::map<std::vector<std::int32_t>, FacetOwner> open;
  // Crowded: every facet's hash is one of 8 values, so that nearly all share a probe run.
  auto hash_of = [&](const std::vector<std::int32_t>& ids) {
    const std::uint32_t h = drange::engine::facet_hash(ids.data(), d);
    return crowded ? h % 8 : h;
  };
  for (int step = 0; step < 20000; ++step) {
    std::vector<std::int32_t> ids(static_cast<std::size_t>(d));
    std::int32_t next = 0;
    for (std::int32_t& id : ids) next = id = next + 1 + static_cast<std::int32_t>(rng() % 60);  // sorted; thousands of keys, each met often
    const std::uint32_t h = hash_of(ids);
    const int action = static_cast<int>(rng() % 3);
    const auto it = open.find(ids);
    if (action == 0) {  // remove
      ASSERT_EQ(table.remove(ids.data(), h), it != open.end()) << "step " << step;
      if (it != open.end()) open.erase(it);
    } else {  // close or open
      const FacetOwner mine{step, d, 1000000000000ll + step};
      FacetOwner seen{};
      const bool closed = table.close_or_open(ids.data(), h, mine, &seen);
      ASSERT_EQ(closed, it != open.end()) << "step " << step;
      if (closed) {
        EXPECT_EQ(seen.simplex, it->second.simplex);
        EXPECT_EQ(seen.face, it->second.face);
        EXPECT_EQ(seen.entry, it->second.entry);  // both halves of the 64-bit queue place
        open.erase(it);
      } else {
        open.emplace(ids, mine);
      }
    }
    ASSERT_EQ(table.size(), open.size());
  }
  for (const auto& [ids, owner] : open) EXPECT_TRUE(table.contains(ids.data(), hash_of(ids)));
}

TEST(FacetTable, AgreesWithAMapThroughGrowthAndRemovals) {
  for (int d = 2; d <= 5; ++d) exercise(d, false, static_cast<std::uint32_t>(d));
}

TEST(FacetTable, LongProbeRunsStayConsistent) {
  for (int d = 2; d <= 3; ++d) exercise(d, true, 100 + static_cast<std::uint32_t>(d));
}

}  // namespace
