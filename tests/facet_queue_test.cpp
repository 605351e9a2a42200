// Tests of the facet queue (delaunay/facet_queue.hpp) against std::deque: FIFO order through
// wrap-around and growth while the ring is wrapped, places, and closed marks.
#include <gtest/gtest.h>

#include <cstdint>
#include <deque>
#include <random>
#include <vector>

#include "delaunay/facet_queue.hpp"

namespace {

using drange::engine::FacetInfo;
using drange::engine::FacetOwner;
using drange::engine::FacetQueue;

struct Queued {
  std::vector<std::int32_t> ids;
  std::int32_t simplex, face, sigma, opposite;
  std::uint32_t hash;
  std::uint64_t place;
};

TEST(FacetQueue, FifoThroughWrapAroundAndGrowth) {
  for (int d = 2; d <= 4; ++d) {
    std::mt19937 rng(static_cast<std::uint32_t>(d));
    FacetQueue queue(d, 4);  // tiny: the ring wraps and grows many times
    std::deque<Queued> model;
    std::uint64_t pushed = 0;
    for (int step = 0; step < 20000; ++step) {
      // Pushes outnumber pops for a while (growth), then the reverse (the ring drains).
      const bool push = model.empty() || rng() % 100 < (step % 4000 < 2000 ? 60u : 40u);
      if (push) {
        Queued q{std::vector<std::int32_t>(static_cast<std::size_t>(d)), static_cast<std::int32_t>(rng() % 1000), static_cast<std::int32_t>(rng() % 5),
                 (rng() & 1) ? 1 : -1, static_cast<std::int32_t>(rng() % 1000), static_cast<std::uint32_t>(rng()), pushed};
        for (std::int32_t& id : q.ids) id = static_cast<std::int32_t>(rng() % 100000);
        ASSERT_EQ(queue.pushed(), pushed);
        queue.push(q.ids.data(), q.hash, FacetOwner{q.simplex, q.face, -1}, q.sigma, q.opposite);
        ++pushed;
        model.push_back(q);
        if (rng() % 10 == 0) {  // close a waiting facet
          Queued& victim = model[rng() % model.size()];
          queue.mark_closed(victim.place);
          victim.sigma = 0;
        }
      } else {
        std::vector<std::int32_t> ids(static_cast<std::size_t>(d));
        FacetInfo info{};
        const Queued& expected = model.front();
        ASSERT_EQ(queue.popped(), expected.place);
        const bool closed = queue.pop(ids.data(), info);
        ASSERT_EQ(ids, expected.ids) << "d=" << d << " step " << step;
        EXPECT_EQ(closed, expected.sigma == 0);
        EXPECT_EQ(info.sigma, expected.sigma);
        EXPECT_EQ(info.owner.simplex, expected.simplex);
        EXPECT_EQ(info.owner.face, expected.face);
        EXPECT_EQ(info.owner.entry, static_cast<std::int64_t>(expected.place));
        EXPECT_EQ(info.opposite, expected.opposite);
        EXPECT_EQ(info.hash, expected.hash);
        model.pop_front();
      }
      ASSERT_EQ(queue.empty(), model.empty());
    }
  }
}

}  // namespace
