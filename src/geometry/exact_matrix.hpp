// geometry/exact_matrix.hpp: exact determinants of matrices built from double coordinates.
//
// Every finite double is m * 2^e with an integer m. Scaling all coordinates that enter one
// determinant by a common power of two makes them integers, so differences, squared norms and
// the determinant itself are computed exactly with GMP integers (Bareiss' fraction-free
// elimination, every division exact).
#pragma once

#include <gmpxx.h>

#include <vector>

namespace drange::geometry {

// Scales a set of doubles to integers by one common power of two: integer(x) = x * 2^-shift.
class IntegerScale {
 public:
  // `values` are every coordinate that will be converted; finite.
  void include(double x);
  mpz_class integer(double x) const;
  // The same into `out`, reusing its limbs (no allocation once `out` is large enough).
  void assign_integer(double x, mpz_class& out) const;
  long shift() const { return shift_; }

 private:
  long shift_ = 0;
  bool any_ = false;
};

// Bareiss' fraction-free elimination of the n x n integer matrix a (row-major), in place and
// without allocating beyond `scratch`. Returns 0 when the matrix is singular; otherwise the
// parity (+1 or -1) of the row swaps made: the determinant is that parity times a[n*n - 1].
int bareiss_in_place(std::vector<mpz_class>& a, int n, mpz_class& scratch);

// The determinant itself; a is destroyed.
mpz_class bareiss_determinant(std::vector<mpz_class>& a, int n);

}  // namespace drange::geometry
