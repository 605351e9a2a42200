// util/select_nth.hpp: std::nth_element's contract, with partitions that do not branch on the
// comparison.
//
// The kd-tree build (spatial/kdtree.cpp) splits every node at the median of random keys, where
// each branch of std::nth_element's partition goes either way with equal odds: about half of
// them are mispredicted. Here the partition is Lomuto's, with the element moves made whatever
// the comparison says and only the write position advanced by it (A. Alexandrescu, "Lomuto's
// Comeback", 2020): a comparison costs a few instructions and no misprediction. The pivot is
// the median of three, of three medians of three from 256 elements, or from 4 096 elements an
// element of a sample chosen for nth's rank (sampled_pivot_to_first); a range that does not
// shrink fast enough (a pathological order) is finished by std::nth_element.
//
// With a strict total order (the kd-tree's: key, then index), the elements before and after nth
// are the same sets whatever the algorithm, so the result matches std::nth_element's up to the
// order within each side.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <type_traits>
#include <utility>

namespace drange::util {

namespace select_detail {

// The partition moves its elements as whole objects, padding included (T is trivially
// copyable): a member-wise copy of the kd-tree's items stores their 4-byte index alone, and a
// later 8-byte load of the same place (the index and the padding after it) then waits for
// that store to leave the store buffer instead of taking its value from it. With the copy
// compared too, GCC keeps it on the stack to index its coordinate by the split axis. Whole
// objects make KdTree::build_and_reorder measurably faster in 2D to 4D. (The few moves
// elsewhere here are not worth it: as whole objects, they were slightly slower in 2D.)
template <class T>
void copy_object(T* to, const T* from) {
  static_assert(std::is_trivially_copyable_v<T>, "moved as bytes");
  std::memcpy(static_cast<void*>(to), static_cast<const void*>(from), sizeof(T));
}
template <class T>
void swap_objects(T* a, T* b) {
  T t;
  copy_object(&t, a);
  copy_object(a, b);
  copy_object(b, &t);
}

// Moves the median of *a, *b, *c (by `less`) to *a.
template <class T, class Less>
void median_to(T* a, T* b, T* c, Less less) {
  if (less(*b, *a)) std::swap(*a, *b);   // a <= b
  if (less(*c, *b)) {                     // c < b: the median is max(a, c)
    if (less(*a, *c)) std::swap(*a, *c);  // c is the median
    return;
  }
  std::swap(*a, *b);  // a <= b <= c: b is the median
}

// Partitions [first, last) around the pivot *first: returns p with *p the pivot, every element
// of [first, p) less than it, and none of (p, last). Out of line: inlined into select_nth's
// loop, it made the kd-tree build slower.
template <class T, class Less>
[[gnu::noinline]] T* partition_around_first(T* first, T* last, Less less) {
  T pivot;
  copy_object(&pivot, first);
  T* write = first + 1;  // [first + 1, write) < pivot <= [write, read)
  for (T* read = first + 1; read != last; ++read) {
    const bool smaller = less(*read, pivot);
    swap_objects(read, write);
    write += smaller;
  }
  --write;
  copy_object(first, write);
  copy_object(write, &pivot);
  return write;
}

}  // namespace select_detail

template <class T, class Less>
void select_nth(T* first, T* nth, T* last, Less less);

namespace select_detail {

// From this many elements on, the pivot is taken from a sample (sampled_pivot_to_first).
constexpr std::ptrdiff_t kSampleFrom = 4096;

// Moves to *first a pivot chosen from a sample of [first, last) so that nth lands, with high
// probability, on the smaller side of the partition and close to the pivot (R. W. Floyd and
// R. L. Rivest, "Expected time bounds for selection", 1975): the sample's element of rank
// nth's rank scaled to the sample, moved by a few standard deviations of that estimate away
// from the range's middle. The median of 2^k points then costs about 1.5 passes over them
// (one over the whole range, one over the half that holds nth, then over a few percent),
// where pivots near the middle of the range cost about 2.5.
template <class T, class Less>
void sampled_pivot_to_first(T* first, T* nth, T* last, Less less) {
  const std::ptrdiff_t n = last - first, k = nth - first;
  // The sample: s elements at a fixed stride, gathered to the front. s ~ n^(2/3) / 2, the
  // classic choice; its own selection then costs about 1% of the pass.
  const auto s = static_cast<std::ptrdiff_t>(0.5 * std::cbrt(static_cast<double>(n) * static_cast<double>(n)));
  const std::ptrdiff_t stride = n / s;
  for (std::ptrdiff_t i = 1; i < s; ++i) std::swap(first[i], first[i * stride]);
  // Rank error of the scaled estimate: about sqrt(s) / 2 sample positions at the middle; the
  // margin of 2 standard deviations misses (nth on the large side) about 2% of the time.
  const auto margin = static_cast<std::ptrdiff_t>(std::sqrt(static_cast<double>(s)));
  std::ptrdiff_t r = static_cast<std::ptrdiff_t>(static_cast<double>(k) * static_cast<double>(s) / static_cast<double>(n));
  r += 2 * k < n ? margin : -margin;
  r = std::clamp<std::ptrdiff_t>(r, 0, s - 1);
  select_nth(first, first + r, first + s, less);
  std::swap(*first, first[r]);
}

}  // namespace select_detail

// Rearranges [first, last) so that *nth is the element a full sort would put there, none of
// [first, nth) comes after it and none of (nth, last) before it.
template <class T, class Less>
void select_nth(T* first, T* nth, T* last, Less less) {
  using select_detail::median_to;
  constexpr std::ptrdiff_t kSmall = 16;  // sorted outright
  int budget = 8;
  for (std::ptrdiff_t n = last - first; n > 1; n >>= 1) budget += 2;
  while (last - first > kSmall) {
    if (budget-- == 0) {
      std::nth_element(first, nth, last, less);
      return;
    }
    const std::ptrdiff_t n = last - first;
    if (n >= select_detail::kSampleFrom) {
      select_detail::sampled_pivot_to_first(first, nth, last, less);
    } else {
      T* middle = first + n / 2;
      if (n >= 256) {  // Tukey's ninther: a pivot nearer the median in fewer passes
        const std::ptrdiff_t step = n / 8;
        median_to(first + 1, first + 1 + step, first + 1 + 2 * step, less);
        median_to(middle, middle - step, middle + step, less);
        median_to(last - 1, last - 1 - step, last - 1 - 2 * step, less);
        median_to(middle, first + 1, last - 1, less);
      } else {
        median_to(middle, first, last - 1, less);
      }
      std::swap(*first, *middle);
    }
    T* pivot = select_detail::partition_around_first(first, last, less);
    if (pivot == nth) return;
    if (nth < pivot) last = pivot;
    else first = pivot + 1;
  }
  // Insertion sort of the few left.
  for (T* i = first + 1; i < last; ++i) {
    T x = std::move(*i);
    T* j = i;
    for (; j > first && less(x, *(j - 1)); --j) *j = std::move(*(j - 1));
    *j = std::move(x);
  }
}

}  // namespace drange::util
