// geometry/refined_sign.cpp: the lifted determinant in double-double arithmetic.
#include "geometry/refined_sign.hpp"

#include <cmath>
#include <type_traits>

#include "drange/points.hpp"
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
template <bool kFma>
void lifted_row(const Frame& f, const double* p, Row& entry, RowSizes& size) {
  DoubleDouble lift;
  double lift_size = 0.0;
  for (int c = 0; c < f.dim; ++c) {
    const DoubleDouble delta = difference(p[c], f.base[c]);
    lift = add(lift, multiply<kFma>(delta, delta));
    lift_size += delta.hi * delta.hi;
  }
  for (int c = 0; c < f.k; ++c) {
    entry[c] = difference(p[f.axis(c)], f.base[f.axis(c)]);
    size[c] = std::fabs(entry[c].hi);
  }
  entry[f.k] = lift;
  size[f.k] = lift_size;
}

// The minor of the rows R - m .. R - 1 (m the bits of `mask`) on the columns of `mask`, expanded
// along its first row `entry` over the minors of the rows below it (`minor`, by column set),
// and its absolute-value tree over the sizes. The one expansion that minors_of and
// candidate_cofactors_as share, so that both give the same bits.
template <int C, bool kFma>
inline void expand_along(const DoubleDouble* entry, const double* size, int mask, const DoubleDouble* minor,
                         const double* tree, DoubleDouble& value, double& t) {
  value = DoubleDouble{};
  t = 0.0;
  int position = 0;
#pragma GCC unroll 8
  for (int c = 0; c < C; ++c) {
    if (!(mask & (1 << c))) continue;
    const int rest = mask & ~(1 << c);
    if (rest == 0) {
      value = entry[c];
      t = size[c];
      break;
    }
    const DoubleDouble term = multiply<kFma>(entry[c], minor[rest]);
    value = add(value, position % 2 ? negate(term) : term);
    t += size[c] * tree[rest];
    ++position;
  }
}

// The minors of the R x C entries (R <= C) by Laplace expansion over every minor of the last m
// rows (m = 1 .. R), by column set: the minor of rows R - m .. R - 1 on the columns of `mask`,
// expanded along its first row, and its absolute-value tree over the sizes (1 << C entries
// each). In increasing order of mask every minor's sub-minors (its mask less one column) come
// first. R and C are template parameters so that the loops unroll and the row of each mask (R
// less its number of columns) is a constant: generic loops, taking every mask n times to pick
// those of each size and counting their bits with a library call, cost several times the
// instructions per determinant.
template <int R, int C, bool kFma>
void minors_of(const Entries& entry, const Sizes& size, DoubleDouble* minor, double* tree) {
#pragma GCC unroll 64
  for (int mask = 1; mask < (1 << C); ++mask) {
    const int m = __builtin_popcount(static_cast<unsigned>(mask));
    if (m > R) continue;
    const int r = R - m;
    DoubleDouble value;
    double t;
    expand_along<C, kFma>(entry[r], size[r], mask, minor, tree, value, t);
    minor[mask] = value;
    tree[mask] = t;
  }
}

template <int N, bool kFma>
void expand(const Entries& entry, const Sizes& size, DoubleDouble& det, double& abs_tree) {
  DoubleDouble minor[1 << N];
  double tree[1 << N];
  minors_of<N, N, kFma>(entry, size, minor, tree);
  det = minor[(1 << N) - 1];
  abs_tree = tree[(1 << N) - 1];
}

// body(std::integral_constant<int, n>) for a run-time n, 2 <= n <= kRefinedMaxRows: the
// templates above take the size at compile time.
template <class Body>
void with_rows(int n, const Body& body) {
  static_assert(kRefinedMaxRows == 6, "one case per size");
  switch (n) {
    case 2: body(std::integral_constant<int, 2>{}); break;
    case 3: body(std::integral_constant<int, 3>{}); break;
    case 4: body(std::integral_constant<int, 4>{}); break;
    case 5: body(std::integral_constant<int, 5>{}); break;
    default: body(std::integral_constant<int, 6>{}); break;
  }
}

// expand<n> for a run-time n.
template <bool kFma>
void expand_rows(int n, const Entries& entry, const Sizes& size, DoubleDouble& det, double& abs_tree) {
  with_rows(n, [&](auto rows) { expand<rows, kFma>(entry, size, det, abs_tree); });
}

