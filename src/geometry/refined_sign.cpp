// geometry/refined_sign.cpp: the lifted determinant in double-double arithmetic.
#include "geometry/refined_sign.hpp"

#include <cmath>

#include "geometry/double_double.hpp"
#include "geometry/error_bound.hpp"

namespace drange::geometry {

namespace {
constexpr double refined_gamma(int n) { return n * kDoubleDoubleRoundoff / (1.0 - n * kDoubleDoubleRoundoff); }

using Entries = DoubleDouble[kRefinedMaxRows][kRefinedMaxRows];
using Sizes = double[kRefinedMaxRows][kRefinedMaxRows];

// The determinant of the N x N entries by Laplace expansion over every minor of the last m
// rows (m = 1 .. N), by column set: the minor of rows N - m .. N - 1 on the columns of `mask`,
// expanded along its first row, and its absolute-value tree over the sizes. In increasing order
// of mask every minor's sub-minors (its mask less one column) come first. N is a template
// parameter so that the loops unroll and the row of each mask (N less its number of columns) is
// a constant: the generic loops, which took every mask n times to pick those of each size and
// counted their bits with a library call, took 5 500 instructions per 4 x 4 determinant.
template <int N>
void expand(const Entries& entry, const Sizes& size, DoubleDouble& det, double& abs_tree) {
  constexpr int kMasks = 1 << N;
  DoubleDouble minor[kMasks];
  double tree[kMasks];
#pragma GCC unroll 32
  for (int mask = 1; mask < kMasks; ++mask) {
    const int r = N - __builtin_popcount(static_cast<unsigned>(mask));
    DoubleDouble value;
    double t = 0.0;
    int position = 0;
#pragma GCC unroll 8
    for (int c = 0; c < N; ++c) {
      if (!(mask & (1 << c))) continue;
      const int rest = mask & ~(1 << c);
      if (rest == 0) {
        value = entry[r][c];
        t = size[r][c];
        break;
      }
      const DoubleDouble term = multiply(entry[r][c], minor[rest]);
      value = add(value, position % 2 ? negate(term) : term);
      t += size[r][c] * tree[rest];
      ++position;
    }
    minor[mask] = value;
    tree[mask] = t;
  }
  det = minor[kMasks - 1];
  abs_tree = tree[kMasks - 1];
}
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
  DoubleDouble det;
  double abs_tree = 0.0;
  switch (n) {
    case 2: expand<2>(entry, size, det, abs_tree); break;
    case 3: expand<3>(entry, size, det, abs_tree); break;
    case 4: expand<4>(entry, size, det, abs_tree); break;
    default: expand<5>(entry, size, det, abs_tree); break;
  }
  if (!watch.clean() || !(abs_tree < kFilterOverflow)) return std::nullopt;
  // The computed tree is within gamma(N) (in doubles) of the exact one, and the sizes drop
  // the entries' low parts (a relative 2^-53): the 1 + 2^-40 covers both.
  const double bound = refined_gamma(laplace_roundings(n, f.dim)) * abs_tree * (1 + 0x1p-40);
  if (det.hi > bound) return 1;
  if (det.hi < -bound) return -1;
  return std::nullopt;
}

}  // namespace drange::geometry
