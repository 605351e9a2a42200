// check/facet_plane.cpp: the facet hyperplane's filter and its exact fallback.
#include "check/facet_plane.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include <gmpxx.h>

#include "geometry/error_bound.hpp"
#include "geometry/exact.hpp"
#include "geometry/predicates.hpp"

namespace drange::check {

using geometry::gamma_bound;
using geometry::laplace_roundings;

FacetPlane::FacetPlane(int dim)
    : dim_(dim),
      cofactor_(static_cast<std::size_t>(dim), 0.0),
      abs_cofactor_(static_cast<std::size_t>(dim), 0.0),
      row_(static_cast<std::size_t>(dim), 0.0),
      corners_(static_cast<std::size_t>(dim) + 1, nullptr) {
  if (dim <= geometry::SubsetTable::kMaxColumns) minors_.emplace(dim);
}

namespace {

// Scales the row by a power of two so that its largest magnitude lies in [1/2, 1). False if
// that would make a nonzero entry underflow (a row spanning a thousand binades), or if an entry
// overflowed (a difference of huge coordinates).
bool normalise_row(std::vector<double>& row) {
  double largest = 0.0, smallest = 0.0;
  for (double x : row) {
    const double a = std::fabs(x);
    largest = std::max(largest, a);
    if (a != 0.0 && (smallest == 0.0 || a < smallest)) smallest = a;
  }
  if (!(largest <= std::numeric_limits<double>::max())) return false;
  if (largest == 0.0) return true;
  int exponent = 0;
  std::frexp(largest, &exponent);
  if (std::ldexp(smallest, -exponent) < 0x1p-1021) return false;
  for (double& x : row) x = std::ldexp(x, -exponent);
  return true;
}

constexpr double kCofactorFloor = 0x1p-1000;

}  // namespace

void FacetPlane::set(const double* const* facet) {
  std::copy(facet, facet + dim_, corners_.begin());
  filter_ = false;
  if (!minors_) return;
  const double* base = facet[0];
  for (int r = 0; r + 1 < dim_; ++r) {
    for (int c = 0; c < dim_; ++c) row_[static_cast<std::size_t>(c)] = facet[r + 1][c] - base[c];
    if (!normalise_row(row_)) return;
    minors_->set_row(r, row_.data());
  }
  filter_ = true;
  // Expansion of D along its last row (row d-1): entry (d-1, j) has cofactor sign (-1)^(d-1+j).
  const std::uint32_t all = (std::uint32_t{1} << dim_) - 1;
  for (int j = 0; j < dim_; ++j) {
    const std::uint32_t rest = all & ~(std::uint32_t{1} << j);
    const double minor = minors_->minor(rest);
    cofactor_[static_cast<std::size_t>(j)] = ((dim_ - 1 + j) & 1) ? -minor : minor;
    abs_cofactor_[static_cast<std::size_t>(j)] = std::max(minors_->abs_minor(rest), kCofactorFloor);
  }
}

void FacetPlane::evaluate(const double* x, double& value, double& abs_tree) const {
  const double* base = corners_[0];
  value = 0.0;
  abs_tree = 0.0;
  for (int j = 0; j < dim_; ++j) {
    const double delta = x[j] - base[j];
    value += delta * cofactor_[static_cast<std::size_t>(j)];
    abs_tree += std::fabs(delta) * abs_cofactor_[static_cast<std::size_t>(j)];
  }
}

int FacetPlane::filtered_side(const double* x) const {
  if (!filter_) return 0;
  double value = 0.0, abs_tree = 0.0;
  evaluate(x, value, abs_tree);
  // The same expression tree as a d x d Laplace expansion whose entries are differences.
  return geometry::certified_sign(value, abs_tree, laplace_roundings(dim_, 1));
}

int FacetPlane::exact_side(const double* x) {
  corners_[static_cast<std::size_t>(dim_)] = x;
  return geometry::simplex_orientation(dim_, corners_.data());
}

int FacetPlane::side(const double* x) {
  const int s = filtered_side(x);
  return s != 0 ? s : exact_side(x);
}

int FacetPlane::side_of_average(const double* const* p, int count) {
  if (filter_) {
    double value = 0.0, abs_tree = 0.0;
    for (int i = 0; i < count; ++i) {
      double v = 0.0, a = 0.0;
      evaluate(p[i], v, a);
      value += v;
      abs_tree += a;
    }
    // count - 1 more roundings on every path: the sum over the points.
    const int s = geometry::certified_sign(value, abs_tree, laplace_roundings(dim_, 1) + count);
    if (s != 0) return s;
  }
  mpq_class sum = 0;
  for (int i = 0; i < count; ++i) {
    corners_[static_cast<std::size_t>(dim_)] = p[i];
    sum += geometry::simplex_volume_times_factorial(dim_, corners_.data());
  }
  return sgn(sum);
}

// Box bound. With C_j exact and Ĉ_j computed, |C_j - Ĉ_j| <= E_j = gamma(n') A_j, where A_j is
// the computed absolute tree of the cofactor and n' the roundings of a (d-1)x(d-1) expansion.
// For x in the box, outer * D(x) = sum_j outer C_j a_j with a_j = x_j - f0_j, and
//   outer C_j a_j <= outer Ĉ_j a_j + E_j |a_j|,
// a convex function of x_j, so its maximum over [lo_j, hi_j] is at an end point. The sum of
// these maxima, U, bounds outer * D over the box; evaluating U in floating point costs at most
// d + 4 roundings on any path (difference, two products, a sum, the running sum of d terms),
// relative to W = sum_j (|Ĉ_j| + E_j) max(|lo_j - f0_j|, |hi_j - f0_j|). Two more roundings
// cover the final comparison.
bool FacetPlane::box_may_reach(const double* lo, const double* hi, int outer) const {
  if (!filter_) return true;
  const double cofactor_error = gamma_bound(laplace_roundings(dim_ - 1, 1));
  const double* base = corners_[0];
  double upper = 0.0, weight = 0.0;
  for (int j = 0; j < dim_; ++j) {
    const double c = outer * cofactor_[static_cast<std::size_t>(j)];
    const double e = cofactor_error * abs_cofactor_[static_cast<std::size_t>(j)];
    const double a = lo[j] - base[j];
    const double b = hi[j] - base[j];
    upper += std::max(c * a + e * std::fabs(a), c * b + e * std::fabs(b));
    weight += (std::fabs(c) + e) * std::max(std::fabs(a), std::fabs(b));
  }
  if (!(weight < geometry::kFilterOverflow)) return true;  // also NaN
  if (weight < geometry::kFilterUnderflow) return true;
  return upper + gamma_bound(dim_ + 6) * weight > 0.0;
}

}  // namespace drange::check
