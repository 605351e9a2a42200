// voronoi/circumcentre.cpp: see circumcentre.hpp.
#include "voronoi/circumcentre.hpp"

#include <gmpxx.h>

#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "drange/points.hpp"

namespace drange::diagram {
namespace {

using Real = long double;

// Past this Hadamard ratio the centre is computed exactly (see simplex_circumcentre).
constexpr double kExactRatio = 1e4;

// Solves a[n x n] x = b in place by Gaussian elimination with partial pivoting.
// Returns the product of the pivots' magnitudes (|det a|), 0 when a pivot vanishes.
Real solve(int n, Real* a, Real* b, Real* x) {
  Real det = 1;
  for (int col = 0; col < n; ++col) {
    int pivot = col;
    for (int r = col + 1; r < n; ++r)
      if (std::fabs(a[r * n + col]) > std::fabs(a[pivot * n + col])) pivot = r;
    if (a[pivot * n + col] == 0) return 0;
    if (pivot != col) {
      for (int c = 0; c < n; ++c) std::swap(a[col * n + c], a[pivot * n + c]);
      std::swap(b[col], b[pivot]);
    }
    det *= std::fabs(a[col * n + col]);
    for (int r = col + 1; r < n; ++r) {
      const Real factor = a[r * n + col] / a[col * n + col];
      if (factor == 0) continue;
      for (int c = col; c < n; ++c) a[r * n + c] -= factor * a[col * n + c];
      b[r] -= factor * b[col];
    }
  }
  for (int r = n - 1; r >= 0; --r) {
    Real sum = b[r];
    for (int c = r + 1; c < n; ++c) sum -= a[r * n + c] * x[c];
    x[r] = sum / a[r * n + r];
  }
  return det;
}

// The double nearest to the rational q (get_d truncates toward zero).
double nearest_double(const mpq_class& q) {
  const double t = q.get_d();
  const double away = std::nextafter(t, q > 0 ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity());
  return abs(q - mpq_class(away)) < abs(q - mpq_class(t)) ? away : t;
}

// The same system solved exactly (Gaussian elimination over the rationals), the centre rounded
// once to double. Returns false when the simplex is exactly flat.
bool exact_circumcentre(int dim, const double* const* vertices, double* centre) {
  const auto n = static_cast<std::size_t>(dim);
  std::vector<mpq_class> a(n * n), b(n);
  for (std::size_t i = 0; i < n; ++i) {
    mpq_class norm2 = 0;
    for (std::size_t k = 0; k < n; ++k) {
      a[i * n + k] = mpq_class(vertices[i + 1][k]) - mpq_class(vertices[0][k]);
      norm2 += a[i * n + k] * a[i * n + k];
    }
    b[i] = norm2 / 2;
  }
  for (std::size_t col = 0; col < n; ++col) {
    std::size_t pivot = col;
    while (pivot < n && sgn(a[pivot * n + col]) == 0) ++pivot;
    if (pivot == n) return false;
    if (pivot != col) {
      for (std::size_t c = 0; c < n; ++c) std::swap(a[col * n + c], a[pivot * n + c]);
      std::swap(b[col], b[pivot]);
    }
    for (std::size_t r = col + 1; r < n; ++r) {
      if (sgn(a[r * n + col]) == 0) continue;
      const mpq_class factor = a[r * n + col] / a[col * n + col];
      for (std::size_t c = col; c < n; ++c) a[r * n + c] -= factor * a[col * n + c];
      b[r] -= factor * b[col];
    }
  }
  std::vector<mpq_class> x(n);
  for (std::size_t r = n; r-- > 0;) {
    mpq_class sum = b[r];
    for (std::size_t c = r + 1; c < n; ++c) sum -= a[r * n + c] * x[c];
    x[r] = sum / a[r * n + r];
  }
  for (std::size_t k = 0; k < n; ++k) centre[k] = nearest_double(mpq_class(vertices[0][k]) + x[k]);
  return true;
}

}  // namespace

double simplex_circumcentre(int dim, const double* const* vertices, double* centre) {
  // Row i: (v_i - v_0) . c' = |v_i - v_0|^2 / 2, with c = v_0 + c'.
  Real a[kMaxDimension * kMaxDimension], b[kMaxDimension], x[kMaxDimension];
  Real row_norms = 1;
  for (int i = 0; i < dim; ++i) {
    Real norm2 = 0;
    for (int k = 0; k < dim; ++k) {
      const Real e = Real(vertices[i + 1][k]) - Real(vertices[0][k]);
      a[i * dim + k] = e;
      norm2 += e * e;
    }
    b[i] = norm2 / 2;
    row_norms *= std::sqrt(norm2);
  }
  const Real det = solve(dim, a, b, x);
  const double ratio = det == 0 ? std::numeric_limits<double>::infinity() : static_cast<double>(row_norms / det);
  // The long double solve's error is about ratio * dim * 2^-63 * R: past kExactRatio it could
  // show in the double result (a sliver of 0.1-spaced points: 1e-4 R), and a pivot rounded
  // to zero does not prove the simplex flat. Then the centre is solved exactly.
  if (ratio > kExactRatio) {
    if (!exact_circumcentre(dim, vertices, centre)) return std::numeric_limits<double>::infinity();
    return std::isfinite(ratio) ? ratio : std::numeric_limits<double>::max();
  }
  for (int k = 0; k < dim; ++k) centre[k] = static_cast<double>(Real(vertices[0][k]) + x[k]);
  return ratio;
}

}  // namespace drange::diagram
