// geometry/wide_integer.hpp: signed integers of a fixed number of 64-bit limbs.
//
// The exact stage of the small predicates (wide_determinant.hpp) needs integers of 64 to 384
// bits whose sizes are known at compile time from the formula. Two's complement in N limbs,
// least significant first; every operation is written for its sizes, unrolled, and checks
// nothing: the caller bounds every value so that it fits.
#pragma once

#include <cstdint>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <x86intrin.h>
#endif

namespace drange::geometry {

__extension__ typedef __int128 Int128;
__extension__ typedef unsigned __int128 Uint128;

// One limb of a carry (borrow) chain: a + b + carry_in, the carry out through `carry`. On
// x86-64 the intrinsics keep the chain in the carry flag (adc, sbb), where the 128-bit sums
// that C++ spells it with cost a shift, a mask and a move per limb.
[[gnu::always_inline]] inline std::uint64_t add_with_carry(std::uint64_t a, std::uint64_t b, unsigned char& carry) {
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
  unsigned long long out;
  carry = _addcarry_u64(carry, a, b, &out);
  return out;
#else
  const Uint128 sum = Uint128{a} + b + carry;
  carry = static_cast<unsigned char>(sum >> 64);
  return static_cast<std::uint64_t>(sum);
#endif
}
[[gnu::always_inline]] inline std::uint64_t subtract_with_borrow(std::uint64_t a, std::uint64_t b, unsigned char& borrow) {
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
  unsigned long long out;
  borrow = _subborrow_u64(borrow, a, b, &out);
  return out;
#else
  const Uint128 difference = Uint128{a} - b - borrow;
  borrow = static_cast<unsigned char>((difference >> 64) & 1);
  return static_cast<std::uint64_t>(difference);
#endif
}

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
  unsigned char carry = 0;
  for (int i = 0; i < N; ++i) out.limb[i] = add_with_carry(a.limb[i], b.limb[i], carry);
  return out;
}

template <int N>
DRANGE_WIDE_INLINE Wide<N> operator-(const Wide<N>& a) {
  Wide<N> out;
  unsigned char borrow = 0;
  for (int i = 0; i < N; ++i) out.limb[i] = subtract_with_borrow(0, a.limb[i], borrow);
  return out;
}

template <int N>
DRANGE_WIDE_INLINE Wide<N> operator-(const Wide<N>& a, const Wide<N>& b) {
  Wide<N> out;
  unsigned char borrow = 0;
  for (int i = 0; i < N; ++i) out.limb[i] = subtract_with_borrow(a.limb[i], b.limb[i], borrow);
  return out;
}

// The product, in A + B limbs (where the product of A- and B-limb values always fits). The
// limbs are multiplied as unsigned, then corrected for the signs: a negative a stands for
// a + 2^(64 A) there, which adds b 2^(64 A) to the product, so b is taken off the upper B
// limbs (and a off the upper A limbs for a negative b); 2^(64 (A + B)) falls out of range.
// Without branches, where taking magnitudes first and negating the product would take three
// conditional negations.
template <int A, int B>
DRANGE_WIDE_INLINE Wide<A + B> operator*(const Wide<A>& a, const Wide<B>& b) {
  Wide<A + B> out;
  for (int i = 0; i < A + B; ++i) out.limb[i] = 0;
  for (int i = 0; i < A; ++i) {
    std::uint64_t carry = 0;
    for (int j = 0; j < B; ++j) {
      const Uint128 t = Uint128{a.limb[i]} * b.limb[j] + out.limb[i + j] + carry;
      out.limb[i + j] = static_cast<std::uint64_t>(t);
      carry = static_cast<std::uint64_t>(t >> 64);
    }
    out.limb[i + B] = carry;
  }
  const std::uint64_t a_mask = a.negative() ? ~std::uint64_t{0} : 0, b_mask = b.negative() ? ~std::uint64_t{0} : 0;
  unsigned char borrow = 0;
  for (int j = 0; j < B; ++j) out.limb[A + j] = subtract_with_borrow(out.limb[A + j], b.limb[j] & a_mask, borrow);
  borrow = 0;
  for (int i = 0; i < A; ++i) out.limb[B + i] = subtract_with_borrow(out.limb[B + i], a.limb[i] & b_mask, borrow);
  return out;
}

// a in M limbs: sign-extended, or its low M limbs where the value is known to fit in them.
template <int M, int N>
DRANGE_WIDE_INLINE Wide<M> resize(const Wide<N>& a) {
  Wide<M> out;
  for (int i = 0; i < M; ++i) out.limb[i] = i < N ? a.limb[i] : (a.negative() ? ~std::uint64_t{0} : 0);
  return out;
}

#undef DRANGE_WIDE_INLINE

}  // namespace drange::geometry
