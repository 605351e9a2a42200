// voronoi/extended_real.hpp: a real type with about twice double's precision, for the cell
// volumes of nearly flat simplices (flag_volumes.cpp).
//
// Where the compiler offers quad precision with its library (GCC's __float128 and
// libquadmath: 113-bit significand), ExtendedReal is that type. Elsewhere (Clang, AArch64,
// macOS) it is a double-double number, hi + lo (about 106 bits), built on the error-free
// transformations of geometry/double_double.hpp; the volumes then differ from the quad ones
// only far below double's precision, where the final rounding to double hides it. Both give
// +, -, *, /, comparisons, a square root (root) and a conversion to double; nothing overflows
// or underflows on the values flag_volumes computes (differences of coordinates scaled near 1).
#pragma once

#include <cmath>

#include "geometry/double_double.hpp"

#if defined(DRANGE_HAVE_QUADMATH)
#include <quadmath.h>
#endif

namespace drange::diagram {

// The square root for each arithmetic, by one name (SimplexPieces<Real> calls root).
inline double root(double x) { return std::sqrt(x); }

// Double-double arithmetic as a number type (the fallback; compiled everywhere, so that the
// tests check it under every compiler).
class DoubleDoubleReal {
 public:
  DoubleDoubleReal() = default;
  DoubleDoubleReal(double x) : v_{x, 0.0} {}  // NOLINT: implicit, as a built-in real's
  explicit operator double() const { return v_.hi + v_.lo; }

  friend DoubleDoubleReal operator+(DoubleDoubleReal x, DoubleDoubleReal y) { return DoubleDoubleReal(geometry::add(x.v_, y.v_)); }
  friend DoubleDoubleReal operator-(DoubleDoubleReal x) { return DoubleDoubleReal(geometry::negate(x.v_)); }
  friend DoubleDoubleReal operator-(DoubleDoubleReal x, DoubleDoubleReal y) { return x + -y; }
  friend DoubleDoubleReal operator*(DoubleDoubleReal x, DoubleDoubleReal y) { return DoubleDoubleReal(geometry::multiply(x.v_, y.v_)); }
  // Long division: three quotient digits, each the remainder's leading part over y's.
  friend DoubleDoubleReal operator/(DoubleDoubleReal x, DoubleDoubleReal y) {
    const double q1 = x.v_.hi / y.v_.hi;
    DoubleDoubleReal r = x - y * DoubleDoubleReal(q1);
    const double q2 = r.v_.hi / y.v_.hi;
    r = r - y * DoubleDoubleReal(q2);
    const double q3 = r.v_.hi / y.v_.hi;
    return DoubleDoubleReal(geometry::add(geometry::two_sum(q1, q2), geometry::DoubleDouble{q3, 0.0}));
  }
  DoubleDoubleReal& operator+=(DoubleDoubleReal y) { return *this = *this + y; }
  DoubleDoubleReal& operator-=(DoubleDoubleReal y) { return *this = *this - y; }
  DoubleDoubleReal& operator*=(DoubleDoubleReal y) { return *this = *this * y; }
  DoubleDoubleReal& operator/=(DoubleDoubleReal y) { return *this = *this / y; }

  // hi + lo is normalised (|lo| <= half an ulp of hi): comparing hi first, then lo, is exact.
  friend bool operator<(DoubleDoubleReal x, DoubleDoubleReal y) { return x.v_.hi < y.v_.hi || (x.v_.hi == y.v_.hi && x.v_.lo < y.v_.lo); }
  friend bool operator>(DoubleDoubleReal x, DoubleDoubleReal y) { return y < x; }
  friend bool operator<=(DoubleDoubleReal x, DoubleDoubleReal y) { return !(y < x); }
  friend bool operator>=(DoubleDoubleReal x, DoubleDoubleReal y) { return !(x < y); }
  friend bool operator==(DoubleDoubleReal x, DoubleDoubleReal y) { return x.v_.hi == y.v_.hi && x.v_.lo == y.v_.lo; }
  friend bool operator!=(DoubleDoubleReal x, DoubleDoubleReal y) { return !(x == y); }

  // One Newton step from the double root s: sqrt(x) = s + (x - s^2) / (2 s), to about 106 bits.
  friend DoubleDoubleReal root(DoubleDoubleReal x) {
    if (!(x.v_.hi > 0.0)) return DoubleDoubleReal(std::sqrt(x.v_.hi));
    const double s = std::sqrt(x.v_.hi);
    const DoubleDoubleReal residual = x - DoubleDoubleReal(s) * DoubleDoubleReal(s);
    return DoubleDoubleReal(geometry::two_sum(s, residual.v_.hi / (2.0 * s)));
  }

 private:
  explicit DoubleDoubleReal(geometry::DoubleDouble v) : v_(v) {}
  geometry::DoubleDouble v_;
};

#if defined(DRANGE_HAVE_QUADMATH)
using ExtendedReal = __float128;
inline ExtendedReal root(ExtendedReal x) { return sqrtq(x); }
#else
using ExtendedReal = DoubleDoubleReal;
#endif

}  // namespace drange::diagram
