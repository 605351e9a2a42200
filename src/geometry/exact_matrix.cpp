// geometry/exact_matrix.cpp: exact integer determinants (Bareiss) and the double-to-integer
// scaling they start from.
#include "geometry/exact_matrix.hpp"

#include <cmath>
#include <utility>

namespace drange::geometry {

void IntegerScale::include(double x) {
  if (x == 0.0) return;
  int exponent = 0;
  std::frexp(x, &exponent);  // x = f * 2^exponent, 0.5 <= |f| < 1: x is a multiple of 2^(exponent-53)
  const long lowest = static_cast<long>(exponent) - 53;
  if (!any_ || lowest < shift_) shift_ = lowest;
  any_ = true;
}

mpz_class IntegerScale::integer(double x) const {
  if (x == 0.0) return 0;
  int exponent = 0;
  const double f = std::frexp(x, &exponent);
  mpz_class m(std::ldexp(f, 53));  // exact: a 53-bit integer
  const long up = static_cast<long>(exponent) - 53 - shift_;
  mpz_mul_2exp(m.get_mpz_t(), m.get_mpz_t(), static_cast<mp_bitcnt_t>(up));
  return m;
}

mpz_class bareiss_determinant(std::vector<mpz_class>& a, int n) {
  auto at = [&](int r, int c) -> mpz_class& { return a[static_cast<std::size_t>(r * n + c)]; };
  int sign = 1;
  mpz_class previous = 1;
  for (int k = 0; k < n - 1; ++k) {
    if (at(k, k) == 0) {
      int swap_row = k + 1;
      while (swap_row < n && at(swap_row, k) == 0) ++swap_row;
      if (swap_row == n) return 0;
      for (int c = 0; c < n; ++c) std::swap(at(k, c), at(swap_row, c));
      sign = -sign;
    }
    for (int i = k + 1; i < n; ++i) {
      for (int j = k + 1; j < n; ++j) {
        // Bareiss step: the division by the previous pivot is exact (Sylvester's identity).
        at(i, j) = at(i, j) * at(k, k) - at(i, k) * at(k, j);
        mpz_divexact(at(i, j).get_mpz_t(), at(i, j).get_mpz_t(), previous.get_mpz_t());
      }
    }
    previous = at(k, k);
  }
  mpz_class det = at(n - 1, n - 1);
  if (sign < 0) det = -det;
  return det;
}

int bareiss_sign(std::vector<mpz_class>& a, int n) { return sgn(bareiss_determinant(a, n)); }

}  // namespace drange::geometry
