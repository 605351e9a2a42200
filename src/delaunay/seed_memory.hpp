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
  static constexpr int kSeeds = 2;  // per point

  explicit SeedMemory(std::int32_t points)
      : size_(static_cast<std::size_t>(points) * kSeeds), seeds_(new std::atomic<std::int32_t>[size_]) {
    util::advise_huge_pages(seeds_.get(), size_ * sizeof(std::atomic<std::int32_t>));
    for (std::size_t i = 0; i < size_; ++i) seeds_[i].store(-1, std::memory_order_relaxed);
  }

  // The i-th most recent seed of point `id` (i < kSeeds), or -1 when none yet.
  std::int32_t seed(std::int32_t id, int i) const {
    return seeds_[static_cast<std::size_t>(id) * kSeeds + static_cast<std::size_t>(i)].load(std::memory_order_relaxed);
  }
  // Records `apex` as the most recent seed of point `id`.
  void remember(std::int32_t id, std::int32_t apex) {
    std::atomic<std::int32_t>* seeds = &seeds_[static_cast<std::size_t>(id) * kSeeds];
    for (int k = kSeeds - 1; k > 0; --k) seeds[k].store(seeds[k - 1].load(std::memory_order_relaxed), std::memory_order_relaxed);
    seeds[0].store(apex, std::memory_order_relaxed);
  }

 private:
  std::size_t size_;
  std::unique_ptr<std::atomic<std::int32_t>[]> seeds_;
};

}  // namespace drange::engine
