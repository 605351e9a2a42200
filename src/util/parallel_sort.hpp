// util/parallel_sort.hpp: sorting on a Team's threads (prepare_points.cpp: the lexicographic
// order of the points). Both sorts take a strict total order, so their result is
// unique: it depends neither on the thread count nor on the algorithm.
//
//   sort_in_parallel   any order: parts sorted at the same time, then merged pairwise.
//   sort_by_key        an order led by a double key (the first coordinate): the items are
//                      distributed into about n / 16 buckets by key, then each bucket sorted:
//                      on spread-out keys, a few passes over the items instead of log n:
//                      measurably faster on uniform points, on one thread and on two, and
//                      slightly slower on a grid with few distinct keys.
#pragma once

#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

#include "delaunay/team.hpp"

namespace drange::util {

// Merges the sorted ranges a = [begin_a, end_a) and b = [end_a, end_b) of `values` into `out`
// at begin_a, cut into `pieces` merges of equal output length that may run at the same time.
// Piece p writes the outputs [k_p, k_{p+1}); it starts where the first k_p outputs took i
// elements of a and k_p - i of b, found by binary search (`less` is a strict total order: the
// split is unique).
template <class Vector, class Less>
void merge_piece(const Vector& values, std::size_t begin_a, std::size_t end_a, std::size_t end_b, Vector& out,
                 std::size_t piece, std::size_t pieces, Less less) {
  const std::size_t size_a = end_a - begin_a, size_b = end_b - end_a, total = size_a + size_b;
  // The number of elements of a among the first k outputs.
  auto taken_from_a = [&](std::size_t k) {
    std::size_t low = k > size_b ? k - size_b : 0, high = std::min(k, size_a);
    while (low < high) {  // the smallest i whose a[i] comes after b[k - i - 1]
      const std::size_t i = low + (high - low) / 2;
      if (less(values[begin_a + i], values[end_a + (k - i - 1)])) low = i + 1;
      else high = i;
    }
    return low;
  };
  const std::size_t first = total * piece / pieces, last = total * (piece + 1) / pieces;
  const std::size_t a0 = taken_from_a(first), a1 = taken_from_a(last);
  const auto at = [&](std::size_t i) { return values.begin() + static_cast<std::ptrdiff_t>(i); };
  std::merge(at(begin_a + a0), at(begin_a + a1), at(end_a + (first - a0)), at(end_a + (last - a1)),
             out.begin() + static_cast<std::ptrdiff_t>(begin_a + first), less);
}

// Sorts `values` by `less`, a strict total order: consecutive parts sorted at the same time,
// then merged pairwise, each merge cut into pieces so that every thread has work in the last
// rounds too.
// `Vector`: a std::vector of any allocator (UninitializedVector, say), as in sort_by_key.
template <class Vector, class Less>
void sort_in_parallel(Vector& values, Less less, engine::Team& team) {
  constexpr std::size_t kMinPart = std::size_t{1} << 15;
  const auto threads = static_cast<std::size_t>(team.threads());
  const std::size_t parts = std::min(threads, values.size() / kMinPart);
  if (parts < 2) {
    std::sort(values.begin(), values.end(), less);
    return;
  }
  std::vector<std::size_t> bounds;  // part i is [bounds[i], bounds[i + 1])
  for (std::size_t i = 0; i <= parts; ++i) bounds.push_back(values.size() * i / parts);
  const auto at = [](Vector& v, std::size_t i) { return v.begin() + static_cast<std::ptrdiff_t>(i); };
  team.for_each(parts, [&](std::size_t i) { std::sort(at(values, bounds[i]), at(values, bounds[i + 1]), less); });
  Vector merged(values.size());
  while (bounds.size() > 2) {
    const std::size_t merges = (bounds.size() - 1) / 2, pieces = std::max<std::size_t>(1, threads / merges);
    team.for_each(merges * pieces, [&](std::size_t task) {
      const std::size_t p = task / pieces;
      merge_piece(values, bounds[2 * p], bounds[2 * p + 1], bounds[2 * p + 2], merged, task % pieces, pieces, less);
    });
    if ((bounds.size() - 1) % 2 == 1) {  // a lone last part is copied
      const std::size_t from = bounds[bounds.size() - 2];
      std::copy(at(values, from), values.end(), at(merged, from));
    }
    std::vector<std::size_t> next;
    for (std::size_t i = 0; i < bounds.size(); i += 2) next.push_back(bounds[i]);
    if (next.back() != bounds.back()) next.push_back(bounds.back());
    bounds.swap(next);
    values.swap(merged);
  }
}

// Sorts `values` by `less`, a strict total order that `key` (a finite double per item) leads:
// less(a, b) implies key(a) <= key(b). Bucket b holds the keys whose (key - min) * scale
// truncates to b; rounding is monotonic, so every key of bucket b is below every key of a
// later bucket, and sorting each bucket sorts the whole. Buckets of clustered keys are large
// and sorted as sort_in_parallel would, so no input is slower than that by much; keys too
// spread out for a finite scale (or all equal) go to sort_in_parallel directly.
template <class Vector, class Key, class Less>
void sort_by_key(Vector& values, Key key, Less less, engine::Team& team) {
  using T = typename Vector::value_type;
  constexpr std::size_t kPerBucket = 16;   // items per bucket on evenly spread keys
  constexpr std::size_t kMinItems = 4096;  // below, one std::sort is as fast
  const std::size_t n = values.size();
  const auto parts = static_cast<std::size_t>(team.threads());
  if (n < kMinItems) {
    sort_in_parallel(values, less, team);
    return;
  }
  // Each part: a range of the input, its keys' extremes, then its count per bucket.
  struct Part {
    std::size_t begin, end;
    double low = std::numeric_limits<double>::infinity(), high = -std::numeric_limits<double>::infinity();
    std::vector<std::size_t> count;
  };
  std::vector<Part> part(parts);
  team.for_each(parts, [&](std::size_t p) {
    Part& mine = part[p];
    mine.begin = n * p / parts;
    mine.end = n * (p + 1) / parts;
    double low = mine.low, high = mine.high;  // locals: the parts share cache lines
    for (std::size_t i = mine.begin; i < mine.end; ++i) {
      low = std::min(low, key(values[i]));
      high = std::max(high, key(values[i]));
    }
    mine.low = low;
    mine.high = high;
  });
  double low = part[0].low, high = part[0].high;
  for (const Part& p : part) {
    low = std::min(low, p.low);
    high = std::max(high, p.high);
  }
  const std::size_t buckets = n / kPerBucket;
  const double scale = static_cast<double>(buckets) / (high - low);
  if (!(scale > 0.0 && scale < std::numeric_limits<double>::infinity())) {
    sort_in_parallel(values, less, team);
    return;
  }
  const auto bucket_of = [&](const T& value) {
    const double b = (key(value) - low) * scale;  // in [0, buckets (1 + u)]: no overflow
    return std::min(static_cast<std::size_t>(b), buckets - 1);
  };
  team.for_each(parts, [&](std::size_t p) {
    Part& mine = part[p];
    mine.count.assign(buckets, 0);
    for (std::size_t i = mine.begin; i < mine.end; ++i) ++mine.count[bucket_of(values[i])];
  });
  // Where each part's items of each bucket go: bucket by bucket, parts in order within one.
  std::vector<std::size_t> bucket_begin(buckets + 1);
  std::size_t offset = 0, largest = 0;
  for (std::size_t b = 0; b < buckets; ++b) {
    bucket_begin[b] = offset;
    for (Part& p : part) {
      const std::size_t count = p.count[b];
      p.count[b] = offset;  // from now on: where the part's next item of bucket b goes
      offset += count;
    }
    largest = std::max(largest, offset - bucket_begin[b]);
  }
  bucket_begin[buckets] = n;
  if (largest > n / 8) {  // clustered keys: a few large buckets, each sorted by one thread
    sort_in_parallel(values, less, team);
    return;
  }
  Vector sorted(n);
  team.for_each(parts, [&](std::size_t p) {
    Part& mine = part[p];
    for (std::size_t i = mine.begin; i < mine.end; ++i) sorted[mine.count[bucket_of(values[i])]++] = values[i];
  });
  // The buckets in chunks of about equal item counts, several per thread (clusters vary).
  const std::size_t chunks = std::min(buckets, parts * 8);
  std::vector<std::size_t> chunk_begin(chunks + 1, buckets);
  for (std::size_t c = 0, b = 0; c < chunks; ++c) {
    while (bucket_begin[b] < n * c / chunks) ++b;
    chunk_begin[c] = b;
  }
  team.for_each(chunks, [&](std::size_t c) {
    for (std::size_t b = chunk_begin[c]; b < chunk_begin[c + 1]; ++b) {
      const auto first = sorted.begin() + static_cast<std::ptrdiff_t>(bucket_begin[b]);
      const auto last = sorted.begin() + static_cast<std::ptrdiff_t>(bucket_begin[b + 1]);
      std::sort(first, last, less);
    }
  });
  values.swap(sorted);
}

}  // namespace drange::util
