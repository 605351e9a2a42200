// hull/perturbation.cpp: the three stages of the perturbed orientation (perturbation.hpp).
#include "hull/perturbation.hpp"

#include <algorithm>
#include <array>
#include <numeric>

#include "drange/errors.hpp"
#include "drange/points.hpp"
#include "geometry/exact_matrix.hpp"
#include "geometry/predicates.hpp"

namespace drange::hull {

bool Perturbation::before(std::int32_t a, std::int32_t b) const {
  const double* x = point(a);
  const double* y = point(b);
  for (int k = 0; k < d_; ++k)
    if (x[k] != y[k]) return x[k] < y[k];
  return a < b;
}

int Perturbation::unperturbed(const std::int32_t* a) const {
  std::array<const double*, kMaxDimension + 1> rows{};
  for (int i = 1; i <= d_; ++i) rows[static_cast<std::size_t>(i - 1)] = point(a[i]);
  return geometry::orientation(geometry::Frame{d_, d_, nullptr, point(a[0])}, rows.data());
}

int Perturbation::sign(const std::int32_t* a, int unperturbed) const {
  if (unperturbed != 0) return unperturbed;
  std::array<const double*, kMaxDimension + 1> rows{};
  for (int i = 0; i <= d_; ++i) rows[static_cast<std::size_t>(i)] = point(a[i]);
  // Stage 2: the eps term.
  const int lifted = lifted_about_interior(rows.data());
  if (lifted != 0) return (d_ % 2 == 0) ? -lifted : lifted;
  // Stage 3: the eta terms, the most perturbed point first.
  std::array<int, kMaxDimension + 1> order{};
  std::iota(order.begin(), order.begin() + d_ + 1, 0);
  std::sort(order.begin(), order.begin() + d_ + 1, [&](int i, int j) { return before(a[i], a[j]); });
  for (int r = 0; r <= d_; ++r) {
    const int i = order[static_cast<std::size_t>(r)];
    std::array<const double*, kMaxDimension> others{};
    for (int k = 0, m = 0; k <= d_; ++k)
      if (k != i) others[static_cast<std::size_t>(m++)] = point(a[k]);
    const int minor = orientation_about_interior(others.data());
    if (minor != 0) return (i % 2 == 0) ? -minor : minor;
  }
  throw InternalError("convex hull: d+1 points and the interior point lie in one hyperplane through it; "
                      "the perturbed orientation is undefined");
}

int Perturbation::lifted_about_interior(const double* const* p) const {
  if (interior_.empty()) return exact_about_centroid(p, d_ + 1, true);
  return geometry::lifted_sign(geometry::Frame{d_, d_, nullptr, interior_.data()}, p);
}

int Perturbation::orientation_about_interior(const double* const* p) const {
  if (interior_.empty()) return exact_about_centroid(p, d_, false);
  return geometry::orientation(geometry::Frame{d_, d_, nullptr, interior_.data()}, p);
}

int Perturbation::exact_about_centroid(const double* const* p, int rows, bool lifted) const {
  geometry::IntegerScale scale;
  for (int i = 0; i < rows; ++i)
    for (int k = 0; k < d_; ++k) scale.include(p[i][k]);
  for (const std::int32_t s : simplex_)
    for (int k = 0; k < d_; ++k) scale.include(point(s)[k]);
  std::vector<mpz_class> sum(static_cast<std::size_t>(d_));
  for (const std::int32_t s : simplex_)
    for (int k = 0; k < d_; ++k) sum[static_cast<std::size_t>(k)] += scale.integer(point(s)[k]);
  const int columns = lifted ? d_ + 1 : d_;
  std::vector<mpz_class> matrix(static_cast<std::size_t>(rows * columns));
  for (int i = 0; i < rows; ++i) {
    mpz_class norm = 0;
    for (int k = 0; k < d_; ++k) {
      mpz_class& q = matrix[static_cast<std::size_t>(i * columns + k)];
      q = (d_ + 1) * scale.integer(p[i][k]) - sum[static_cast<std::size_t>(k)];
      norm += q * q;
    }
    if (lifted) matrix[static_cast<std::size_t>(i * columns + d_)] = norm;
  }
  mpz_class scratch;
  const int parity = geometry::bareiss_in_place(matrix, rows, scratch);
  return parity * sgn(matrix.back());
}

}  // namespace drange::hull
