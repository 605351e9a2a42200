// util/key_groups.hpp: finds the items that share a key, where a key is a short sorted list
// of vertex ids (a facet, a ridge). Used for facet pairing and for ridge adjacency.
//
// No hashing: a counting sort on the first id of the key puts the items into one bucket per
// vertex, then each bucket (small: the facets whose smallest vertex is v) is sorted on the rest
// of the key and scanned for runs of equal keys. Linear in the number of items plus the
// number of vertices, deterministic, and collision-free by construction.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace drange::util {

// `for_each_item(f)` calls f(item) for every item (it is called twice, and must enumerate the
// same items both times); `key(item, k)` is id k (0 <= k < key_length) of the item's key, ids in
// [0, vertex_count) (non-negative 32-bit), increasing in k. `visit(const Item* group, std::size_t size)` is called once
// per distinct key with all items that have it, in increasing key order.
template <class Item, class ForEachItem, class Key, class Visit>
void for_each_key_group(std::size_t vertex_count, int key_length, ForEachItem for_each_item, Key key, Visit visit) {
  std::vector<std::size_t> start(vertex_count + 1, 0);
  for_each_item([&](Item item) { ++start[static_cast<std::size_t>(key(item, 0)) + 1]; });
  for (std::size_t v = 0; v < vertex_count; ++v) start[v + 1] += start[v];

  std::vector<Item> items(start[vertex_count]);
  {
    std::vector<std::size_t> next(start.begin(), start.end() - 1);
    for_each_item([&](Item item) { items[next[static_cast<std::size_t>(key(item, 0))]++] = item; });
  }

  // Inside a bucket, ids 1 and 2 of each key are packed into one integer, read once per item
  // (the reads are the cache misses); ids 3 and beyond, compared only on ties, are rare work.
  struct Entry {
    std::uint64_t packed;
    Item item;
  };
  auto pack = [&](Item item) {
    std::uint64_t packed = 0;
    if (key_length > 1) packed = static_cast<std::uint64_t>(static_cast<std::uint32_t>(key(item, 1))) << 32;
    if (key_length > 2) packed |= static_cast<std::uint32_t>(key(item, 2));
    return packed;
  };
  auto rest_less = [&](Item a, Item b) {
    for (int k = 3; k < key_length; ++k) {
      const auto ka = key(a, k), kb = key(b, k);
      if (ka != kb) return ka < kb;
    }
    return false;
  };
  auto less = [&](const Entry& a, const Entry& b) {
    if (a.packed != b.packed) return a.packed < b.packed;
    return rest_less(a.item, b.item);
  };
  auto same = [&](const Entry& a, const Entry& b) {
    return a.packed == b.packed && !rest_less(a.item, b.item) && !rest_less(b.item, a.item);
  };

  std::vector<Entry> bucket;
  std::vector<Item> group;
  for (std::size_t v = 0; v < vertex_count; ++v) {
    if (start[v] == start[v + 1]) continue;
    bucket.clear();
    for (std::size_t i = start[v]; i < start[v + 1]; ++i) bucket.push_back({pack(items[i]), items[i]});
    std::sort(bucket.begin(), bucket.end(), less);
    for (std::size_t first = 0; first < bucket.size();) {
      std::size_t end = first + 1;
      while (end < bucket.size() && same(bucket[first], bucket[end])) ++end;
      group.clear();
      for (std::size_t i = first; i < end; ++i) group.push_back(bucket[i].item);
      visit(static_cast<const Item*>(group.data()), group.size());
      first = end;
    }
  }
}

}  // namespace drange::util
