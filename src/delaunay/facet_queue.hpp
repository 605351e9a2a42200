// delaunay/facet_queue.hpp: the open facets waiting for their turn (paper, section 2.3: the
// queue beside the facet table), in one of two orders (SearchOptions::facet_order):
//
//   FacetQueue         FIFO, the paper's order. A ring of fixed-width entries: the facet queued
//                      k-th (its place, counting every push) lives in entry k mod capacity, and
//                      the ring doubles when full. No facet moves while it waits except when the
//                      ring grows (a vector would move its whole rest at every pop).
//   SpatialFacetQueue  spatial: the facet whose smallest vertex id, shifted right by a block
//                      shift, is least comes first; FIFO among equal keys. Point ids follow the
//                      kd-tree's order, a space-filling one, so the frontier sweeps through space
//                      instead of growing as a ball: it stays several times smaller in 3D, and
//                      consecutive searches read the same kd-tree nodes. A bucket queue: one FIFO
//                      list per key, entries in a slab reused through a free list, and a bit per
//                      bucket to find the least non-empty one; O(1) per push and pop but for the
//                      scan of the bits, which is short because the keys popped are local.
//
// Both give each waiting facet an entry number (FacetOwner::entry in the facet table), so that
// a facet closed while it waits can be marked; with threads, a facet that left the queue for
// the driver's search window is found there by its window position instead (search_pipeline.hpp).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "delaunay/facet_table.hpp"
#include "util/return_free_memory.hpp"

namespace drange::engine {

// An open facet waiting for its turn, besides its sorted ids: the simplex that opened it
// (owner.entry is its place in the queue), the open side, the owner's vertex opposite it, and
// its hash (facet_hash, computed once when the facet was derived).
struct FacetInfo {
  FacetOwner owner;
  std::int32_t sigma;     // for open facets only: pop() says whether it closed while it waited
  std::int32_t opposite;  // -1 for the first facet
  std::uint32_t hash;
};

// A facet closed while it waits is marked, so that its turn needs no table lookup. The marks
// are bits apart from the entries: marking then writes to a small array that stays in cache,
// not to a random entry of a large ring (a miss each), and a facet's turn reads its bit
// where it would otherwise probe the facet table (a miss on a large frontier, where in high d
// most of the facets popped were closed while they waited).
class FacetQueue {
 public:
  // Closures are marked on every thread count (Frontier, frontier.hpp).
  static constexpr bool kMarksCheaply = true;

  // `capacity`, a power of two, is raised to at least two words of marks (128).
  explicit FacetQueue(int d, std::size_t capacity = 1024)
      : d_(d),
        width_(static_cast<std::size_t>(d) + 5),
        mask_(std::max<std::size_t>(capacity, 128) - 1),
        data_((mask_ + 1) * width_),
        closed_((mask_ + 1) / 64, 0) {}

