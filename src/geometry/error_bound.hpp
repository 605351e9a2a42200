// geometry/error_bound.hpp: the forward error bound that every floating-point filter uses.
//
// A polynomial evaluated in IEEE double arithmetic along a fixed expression tree, with at most
// n roundings on any path from an input to the result, has an absolute error of at most
// gamma(n) * P, where P is the same tree evaluated on the absolute values of the inputs with
// every subtraction turned into an addition, and gamma(n) = n u / (1 - n u), u = 2^-53
// (Higham, "Accuracy and Stability of Numerical Algorithms", 2nd ed., section 3.1).
// P is itself computed in floating point; its own relative error is below gamma(n) too, which
// the safety factor below absorbs. Underflow adds to that an absolute error: each product that
// underflows is off by up to 2^-1075, times whatever multiplies it later. The filters treat
// tiny magnitudes of P as undecided and let the exact code decide; above that floor the
// safety factor's 1e-6 absorbs the absolute error wherever it is bounded (kUnderflowError).
#pragma once

#include <cfenv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#if defined(__x86_64__) && defined(__SSE2__)
#include <xmmintrin.h>
#endif

#include "geometry/double_bits.hpp"

namespace drange::geometry {

constexpr double kUnitRoundoff = 0x1p-53;
// Below this magnitude of P a filter does not decide (denormals and underflow are possible).
// Above it, 1e-6 gamma P > 2^-20 2^-53 2^-800 = 2^-873, far above kUnderflowError.
constexpr double kFilterUnderflow = 0x1p-800;
// A bound on the absolute error that underflow adds to any value the search computes from
// points scaled below 1 in magnitude (PointStore::scaled; d <= 11): the minors of the facet's
// lifted rows, the candidate's w and I(p, x) (lifted_sphere_test.hpp, facet_plane_test.hpp). The entries of the
// lifted rows are below 2^6, so the (d-1)-minors are below 10! 2^60 < 2^82, w below 2^92 and
// I below 2^102; an underflowing product is multiplied afterwards by at most 2^94 (the
// cofactor of the deepest lift entry's square), and the expanded expression of I has fewer
// than 2^35 products: 2^35 2^-1075 2^94 = 2^-946. Nothing overflows there, and so nothing is
// invalid either: the search reads no floating-point flag.
constexpr double kUnderflowError = 0x1p-940;
// Above it, overflow is possible in the evaluation.
constexpr double kFilterOverflow = 0x1p+900;

constexpr double gamma_bound(int n) {
  return (1.0 + 1e-6) * (n * kUnitRoundoff) / (1.0 - n * kUnitRoundoff) * (1.0 + (n + 1) * kUnitRoundoff);
}

// Roundings on any path of the Laplace expansion of a k x k determinant whose entries carry up
// to `entry_roundings` roundings each: k products of entries, the expansion's own products and
// the sums along each row (at most k terms).
constexpr int laplace_roundings(int k, int entry_roundings) { return k * entry_roundings + k * (k + 2); }

// Roundings in an entry of a relative lifted row in `dim` ambient dimensions: the differences
// (1), the squares (1) and the sum of dim squares (dim - 1).
constexpr int lifted_entry_roundings(int dim) { return dim + 1; }

// The sign of `value` if the bound gamma * abs_tree proves it, else 0 (undecided). Hot loops
// pass a gamma computed once with gamma_bound.
inline int certified_sign_with(double value, double abs_tree, double gamma) {
  if (!(abs_tree > kFilterUnderflow && abs_tree < kFilterOverflow)) return 0;  // also catches NaN
  const double bound = gamma * abs_tree;
  if (value > bound) return 1;
  if (value < -bound) return -1;
  return 0;
}

inline int certified_sign(double value, double abs_tree, int roundings) {
  return certified_sign_with(value, abs_tree, gamma_bound(roundings));
}

// Watches the floating-point exception flags over an evaluation: the error bounds above
// assume that no operation underflowed, overflowed or was invalid, and the flags say so
// exactly (an underflow flag is raised by every tiny inexact result, even one that ends up
// multiplied by a huge entry). The library is compiled with -frounding-math so that the
// compiler keeps floating-point operations between the two calls.
// On x86-64 the arithmetic is SSE2, whose flags live in MXCSR: reading it directly costs less
// than glibc's fenv functions, which also save and restore the x87 state, but a read still
// waits for the arithmetic before it; the facet search, which would read it several times per
// facet, does without (kUnderflowError; search/search_kernel.hpp, filters_hold_). The empty asm
// statements keep the compiler from moving memory accesses (the watched results) across.
#if defined(__x86_64__) && defined(__SSE2__)
class FloatingPointWatch {
 public:
  FloatingPointWatch() {
    const unsigned csr = _mm_getcsr();
    if (csr & kWatched) _mm_setcsr(csr & ~kWatched);  // flags are sticky: clear them only when set
    asm volatile("" ::: "memory");
  }
  bool clean() const {
    asm volatile("" ::: "memory");
    return (_mm_getcsr() & kWatched) == 0;
  }

 private:
  static constexpr unsigned kWatched = _MM_EXCEPT_UNDERFLOW | _MM_EXCEPT_OVERFLOW | _MM_EXCEPT_INVALID;
};
#else
class FloatingPointWatch {
 public:
  FloatingPointWatch() { std::feclearexcept(kWatched); }
  bool clean() const { return std::fetestexcept(kWatched) == 0; }

 private:
  static constexpr int kWatched = FE_UNDERFLOW | FE_OVERFLOW | FE_INVALID;
};
#endif

// x = odd * 2^e (x != 0, finite): returns e. A set of doubles with smallest such e is a set of
// integer multiples of 2^e: the basis of the static exactness proofs (predicates.cpp). Read
// from the bits: the degenerate inputs call it for every coordinate of every tie.
inline int lowest_bit_exponent(double x) {
  const DoubleParts p = parts_of(x);
  return p.exponent + __builtin_ctzll(static_cast<unsigned long long>(p.significand < 0 ? -p.significand : p.significand));
}

// 2^e as a double for a normal power (-1022 <= e <= 1023); +infinity above, 0 below. Used as
// an upper limit "x < 2^e": 0 below the normal range only makes such a test fail, which the
// exactness proofs read as "not proved".
inline double power_of_two_limit(int e) {
  if (e > 1023) return std::numeric_limits<double>::infinity();
  if (e < -1022) return 0.0;
  const std::uint64_t bits = static_cast<std::uint64_t>(e + 1023) << 52;
  double x;
  std::memcpy(&x, &bits, sizeof x);
  return x;
}

}  // namespace drange::geometry
