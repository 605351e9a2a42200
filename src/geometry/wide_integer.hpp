// geometry/wide_integer.hpp: signed integers of a fixed number of 64-bit limbs.
//
// The exact stage of the small predicates (wide_determinant.hpp) needs integers of 64 to 384
// bits whose sizes are known at compile time from the formula. Two's complement in N limbs,
// least significant first; every operation is written for its sizes, unrolled, and checks
// nothing: the caller bounds every value so that it fits.
#pragma once

#include <cstdint>

namespace drange::geometry {

__extension__ typedef __int128 Int128;
__extension__ typedef unsigned __int128 Uint128;

template <int N>
struct Wide {
  std::uint64_t limb[N];

  static Wide from(Int128 x) {
    Wide w;
    w.limb[0] = static_cast<std::uint64_t>(x);
    if constexpr (N > 1) w.limb[1] = static_cast<std::uint64_t>(static_cast<Uint128>(x) >> 64);
    const std::uint64_t extension = x < 0 ? ~std::uint64_t{0} : 0;
    for (int i = 2; i < N; ++i) w.limb[i] = extension;
    return w;
  }
  bool negative() const { return (limb[N - 1] >> 63) != 0; }
  int sign() const {
    if (negative()) return -1;
    for (int i = 0; i < N; ++i)
      if (limb[i] != 0) return 1;
    return 0;
  }
};

#define DRANGE_WIDE_INLINE [[gnu::always_inline]] inline

template <int N>
DRANGE_WIDE_INLINE Wide<N> operator+(const Wide<N>& a, const Wide<N>& b) {
  Wide<N> out;
  std::uint64_t carry = 0;
  for (int i = 0; i < N; ++i) {
    const Uint128 sum = Uint128{a.limb[i]} + b.limb[i] + carry;
    out.limb[i] = static_cast<std::uint64_t>(sum);
    carry = static_cast<std::uint64_t>(sum >> 64);
  }
  return out;
}

template <int N>
DRANGE_WIDE_INLINE Wide<N> operator-(const Wide<N>& a) {
  Wide<N> out;
  std::uint64_t carry = 1;
  for (int i = 0; i < N; ++i) {
    const Uint128 sum = Uint128{~a.limb[i]} + carry;
    out.limb[i] = static_cast<std::uint64_t>(sum);
    carry = static_cast<std::uint64_t>(sum >> 64);
  }
  return out;
}

template <int N>
DRANGE_WIDE_INLINE Wide<N> operator-(const Wide<N>& a, const Wide<N>& b) {
  return a + -b;
}

// The product, in A + B limbs (where the product of A- and B-limb values always fits).
template <int A, int B>
DRANGE_WIDE_INLINE Wide<A + B> operator*(const Wide<A>& a, const Wide<B>& b) {
  const bool negative = a.negative() != b.negative();
  const Wide<A> x = a.negative() ? -a : a;  // magnitudes (the most negative value never occurs)
  const Wide<B> y = b.negative() ? -b : b;
  Wide<A + B> out;
  for (int i = 0; i < A + B; ++i) out.limb[i] = 0;
  for (int i = 0; i < A; ++i) {
    std::uint64_t carry = 0;
    for (int j = 0; j < B; ++j) {
      const Uint128 t = Uint128{x.limb[i]} * y.limb[j] + out.limb[i + j] + carry;
      out.limb[i + j] = static_cast<std::uint64_t>(t);
      carry = static_cast<std::uint64_t>(t >> 64);
    }
    out.limb[i + B] = carry;
  }
  return negative ? -out : out;
}

// a in M >= N limbs (sign-extended).
template <int M, int N>
DRANGE_WIDE_INLINE Wide<M> widen(const Wide<N>& a) {
  static_assert(M >= N, "widen only widens");
  Wide<M> out;
  for (int i = 0; i < N; ++i) out.limb[i] = a.limb[i];
  for (int i = N; i < M; ++i) out.limb[i] = a.negative() ? ~std::uint64_t{0} : 0;
  return out;
}

#undef DRANGE_WIDE_INLINE

}  // namespace drange::geometry
