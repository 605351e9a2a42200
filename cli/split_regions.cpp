// cli/split_regions.cpp: see split_regions.hpp.
#include "split_regions.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include <gmpxx.h>

namespace drange::cli {
namespace {

// Beyond this condition number times the rounding unit, the first-order rounding bound is not
// trusted: the computation is repeated in long double, and failing that the region is the whole
// bounding box.
template <class Real>
constexpr Real kLargestCondition = Real(1e-7) / std::numeric_limits<Real>::epsilon();

template <class Real, class V>
Real norm(const V& v, std::size_t n) {
  Real s = 0;
  for (std::size_t k = 0; k < n; ++k) s += v[k] * v[k];
  return std::sqrt(s);
}

// Solves a x = b (n x n, row-major) by elimination with partial pivoting; false when singular.
// `inverse_norm` gets the Frobenius norm of the inverse computed from the same factors.
// A double at most (down) or at least (up) x: the box never shrinks in the conversion.
template <class Real>
double down(Real x) {
  return std::nextafter(static_cast<double>(x), -std::numeric_limits<double>::infinity());
}
template <class Real>
double up(Real x) {
  return std::nextafter(static_cast<double>(x), std::numeric_limits<double>::infinity());
}

constexpr std::size_t kMax = kMaxDimension;
template <class Real>
using Vector = std::array<Real, kMax>;
template <class Real>
using Matrix = std::array<Real, kMax * kMax>;

// Whether the rounding bound widened `box` much beyond the region as computed (`tight`): then
// the computation is repeated more precisely. A flat simplex's circumball is huge, and its cap
// within the bounds, thin but wide, is very sensitive to the radius.
bool loose(const Box& box, const Box& tight, const Box& bounds) {
  for (std::size_t k = 0; k < bounds.dim; ++k) {
    const double allowed = 1e-6 * (bounds.hi[k] - bounds.lo[k]);
    if (tight.lo[k] - box.lo[k] > allowed || box.hi[k] - tight.hi[k] > allowed) return true;
  }
  return false;
}

template <class Real>
bool solve(Matrix<Real> a, Vector<Real>& x, const Vector<Real>& b, std::size_t n, Real& inverse_norm) {
  std::array<std::size_t, kMax> pivot{};
  for (std::size_t c = 0; c < n; ++c) {
    std::size_t best = c;
    for (std::size_t r = c + 1; r < n; ++r)
      if (std::fabs(a[r * n + c]) > std::fabs(a[best * n + c])) best = r;
    if (a[best * n + c] == 0.0) return false;
    pivot[c] = best;
    if (best != c)
      for (std::size_t k = 0; k < n; ++k) std::swap(a[c * n + k], a[best * n + k]);
    for (std::size_t r = c + 1; r < n; ++r) {
      const Real f = a[r * n + c] / a[c * n + c];
      a[r * n + c] = f;
      for (std::size_t k = c + 1; k < n; ++k) a[r * n + k] -= f * a[c * n + k];
    }
  }
  const auto apply = [&](Vector<Real> y) {
    // The rows were swapped whole, multipliers included: every swap first, then L.
    for (std::size_t c = 0; c < n; ++c) std::swap(y[c], y[pivot[c]]);
    for (std::size_t c = 0; c < n; ++c)
      for (std::size_t r = c + 1; r < n; ++r) y[r] -= a[r * n + c] * y[c];
    for (std::size_t c = n; c-- > 0;) {
      for (std::size_t k = c + 1; k < n; ++k) y[c] -= a[c * n + k] * y[k];
      y[c] /= a[c * n + c];
    }
    return y;
  };
  x = apply(b);
  Real sum = 0;
  for (std::size_t c = 0; c < n; ++c) {
    Vector<Real> unit{};
    unit[c] = 1;
    const Vector<Real> column = apply(unit);
    for (std::size_t k = 0; k < n; ++k) sum += column[k] * column[k];
  }
  inverse_norm = std::sqrt(sum);
  return std::isfinite(inverse_norm) && std::isfinite(norm<Real>(x, n));
}

template <class Real>
bool ball_region_in(const std::vector<const double*>& vertices, const Box& bounds, Box& box) {
  constexpr Real eps = std::numeric_limits<Real>::epsilon();
  const std::size_t d = bounds.dim;
  // The centre is v0 + x with (vi - v0) . x = |vi - v0|^2 / 2.
  Matrix<Real> a{};
  Vector<Real> b{}, x{};
  Real a_norm = 0;
  for (std::size_t i = 0; i < d; ++i) {
    Real s = 0;
    for (std::size_t k = 0; k < d; ++k) {
      const Real e = Real(vertices[i + 1][k]) - vertices[0][k];
      a[i * d + k] = e;
      s += e * e;
    }
    a_norm += s;
    b[i] = s / 2;
  }
  a_norm = std::sqrt(a_norm);
  Real inverse_norm = 0;
  if (d == 3) {
    // The common case in closed form: the inverse's columns are the edges' cross products.
    Vector<Real> c[3];
    for (std::size_t i = 0; i < 3; ++i) {
      const Real* p = &a[((i + 1) % 3) * d];
      const Real* q = &a[((i + 2) % 3) * d];
      c[i] = {p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]};
    }
    const Real det = a[0] * c[0][0] + a[1] * c[0][1] + a[2] * c[0][2];
    if (!(det != 0)) return false;
    Real sum = 0;
    for (std::size_t i = 0; i < 3; ++i) sum += norm<Real>(c[i], 3) * norm<Real>(c[i], 3);
    inverse_norm = std::sqrt(sum) / std::fabs(det);
    for (std::size_t k = 0; k < 3; ++k) x[k] = (b[0] * c[0][k] + b[1] * c[1][k] + b[2] * c[2][k]) / det;
    if (!std::isfinite(inverse_norm) || !std::isfinite(norm<Real>(x, 3))) return false;
  } else if (!solve(a, x, b, d, inverse_norm)) {
    return false;
  }
  if (inverse_norm * a_norm > kLargestCondition<Real>) return false;
  // A bound on the centre's error: the residual and the rounding of a and b, through the
  // inverse (to first order; doubled for what the computed inverse misses).
  Real residual = 0;
  for (std::size_t i = 0; i < d; ++i) {
    Real s = -b[i];
    for (std::size_t k = 0; k < d; ++k) s += a[i * d + k] * x[k];
    residual += s * s;
  }
  const Real dd = static_cast<Real>(d);
  const Real centre_error =
      2 * inverse_norm * (std::sqrt(residual) + 8 * dd * eps * (norm<Real>(b, d) + a_norm * norm<Real>(x, d)));
  Vector<Real> centre{};
  Real radius = 0, scale = 0;
  for (std::size_t k = 0; k < d; ++k) centre[k] = vertices[0][k] + x[k];
  for (const double* v : vertices) {
    Real s = 0;
    for (std::size_t k = 0; k < d; ++k) s += (centre[k] - v[k]) * (centre[k] - v[k]);
    radius = std::max(radius, std::sqrt(s));
  }
  for (std::size_t k = 0; k < d; ++k) scale = std::max(scale, std::fabs(centre[k]) + radius);
  // The true ball lies in the computed centre's ball of radius (true radius + centre error),
  // and the true radius is at most the computed one plus the centre error; the rest covers the
  // rounding of this arithmetic.
  const Real computed = radius;
  radius = radius * (1 + 16 * eps) + 2 * centre_error + 16 * dd * eps * scale;
  if (!std::isfinite(radius)) return false;
  // The ball's part within the bounds, axis by axis: the other coordinates as near the centre as
  // the bounds allow leave the most room along this one.
  Vector<Real> gap{};
  Real gaps = 0;
  for (std::size_t k = 0; k < d; ++k) {
    const Real nearest = std::clamp(centre[k], Real(bounds.lo[k]), Real(bounds.hi[k]));
    gap[k] = (nearest - centre[k]) * (nearest - centre[k]);
    gaps += gap[k];
  }
  const auto cap = [&](Real r, Real pad, Box& out) {
    out = bounds;
    for (std::size_t k = 0; k < d; ++k) {
      // The vertices are in the ball and the bounds: the room is not negative but for rounding.
      const Real room = std::max(Real(0), r * r - (gaps - gap[k]) * (1 - pad * dd * eps));
      const Real reach = std::sqrt(room) * (1 + pad * eps) + pad * eps * scale;
      out.lo[k] = std::max(bounds.lo[k], down(centre[k] - reach));
      out.hi[k] = std::min(bounds.hi[k], up(centre[k] + reach));
      if (out.lo[k] > out.hi[k]) return false;
    }
    return true;
  };
  Box tight;
  return cap(radius, 8, box) && cap(computed, 0, tight) && !loose(box, tight, bounds);
}

template <class Real>
bool beyond_region_in(const std::vector<const double*>& facet, const double* inside, const Box& bounds, Box& box) {
  constexpr Real eps = std::numeric_limits<Real>::epsilon();
  const std::size_t d = bounds.dim;
  // The normal n: n . (vi - v0) = 0 for the facet's other vertices and n . (inside - v0) = -1,
  // so that beyond is n . (x - v0) >= 0.
  Matrix<Real> a{};
  Vector<Real> b{}, n{};
  Real a_norm = 0;
  for (std::size_t i = 0; i < d; ++i) {
    const double* v = i + 1 < d ? facet[i + 1] : inside;
    for (std::size_t k = 0; k < d; ++k) {
      a[i * d + k] = Real(v[k]) - facet[0][k];
      a_norm += a[i * d + k] * a[i * d + k];
    }
  }
  a_norm = std::sqrt(a_norm);
  b[d - 1] = -1;
  Real inverse_norm = 0;
  if (!solve(a, n, b, d, inverse_norm) || inverse_norm * a_norm > kLargestCondition<Real>) return false;
  // The half-space relaxed by a bound on the plane's error across the bounds: the direction's
  // relative error (a multiple of the condition times the rounding unit) times their extent.
  Real extent = 0;
  for (std::size_t k = 0; k < d; ++k)
    extent = std::max({extent, std::fabs(Real(bounds.hi[k]) - facet[0][k]), std::fabs(Real(bounds.lo[k]) - facet[0][k])});
  const Real dd = static_cast<Real>(d);
  const Real slack = norm<Real>(n, d) * extent * 1e3 * dd * eps * (1 + inverse_norm * a_norm);
  // Beyond: sum_k n_k (x_k - v0_k) >= -slack. Along each axis, the others at their most
  // favourable.
  Vector<Real> best{};
  Real total = 0;
  for (std::size_t k = 0; k < d; ++k) {
    best[k] = std::max(n[k] * (Real(bounds.lo[k]) - facet[0][k]), n[k] * (Real(bounds.hi[k]) - facet[0][k]));
    total += best[k];
  }
  const auto part = [&](Real relax, Real pad, Box& out) {
    out = bounds;
    for (std::size_t k = 0; k < d; ++k) {
      if (n[k] == 0) continue;
      const Real need = -relax - (total - best[k]) * (1 + pad * dd * eps) - pad * dd * eps * std::fabs(total);
      const Real bound = facet[0][k] + need / n[k];
      if (!std::isfinite(bound)) continue;
      const Real wiggle = pad * eps * (std::fabs(bound) + extent);
      if (n[k] > 0) out.lo[k] = std::max(bounds.lo[k], down(bound - wiggle));
      else out.hi[k] = std::min(bounds.hi[k], up(bound + wiggle));
      if (out.lo[k] > out.hi[k]) return false;
    }
    return true;
  };
  Box tight;
  return part(slack, 8, box) && part(0, 0, tight) && !loose(box, tight, bounds);
}

// The last resort, for simplices and facets too flat for long double: the centre or normal in
// rational arithmetic (exact), the box rounded outward. False only when flat in exact terms.
double down_exact(const mpq_class& x) {
  const double d = x.get_d();  // truncated toward zero: one step outward is below x
  return std::nextafter(d, -std::numeric_limits<double>::infinity());
}
double up_exact(const mpq_class& x) {
  const double d = x.get_d();
  return std::nextafter(d, std::numeric_limits<double>::infinity());
}
// A double at least sqrt(x), x >= 0.
mpq_class sqrt_up(const mpq_class& x) {
  double s = std::sqrt(x.get_d());
  while (mpq_class(s) * mpq_class(s) < x) s = std::nextafter(s, std::numeric_limits<double>::infinity());
  return mpq_class(s);
}

bool solve_exact(std::vector<std::vector<mpq_class>> a, std::vector<mpq_class> b, std::vector<mpq_class>& x) {
  const std::size_t n = b.size();
  for (std::size_t c = 0; c < n; ++c) {
    std::size_t p = c;
    while (p < n && a[p][c] == 0) ++p;
    if (p == n) return false;
    std::swap(a[p], a[c]);
    std::swap(b[p], b[c]);
    for (std::size_t r = 0; r < n; ++r) {
      if (r == c || a[r][c] == 0) continue;
      const mpq_class f = a[r][c] / a[c][c];
      for (std::size_t k = c; k < n; ++k) a[r][k] -= f * a[c][k];
      b[r] -= f * b[c];
    }
  }
  x.resize(n);
  for (std::size_t c = 0; c < n; ++c) x[c] = b[c] / a[c][c];
  return true;
}

bool ball_region_exact(const std::vector<const double*>& vertices, const Box& bounds, Box& box) {
  const std::size_t d = bounds.dim;
  std::vector<std::vector<mpq_class>> a(d, std::vector<mpq_class>(d));
  std::vector<mpq_class> b(d), x;
  for (std::size_t i = 0; i < d; ++i) {
    b[i] = 0;
    for (std::size_t k = 0; k < d; ++k) {
      a[i][k] = mpq_class(vertices[i + 1][k]) - mpq_class(vertices[0][k]);
      b[i] += a[i][k] * a[i][k] / 2;
    }
  }
  if (!solve_exact(a, b, x)) return false;
  std::vector<mpq_class> centre(d), gap(d);
  mpq_class radius2 = 0, gaps = 0;
  for (std::size_t k = 0; k < d; ++k) {
    centre[k] = x[k] + mpq_class(vertices[0][k]);
    radius2 += x[k] * x[k];
    mpq_class nearest = centre[k];
    if (nearest < bounds.lo[k]) nearest = bounds.lo[k];
    if (nearest > bounds.hi[k]) nearest = bounds.hi[k];
    gap[k] = (nearest - centre[k]) * (nearest - centre[k]);
    gaps += gap[k];
  }
  box = bounds;
  for (std::size_t k = 0; k < d; ++k) {
    mpq_class room = radius2 - (gaps - gap[k]);
    if (room < 0) room = 0;
    const mpq_class reach = sqrt_up(room);
    box.lo[k] = std::max(bounds.lo[k], down_exact(centre[k] - reach));
    box.hi[k] = std::min(bounds.hi[k], up_exact(centre[k] + reach));
    if (box.lo[k] > box.hi[k]) return false;
  }
  return true;
}

bool beyond_region_exact(const std::vector<const double*>& facet, const double* inside, const Box& bounds, Box& box) {
  const std::size_t d = bounds.dim;
  std::vector<std::vector<mpq_class>> a(d, std::vector<mpq_class>(d));
  std::vector<mpq_class> b(d, mpq_class(0)), n;
  for (std::size_t i = 0; i < d; ++i) {
    const double* v = i + 1 < d ? facet[i + 1] : inside;
    for (std::size_t k = 0; k < d; ++k) a[i][k] = mpq_class(v[k]) - mpq_class(facet[0][k]);
  }
  b[d - 1] = -1;
  if (!solve_exact(a, b, n)) return false;
  std::vector<mpq_class> best(d);
  mpq_class total = 0;
  for (std::size_t k = 0; k < d; ++k) {
    const mpq_class low = n[k] * (mpq_class(bounds.lo[k]) - mpq_class(facet[0][k]));
    const mpq_class high = n[k] * (mpq_class(bounds.hi[k]) - mpq_class(facet[0][k]));
    best[k] = low > high ? low : high;
    total += best[k];
  }
  box = bounds;
  for (std::size_t k = 0; k < d; ++k) {
    if (n[k] == 0) continue;
    const mpq_class bound = mpq_class(facet[0][k]) - (total - best[k]) / n[k];
    if (n[k] > 0) box.lo[k] = std::max(bounds.lo[k], down_exact(bound));
    else box.hi[k] = std::min(bounds.hi[k], up_exact(bound));
    if (box.lo[k] > box.hi[k]) return false;
  }
  return true;
}

}  // namespace

