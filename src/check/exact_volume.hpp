// check/exact_volume.hpp: exact sums of many simplex determinants, for the volume identity.
//
// geometry::simplex_volume_times_factorial returns one exact rational per call; summing
// millions of them is dominated by allocation, conversion and rational normalisation. Here
// every point's coordinates are scaled once, by one common power of two, into integers (every
// double is m * 2^e, see geometry/exact_matrix.hpp) stored as flat GMP limbs; each determinant
// is then an integer in the common unit 2^(d * shift), and the sums are plain GMP integers,
// computed with preallocated temporaries (geometry::bareiss_in_place).
#pragma once

#include <gmpxx.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace drange::check {

// The points' coordinates as integers: coordinate c of point i is x * 2^-shift.
class IntegerPoints {
 public:
  // Converts the points listed in `ids` (others are left zero); shift is the largest that
  // makes all of them integers.
  IntegerPoints(const double* coords, std::size_t n, int dim, const std::vector<std::int32_t>& ids);

  long shift() const { return shift_; }
  // A read-only GMP view of coordinate c of point i (valid while this object lives).
  void view(std::size_t i, int c, mpz_t out) const;

 private:
  int dim_;
  long shift_ = 0;
  std::size_t limbs_ = 1;             // limbs per coordinate
  std::vector<mp_limb_t> magnitude_;  // n * dim * limbs_
  std::vector<std::int32_t> size_;    // signed limb counts, as GMP's _mp_size
};

// A running sum of signed simplex determinants over IntegerPoints.
class DeterminantSum {
 public:
  explicit DeterminantSum(const IntegerPoints& points, int dim);

  // Adds sign * det[p_1 - p_0, ..., p_d - p_0] (sign +1 or -1), the points given by id.
  void add(const std::int32_t* ids, int sign);
  // The sum, in units of 2^(dim * shift).
  const mpz_class& total() const { return total_; }

 private:
  mpz_class& at(int r, int c) { return matrix_[static_cast<std::size_t>(r * dim_ + c)]; }

  const IntegerPoints& points_;
  int dim_;
  std::vector<mpz_class> matrix_;
  mpz_class scratch_, total_;
};

}  // namespace drange::check