  void push(const std::int32_t* ids, std::uint32_t hash, FacetOwner owner, int sigma, std::int32_t opposite) {
    // A word of marks is reused only once all its places of the previous lap were popped
    // (pop() clears it then): the ring keeps a word's worth of places free.
    if (pushed_ - popped_ + 64 > mask_) grow();
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
  std::int64_t next_entry() const { return static_cast<std::int64_t>(pushed_); }
  std::uint64_t popped() const { return popped_; }
  // Whether a facet waits `ahead` places after the next one to pop; if so, its hash.
  bool hash_ahead(std::uint64_t ahead, std::uint32_t& hash) const {
    const std::uint64_t place = popped_ + ahead;
    if (place >= pushed_) return false;
    hash = static_cast<std::uint32_t>(data_[(static_cast<std::size_t>(place) & mask_) * width_ + d_ + 4]);
    return true;
  }
  // Takes the next facet: its ids and info; returns whether it was closed while it waited.
  bool pop(std::int32_t* ids, FacetInfo& info) {
    const std::int32_t* e = entry(popped_);
    const int d = d_;
    for (int k = 0; k < d; ++k) ids[k] = e[k];
    info.owner = FacetOwner{e[d], e[d + 1], static_cast<std::int64_t>(popped_)};
    info.sigma = e[d + 2];
    info.opposite = e[d + 3];
    info.hash = static_cast<std::uint32_t>(e[d + 4]);
    std::uint64_t& marks = closed_[word(popped_)];
    const bool closed = (marks & bit(popped_)) != 0;
    // A word's marks are cleared once its last place is popped: its places are free until
    // pushes reach them again, and marks go only to facets still waiting.
    if ((popped_ & 63) == 63) marks = 0;
    ++popped_;
    return closed;
  }
  // The same, for the driver's window: its k-th facet is the queue's k-th, so `window` is the
  // place already, and nothing is kept for release().
  bool pop(std::int32_t* ids, FacetInfo& info, std::int64_t /*window*/) { return pop(ids, info); }
  void release(std::int64_t /*entry*/) {}
  // Marks the facet at place `place` (still in the queue) closed.
  void mark_closed(std::uint64_t place) { closed_[word(place)] |= bit(place); }
  // A facet closed while it waits, at place `place`: marked when still in the queue (true);
  // otherwise it is in the driver's window, whose k-th facet is the queue's k-th: `window` is
  // its place.
  bool mark_closed(std::int64_t place, std::uint64_t& window) {
    const auto p = static_cast<std::uint64_t>(place);
    if (p >= popped_) {
      mark_closed(p);
      return true;
    }
    window = p;
    return false;
  }

 private:
  std::int32_t* entry(std::uint64_t place) { return &data_[(static_cast<std::size_t>(place) & mask_) * width_]; }
  std::size_t word(std::uint64_t place) const { return (static_cast<std::size_t>(place) & mask_) >> 6; }
  static std::uint64_t bit(std::uint64_t place) { return std::uint64_t{1} << (place & 63); }
  // Doubles the ring; each waiting facet goes to its place's entry in the larger one, its mark
  // with it.
  void grow() {
    const std::size_t mask = 2 * mask_ + 1;
    std::vector<std::int32_t> bigger((mask + 1) * width_);
    std::vector<std::uint64_t> closed((mask + 1) / 64, 0);
    for (std::uint64_t place = popped_; place < pushed_; ++place) {
      const std::int32_t* from = entry(place);
      std::int32_t* to = &bigger[(static_cast<std::size_t>(place) & mask) * width_];
      for (std::size_t k = 0; k < width_; ++k) to[k] = from[k];
      if (closed_[word(place)] & bit(place)) closed[(static_cast<std::size_t>(place) & mask) >> 6] |= bit(place);
    }
    data_.swap(bigger);
    closed_.swap(closed);
    std::vector<std::int32_t>().swap(bigger);
    util::return_free_memory();
    mask_ = mask;
  }

  int d_;
  std::size_t width_;  // d ids, owner simplex and face, sigma, opposite, hash
  std::size_t mask_;   // capacity - 1, the capacity a power of two
  std::uint64_t pushed_ = 0, popped_ = 0;
  std::vector<std::int32_t> data_;
  std::vector<std::uint64_t> closed_;  // a bit per entry: closed while it waits
};

// The spatial order: keys ids[0] >> shift (ids sorted, so ids[0] is the smallest), FIFO among
// equal keys. A facet's entry is its slab slot, stable while it waits; after pop(), the slot
// stays the facet's until release() when the caller keeps the facet in a window (threads: so
// that its closure can still be routed to its window position), or is freed at once.
class SpatialFacetQueue {
 public:
  // Closures are marked with threads only: the serial loop's facets leave this queue ahead of
  // their turn and free their entries at once, so a closure finds no entry to mark; their
  // turn's table lookup tells instead.
  static constexpr bool kMarksCheaply = false;

  // Point ids are below `points`.
  SpatialFacetQueue(int d, std::int32_t points, int shift)
      : d_(d),
        width_(static_cast<std::size_t>(d) + 6),
        shift_(shift),
        head_((static_cast<std::size_t>(points) >> shift) + 1, -1),
        tail_(head_.size(), -1),
        nonempty_(head_.size() / 64 + 1, 0),
        cursor_(head_.size()) {}

  bool empty() const { return size_ == 0; }
  std::size_t size() const { return size_; }
  // The entry that the next push takes.
  std::int64_t next_entry() const { return free_.empty() ? static_cast<std::int64_t>(data_.size() / width_) : free_.back(); }

