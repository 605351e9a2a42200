// delaunay/seed_memory.hpp: for each point, the apexes of the last searches whose facet held it
// (SearchOptions::seed_candidate). The search tries them first: a Delaunay neighbour of a
// facet's vertices is likely to close it, and a good first candidate makes the first query
// ball small.
//
// One memory serves every search thread. Per-thread memories each saw only the searches of
// their own thread: with 2 threads taking alternate runs of facets, the neighbours found by
// the other thread were missing, and the searches tested markedly more points per simplex than
// on one thread. The entries are relaxed atomics: a seed is only a hint (the search's result
// never depends on it), so a thread may read a seed another is replacing, and any point id it
// reads is a valid one. On x86 relaxed loads and stores are plain moves.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>

#include "util/huge_pages.hpp"

namespace drange::engine {

class SeedMemory {
 public:
  // Seeds kept per point in dimension d. Two from 3D on: one or four are slower, and three
  // distinct seeds take fewer candidates but are no faster. One in 2D, where the search tries
  // the best point of a leaf block first and so finds in the walk what a second seed would
  // offer: one seed is faster there, and smaller.
  // The searches compiled for one dimension pass it as K to seed() and remember(): with the
  // count a variable, its loops and strides cost more instructions.
  static constexpr int per_point_in(int d) { return d == 2 ? 1 : 2; }

  SeedMemory(std::int32_t points, int d)
      : per_point_(per_point_in(d)),
        size_(static_cast<std::size_t>(points) * static_cast<std::size_t>(per_point_)),
        seeds_(new std::atomic<std::int32_t>[size_]) {
    util::advise_huge_pages(seeds_.get(), size_ * sizeof(std::atomic<std::int32_t>));
    for (std::size_t i = 0; i < size_; ++i) seeds_[i].store(-1, std::memory_order_relaxed);
  }

  int seeds_per_point() const { return per_point_; }
  // The i-th most recent seed of point `id` (i < seeds_per_point()), or -1 when none yet.
  // K > 0: the caller promises seeds_per_point() == K.
  template <int K = 0>
  std::int32_t seed(std::int32_t id, int i) const {
    const auto per_point = static_cast<std::size_t>(K > 0 ? K : per_point_);
    return seeds_[static_cast<std::size_t>(id) * per_point + static_cast<std::size_t>(i)].load(std::memory_order_relaxed);
  }
  // Records `apex` as the most recent seed of point `id`: moved to the front if it is a seed
  // already, so that a point keeps distinct seeds. Consecutive searches around a point often
  // find the same apex (the facets of one ring around an edge), and shifting it in again would
  // push out the one other seed: moving it to the front gives fewer candidates per simplex and
  // faster searches in 3D and 4D.
  template <int K = 0>
  void remember(std::int32_t id, std::int32_t apex) {
    const int per_point = K > 0 ? K : per_point_;
    std::atomic<std::int32_t>* seeds = &seeds_[static_cast<std::size_t>(id) * static_cast<std::size_t>(per_point)];
    // A memory that holds the apex first already is not written (as after a search that this
    // point's latest seed decided). Skipping that store is measurably faster in 2D, on one
    // thread and on two, likely as fewer cache lines are dirtied, and fewer must move between
    // the threads' caches.
    int last = per_point - 1;  // the seed that leaves (none if apex is one)
    for (int k = 0; k < per_point; ++k)
      if (seeds[k].load(std::memory_order_relaxed) == apex) {
        if (k == 0) return;
        last = k;
        break;
      }
    for (int k = last; k > 0; --k) seeds[k].store(seeds[k - 1].load(std::memory_order_relaxed), std::memory_order_relaxed);
    seeds[0].store(apex, std::memory_order_relaxed);
  }

 private:
  int per_point_;
  std::size_t size_;
  std::unique_ptr<std::atomic<std::int32_t>[]> seeds_;
};

}  // namespace drange::engine
