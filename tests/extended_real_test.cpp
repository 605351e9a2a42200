// tests/extended_real_test.cpp: the double-double number type that the Voronoi volumes use
// where quad precision is missing (voronoi/extended_real.hpp), against exact rationals (GMP):
// every operation within a relative 2^-100 of the exact result, comparisons exact. It is
// compiled under every compiler, so GCC's runs check Clang's fallback too.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

#include "geometry/double_double.hpp"
#include "voronoi/extended_real.hpp"

namespace {

using drange::diagram::DoubleDoubleReal;

// The exact value of x = hi + lo, recovered through two conversions to double: hi is
// double(x) rounded, and (x - hi) converts exactly to the low part.
mpq_class exact(DoubleDoubleReal x) {
  const double hi = static_cast<double>(x);
  const double lo = static_cast<double>(x - DoubleDoubleReal(hi));
  return mpq_class(hi) + mpq_class(lo);
}

bool close(const mpq_class& computed, const mpq_class& truth) {
  if (truth == 0) return computed == 0;
  const mpq_class error = abs(computed - truth) / abs(truth);
  return error < mpq_class(1, mpz_class(1) << 100);
}

// Random values over many magnitudes, each the sum of two doubles, as the volumes' terms are.
DoubleDoubleReal random_value(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-30, 30);
  const double big = std::ldexp(unit(rng), exponent(rng));
  return DoubleDoubleReal(big) + DoubleDoubleReal(std::ldexp(big, -60) * unit(rng));
}

TEST(DoubleDoubleReal, ArithmeticIsWithinTwoToTheMinus100OfExact) {
  std::mt19937_64 rng(41);
  for (int trial = 0; trial < 2000; ++trial) {
    const DoubleDoubleReal a = random_value(rng), b = random_value(rng);
    const mpq_class ea = exact(a), eb = exact(b);
    // A sum may cancel: its error is bounded by the operands' magnitudes.
    ASSERT_LE(abs(exact(a + b) - (ea + eb)), (abs(ea) + abs(eb)) * mpq_class(1, mpz_class(1) << 100)) << "trial " << trial;
    ASSERT_TRUE(close(exact(a * b), ea * eb)) << "trial " << trial;
    if (eb != 0) ASSERT_TRUE(close(exact(a / b), ea / eb)) << "trial " << trial;
    if (ea > 0) {
      const mpq_class r = exact(root(a));
      ASSERT_TRUE(close(r * r, ea)) << "trial " << trial;
    }
    EXPECT_EQ(a < b, ea < eb) << "trial " << trial;
    EXPECT_EQ(a == b, ea == eb) << "trial " << trial;
    EXPECT_EQ(a >= DoubleDoubleReal(0), ea >= 0) << "trial " << trial;
  }
}

TEST(DoubleDoubleReal, KeepsWhatADoubleLoses) {
  // 1 + 2^-80 - 1 is 2^-80 in double-double, 0 in double.
  const DoubleDoubleReal tiny = DoubleDoubleReal(1.0) + DoubleDoubleReal(std::ldexp(1.0, -80));
  EXPECT_EQ(static_cast<double>(tiny - DoubleDoubleReal(1.0)), std::ldexp(1.0, -80));
  EXPECT_EQ(static_cast<double>(root(DoubleDoubleReal(4.0))), 2.0);
  EXPECT_EQ(static_cast<double>(root(DoubleDoubleReal(0.0))), 0.0);
  EXPECT_EQ(static_cast<double>(DoubleDoubleReal(1.0) / DoubleDoubleReal(3.0) * DoubleDoubleReal(3.0)), 1.0);
}

}  // namespace