// The cofactors along the first row of an N x N matrix whose other rows are entry[0 .. N - 2]:
// the minors of those rows on every column but c, c = 0 .. N - 1, as minors_of gives them.
template <int N, bool kFma>
void cofactors_of(const Entries& entry, const Sizes& size, DoubleDouble* cofactor, double* tree) {
  DoubleDouble minor[1 << N];
  double minor_tree[1 << N];
  minors_of<N - 1, N, kFma>(entry, size, minor, minor_tree);
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

template <bool kFma>
std::optional<int> lifted_sign_as(const Frame& f, const double* const* points) {
  const int n = f.k + 1;
  const FloatingPointWatch watch;
  Entries entry;
  Sizes size;
  for (int r = 0; r < n; ++r) lifted_row<kFma>(f, points[r], entry[r], size[r]);
  DoubleDouble det;
  double abs_tree = 0.0;
  expand_rows<kFma>(n, entry, size, det, abs_tree);
  if (!watch.clean()) return std::nullopt;
  return certified(det, abs_tree, n, f.dim);
}

// The row [pi(p - base)] of orientation's determinant: exact differences, their sizes.
void difference_row(const Frame& f, const double* p, Row& entry, RowSizes& size) {
  for (int c = 0; c < f.k; ++c) {
    entry[c] = difference(p[f.axis(c)], f.base[f.axis(c)]);
    size[c] = std::fabs(entry[c].hi);
  }
}

// A row of the lifted determinant (kLifted) or of orientation's.
template <bool kFma, bool kLifted>
void row_of(const Frame& f, const double* p, Row& entry, RowSizes& size) {
  if constexpr (kLifted) lifted_row<kFma>(f, p, entry, size);
  else difference_row(f, p, entry, size);
}

// Roundings in each entry: the lift's f.dim (differences are exact; counting one rounding for
// them, as the lifted rows' spatial entries do, only widens the bound).
template <bool kLifted>
int entry_roundings(const Frame& f) {
  return kLifted ? f.dim : 1;
}

template <bool kFma>
std::optional<int> orientation_as(const Frame& f, const double* const* points) {
  const int n = f.k;
  const FloatingPointWatch watch;
  Entries entry;
  Sizes size;
  for (int r = 0; r < n; ++r) difference_row(f, points[r], entry[r], size[r]);
  DoubleDouble det;
  double abs_tree = 0.0;
  expand_rows<kFma>(n, entry, size, det, abs_tree);
  if (!watch.clean()) return std::nullopt;
  return certified(det, abs_tree, n, entry_roundings<false>(f));
}

// The cofactors of orientation's n rows whose first is left out, from the n - 1 others
// (`points`); false on under- or overflow.
template <bool kFma>
bool orientation_cofactors_as(const Frame& f, const double* const* points, int n, DoubleDouble* cofactor, double* tree) {
  const FloatingPointWatch watch;
  Entries entry;
  Sizes size;
  for (int r = 0; r + 1 < n; ++r) difference_row(f, points[r], entry[r], size[r]);
  with_rows(n, [&](auto rows) { cofactors_of<rows, kFma>(entry, size, cofactor, tree); });
  return watch.clean();
}

// The facet's part of a candidate's lifted cofactors: the minors of the rows p_1 .. p_{n-2}
// (`points`) on every column set of up to n - 2 columns (minors_of's, 1 << n entries each);
// false on under- or overflow.
template <bool kFma>
bool facet_minors_as(const Frame& f, const double* const* points, int n, DoubleDouble* minor, double* tree) {
  const FloatingPointWatch watch;
  Entries entry;
  Sizes size;
  for (int r = 0; r + 2 < n; ++r) lifted_row<kFma>(f, points[r], entry[r], size[r]);
  with_rows(n, [&](auto rows) { minors_of<rows - 2, rows, kFma>(entry, size, minor, tree); });
  return watch.clean();
}

// The cofactors of [x; candidate; p_1; ...; p_{n-2}] along x's row from facet_minors_as's minors:
// each expanded along the candidate's row, as minors_of expands its top level, so that they are
// the bits cofactors_of gives on the lifted rows [candidate; p_1; ...] (n products per cofactor
// instead of all the levels: in 4D 20 double-double products instead of 70).
template <bool kFma>
bool candidate_cofactors_as(const Frame& f, const double* candidate, int n, const DoubleDouble* minor,
                            const double* minor_tree, DoubleDouble* cofactor, double* tree) {
  const FloatingPointWatch watch;
  Row entry;
  RowSizes size;
  lifted_row<kFma>(f, candidate, entry, size);
  with_rows(n, [&](auto rows) {
    constexpr int kColumns = rows;
#pragma GCC unroll 8
    for (int c = 0; c < kColumns; ++c) {
      DoubleDouble value;
      double t;
      expand_along<kColumns, kFma>(entry, size, ((1 << kColumns) - 1) & ~(1 << c), minor, minor_tree, value, t);
      cofactor[c] = value;
      tree[c] = t;
    }
  });
  return watch.clean();
}

// minors_of's expansion of the matrix [x; p_1; ...; p_{n-1}] along its first row, in the same
// order: the same value and tree as lifted_sign_as (orientation_as) of those rows, bit for bit.
template <bool kFma, bool kLifted>
std::optional<int> sign_with_as(const Frame& f, const double* x, int n, const DoubleDouble* cofactor, const double* tree) {
  const FloatingPointWatch watch;
  Row entry;
  RowSizes size;
  row_of<kFma, kLifted>(f, x, entry, size);
  DoubleDouble det;
  double abs_tree = 0.0;
  for (int c = 0; c < n; ++c) {
    const DoubleDouble term = multiply<kFma>(entry[c], cofactor[c]);
    det = add(det, c % 2 ? negate(term) : term);
    abs_tree += size[c] * tree[c];
  }
  if (!watch.clean()) return std::nullopt;
  return certified(det, abs_tree, n, entry_roundings<kLifted>(f));
}

// The kFma instances, compiled for processors with fused multiply-add: `flatten` inlines the
// whole computation into them, so that every two_product is the instruction. Called only where
// the processor has it (uses_fma).
#define DRANGE_FMA_CODE __attribute__((target("fma"), flatten))
DRANGE_FMA_CODE std::optional<int> lifted_sign_fma(const Frame& f, const double* const* points) {
  return lifted_sign_as<true>(f, points);
}
DRANGE_FMA_CODE std::optional<int> orientation_fma(const Frame& f, const double* const* points) {
  return orientation_as<true>(f, points);
}
DRANGE_FMA_CODE bool facet_minors_fma(const Frame& f, const double* const* points, int n, DoubleDouble* minor, double* tree) {
  return facet_minors_as<true>(f, points, n, minor, tree);
}
DRANGE_FMA_CODE bool candidate_cofactors_fma(const Frame& f, const double* candidate, int n, const DoubleDouble* minor,
                                             const double* minor_tree, DoubleDouble* cofactor, double* tree) {
  return candidate_cofactors_as<true>(f, candidate, n, minor, minor_tree, cofactor, tree);
}
DRANGE_FMA_CODE bool orientation_cofactors_fma(const Frame& f, const double* const* points, int n, DoubleDouble* cofactor,
                                               double* tree) {
  return orientation_cofactors_as<true>(f, points, n, cofactor, tree);
}
template <bool kLifted>
DRANGE_FMA_CODE std::optional<int> sign_with_fma(const Frame& f, const double* x, int n, const DoubleDouble* cofactor,
                                                 const double* tree) {
  return sign_with_as<true, kLifted>(f, x, n, cofactor, tree);
}
#undef DRANGE_FMA_CODE

bool processor_has_fma() {
  __builtin_cpu_init();
  return __builtin_cpu_supports("fma");
}

// Read on every call (a load and a branch); written by set_refined_fma only.
bool uses_fma = processor_has_fma();
}  // namespace

