// delaunay/seed_memory.hpp: for each point, the apexes of the last searches whose facet held it
// (SearchOptions::seed_candidate). The search tries them first: a Delaunay neighbour of a
// facet's vertices is likely to close it, and a good first candidate makes the first query
// ball small.
//
// One memory serves every search thread. Per-thread memories each saw only the searches of
// their own thread: with 2 threads taking alternate runs of facets, the neighbours found by
// the other thread were missing, and 2D 1M points tested 36% more points per simplex than on
// one thread. The entries are relaxed atomics: a seed is only a hint (the search's result
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
  // Seeds kept per point in dimension d. Two from 3D on (one or four were slower, three within
  // the noise: tenth and eleventh rounds). One in 2D since the twenty-eighth round, where the
  // search tries the best point of a leaf block first, which finds in the walk what a second
  // seed offered: 2D 1M time_search 0.840 -> 0.801 s (medians of 5 interleaved runs, every
  // pair faster; points tested per triangle 2.56 -> 2.58; callgrind 2D 100k -1.2%; 4 MB less),
  // while three or four from 3D on stayed level (3D 1M, 4D 100k, 5D 20k, three interleaved
  // runs). Three distinct seeds (twenty-ninth round) took fewer candidates again but were not
  // faster (callgrind 3D -0.6%, 4D -0.2%, 5D +0.25%; time_search level or slower).
  // The searches compiled for one dimension pass it as K to seed() and remember(): with the
  // count a variable, its loops and strides cost 3D 20k 1.1% more instructions (callgrind).
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
  // find the same apex (the facets of one ring around an edge), and shifting it in again had
  // pushed out the one other seed: 3D 216k candidates per simplex 2.50 -> 2.36, time_search
  // 1.214 -> 1.142 s (medians of 5 interleaved runs); 4D 100k 2.72 -> 2.60, 3.900 -> 3.721 s
  // (medians of 3); 5D 20k and 3D 1M level; callgrind 3D 50k -1.9%, 4D 20k -1.4%, 5D 5k -1.1%.
  template <int K = 0>
  void remember(std::int32_t id, std::int32_t apex) {
    const int per_point = K > 0 ? K : per_point_;
    std::atomic<std::int32_t>* seeds = &seeds_[static_cast<std::size_t>(id) * static_cast<std::size_t>(per_point)];
    // A memory that holds the apex first already is not written (as after a search that this
    // point's latest seed decided). In 2D skipping that store saved 2% (2D 1M time_search 0.750
    // -> 0.734 s, medians of 8 interleaved runs; 2 threads 0.444 -> 0.437 s, medians of 5; 3D
    // 216k on 2 threads level), likely as fewer cache lines are dirtied, and fewer must move
    // between the two threads' caches.
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