  void push(const std::int32_t* ids, std::uint32_t hash, FacetOwner owner, int sigma, std::int32_t opposite) {
    std::int32_t slot;
    if (!free_.empty()) {
      slot = free_.back();
      free_.pop_back();
    } else {
      slot = static_cast<std::int32_t>(data_.size() / width_);
      data_.resize(data_.size() + width_);
      next_.push_back(-1);
    }
    std::int32_t* e = at(slot);
    const int d = d_;
    for (int k = 0; k < d; ++k) e[k] = ids[k];
    e[d] = owner.simplex;
    e[d + 1] = owner.face;
    e[d + 2] = sigma;
    e[d + 3] = opposite;
    e[d + 4] = static_cast<std::int32_t>(hash);
    next_[static_cast<std::size_t>(slot)] = -1;
    e[d + kWindow] = -1;
    const std::size_t key = static_cast<std::size_t>(ids[0]) >> shift_;
    if (head_[key] < 0) {
      head_[key] = slot;
      nonempty_[key >> 6] |= std::uint64_t{1} << (key & 63);
      if (key < cursor_) cursor_ = key;
    } else {
      next_[static_cast<std::size_t>(tail_[key])] = slot;
    }
    tail_[key] = slot;
    ++size_;
  }

  // Takes the facet of least key (the queue must not be empty): its ids and info (owner.entry
  // is its own entry); returns whether it was closed while it waited. With window >= 0, the
  // entry stays the facet's, at that window position, until release(); otherwise it is freed.
  bool pop(std::int32_t* ids, FacetInfo& info, std::int64_t window = -1) {
    std::size_t word = cursor_ >> 6;
    std::uint64_t bits = nonempty_[word] & (~std::uint64_t{0} << (cursor_ & 63));
    while (bits == 0) bits = nonempty_[++word];
    const std::size_t key = word * 64 + static_cast<std::size_t>(__builtin_ctzll(bits));
    cursor_ = key;
    const std::int32_t slot = head_[key];
    std::int32_t* e = at(slot);
    const int d = d_;
    head_[key] = next_[static_cast<std::size_t>(slot)];
    if (head_[key] < 0) nonempty_[key >> 6] &= ~(std::uint64_t{1} << (key & 63));
    --size_;
    for (int k = 0; k < d; ++k) ids[k] = e[k];
    info.owner = FacetOwner{e[d], e[d + 1], slot};
    info.sigma = e[d + 2];
    info.opposite = e[d + 3];
    info.hash = static_cast<std::uint32_t>(e[d + 4]);
    if (window >= 0) e[d + kWindow] = static_cast<std::int32_t>(window & 0x7fffffff);
    else release(slot);
    return info.sigma == 0;
  }
  // Frees the entry of a facet that pop() left in a window. (A stack of free entries, not a
  // chain through them: the entry's line, last read at pop(), is not written again.)
  void release(std::int64_t entry) { free_.push_back(static_cast<std::int32_t>(entry)); }
  // A facet closed while it waits, at entry `entry`: marked when still in the queue (true);
  // otherwise `window` is the window position that pop() was given, modulo 2^31.
  bool mark_closed(std::int64_t entry, std::uint64_t& window) {
    std::int32_t* e = at(static_cast<std::int32_t>(entry));
    if (e[d_ + kWindow] < 0) {
      e[d_ + 2] = 0;
      return true;
    }
    window = static_cast<std::uint64_t>(e[d_ + kWindow]);
    return false;
  }

 private:
  static constexpr int kWindow = 5;  // after the ids: the window position
  std::int32_t* at(std::int32_t slot) { return &data_[static_cast<std::size_t>(slot) * width_]; }

  int d_;
  std::size_t width_;  // d ids, owner simplex and face, sigma, opposite, hash, window position
  int shift_;
  std::vector<std::int32_t> head_, tail_;  // per key: the first and last entry of its list, -1 if none
  std::vector<std::uint64_t> nonempty_;     // per key: a bit, set while its list is not empty
  std::size_t cursor_;                      // every key below it has an empty list
  std::size_t size_ = 0;
  std::vector<std::int32_t> free_;  // free entries, the last freed on top
  std::vector<std::int32_t> data_;
  // Per entry: the next entry of its key's list, -1 at the end. Apart from the entries: the
  // driver pops a batch of up to 256 facets at once, mostly down one key's list, and with the
  // link inside each entry every pop waited for the miss on the entry before. Read from this
  // small array, the links are found first and the entries' misses overlap.
  std::vector<std::int32_t> next_;
};

}  // namespace drange::engine
