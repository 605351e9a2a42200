// delaunay/facet_table.cpp: open addressing with backward-shift deletion.
#include "delaunay/facet_table.hpp"

#include <algorithm>

namespace drange::engine {

long FacetTable::find(const std::int32_t* ids, std::uint64_t h) const {
  for (std::size_t slot = h & mask_;; slot = (slot + 1) & mask_) {
    if (empty(slot)) return -1;
    if (equal(slot, ids)) return static_cast<long>(slot);
  }
}

bool FacetTable::close_or_open(const std::int32_t* ids, FacetOwner owner, FacetOwner* other) {
  const std::uint64_t h = hash(ids);
  std::size_t slot = h & mask_;
  for (;; slot = (slot + 1) & mask_) {
    if (empty(slot)) break;
    if (equal(slot, ids)) {
      *other = this->owner(slot);
      erase(slot);
      return true;
    }
  }
  std::copy(ids, ids + d_, slot_ids(slot));
  set_owner(slot, owner);
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
    const std::size_t home = hash(slot_ids(next)) & mask_;
    // The entry at `next` may move to `hole` if its home is not in the cyclic range (hole, next].
    const bool home_after_hole = (next > hole) ? (home > hole && home <= next) : (home > hole || home <= next);
    if (home_after_hole) continue;
    std::copy(slot_ids(next), slot_ids(next) + stride(), slot_ids(hole));  // ids and owner
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
    std::size_t slot = hash(entry) & mask_;
    while (!empty(slot)) slot = (slot + 1) & mask_;
    std::copy(entry, entry + stride(), slot_ids(slot));
  }
}

}  // namespace drange::engine