bool refined_fma() { return uses_fma; }

void set_refined_fma(bool on) { uses_fma = on && processor_has_fma(); }

std::optional<int> refined_lifted_sign(const Frame& f, const double* const* points) {
  if (f.k + 1 > kRefinedMaxRows) return std::nullopt;
  return uses_fma ? lifted_sign_fma(f, points) : lifted_sign_as<false>(f, points);
}

std::optional<int> refined_orientation(const Frame& f, const double* const* points) {
  if (f.k < 2 || f.k > kRefinedMaxRows) return std::nullopt;
  return uses_fma ? orientation_fma(f, points) : orientation_as<false>(f, points);
}

void RefinedCofactors::prepare(const Frame& f, const double* const* points) {
  prepare_facet(f, points);
  prepare_candidate(f, points[f.k - 1]);
}

void RefinedCofactors::prepare_facet(const Frame& f, const double* const* points) {
  n_ = f.k + 1;
  lifted_ = true;
  usable_ = false;
  facet_usable_ = n_ <= kRefinedMaxRows &&
                  (uses_fma ? facet_minors_fma(f, points, n_, facet_minor_, facet_tree_)
                            : facet_minors_as<false>(f, points, n_, facet_minor_, facet_tree_));
}

void RefinedCofactors::prepare_candidate(const Frame& f, const double* candidate) {
  usable_ = facet_usable_ &&
            (uses_fma ? candidate_cofactors_fma(f, candidate, n_, facet_minor_, facet_tree_, cofactor_, tree_)
                      : candidate_cofactors_as<false>(f, candidate, n_, facet_minor_, facet_tree_, cofactor_, tree_));
  if (!usable_) return;
  // Each cofactor is an (n - 1)-minor of rows whose entries carry f.dim roundings: certified's
  // bound for such a minor (the 1 + 2^-40 also covers this product's roundings).
  const double gamma = refined_gamma(laplace_roundings(n_ - 1, f.dim)) * (1 + 0x1p-40);
  for (int c = 0; c < n_; ++c) error_[c] = gamma * tree_[c];
  quick_gamma_ = gamma_bound(n_ + f.dim + 1);  // quick_sign_with's, once per candidate
}

