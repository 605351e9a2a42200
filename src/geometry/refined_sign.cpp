// geometry/refined_sign.cpp: the lifted determinant in double-double arithmetic.
#include "geometry/refined_sign.hpp"

#include <cmath>

#include "geometry/double_double.hpp"
#include "geometry/error_bound.hpp"

namespace drange::geometry {

namespace {
constexpr double refined_gamma(int n) { return n * kDoubleDoubleRoundoff / (1.0 - n * kDoubleDoubleRoundoff); }

using Row = DoubleDouble[kRefinedMaxRows];
using RowSizes = double[kRefinedMaxRows];
using Entries = Row[kRefinedMaxRows];
using Sizes = RowSizes[kRefinedMaxRows];

// The row [pi(p - base), |p - base|^2] of p: the differences are exact in double-double, the
// lift carries dim roundings (its squares and sums). `size` is each entry's absolute value, the
// leaves of the error bound's tree.
void lifted_row(const Frame& f, const double* p, Row& entry, RowSizes& size) {
  DoubleDouble lift;
  double lift_size = 0.0;
  for (int c = 0; c < f.dim; ++c) {
    const DoubleDouble delta = difference(p[c], f.base[c]);
    lift = add(lift, multiply(delta, delta));
    lift_size += delta.hi * delta.hi;
  }
  for (int c = 0; c < f.k; ++c) {
    entry[c] = difference(p[f.axis(c)], f.base[f.axis(c)]);
    size[c] = std::fabs(entry[c].hi);
  }
  entry[f.k] = lift;
  size[f.k] = lift_size;
}

// The minors of the R x C entries (R <= C) by Laplace expansion over every minor of the last m
// rows (m = 1 .. R), by column set: the minor of rows R - m .. R - 1 on the columns of `mask`,
// expanded along its first row, and its absolute-value tree over the sizes. In increasing order
// of mask every minor's sub-minors (its mask less one column) come first. R and C are template
// parameters so that the loops unroll and the row of each mask (R less its number of columns)
// is a constant: the generic loops, which took every mask n times to pick those of each size
// and counted their bits with a library call, took 5 500 instructions per 4 x 4 determinant.
template <int R, int C>
void minors_of(const Entries& entry, const Sizes& size, DoubleDouble (&minor)[1 << C], double (&tree)[1 << C]) {
#pragma GCC unroll 32
  for (int mask = 1; mask < (1 << C); ++mask) {
    const int m = __builtin_popcount(static_cast<unsigned>(mask));
    if (m > R) continue;
    const int r = R - m;
    DoubleDouble value;
    double t = 0.0;
    int position = 0;
#pragma GCC unroll 8
    for (int c = 0; c < C; ++c) {
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
}

template <int N>
void expand(const Entries& entry, const Sizes& size, DoubleDouble& det, double& abs_tree) {
  DoubleDouble minor[1 << N];
  double tree[1 << N];
  minors_of<N, N>(entry, size, minor, tree);
  det = minor[(1 << N) - 1];
  abs_tree = tree[(1 << N) - 1];
}

// expand<n> for a run-time n, 2 <= n <= kRefinedMaxRows.
void expand_rows(int n, const Entries& entry, const Sizes& size, DoubleDouble& det, double& abs_tree) {
  switch (n) {
    case 2: expand<2>(entry, size, det, abs_tree); break;
    case 3: expand<3>(entry, size, det, abs_tree); break;
    case 4: expand<4>(entry, size, det, abs_tree); break;
    default: expand<5>(entry, size, det, abs_tree); break;
  }
}

// The cofactors along the first row of an N x N matrix whose other rows are entry[0 .. N - 2]:
// the minors of those rows on every column but c, c = 0 .. N - 1, as minors_of gives them.
template <int N>
void cofactors_of(const Entries& entry, const Sizes& size, DoubleDouble* cofactor, double* tree) {
  DoubleDouble minor[1 << N];
  double minor_tree[1 << N];
  minors_of<N - 1, N>(entry, size, minor, minor_tree);
  for (int c = 0; c < N; ++c) {
    cofactor[c] = minor[((1 << N) - 1) & ~(1 << c)];
    tree[c] = minor_tree[((1 << N) - 1) & ~(1 << c)];
  }
}

// The sign of a determinant computed by minors_of, with its absolute tree, when certified (n
// rows, each entry carrying `entry_roundings` roundings).
std::optional<int> certified(DoubleDouble det, double abs_tree, int n, int entry_roundings) {
  if (!(abs_tree < kFilterOverflow)) return std::nullopt;
  // The computed tree is within gamma(N) (in doubles) of the exact one, and the sizes drop
  // the entries' low parts (a relative 2^-53): the 1 + 2^-40 covers both.
  const double bound = refined_gamma(laplace_roundings(n, entry_roundings)) * abs_tree * (1 + 0x1p-40);
  if (det.hi > bound) return 1;
  if (det.hi < -bound) return -1;
  return std::nullopt;
}
}  // namespace

std::optional<int> refined_lifted_sign(const Frame& f, const double* const* points) {
  const int n = f.k + 1;
  if (n > kRefinedMaxRows) return std::nullopt;
  const FloatingPointWatch watch;
  Entries entry;
  Sizes size;
  for (int r = 0; r < n; ++r) lifted_row(f, points[r], entry[r], size[r]);
  DoubleDouble det;
  double abs_tree = 0.0;
  expand_rows(n, entry, size, det, abs_tree);
  if (!watch.clean()) return std::nullopt;
  return certified(det, abs_tree, n, f.dim);
}

std::optional<int> refined_orientation(const Frame& f, const double* const* points) {
  const int n = f.k;
  if (n < 2 || n > kRefinedMaxRows) return std::nullopt;
  const FloatingPointWatch watch;
  Entries entry;
  Sizes size;
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) {
      entry[r][c] = difference(points[r][f.axis(c)], f.base[f.axis(c)]);
      size[r][c] = std::fabs(entry[r][c].hi);
    }
  DoubleDouble det;
  double abs_tree = 0.0;
  expand_rows(n, entry, size, det, abs_tree);
  if (!watch.clean()) return std::nullopt;
  // The entries are exact; counting one rounding each, as the lifted rows' spatial entries, only
  // widens the bound.
  return certified(det, abs_tree, n, 1);
}

void RefinedCofactors::prepare(const Frame& f, const double* const* points) {
  n_ = f.k + 1;
  usable_ = false;
  if (n_ > kRefinedMaxRows) return;
  const FloatingPointWatch watch;
  Entries entry;
  Sizes size;
  for (int r = 0; r + 1 < n_; ++r) lifted_row(f, points[r], entry[r], size[r]);
  switch (n_) {
    case 2: cofactors_of<2>(entry, size, cofactor_, tree_); break;
    case 3: cofactors_of<3>(entry, size, cofactor_, tree_); break;
    case 4: cofactors_of<4>(entry, size, cofactor_, tree_); break;
    default: cofactors_of<5>(entry, size, cofactor_, tree_); break;
  }
  usable_ = watch.clean();
}

std::optional<int> RefinedCofactors::sign_with(const Frame& f, const double* x) const {
  if (!usable_) return std::nullopt;
  const FloatingPointWatch watch;
  Row entry;
  RowSizes size;
  lifted_row(f, x, entry, size);
  // minors_of's expansion of the matrix [x; p_1; ...; p_{n-1}] along its first row, in the same
  // order: the same value and tree as refined_lifted_sign of those rows, bit for bit.
  DoubleDouble det;
  double abs_tree = 0.0;
  for (int c = 0; c < n_; ++c) {
    const DoubleDouble term = multiply(entry[c], cofactor_[c]);
    det = add(det, c % 2 ? negate(term) : term);
    abs_tree += size[c] * tree_[c];
  }
  if (!watch.clean()) return std::nullopt;
  const std::optional<int> s = certified(det, abs_tree, n_, f.dim);
  // x's row moved from last to first: n - 1 transpositions.
  if (s && n_ % 2 == 0) return -*s;
  return s;
}

}  // namespace drange::geometry
