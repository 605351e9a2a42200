// delaunay/shell/sphere_fit.cpp: the tools that both sphere searches share (sphere_fit.hpp):
// the least-squares sphere of a set of points and the tests of how many of them lie near it.
// Plain floating point: the fit chooses the spheres, it proves nothing (sphere_fit.hpp).
#include "delaunay/shell/sphere_fit.hpp"

#include <algorithm>
#include <array>
#include <limits>

namespace drange::engine::sphere_fit {

bool solve(double* a, double* b, int m) {
  for (int col = 0; col < m; ++col) {
    int pivot = col;
    for (int r = col + 1; r < m; ++r)
      if (std::fabs(a[static_cast<std::size_t>(r * m + col)]) > std::fabs(a[static_cast<std::size_t>(pivot * m + col)])) pivot = r;
    const double p = a[static_cast<std::size_t>(pivot * m + col)];
    if (!(std::fabs(p) > 0.0) || !std::isfinite(p)) return false;
    if (pivot != col) {
      for (int c = 0; c < m; ++c) std::swap(a[static_cast<std::size_t>(pivot * m + c)], a[static_cast<std::size_t>(col * m + c)]);
      std::swap(b[static_cast<std::size_t>(pivot)], b[static_cast<std::size_t>(col)]);
    }
    for (int r = col + 1; r < m; ++r) {
      const double f = a[static_cast<std::size_t>(r * m + col)] / p;
      for (int c = col; c < m; ++c) a[static_cast<std::size_t>(r * m + c)] -= f * a[static_cast<std::size_t>(col * m + c)];
      b[static_cast<std::size_t>(r)] -= f * b[static_cast<std::size_t>(col)];
    }
  }
  for (int r = m - 1; r >= 0; --r) {
    double s = b[static_cast<std::size_t>(r)];
    for (int c = r + 1; c < m; ++c) s -= a[static_cast<std::size_t>(r * m + c)] * b[static_cast<std::size_t>(c)];
    b[static_cast<std::size_t>(r)] = s / a[static_cast<std::size_t>(r * m + r)];
  }
  for (int r = 0; r < m; ++r)
    if (!std::isfinite(b[static_cast<std::size_t>(r)])) return false;
  return true;
}

// The algebraic least-squares sphere of the points `ids`: |y|^2 = 2 c . y + k with y = x - m
// (m their mean, which keeps the normal equations well scaled), then one step of refinement
// on the residuals (with `passes` 2). False when the system is singular (points in a
// hyperplane).
bool fit(const double* coords, int dim, const std::vector<std::int32_t>& ids, Sphere& sphere, int passes) {
  if (ids.size() < static_cast<std::size_t>(dim + 2) || dim + 1 > kMaxUnknowns) return false;
  const auto point = [&](std::int32_t id) { return coords + static_cast<std::size_t>(id) * static_cast<std::size_t>(dim); };
  // Arrays on the stack: the patches' search fits thousands of spheres of a few points.
  std::array<double, kMaxUnknowns> mean{}, z{}, solution{}, rhs{};
  std::array<double, kMaxUnknowns * kMaxUnknowns> normal{};
  for (std::int32_t id : ids)
    for (int k = 0; k < dim; ++k) mean[static_cast<std::size_t>(k)] += point(id)[k];
  for (int k = 0; k < dim; ++k) mean[static_cast<std::size_t>(k)] /= static_cast<double>(ids.size());

  const int m = dim + 1;
  // The normal equations' right-hand side for the residual of (c, k): the first pass with
  // c = 0, k = 0, the refinement with the first solution.
  for (int pass = 0; pass < passes; ++pass) {
    std::fill(normal.begin(), normal.end(), 0.0);
    std::fill(rhs.begin(), rhs.end(), 0.0);
    for (std::int32_t id : ids) {
      double norm2 = 0.0, predicted = solution[static_cast<std::size_t>(dim)];
      for (int k = 0; k < dim; ++k) {
        const double y = point(id)[k] - mean[static_cast<std::size_t>(k)];
        z[static_cast<std::size_t>(k)] = 2 * y;
        norm2 += y * y;
        predicted += 2 * y * solution[static_cast<std::size_t>(k)];
      }
      z[static_cast<std::size_t>(dim)] = 1.0;
      const double residual = norm2 - predicted;
      for (int r = 0; r < m; ++r) {
        rhs[static_cast<std::size_t>(r)] += z[static_cast<std::size_t>(r)] * residual;
        for (int c = 0; c < m; ++c) normal[static_cast<std::size_t>(r * m + c)] += z[static_cast<std::size_t>(r)] * z[static_cast<std::size_t>(c)];
      }
    }
    if (!solve(normal.data(), rhs.data(), m)) return false;
    for (int r = 0; r < m; ++r) solution[static_cast<std::size_t>(r)] += rhs[static_cast<std::size_t>(r)];
  }
  sphere.centre.assign(static_cast<std::size_t>(dim), 0.0);
  double c2 = 0.0;
  for (int k = 0; k < dim; ++k) {
    sphere.centre[static_cast<std::size_t>(k)] = mean[static_cast<std::size_t>(k)] + solution[static_cast<std::size_t>(k)];
    c2 += solution[static_cast<std::size_t>(k)] * solution[static_cast<std::size_t>(k)];
  }
  sphere.radius2 = solution[static_cast<std::size_t>(dim)] + c2;
  return std::isfinite(sphere.radius2) && sphere.radius2 > 0.0;
}

std::vector<std::int32_t> near(const double* coords, int dim, const std::vector<std::int32_t>& ids, const Sphere& sphere) {
  std::vector<std::int32_t> kept;
  kept.reserve(ids.size());
  for (std::int32_t id : ids)
    if (is_near(coords, dim, id, sphere)) kept.push_back(id);
  return kept;
}

// Stops counting once too many are off the sphere, so that a sphere far from the points costs
// a few hundred of them, not all.
bool mostly_near(const double* coords, int dim, const std::vector<std::int32_t>& ids, const Sphere& sphere) {
  const auto allowed = static_cast<std::size_t>((1.0 - kInlierShare) * static_cast<double>(ids.size()));
  std::size_t off = 0;
  for (std::int32_t id : ids)
    if (!is_near(coords, dim, id, sphere) && ++off > allowed) return false;
  return true;
}

double bounding_diagonal2(const double* coords, int dim, const std::vector<std::int32_t>& ids) {
  double total = 0.0;
  for (int k = 0; k < dim; ++k) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::int32_t id : ids) {
      const double x = coords[static_cast<std::size_t>(id) * static_cast<std::size_t>(dim) + static_cast<std::size_t>(k)];
      lo = std::min(lo, x);
      hi = std::max(hi, x);
    }
    total += (hi - lo) * (hi - lo);
  }
  return total;
}

}  // namespace drange::engine::sphere_fit
