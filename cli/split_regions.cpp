// cli/split_regions.cpp: see split_regions.hpp.
#include "split_regions.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace drange::cli {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
// Beyond this condition number of the linear system, the rounding bound is not trusted and the
// region is the whole bounding box.
constexpr double kLargestCondition = 1e9;

double norm(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x * x;
  return std::sqrt(s);
}

// Solves a x = b (n x n, row-major) by elimination with partial pivoting; false when singular.
// `inverse_norm` gets the Frobenius norm of the inverse computed from the same factors.
bool solve(std::vector<double> a, std::vector<double>& x, const std::vector<double>& b, std::size_t n,
           double& inverse_norm) {
  std::vector<std::size_t> pivot(n);
  for (std::size_t c = 0; c < n; ++c) {
    std::size_t best = c;
    for (std::size_t r = c + 1; r < n; ++r)
      if (std::fabs(a[r * n + c]) > std::fabs(a[best * n + c])) best = r;
    if (a[best * n + c] == 0.0) return false;
    pivot[c] = best;
    if (best != c)
      for (std::size_t k = 0; k < n; ++k) std::swap(a[c * n + k], a[best * n + k]);
    for (std::size_t r = c + 1; r < n; ++r) {
      const double f = a[r * n + c] / a[c * n + c];
      a[r * n + c] = f;
      for (std::size_t k = c + 1; k < n; ++k) a[r * n + k] -= f * a[c * n + k];
    }
  }
  const auto apply = [&](std::vector<double> y) {
    for (std::size_t c = 0; c < n; ++c) {
      std::swap(y[c], y[pivot[c]]);
      for (std::size_t r = c + 1; r < n; ++r) y[r] -= a[r * n + c] * y[c];
    }
    for (std::size_t c = n; c-- > 0;) {
      for (std::size_t k = c + 1; k < n; ++k) y[c] -= a[c * n + k] * y[k];
      y[c] /= a[c * n + c];
    }
    return y;
  };
  x = apply(b);
  double sum = 0;
  for (std::size_t c = 0; c < n; ++c) {
    std::vector<double> unit(n, 0.0);
    unit[c] = 1.0;
    for (double v : apply(unit)) sum += v * v;
  }
  inverse_norm = std::sqrt(sum);
  return std::isfinite(inverse_norm) && std::isfinite(norm(x));
}

}  // namespace

bool Box::contains(const Box& inner) const {
  for (std::size_t k = 0; k < lo.size(); ++k)
    if (inner.lo[k] < lo[k] || inner.hi[k] > hi[k]) return false;
  return true;
}

bool Box::meets(const Box& other) const {
  for (std::size_t k = 0; k < lo.size(); ++k)
    if (other.hi[k] < lo[k] || other.lo[k] > hi[k]) return false;
  return true;
}

bool Box::contains_point(const double* p) const {
  for (std::size_t k = 0; k < lo.size(); ++k)
    if (p[k] < lo[k] || p[k] > hi[k]) return false;
  return true;
}

