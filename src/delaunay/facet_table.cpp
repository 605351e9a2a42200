// delaunay/facet_table.cpp: open addressing with backward-shift deletion.
#include "delaunay/facet_table.hpp"

#include <algorithm>

#include "util/return_free_memory.hpp"

namespace drange::engine {

long FacetTable::find(const std::int32_t* ids, std::uint32_t h) const {
  for (std::size_t slot = h & mask_;; slot = (slot + 1) & mask_) {
    if (empty(slot)) return -1;
    if (equal(slot, ids)) return static_cast<long>(slot);
  }
}

bool FacetTable::close_or_open(const std::int32_t* ids, std::uint32_t h, FacetOwner owner, FacetOwner* other) {
  std::size_t slot = h & mask_;
  for (;; slot = (slot + 1) & mask_) {
    if (empty(slot)) break;
    if (equal(slot, ids)) {
      *other = this->owner(slot);
      erase(slot);
      return true;
    }
  }
  std::int32_t* entry = slot_ids(slot);
  const int d = d_;
  for (int k = 0; k < d; ++k) entry[k] = ids[k];  // a loop: std::copy of a few ints calls memmove
  set_owner(slot, owner);
  entry[d + 4] = static_cast<std::int32_t>(h);
  if (++size_ * 2 > mask_ + 1) rehash((mask_ + 1) * 2);
  return false;
}

void FacetTable::erase(std::size_t hole) {
  // Backward shift: move later entries of the same probe run into the hole, so that every
  // entry stays reachable from its home slot without tombstones.
  --size_;
  std::size_t next = hole;
  for (;;) {
    next = (next + 1) & mask_;
    if (empty(next)) break;
    const std::size_t home = stored_hash(next) & mask_;
    // The entry at `next` may move to `hole` if its home is not in the cyclic range (hole, next].
    const bool home_after_hole = (next > hole) ? (home > hole && home <= next) : (home > hole || home <= next);
    if (home_after_hole) continue;
    const std::int32_t* from = slot_ids(next);
    std::int32_t* to = slot_ids(hole);
    for (std::size_t k = 0, n = stride(); k < n; ++k) to[k] = from[k];  // ids, owner and hash
    hole = next;
  }
  slot_ids(hole)[0] = -1;
}

void FacetTable::rehash(std::size_t capacity) {
  std::vector<std::int32_t> old(capacity * stride(), -1);
  old.swap(slots_);
  const std::size_t old_capacity = old.size() / stride();
  mask_ = capacity - 1;
  for (std::size_t s = 0; s < old_capacity; ++s) {
    const std::int32_t* entry = &old[s * stride()];
    if (entry[0] < 0) continue;
    std::size_t slot = static_cast<std::uint32_t>(entry[d_ + 4]) & mask_;
    while (!empty(slot)) slot = (slot + 1) & mask_;
    std::copy(entry, entry + stride(), slot_ids(slot));
  }
  std::vector<std::int32_t>().swap(old);
  util::return_free_memory();
}

}  // namespace drange::engine