void RefinedCofactors::prepare_orientation(const Frame& f, const double* const* points) {
  n_ = f.k;
  lifted_ = false;
  facet_usable_ = false;
  usable_ = n_ >= 2 && n_ <= kRefinedMaxRows &&
            (uses_fma ? orientation_cofactors_fma(f, points, n_, cofactor_, tree_)
                      : orientation_cofactors_as<false>(f, points, n_, cofactor_, tree_));
}

bool RefinedCofactors::linear_form(double* coefficient, double* slack) const {
  if (!usable_ || !lifted_) return false;
  // The points' order negates sign_with's expansion (to_points_order), whose terms alternate.
  for (int c = 0; c < n_; ++c) {
    coefficient[c] = (c % 2 ? 1.0 : -1.0) * cofactor_[c].hi;
    slack[c] = std::fabs(cofactor_[c].lo) + error_[c];
  }
  return true;
}

std::optional<int> RefinedCofactors::quick_sign_with(const Frame& f, const double* x) const {
  if (!usable_ || !lifted_ || f.dim > kMaxDimension) return std::nullopt;
  // x's row R in doubles: the differences carry one rounding, the lift dim + 1 (at most
  // eps = gamma(dim + 1) relative to the exact row r).
  double delta[kMaxDimension];
  double lift = 0.0;
  for (int c = 0; c < f.dim; ++c) {
    delta[c] = x[c] - f.base[c];
    lift += delta[c] * delta[c];
  }
  // The exact value is sum_c +-C_c r_c, C_c the exact cofactor, within error_[c] of hi + lo:
  //   |sum +-C_c r_c - v| <= sum (|lo_c| + error_c) |r_c| + eps sum |hi_c| |r_c| + gamma(n) mag,
  // v and mag = sum |hi_c| |R_c| as computed, |r_c| <= |R_c| / (1 - eps). gamma_bound(n + dim
  // + 1) covers the last two terms (Higham's lemma 3.3 and its 1e-6 margin), 1 + 2^-40 the
  // rest's roundings, kUnderflowError what underflow adds (points scaled below 1).
  double v = 0.0, mag = 0.0, low = 0.0;
  for (int c = 0; c < n_; ++c) {
    const double r = c < f.k ? delta[f.axis(c)] : lift;
    const double term = cofactor_[c].hi * r;
    v += c % 2 ? -term : term;
    mag += std::fabs(term);
    low += (std::fabs(cofactor_[c].lo) + error_[c]) * std::fabs(r);
  }
  if (!(mag > kFilterUnderflow && mag < kFilterOverflow)) return std::nullopt;  // also NaN
  const double bound = (quick_gamma_ * mag + low + kUnderflowError) * (1 + 0x1p-40);
  int s = 0;
  if (v > bound) s = 1;
  else if (v < -bound) s = -1;
  else return std::nullopt;
  return to_points_order(s);
}

std::optional<int> RefinedCofactors::sign_with(const Frame& f, const double* x) const {
  if (!usable_) return std::nullopt;
  std::optional<int> s;
  if (lifted_) s = uses_fma ? sign_with_fma<true>(f, x, n_, cofactor_, tree_) : sign_with_as<false, true>(f, x, n_, cofactor_, tree_);
  else s = uses_fma ? sign_with_fma<false>(f, x, n_, cofactor_, tree_) : sign_with_as<false, false>(f, x, n_, cofactor_, tree_);
  if (s) return to_points_order(*s);
  return s;
}

}  // namespace drange::geometry