Box ball_region(const std::vector<const double*>& vertices, const Box& bounds) {
  const std::size_t d = bounds.lo.size();
  // The centre is v0 + x with (vi - v0) . x = |vi - v0|^2 / 2.
  std::vector<double> a(d * d), b(d), x;
  double a_norm = 0;
  for (std::size_t i = 0; i < d; ++i) {
    double s = 0;
    for (std::size_t k = 0; k < d; ++k) {
      const double e = vertices[i + 1][k] - vertices[0][k];
      a[i * d + k] = e;
      s += e * e;
    }
    a_norm += s;
    b[i] = s / 2;
  }
  a_norm = std::sqrt(a_norm);
  double inverse_norm = 0;
  if (!solve(a, x, b, d, inverse_norm) || inverse_norm * a_norm > kLargestCondition) return bounds;
  // A bound on the centre's error: the residual and the rounding of a and b, through the
  // inverse (to first order; doubled for what the computed inverse misses).
  double residual = 0;
  for (std::size_t i = 0; i < d; ++i) {
    double s = -b[i];
    for (std::size_t k = 0; k < d; ++k) s += a[i * d + k] * x[k];
    residual += s * s;
  }
  const double dd = static_cast<double>(d);
  const double centre_error =
      2 * inverse_norm * (std::sqrt(residual) + 8 * dd * kEps * (norm(b) + a_norm * norm(x)));
  std::vector<double> centre(d);
  double radius = 0, scale = 0;
  for (std::size_t k = 0; k < d; ++k) centre[k] = vertices[0][k] + x[k];
  for (const double* v : vertices) {
    double s = 0;
    for (std::size_t k = 0; k < d; ++k) s += (centre[k] - v[k]) * (centre[k] - v[k]);
    radius = std::max(radius, std::sqrt(s));
  }
  for (std::size_t k = 0; k < d; ++k) scale = std::max(scale, std::fabs(centre[k]) + radius);
  // The true ball lies in the computed centre's ball of radius (true radius + centre error),
  // and the true radius is at most the computed one plus the centre error; the rest covers the
  // rounding of this arithmetic.
  radius = radius * (1 + 16 * kEps) + 2 * centre_error + 16 * dd * kEps * scale;
  if (!std::isfinite(radius)) return bounds;
  // The ball's part within the bounds, axis by axis: the other coordinates as near the centre as
  // the bounds allow leave the most room along this one.
  std::vector<double> gap(d);
  double gaps = 0;
  for (std::size_t k = 0; k < d; ++k) {
    const double nearest = std::clamp(centre[k], bounds.lo[k], bounds.hi[k]);
    gap[k] = (nearest - centre[k]) * (nearest - centre[k]);
    gaps += gap[k];
  }
  Box box = bounds;
  for (std::size_t k = 0; k < d; ++k) {
    // The vertices are in the ball and the bounds, so the room is not negative but for rounding.
    const double room = std::max(0.0, radius * radius - (gaps - gap[k]) * (1 - 8 * dd * kEps));
    const double reach = std::sqrt(room) * (1 + 8 * kEps) + 8 * kEps * scale;
    box.lo[k] = std::max(bounds.lo[k], centre[k] - reach);
    box.hi[k] = std::min(bounds.hi[k], centre[k] + reach);
    if (box.lo[k] > box.hi[k]) return bounds;
  }
  return box;
}

Box beyond_region(const std::vector<const double*>& facet, const double* inside, const Box& bounds) {
  const std::size_t d = bounds.lo.size();
  // The normal n: n . (vi - v0) = 0 for the facet's other vertices and n . (inside - v0) = -1,
  // so that beyond is n . (x - v0) >= 0.
  std::vector<double> a(d * d), b(d, 0.0), n;
  double a_norm = 0;
  for (std::size_t i = 0; i < d; ++i) {
    const double* v = i + 1 < d ? facet[i + 1] : inside;
    for (std::size_t k = 0; k < d; ++k) {
      a[i * d + k] = v[k] - facet[0][k];
      a_norm += a[i * d + k] * a[i * d + k];
    }
  }
  a_norm = std::sqrt(a_norm);
  b[d - 1] = -1;
  double inverse_norm = 0;
  if (!solve(a, n, b, d, inverse_norm) || inverse_norm * a_norm > kLargestCondition) return bounds;
  // The half-space relaxed by a bound on the plane's error across the bounds: the direction's
  // relative error (a multiple of the condition times the rounding unit) times their extent.
  double extent = 0;
  for (std::size_t k = 0; k < d; ++k)
    extent = std::max({extent, std::fabs(bounds.hi[k] - facet[0][k]), std::fabs(bounds.lo[k] - facet[0][k])});
  const double dd = static_cast<double>(d);
  const double slack = norm(n) * extent * 1e3 * dd * kEps * (1 + inverse_norm * a_norm);
  // Beyond: sum_k n_k (x_k - v0_k) >= -slack. Along each axis, the others at their most
  // favourable.
  std::vector<double> best(d);
  double total = 0;
  for (std::size_t k = 0; k < d; ++k) {
    best[k] = std::max(n[k] * (bounds.lo[k] - facet[0][k]), n[k] * (bounds.hi[k] - facet[0][k]));
    total += best[k];
  }
  Box box = bounds;
  for (std::size_t k = 0; k < d; ++k) {
    if (n[k] == 0) continue;
    const double need = -slack - (total - best[k]) * (1 + 8 * dd * kEps) - 8 * dd * kEps * std::fabs(total);
    const double bound = facet[0][k] + need / n[k];
    if (!std::isfinite(bound)) continue;
    const double wiggle = 8 * kEps * (std::fabs(bound) + extent);
    if (n[k] > 0) box.lo[k] = std::max(bounds.lo[k], bound - wiggle);
    else box.hi[k] = std::min(bounds.hi[k], bound + wiggle);
    if (box.lo[k] > box.hi[k]) return bounds;
  }
  return box;
}

}  // namespace drange::cli
