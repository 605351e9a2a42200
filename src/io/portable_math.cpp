// io/portable_math.cpp: reproducible log and exp (see portable_math.hpp).
//
// log: x = m 2^e with m in [sqrt(1/2), sqrt(2)), then log m = 2 atanh(f), f = (m-1)/(m+1),
// |f| < 0.172, by its odd power series. exp: x = k ln2 + r with |r| <= ln2/2 (Cody and
// Waite's two-part ln2 keeps r accurate), e^r by its Taylor series, then scaled by 2^k.
// Both series are cut where the next term is below 1e-20 relative to the sum.
#include "io/portable_math.hpp"

#include <cmath>

namespace drange::io {
namespace {

// ln 2 split so that k * kLn2High is exact for |k| < 2^11 (its low mantissa bits are zero).
constexpr double kLn2High = 0x1.62e42fee00000p-1;
constexpr double kLn2Low = 0x1.a39ef35793c76p-33;
constexpr double kSqrtHalf = 0x1.6a09e667f3bcdp-1;

}  // namespace

double portable_log(double x) {
  int exponent = 0;
  double m = std::frexp(x, &exponent);  // exact: x = m 2^exponent, m in [0.5, 1)
  if (m < kSqrtHalf) {
    m *= 2.0;
    --exponent;
  }
  const double f = (m - 1.0) / (m + 1.0);
  const double f2 = f * f;
  // 2 (f + f^3/3 + ... + f^27/27), f2^13 / 27 < 1e-21.
  double series = 1.0 / 27.0;
  for (int k = 25; k >= 1; k -= 2) series = 1.0 / k + f2 * series;
  const double log_m = 2.0 * f * series;
  const double e = exponent;
  return e * kLn2High + (e * kLn2Low + log_m);
}

double portable_exp(double x) {
  if (x > 710.0) return HUGE_VAL;
  if (x < -746.0) return 0.0;
  const double k = std::floor(x / (kLn2High + kLn2Low) + 0.5);
  const double r = (x - k * kLn2High) - k * kLn2Low;
  // Taylor series to r^20 / 20!: (ln2/2)^21 / 21! < 1e-29.
  double series = 1.0;
  for (int n = 20; n >= 1; --n) series = 1.0 + series * r / n;
  // Two steps, so that 2^k for k near -1074 does not underflow before the product.
  const int half = static_cast<int>(k) / 2;
  return std::ldexp(std::ldexp(series, half), static_cast<int>(k) - half);
}

}  // namespace drange::io
