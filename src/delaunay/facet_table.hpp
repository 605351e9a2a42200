// delaunay/facet_table.hpp: the open facets of the paper's section 2.3.
//
// A facet is keyed by its d vertex ids in increasing order. The table holds the frontier only:
// a facet is inserted when the first simplex on one of its sides is found, and removed when it
// is met a second time (the simplex on its other side was found). The hash is the paper's
// polynomial in the ids, taken modulo 2^64 and mixed; collisions are resolved by linear probing,
// and removal shifts the following entries back (no tombstones), so lookups stay short. A slot
// holds the ids, the owner and the hash side by side (d + 5 ints): one cache line per probe on
// a large frontier, where the table no longer fits in cache.
//
// The hash is computed once per facet, by whoever derives the facet (facet_hash, a pure function
// that any thread may call), and passed to every call; the slot keeps it, so that removal's
// backward shift finds each entry's home slot without hashing again.
#pragma once

#include <cstdint>
#include <vector>

namespace drange::engine {

// Where a facet was seen: the simplex, and the index (0..d) of the vertex opposite the facet;
// and the facet's place in the driver's queue (the number of facets queued before it), so that
// closing it can mark it there (frontier.hpp).
struct FacetOwner {
  std::int32_t simplex;
  std::int32_t face;
  std::int64_t entry = -1;
};

// The hash of a facet of d sorted ids. Only its low 32 bits are kept: they index the slots
// (the table never comes near 2^32 slots).
inline std::uint32_t facet_hash(const std::int32_t* sorted_ids, int d) {
  std::uint64_t h = 0;
  for (int k = 0; k < d; ++k) h = h * 0x9E3779B97F4A7C15ull + static_cast<std::uint32_t>(sorted_ids[k]);
  h ^= h >> 29;
  h *= 0xBF58476D1CE4E5B9ull;
  return static_cast<std::uint32_t>(h ^ (h >> 32));
}

class FacetTable {
 public:
  explicit FacetTable(int d) : d_(d) { rehash(1024); }

  // Every `hash` below is facet_hash(sorted_ids, d).
  // If the facet is open, removes it and returns its owner through `other` (true: closed).
  // Otherwise inserts it as open with `owner` and returns false.
  bool close_or_open(const std::int32_t* sorted_ids, std::uint32_t hash, FacetOwner owner, FacetOwner* other);
  bool contains(const std::int32_t* sorted_ids, std::uint32_t hash) const { return find(sorted_ids, hash) >= 0; }
  // Removes the facet if it is open; returns whether it was.
  bool remove(const std::int32_t* sorted_ids, std::uint32_t hash) {
    const long slot = find(sorted_ids, hash);
    if (slot < 0) return false;
    erase(static_cast<std::size_t>(slot));
    return true;
  }
  // Asks the cache for the facet's home slot ahead of a lookup: on a frontier larger than the
  // cache, each lookup is a miss, and several issued together overlap.
  void prefetch(std::uint32_t hash) const {
    const std::int32_t* slot = &slots_[(hash & mask_) * stride()];
    __builtin_prefetch(slot, 1);
    // An empty volatile asm: without a visible effect, GCC takes a caller that only prefetches
    // (Frontier::prefetch_ahead) for a pure function and drops the call.
    asm volatile("" : : "r"(slot));
  }
  std::size_t size() const { return size_; }
  std::size_t memory_bytes() const { return slots_.capacity() * sizeof(std::int32_t); }

 private:
  std::size_t stride() const { return static_cast<std::size_t>(d_) + 5; }
  std::int32_t* slot_ids(std::size_t slot) { return &slots_[slot * stride()]; }
  const std::int32_t* slot_ids(std::size_t slot) const { return &slots_[slot * stride()]; }
  FacetOwner owner(std::size_t slot) const {
    const std::int32_t* s = slot_ids(slot) + d_;
    const auto entry = static_cast<std::int64_t>((std::uint64_t(std::uint32_t(s[3])) << 32) | std::uint32_t(s[2]));
    return FacetOwner{s[0], s[1], entry};
  }
  void set_owner(std::size_t slot, FacetOwner owner) {
    std::int32_t* s = slot_ids(slot) + d_;
    s[0] = owner.simplex;
    s[1] = owner.face;
    s[2] = static_cast<std::int32_t>(static_cast<std::uint32_t>(static_cast<std::uint64_t>(owner.entry)));
    s[3] = static_cast<std::int32_t>(static_cast<std::uint32_t>(static_cast<std::uint64_t>(owner.entry) >> 32));
  }
  std::uint32_t stored_hash(std::size_t slot) const { return static_cast<std::uint32_t>(slot_ids(slot)[d_ + 4]); }
  bool empty(std::size_t slot) const { return slots_[slot * stride()] < 0; }
  bool equal(std::size_t slot, const std::int32_t* ids) const {
    const std::int32_t* s = slot_ids(slot);
    const int d = d_;  // a local: the compiler cannot tell that ids do not alias d_
    for (int k = 0; k < d; ++k)
      if (s[k] != ids[k]) return false;
    return true;
  }
  long find(const std::int32_t* ids, std::uint32_t h) const;
  void erase(std::size_t slot);
  void rehash(std::size_t capacity);

  int d_;
  std::size_t mask_ = 0;
  std::size_t size_ = 0;
  // capacity slots of d + 5 ints: the ids (-1 in the first marks an empty slot), then the owner
  // (simplex, face, and the queue entry's low and high halves), then the hash.
  std::vector<std::int32_t> slots_;
};

}  // namespace drange::engine
