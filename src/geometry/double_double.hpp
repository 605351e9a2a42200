// geometry/double_double.hpp: double-double arithmetic, a number as the unevaluated sum hi + lo
// of two doubles (|lo| <= half an ulp of hi), for about 106 bits of precision in a few double
// operations each (refined_sign.cpp uses it between the double filters and GMP).
//
// The error-free transformations are exact in round to nearest when nothing overflows or
// underflows: two_sum always, fast_two_sum when |a| >= |b| (or a is 0), two_product either by
// Dekker's splitting or, with kFma, by one fused multiply-add. Both give the product's exact
// error, so the two are the same bits; the build targets plain x86-64, where std::fma is a
// library call, and refined_sign.cpp compiles its kFma code for processors that have it.
// On them, add is Joldes, Muller and Popescu's accurate double-word sum (relative error below
// 3u^2 + 13u^3, u = 2^-53; "Tight and rigorous error bounds for basic building blocks of
// double-word arithmetic", ACM TOMS 44(2), 2017, algorithm 6) and multiply their double-word
// product without fma (algorithm 10; below 7u^2 for u <= 2^-53 and no underflow). So each
// operation has the standard model's form, (x op y)(1 + delta), with |delta| below
// kDoubleDoubleRoundoff: Higham's gamma bounds (error_bound.hpp) then hold with that unit.
// Callers watch the floating-point flags: an underflow or overflow voids all of this.
#pragma once

namespace drange::geometry {

// A bound on every operation's relative error (7u^2 < 2^-103), with a margin.
constexpr double kDoubleDoubleRoundoff = 0x1p-100;

struct DoubleDouble {
  double hi = 0.0, lo = 0.0;
};

// a + b = hi + lo exactly, hi = fl(a + b) (Knuth's two-sum).
inline DoubleDouble two_sum(double a, double b) {
  const double s = a + b;
  const double b_part = s - a;
  return {s, (a - (s - b_part)) + (b - b_part)};
}

namespace double_double_detail {
inline DoubleDouble fast_two_sum(double a, double b) {
  const double s = a + b;
  return {s, b - (s - a)};
}
// Veltkamp's split of a into two halves of 26 bits each, a = high + low exactly.
inline void split(double a, double& high, double& low) {
  const double c = 134217729.0 * a;  // 2^27 + 1
  high = c - (c - a);
  low = a - high;
}
// a * b = hi + lo exactly. kFma: 2 operations, and an instruction only where the caller is
// compiled for a processor with fused multiply-add (else a correct but slow library call).
template <bool kFma>
inline DoubleDouble two_product(double a, double b) {
  const double p = a * b;
  if constexpr (kFma) {
    return {p, __builtin_fma(a, b, -p)};
  } else {
    double ah, al, bh, bl;
    split(a, ah, al);
    split(b, bh, bl);
    return {p, ((ah * bh - p) + ah * bl + al * bh) + al * bl};
  }
}
}  // namespace double_double_detail

// x - y of two doubles, exactly.
inline DoubleDouble difference(double x, double y) { return two_sum(x, -y); }

inline DoubleDouble negate(DoubleDouble x) { return {-x.hi, -x.lo}; }

inline DoubleDouble add(DoubleDouble x, DoubleDouble y) {
  using namespace double_double_detail;
  const DoubleDouble s = two_sum(x.hi, y.hi);
  const DoubleDouble t = two_sum(x.lo, y.lo);
  const DoubleDouble v = fast_two_sum(s.hi, s.lo + t.hi);
  return fast_two_sum(v.hi, v.lo + t.lo);
}

// The same bits with either kFma (two_product is exact both ways, and the rest does not fuse:
// the library is built with -ffp-contract=off).
template <bool kFma = false>
inline DoubleDouble multiply(DoubleDouble x, DoubleDouble y) {
  using namespace double_double_detail;
  const DoubleDouble c = two_product<kFma>(x.hi, y.hi);
  const double cross = x.hi * y.lo + x.lo * y.hi;
  return fast_two_sum(c.hi, c.lo + cross);
}

}  // namespace drange::geometry
