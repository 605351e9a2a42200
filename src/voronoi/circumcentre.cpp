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

void face_circumcentre(int dim, int k, const double* const* points, const double* origin, long double* offset) {
  // c = p_0 + sum_j lambda_j e_j with e_j = p_j - p_0 and (e_i . e_j) lambda = |e_i|^2 / 2.
  Real e[kMaxDim * kMaxDim], gram[kMaxDim * kMaxDim], b[kMaxDim], lambda[kMaxDim];
  for (int i = 0; i < k; ++i)
    for (int c = 0; c < dim; ++c) e[i * dim + c] = Real(points[i + 1][c]) - Real(points[0][c]);
  for (int i = 0; i < k; ++i) {
    for (int j = 0; j <= i; ++j) {
      Real dot = 0;
      for (int c = 0; c < dim; ++c) dot += e[i * dim + c] * e[j * dim + c];
      gram[i * k + j] = gram[j * k + i] = dot;
    }
    b[i] = gram[i * k + i] / 2;
  }
  if (k > 0) solve(k, gram, b, lambda);
  for (int c = 0; c < dim; ++c) {
    Real sum = Real(points[0][c]) - Real(origin[c]);
    for (int j = 0; j < k; ++j) sum += lambda[j] * e[j * dim + c];
    offset[c] = sum;
  }
}

}  // namespace drange::diagram
