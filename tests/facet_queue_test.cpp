// Tests of the facet queues (delaunay/facet_queue.hpp). FacetQueue against std::deque: FIFO
// order through wrap-around and growth while the ring is wrapped, places, and closed marks.
// SpatialFacetQueue against std::map keyed by (smallest id >> shift, push count): its order,
// entries reused only once released, closed marks while waiting, window positions after pop.
#include <gtest/gtest.h>

#include <cstdint>
#include <deque>
#include <map>
#include <random>
#include <set>
#include <utility>
#include <string>
#include <vector>

#include "delaunay/facet_queue.hpp"

namespace {

using drange::engine::FacetInfo;
using drange::engine::FacetOwner;
using drange::engine::FacetQueue;
using drange::engine::SpatialFacetQueue;

struct Queued {
  std::vector<std::int32_t> ids;
  std::int32_t simplex, face, sigma, opposite;
  std::uint32_t hash;
  std::uint64_t place;
  bool closed = false;
};

// What pop() returned besides the ids: the closed mark and the facet's info, as pushed (its
// entry is the model's `place`). A closed facet's sigma is not for use (the spatial queue
// marks it there), so it is checked on open facets only.
void expect_popped(bool closed, const FacetInfo& info, const Queued& expected, const std::string& at) {
  EXPECT_EQ(closed, expected.closed) << at;
  if (!expected.closed) EXPECT_EQ(info.sigma, expected.sigma) << at;
  EXPECT_EQ(info.owner.simplex, expected.simplex) << at;
  EXPECT_EQ(info.owner.face, expected.face) << at;
  EXPECT_EQ(info.owner.entry, static_cast<std::int64_t>(expected.place)) << at;
  EXPECT_EQ(info.opposite, expected.opposite) << at;
  EXPECT_EQ(info.hash, expected.hash) << at;
}

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
          victim.closed = true;
        }
      } else {
        std::vector<std::int32_t> ids(static_cast<std::size_t>(d));
        FacetInfo info{};
        const Queued& expected = model.front();
        ASSERT_EQ(queue.popped(), expected.place);
        const bool closed = queue.pop(ids.data(), info);
        ASSERT_EQ(ids, expected.ids) << "d=" << d << " step " << step;
        expect_popped(closed, info, expected, "d=" + std::to_string(d));
        model.pop_front();
      }
      ASSERT_EQ(queue.empty(), model.empty());
    }
  }
}

// The window of the driver's threads: facets popped with a position stay there until
// released; a closure then reports the position instead of marking the queue.
struct Windowed {
  std::int64_t entry;
  std::int64_t position;
};

