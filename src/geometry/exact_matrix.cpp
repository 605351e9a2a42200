// geometry/exact_matrix.cpp: exact integer determinants (Bareiss) and the double-to-integer
// scaling they start from.
#include "geometry/exact_matrix.hpp"

#include <utility>

#include "geometry/double_bits.hpp"

namespace drange::geometry {

void IntegerScale::include(double x) {
  if (x == 0.0) return;
  const long lowest = parts_of(x).exponent;  // x is a multiple of 2^lowest (double_bits.hpp)
  if (!any_ || lowest < shift_) shift_ = lowest;
  any_ = true;
}

mpz_class IntegerScale::integer(double x) const {
  mpz_class m;
  assign_integer(x, m);
  return m;
}

void IntegerScale::assign_integer(double x, mpz_class& out) const {
  if (x == 0.0) {
    out = 0;
    return;
  }
  const DoubleParts p = parts_of(x);
  mpz_set_si(out.get_mpz_t(), static_cast<long>(p.significand));
  mpz_mul_2exp(out.get_mpz_t(), out.get_mpz_t(), static_cast<mp_bitcnt_t>(p.exponent - shift_));
}

int bareiss_in_place(std::vector<mpz_class>& a, int n, mpz_class& scratch) {
  auto at = [&](int r, int c) -> mpz_class& { return a[static_cast<std::size_t>(r * n + c)]; };
  int parity = 1;
  for (int k = 0; k + 1 < n; ++k) {
    if (at(k, k) == 0) {
      int swap_row = k + 1;
      while (swap_row < n && at(swap_row, k) == 0) ++swap_row;
      if (swap_row == n) return 0;
      for (int c = 0; c < n; ++c) mpz_swap(at(k, c).get_mpz_t(), at(swap_row, c).get_mpz_t());
      parity = -parity;
    }
    for (int i = k + 1; i < n; ++i)
      for (int j = k + 1; j < n; ++j) {
        // Bareiss step: a_ij a_kk - a_ik a_kj, divided exactly by the previous pivot
        // (Sylvester's identity); row swaps below k leave that pivot in place.
        mpz_mul(scratch.get_mpz_t(), at(i, j).get_mpz_t(), at(k, k).get_mpz_t());
        mpz_submul(scratch.get_mpz_t(), at(i, k).get_mpz_t(), at(k, j).get_mpz_t());
        if (k > 0) mpz_divexact(at(i, j).get_mpz_t(), scratch.get_mpz_t(), at(k - 1, k - 1).get_mpz_t());
        else mpz_swap(at(i, j).get_mpz_t(), scratch.get_mpz_t());
      }
  }
  return at(n - 1, n - 1) == 0 ? 0 : parity;
}

mpz_class bareiss_determinant(std::vector<mpz_class>& a, int n) {
  mpz_class scratch;
  const int parity = bareiss_in_place(a, n, scratch);
  if (parity == 0) return 0;
  mpz_class det = a[static_cast<std::size_t>(n * n - 1)];
  if (parity < 0) det = -det;
  return det;
}

}  // namespace drange::geometry
