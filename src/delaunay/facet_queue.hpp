// delaunay/facet_queue.hpp: the open facets waiting for their turn, in FIFO order (paper,
// section 2.3: the queue beside the facet table).
//
// A ring of fixed-width entries: the facet queued k-th (its place, counting every push) lives in
// entry k mod capacity, and the ring doubles when full. No facet moves while it waits except
// when the ring grows; the vector this replaced dropped its consumed front with a memmove of the
// rest (3% of a 2D run on one thread).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "delaunay/facet_table.hpp"

namespace drange::engine {

// An open facet waiting for its turn, besides its sorted ids: the simplex that opened it
// (owner.entry is its place in the queue), the open side, the owner's vertex opposite it, and
// its hash (facet_hash, computed once when the facet was derived).
struct FacetInfo {
  FacetOwner owner;
  std::int32_t sigma;
  std::int32_t opposite;  // -1 for the first facet
  std::uint32_t hash;
};

// With threads, a facet closed while it waits is marked (sigma 0), so that its turn needs no
// table lookup.
class FacetQueue {
 public:
  explicit FacetQueue(int d, std::size_t capacity = 1024)
      : d_(d), width_(static_cast<std::size_t>(d) + 5), mask_(capacity - 1), data_(capacity * width_) {}

  void push(const std::int32_t* ids, std::uint32_t hash, FacetOwner owner, int sigma, std::int32_t opposite) {
    if (pushed_ - popped_ > mask_) grow();
    std::int32_t* e = entry(pushed_);
    const int d = d_;
    for (int k = 0; k < d; ++k) e[k] = ids[k];  // a loop: std::copy of a few ints calls memmove
    e[d] = owner.simplex;
    e[d + 1] = owner.face;
    e[d + 2] = sigma;
    e[d + 3] = opposite;
    e[d + 4] = static_cast<std::int32_t>(hash);
    ++pushed_;
  }
  bool empty() const { return popped_ == pushed_; }
  // The place in the queue that the next push gets, and that the next pop returns.
  std::uint64_t pushed() const { return pushed_; }
  std::uint64_t popped() const { return popped_; }
  // Takes the next facet: its ids and info; returns whether it was closed while it waited.
  bool pop(std::int32_t* ids, FacetInfo& info) {
    const std::int32_t* e = entry(popped_);
    const int d = d_;
    for (int k = 0; k < d; ++k) ids[k] = e[k];
    info.owner = FacetOwner{e[d], e[d + 1], static_cast<std::int64_t>(popped_)};
    info.sigma = e[d + 2];
    info.opposite = e[d + 3];
    info.hash = static_cast<std::uint32_t>(e[d + 4]);
    ++popped_;
    return info.sigma == 0;
  }
  // Marks the facet at place `place` (still in the queue) closed.
  void mark_closed(std::uint64_t place) { entry(place)[d_ + 2] = 0; }

 private:
  std::int32_t* entry(std::uint64_t place) { return &data_[(static_cast<std::size_t>(place) & mask_) * width_]; }
  // Doubles the ring; each waiting facet goes to its place's entry in the larger one.
  void grow() {
    const std::size_t mask = 2 * mask_ + 1;
    std::vector<std::int32_t> bigger((mask + 1) * width_);
    for (std::uint64_t place = popped_; place < pushed_; ++place) {
      const std::int32_t* from = entry(place);
      std::int32_t* to = &bigger[(static_cast<std::size_t>(place) & mask) * width_];
      for (std::size_t k = 0; k < width_; ++k) to[k] = from[k];
    }
    data_.swap(bigger);
    mask_ = mask;
  }

  int d_;
  std::size_t width_;  // d ids, owner simplex and face, sigma, opposite, hash
  std::size_t mask_;   // capacity - 1, the capacity a power of two
  std::uint64_t pushed_ = 0, popped_ = 0;
  std::vector<std::int32_t> data_;
};

}  // namespace drange::engine
