// check/exact_volume.cpp: exact determinant sums over integer-scaled points.
#include "check/exact_volume.hpp"

#include "geometry/exact_matrix.hpp"

#include <algorithm>
#include <cmath>

namespace drange::check {

IntegerPoints::IntegerPoints(const double* coords, std::size_t n, int dim, const std::vector<std::int32_t>& ids)
    : dim_(dim) {
  auto coordinate = [&](std::int32_t i, int c) { return coords[static_cast<std::size_t>(i) * static_cast<std::size_t>(dim) + static_cast<std::size_t>(c)]; };
  // One common power of two for every coordinate (geometry::IntegerScale); the largest
  // magnitude sets how many limbs each converted coordinate may need.
  geometry::IntegerScale scale;
  double largest = 0.0;
  for (const std::int32_t i : ids)
    for (int c = 0; c < dim; ++c) {
      scale.include(coordinate(i, c));
      largest = std::max(largest, std::fabs(coordinate(i, c)));
    }
  shift_ = scale.shift();
  limbs_ = std::max<std::size_t>(1, mpz_size(scale.integer(largest).get_mpz_t()));
  magnitude_.assign(n * static_cast<std::size_t>(dim) * limbs_, 0);
  size_.assign(n * static_cast<std::size_t>(dim), 0);
  for (const std::int32_t i : ids)
    for (int c = 0; c < dim; ++c) {
      const double x = coordinate(i, c);
      if (x == 0.0) continue;
      const mpz_class value = scale.integer(x);
      const std::size_t slot = static_cast<std::size_t>(i) * static_cast<std::size_t>(dim) + static_cast<std::size_t>(c);
      size_t count = 0;
      mpz_export(&magnitude_[slot * limbs_], &count, -1, sizeof(mp_limb_t), 0, GMP_NAIL_BITS, value.get_mpz_t());
      size_[slot] = static_cast<std::int32_t>(sgn(value) < 0 ? -static_cast<long>(count) : static_cast<long>(count));
    }
}

void IntegerPoints::view(std::size_t i, int c, mpz_t out) const {
  const std::size_t slot = i * static_cast<std::size_t>(dim_) + static_cast<std::size_t>(c);
  mpz_roinit_n(out, &magnitude_[slot * limbs_], size_[slot]);
}

DeterminantSum::DeterminantSum(const IntegerPoints& points, int dim)
    : points_(points), dim_(dim), matrix_(static_cast<std::size_t>(dim * dim)) {}

void DeterminantSum::add(const std::int32_t* ids, int sign) {
  const int d = dim_;
  mpz_t a, b;
  for (int r = 0; r < d; ++r)
    for (int c = 0; c < d; ++c) {
      points_.view(static_cast<std::size_t>(ids[r + 1]), c, a);
      points_.view(static_cast<std::size_t>(ids[0]), c, b);
      mpz_sub(at(r, c).get_mpz_t(), a, b);
    }
  const int parity = geometry::bareiss_in_place(matrix_, d, scratch_);
  if (parity == 0) return;  // a flat simplex adds nothing
  const mpz_class& det = at(d - 1, d - 1);
  if (parity * sign > 0) mpz_add(total_.get_mpz_t(), total_.get_mpz_t(), det.get_mpz_t());
  else mpz_sub(total_.get_mpz_t(), total_.get_mpz_t(), det.get_mpz_t());
}

}  // namespace drange::check
