// voronoi/circumcentre.cpp: see circumcentre.hpp.
#include "voronoi/circumcentre.hpp"

#include <cmath>
#include <limits>
#include <utility>

namespace drange::diagram {
namespace {

using Real = long double;

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

}  // namespace

double simplex_circumcentre(int dim, const double* const* vertices, double* centre) {
  // Row i: (v_i - v_0) . c' = |v_i - v_0|^2 / 2, with c = v_0 + c'.
  Real a[kMaxDim * kMaxDim], b[kMaxDim], x[kMaxDim];
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
  if (det == 0) return std::numeric_limits<double>::infinity();
  for (int k = 0; k < dim; ++k) centre[k] = static_cast<double>(Real(vertices[0][k]) + x[k]);
  return static_cast<double>(row_norms / det);
}

}  // namespace drange::diagram
