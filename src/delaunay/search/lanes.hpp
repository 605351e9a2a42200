// delaunay/search/lanes.hpp: the leaf scan's arithmetic over a block's lanes (LeafBlocks), two
// doubles at a time (SSE2 on x86-64, NEON on AArch64) or four (AVX2, chosen at run time).
//
// Every function returns a bit mask of lanes rather than a value per lane: the scan then
// branches once per selected point, not once per lane. Each lane's operations, and their
// order, are those of the one-point versions they stand for (CandidateBall::holds, the
// kernel's prune, the plane's filter), so the same points pass whatever the vector width; the
// AVX2 versions use no FMA, so their doubles are the two-double versions' too.
#pragma once

#include <cstring>

#include "delaunay/leaf_blocks.hpp"
#include "geometry/error_bound.hpp"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define DRANGE_AVX2_LANES 1
#include <immintrin.h>
#else
#define DRANGE_AVX2_LANES 0
#endif

namespace drange::engine::lanes {
// Internal linkage, as for the search kernel that includes this (search_kernel.hpp): the
// compiler then inlines each function into its one caller where that pays.
namespace {

// Two doubles as one value (GCC and Clang vector extensions). Unaligned loads.
using Pair = double __attribute__((vector_size(2 * sizeof(double))));
constexpr int kLanes = LeafBlocks::kLanes;
constexpr int kPairs = kLanes / 2;
constexpr unsigned kAllLanes = (1u << kLanes) - 1;

inline Pair load_pair(const double* x) {
  Pair v;
  std::memcpy(&v, x, sizeof v);
  return v;
}

// The lanes whose squared distance is not above reach2 (NaN counts as in reach).
inline unsigned not_above(const Pair* distance2, double reach2) {
  const Pair reach = {reach2, reach2};
  unsigned mask = 0;
  for (int i = 0; i < kPairs; ++i) {
    const auto above = distance2[i] > reach;
    mask |= static_cast<unsigned>((above[0] & 1) | (above[1] & 2)) << (2 * i);
  }
  return ~mask & kAllLanes;
}

// The lanes (kPairs pairs of a value and its absolute tree) whose sign the filter
// certified_sign_with certifies negative with the bound factor `factor`.
inline unsigned certified_negative(const Pair* value, const Pair* abs_tree, double factor) {
  const Pair gamma = {factor, factor};
  const Pair low = {geometry::kFilterUnderflow, geometry::kFilterUnderflow};
  const Pair high = {geometry::kFilterOverflow, geometry::kFilterOverflow};
  unsigned negative = 0;
  for (int i = 0; i < kPairs; ++i) {
    const auto certified = (abs_tree[i] > low) & (abs_tree[i] < high) & (value[i] < -(gamma * abs_tree[i]));
    negative |= static_cast<unsigned>((certified[0] & 1) | (certified[1] & 2)) << (2 * i);
  }
  return negative;
}

#if DRANGE_AVX2_LANES
// Four doubles as one value, for the AVX2 versions.
using Quad = double __attribute__((vector_size(4 * sizeof(double))));
constexpr int kQuads = kLanes / 4;
__attribute__((target("avx2"))) inline Quad load_quad(const double* x) {
  Quad v;
  std::memcpy(&v, x, sizeof v);
  return v;
}
__attribute__((target("avx2"))) inline Quad broadcast(double x) { return Quad{x, x, x, x}; }

__attribute__((target("avx2"))) inline unsigned not_above(const Quad* distance2, double reach2) {
  unsigned mask = 0;
  for (int i = 0; i < kQuads; ++i)
    mask |= static_cast<unsigned>(_mm256_movemask_pd(_mm256_cmp_pd(reinterpret_cast<__m256d>(distance2[i]), _mm256_set1_pd(reach2), _CMP_NGT_UQ))) << (4 * i);
  return mask;
}

template <int D>
__attribute__((target("avx2"))) unsigned points_in_reach_avx2(const double* lanes, const double* centre, int d, double reach2) {
  if constexpr (D > 0) d = D;
  Quad sum[kQuads];
  const Quad c0 = broadcast(centre[0]);
  for (int i = 0; i < kQuads; ++i) {
    const Quad delta = load_quad(lanes + 4 * i) - c0;
    sum[i] = delta * delta;
  }
  for (int k = 1; k < d; ++k) {
    const Quad c = broadcast(centre[k]);
    for (int i = 0; i < kQuads; ++i) {
      const Quad delta = load_quad(lanes + k * kLanes + 4 * i) - c;
      sum[i] += delta * delta;
    }
  }
  return not_above(sum, reach2);
}

// The squared distance on one axis from c to four boxes [lo, hi]. MAXPD gives its second
// operand unless the first is greater: these are the selects below > above ? below : above
// and delta > 0 ? delta : 0 (NaN and -0 give 0) of the SSE2 version, one instruction each.
__attribute__((target("avx2"))) inline Quad box_square(const double* lo, const double* hi, Quad c) {
  const Quad below = load_quad(lo) - c, above = c - load_quad(hi);
  const __m256d larger = _mm256_max_pd(reinterpret_cast<__m256d>(below), reinterpret_cast<__m256d>(above));
  const Quad delta = reinterpret_cast<Quad>(_mm256_max_pd(larger, _mm256_setzero_pd()));
  return delta * delta;
}

template <int D>
__attribute__((target("avx2"))) unsigned boxes_in_reach_avx2(const double* boxes, const double* centre, int d, double reach2) {
  if constexpr (D > 0) d = D;
  // The first axis starts the sum: 0 + delta^2 is delta^2 (a square is never -0).
  Quad sum[kQuads];
  for (int i = 0; i < kQuads; ++i) sum[i] = box_square(boxes + 4 * i, boxes + d * kLanes + 4 * i, broadcast(centre[0]));
  for (int k = 1; k < d; ++k) {
    const Quad c = broadcast(centre[k]);
    for (int i = 0; i < kQuads; ++i) sum[i] += box_square(boxes + k * kLanes + 4 * i, boxes + (d + k) * kLanes + 4 * i, c);
  }
  return not_above(sum, reach2);
}
#endif

// The lanes of a block (transposed coordinates) whose squared distance to `centre` is not
// above reach2, two lanes at a time: the region's arithmetic, lane by lane. Empty lanes lie at infinity and never are.
template <int D>
unsigned points_in_reach_pairs(const double* lanes, const double* centre, int d, double reach2) {
  if constexpr (D > 0) d = D;
  Pair sum[kPairs];
  const Pair c0 = {centre[0], centre[0]};
  for (int i = 0; i < kPairs; ++i) {
    const Pair delta = load_pair(lanes + 2 * i) - c0;
    sum[i] = delta * delta;
  }
  for (int k = 1; k < d; ++k) {
    const Pair c = {centre[k], centre[k]};
    const double* x = lanes + k * kLanes;
    for (int i = 0; i < kPairs; ++i) {
      const Pair delta = load_pair(x + 2 * i) - c;
      sum[i] += delta * delta;
    }
  }
  return not_above(sum, reach2);
}

// The blocks of a group whose box's lower bound of the squared distance to `centre` is not
// above reach2: prune's arithmetic, lane by lane (rounding is monotonic, so it bounds the
// computed distance of every point in the box). Empty slots lie at infinity and never are.
template <int D>
unsigned boxes_in_reach_pairs(const double* boxes, const double* centre, int d, double reach2) {
  if constexpr (D > 0) d = D;
  const Pair zero = {0.0, 0.0};
  Pair sum[kPairs];
  for (int i = 0; i < kPairs; ++i) sum[i] = zero;
  for (int k = 0; k < d; ++k) {
    const Pair c = {centre[k], centre[k]};
    const double* lo = boxes + k * kLanes;
    const double* hi = boxes + (d + k) * kLanes;
    for (int i = 0; i < kPairs; ++i) {
      const Pair below = load_pair(lo + 2 * i) - c;
      const Pair above = c - load_pair(hi + 2 * i);
      Pair delta = below > above ? below : above;
      delta = delta > zero ? delta : zero;
      sum[i] += delta * delta;
    }
  }
  return not_above(sum, reach2);
}

}  // namespace
}  // namespace drange::engine::lanes