Box Box::filled(std::size_t dim, double low, double high) {
  Box box;
  box.dim = dim;
  box.lo.fill(low);
  box.hi.fill(high);
  return box;
}

bool Box::contains(const Box& inner) const {
  for (std::size_t k = 0; k < dim; ++k)
    if (inner.lo[k] < lo[k] || inner.hi[k] > hi[k]) return false;
  return true;
}

bool Box::meets(const Box& other) const {
  for (std::size_t k = 0; k < dim; ++k)
    if (other.hi[k] < lo[k] || other.lo[k] > hi[k]) return false;
  return true;
}

bool Box::contains_point(const double* p) const {
  for (std::size_t k = 0; k < dim; ++k)
    if (p[k] < lo[k] || p[k] > hi[k]) return false;
  return true;
}

Box ball_region(const std::vector<const double*>& vertices, const Box& bounds) {
  Box box;
  if (ball_region_in<double>(vertices, bounds, box) || ball_region_in<long double>(vertices, bounds, box) ||
      ball_region_exact(vertices, bounds, box))
    return box;
  return bounds;
}

Box beyond_region(const std::vector<const double*>& facet, const double* inside, const Box& bounds) {
  Box box;
  if (beyond_region_in<double>(facet, inside, bounds, box) || beyond_region_in<long double>(facet, inside, bounds, box) ||
      beyond_region_exact(facet, inside, bounds, box))
    return box;
  return bounds;
}

}  // namespace drange::cli
