// geometry/refined_sign.cpp: the lifted determinant in double-double arithmetic.
#include "geometry/refined_sign.hpp"

#include <cmath>

#include "geometry/double_double.hpp"
#include "geometry/error_bound.hpp"

namespace drange::geometry {

namespace {
constexpr double refined_gamma(int n) { return n * kDoubleDoubleRoundoff / (1.0 - n * kDoubleDoubleRoundoff); }
}  // namespace

std::optional<int> refined_lifted_sign(const Frame& f, const double* const* points) {
  const int n = f.k + 1;
  if (n > kRefinedMaxRows) return std::nullopt;
  const FloatingPointWatch watch;
  // The rows [pi(p_r - base), |p_r - base|^2]: the differences are exact in double-double, the
  // lift carries dim roundings (its squares and sums). `size` is each entry's absolute value,
  // the leaves of the error bound's tree.
  DoubleDouble entry[kRefinedMaxRows][kRefinedMaxRows];
  double size[kRefinedMaxRows][kRefinedMaxRows];
  for (int r = 0; r < n; ++r) {
    DoubleDouble lift;
    double lift_size = 0.0;
    for (int c = 0; c < f.dim; ++c) {
      const DoubleDouble delta = difference(points[r][c], f.base[c]);
      lift = add(lift, multiply(delta, delta));
      lift_size += delta.hi * delta.hi;
    }
    for (int c = 0; c < f.k; ++c) {
      entry[r][c] = difference(points[r][f.axis(c)], f.base[f.axis(c)]);
      size[r][c] = std::fabs(entry[r][c].hi);
    }
    entry[r][f.k] = lift;
    size[r][f.k] = lift_size;
  }
  // Laplace expansion over every minor of the last m rows (m = 1 .. n), by column set: the
  // minor of rows n - m .. n - 1 on the columns of `mask`, expanded along its first row.
  constexpr int kMasks = 1 << kRefinedMaxRows;
  DoubleDouble minor[kMasks];
  double tree[kMasks];
  for (int c = 0; c < n; ++c) {
    minor[1 << c] = entry[n - 1][c];
    tree[1 << c] = size[n - 1][c];
  }
  for (int m = 2; m <= n; ++m) {
    const int r = n - m;
    for (int mask = 0; mask < (1 << n); ++mask) {
      if (__builtin_popcount(static_cast<unsigned>(mask)) != m) continue;
      DoubleDouble value;
      double t = 0.0;
      int position = 0;
      for (int c = 0; c < n; ++c) {
        if (!(mask & (1 << c))) continue;
        const int rest = mask & ~(1 << c);
        const DoubleDouble term = multiply(entry[r][c], minor[rest]);
        value = add(value, position % 2 ? negate(term) : term);
        t += size[r][c] * tree[rest];
        ++position;
      }
      minor[mask] = value;
      tree[mask] = t;
    }
  }
  const DoubleDouble det = minor[(1 << n) - 1];
  const double abs_tree = tree[(1 << n) - 1];
  if (!watch.clean() || !(abs_tree < kFilterOverflow)) return std::nullopt;
  // The computed tree is within gamma(N) (in doubles) of the exact one, and the sizes drop
  // the entries' low parts (a relative 2^-53): the 1 + 2^-40 covers both.
  const double bound = refined_gamma(laplace_roundings(n, f.dim)) * abs_tree * (1 + 0x1p-40);
  if (det.hi > bound) return 1;
  if (det.hi < -bound) return -1;
  return std::nullopt;
}

}  // namespace drange::geometry