void exercise_spatial_queue(int d, int shift, bool windowed, std::uint32_t seed) {
  const std::int32_t points = 5000;
  std::mt19937 rng(seed);
  SpatialFacetQueue queue(d, points, shift);
  std::map<std::pair<std::int32_t, std::uint64_t>, Queued> model;  // (key, push count) -> facet
  std::map<std::int64_t, std::pair<std::int32_t, std::uint64_t>> waiting;  // entry -> model key
  std::set<std::int64_t> live;  // entries waiting or in the window
  std::deque<Windowed> window;
  std::int64_t position = 0;
  std::uint64_t pushed = 0;
  const std::string at = "d=" + std::to_string(d) + " shift=" + std::to_string(shift) + (windowed ? " windowed" : "");
  for (int step = 0; step < 30000; ++step) {
    const bool push = model.empty() || rng() % 100 < (step % 6000 < 3000 ? 60u : 40u);
    if (push) {
      Queued q{std::vector<std::int32_t>(static_cast<std::size_t>(d)), static_cast<std::int32_t>(rng() % 1000),
               static_cast<std::int32_t>(rng() % 5), (rng() & 1) ? 1 : -1, static_cast<std::int32_t>(rng() % 1000),
               static_cast<std::uint32_t>(rng()), pushed};
      // Sorted ids below `points`; the smallest often near the last ones, as on a frontier.
      q.ids[0] = static_cast<std::int32_t>(rng() % 2 ? rng() % points : (step * 7 + rng() % 64) % points);
      for (int k = 1; k < d; ++k) q.ids[static_cast<std::size_t>(k)] = q.ids[static_cast<std::size_t>(k - 1)] + static_cast<std::int32_t>(rng() % 50);
      const std::int64_t entry = queue.next_entry();
      ASSERT_EQ(live.count(entry), 0u) << at << ": entry " << entry << " still in use";
      queue.push(q.ids.data(), q.hash, FacetOwner{q.simplex, q.face, -1}, q.sigma, q.opposite);
      q.place = static_cast<std::uint64_t>(entry);  // here: the entry, reported back by pop
      const std::pair<std::int32_t, std::uint64_t> key{q.ids[0] >> shift, pushed++};
      model.emplace(key, q);
      waiting.emplace(entry, key);
      live.insert(entry);
    } else {
      std::vector<std::int32_t> ids(static_cast<std::size_t>(d));
      FacetInfo info{};
      const Queued expected = model.begin()->second;
      const bool closed = queue.pop(ids.data(), info, windowed ? position : -1);
      ASSERT_EQ(ids, expected.ids) << at << " step " << step;
      expect_popped(closed, info, expected, at);
      model.erase(model.begin());
      waiting.erase(info.owner.entry);
      if (windowed) {
        window.push_back(Windowed{info.owner.entry, position++});
      } else {
        live.erase(info.owner.entry);
      }
    }
    if (rng() % 10 == 0 && !waiting.empty()) {  // close a waiting facet: it is marked
      auto it = waiting.begin();
      std::advance(it, static_cast<long>(rng() % waiting.size()));
      std::uint64_t where = 0;
      EXPECT_TRUE(queue.mark_closed(it->first, where)) << at;
      model.at(it->second).closed = true;
    }
    if (windowed && !window.empty() && rng() % 4 == 0) {  // close a facet in the window: its position
      const Windowed& w = window[rng() % window.size()];
      std::uint64_t where = 0;
      EXPECT_FALSE(queue.mark_closed(w.entry, where)) << at;
      EXPECT_EQ(where, static_cast<std::uint64_t>(w.position)) << at;
    }
    if (windowed && (window.size() > 20 || (model.empty() && !window.empty()))) {  // the turn of the oldest
      queue.release(window.front().entry);
      live.erase(window.front().entry);
      window.pop_front();
    }
    ASSERT_EQ(queue.empty(), model.empty()) << at;
    ASSERT_EQ(queue.size(), model.size()) << at;
  }
}

TEST(SpatialFacetQueue, LeastKeyFirstFifoAmongEqualKeys) {
  for (int d = 2; d <= 4; ++d)
    for (const int shift : {0, 4, 12})
      for (const bool windowed : {false, true}) exercise_spatial_queue(d, shift, windowed, static_cast<std::uint32_t>(d * 100 + shift));
}

// A shift past every id's bits puts every facet in one list: the FIFO queue's order.
TEST(SpatialFacetQueue, OneBlockIsFifo) {
  const int d = 3;
  SpatialFacetQueue spatial(d, 1000, 31);
  FacetQueue fifo(d);
  std::mt19937 rng(5);
  for (int step = 0; step < 5000; ++step) {
    if (fifo.empty() || rng() % 2) {
      std::int32_t ids[3];
      ids[0] = static_cast<std::int32_t>(rng() % 1000);
      ids[1] = ids[0] + 1;
      ids[2] = ids[0] + 2;
      const FacetOwner owner{static_cast<std::int32_t>(step), 0, -1};
      fifo.push(ids, 0, owner, 1, 0);
      spatial.push(ids, 0, owner, 1, 0);
    } else {
      std::int32_t a[3], b[3];
      FacetInfo ia{}, ib{};
      fifo.pop(a, ia);
      spatial.pop(b, ib);
      ASSERT_EQ(ia.owner.simplex, ib.owner.simplex) << "step " << step;
      ASSERT_EQ(a[0], b[0]);
    }
  }
}

}  // namespace
