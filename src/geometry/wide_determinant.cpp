// geometry/wide_determinant.cpp: exact signs of small determinants in fixed-width integers.
#include "geometry/wide_determinant.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <cstdint>
#include <limits>
#include <utility>

#include "geometry/double_bits.hpp"
#include "geometry/error_bound.hpp"
#include "geometry/minors.hpp"
#include "geometry/wide_integer.hpp"

namespace drange::geometry {
namespace {

constexpr int kMaxColumns = WideLiftedCofactors::kMaxDim;  // 7 x 7 orientations, 8 x 8 lifted determinants (7D)
// The largest difference taken, in the common unit: below it, a difference's rounding to a
// double and its error are each at most 2^62 - 2^10 and 2^8, so the difference is below 2^62,
// the bound of every formula below.
constexpr double kLargestDifference = 0x1p62 - 0x1p10;

// The common unit of the coordinates that enter one determinant: the least exponent of their
// lowest set bits. Every coordinate is then an integer multiple of 2^unit.
class CommonUnit {
 public:
  void include(double x) {
    if (x != 0.0) unit_ = std::min(unit_, lowest_bit_exponent(x));
  }
  int unit() const { return unit_; }
  // 2^-unit, or 0 where that is not a normal double (a unit below 2^-1023 or above 2^1022:
  // the caller declines).
  double inverse() const {
    if (unit_ == std::numeric_limits<int>::max()) return 1.0;  // every coordinate 0
    const int exponent = -unit_;
    if (exponent < -1022 || exponent > 1023) return 0.0;
    const std::uint64_t bits = static_cast<std::uint64_t>(exponent + 1023) << 52;
    double out;
    std::memcpy(&out, &bits, sizeof out);
    return out;
  }

 private:
  int unit_ = std::numeric_limits<int>::max();
};

// (x - base) / 2^unit into `out` (`inverse` = 2^-unit, nonzero; x and base multiples of
// 2^unit); false when it is not below kLargestDifference. The difference is hi + lo exactly
// (Knuth's two-sum), each a multiple of 2^unit (a rounding of one is a multiple of its ulp, at
// least 2^unit), so each scales to an integer exactly: two conversions, where shifting each
// coordinate's significand into 128 bits would take several times the instructions.
[[gnu::always_inline]] inline bool difference(double x, double base, double inverse, std::int64_t& out) {
  const double hi = x - base;  // two-sum of x and -base
  const double base_part = hi - x, x_part = hi - base_part;
  const double lo = (x - x_part) - (base + base_part);
  const double hi_units = hi * inverse;
  if (!(std::fabs(hi_units) <= kLargestDifference)) return false;
  out = static_cast<std::int64_t>(hi_units) + static_cast<std::int64_t>(lo * inverse);
  return true;
}

Int128 product(std::int64_t a, std::int64_t b) { return static_cast<Int128>(a) * b; }

// a d - b c, of differences: below 2^125.
Int128 minor2(std::int64_t a, std::int64_t b, std::int64_t c, std::int64_t d) { return product(a, d) - product(b, c); }

// The rows of the lifted determinant: x[r] the spatial differences on the frame's axes, lift[r]
// the squared distance over all dim axes, for rows [0, rows); false when one does not fit.
bool lifted_rows(const Frame& f, double inverse, const double* const* points, int rows,
                 std::int64_t (*x)[kMaxColumns], Int128* lift) {
  for (int r = 0; r < rows; ++r) {
    std::int64_t delta[kMaxColumns];
    lift[r] = 0;
    for (int c = 0; c < f.dim; ++c) {
      if (!difference(points[r][c], f.base[c], inverse, delta[c])) return false;
      lift[r] += product(delta[c], delta[c]);
    }
    for (int c = 0; c < f.k; ++c) x[r][c] = delta[f.axis(c)];
  }
  return true;
}

// The 2 x 2 spatial minors of the first three rows' pairs (0, 1), (0, 2), (1, 2) on three
// columns: m[pair][the column left out], each below 2^125.
void pair_minors3(const std::int64_t (*x)[kMaxColumns], Wide<2> (&m)[3][3]) {
  const int pairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};
  for (int p = 0; p < 3; ++p) {
    const int r = pairs[p][0], s = pairs[p][1];
    m[p][0] = Wide<2>::from(minor2(x[r][1], x[r][2], x[s][1], x[s][2]));
    m[p][1] = Wide<2>::from(minor2(x[r][0], x[r][2], x[s][0], x[s][2]));
    m[p][2] = Wide<2>::from(minor2(x[r][0], x[r][1], x[s][0], x[s][1]));
  }
}

// The 2 x 2 minor of rows r, s over spatial column a and the lift, x_r[a] L_s - L_r x_s[a]:
// below 2^62 2^126.6 2 < 2^189.6 (6D lifts).
[[gnu::always_inline]] inline Wide<3> lift_minor(const std::int64_t (*x)[kMaxColumns], const Int128* lift, int r, int s, int a) {
  return Wide<1>::from(x[r][a]) * Wide<2>::from(lift[s]) - Wide<1>::from(x[s][a]) * Wide<2>::from(lift[r]);
}

// The index of the pair a < b of 0 .. n - 1, pairs in lexicographic order: for n = 4, (0,1) 0,
// (0,2) 1, (0,3) 2, (1,2) 3, (1,3) 4, (2,3) 5.
constexpr int pair_index(int a, int b, int n = 4) { return a * (2 * n - a - 1) / 2 + (b - a - 1); }

// The 2 x 2 minors of rows r, s of x on the pairs of the first N columns, by pair_index.
template <int N>
void pair_minors(const std::int64_t (*x)[kMaxColumns], int r, int s, Wide<2> (&m)[N * (N - 1) / 2]) {
#pragma GCC unroll 10
  for (int a = 0; a < N; ++a)
#pragma GCC unroll 10
    for (int b = a + 1; b < N; ++b) m[pair_index(a, b, N)] = Wide<2>::from(minor2(x[r][a], x[r][b], x[s][a], x[s][b]));
}

// A 4 x 4 determinant by Laplace along its first two rows, from their 2 x 2 minors (top) and
// the last two rows' (bottom): the sum over column pairs a < b of (-1)^(a + b + 1) top(a, b)
// bottom(the other two). Each minor below 2^125, each product below 2^250, the sum below 2^253.
Wide<4> laplace4(const Wide<2> (&top)[6], const Wide<2> (&bottom)[6]) {
  return top[0] * bottom[5] - top[1] * bottom[4] + top[2] * bottom[3] + top[3] * bottom[2] - top[4] * bottom[1] + top[5] * bottom[0];
}

// The 4 x 4 spatial determinant of rows r0, r1, r2, r3 of x.
Wide<4> spatial4(const std::int64_t (*x)[kMaxColumns], int r0, int r1, int r2, int r3) {
  Wide<2> top[6], bottom[6];
  pair_minors<4>(x, r0, r1, top);
  pair_minors<4>(x, r2, r3, bottom);
  return laplace4(top, bottom);
}

// The 3 x 3 minor of `row` above the two rows whose 2 x 2 minors on 5 columns are `m`, over
// the columns other than a < b, along `row`: below 3 2^187 < 2^189.
Wide<3> triple5(const std::int64_t* row, const Wide<2> (&m)[10], int a, int b) {
  int c[3], n = 0;
#pragma GCC unroll 10
  for (int k = 0; k < 5; ++k)
    if (k != a && k != b) c[n++] = k;
  return Wide<1>::from(row[c[0]]) * m[pair_index(c[1], c[2], 5)] - Wide<1>::from(row[c[1]]) * m[pair_index(c[0], c[2], 5)] +
         Wide<1>::from(row[c[2]]) * m[pair_index(c[0], c[1], 5)];
}

// A 5 x 5 determinant by Laplace along its first two rows: the sum over column pairs a < b of
// (-1)^(a + b + 1) top(a, b) bottom(the other three), from the first two rows' 2 x 2 minors
// (top) and the last three rows' 3 x 3 minors by the pair they leave out (bottom). Each
// product below 2^125 2^189, the ten below 2^318.
Wide<5> laplace5(const Wide<2> (&top)[10], const Wide<3> (&bottom)[10]) {
  Wide<5> det = Wide<5>::from(0);
#pragma GCC unroll 10
  for (int a = 0; a < 5; ++a)
#pragma GCC unroll 10
    for (int b = a + 1; b < 5; ++b) {
      const Wide<5> term = top[pair_index(a, b, 5)] * bottom[pair_index(a, b, 5)];
      det = ((a + b) & 1) ? det + term : det - term;
    }
  return det;
}

// The 3 x 3 minors of rows 2, 3, 4 of x over 5 columns, by the pair of columns they leave out.
void bottom_triples5(const std::int64_t (*x)[kMaxColumns], const Wide<2> (&rows34)[10], Wide<3> (&bottom)[10]) {
#pragma GCC unroll 10
  for (int a = 0; a < 5; ++a)
#pragma GCC unroll 10
    for (int b = a + 1; b < 5; ++b) bottom[pair_index(a, b, 5)] = triple5(x[2], rows34, a, b);
}

// The 5 x 5 spatial determinant of rows 0 .. 4 of x.
Wide<5> spatial5(const std::int64_t (*x)[kMaxColumns]) {
  Wide<2> top[10], rows34[10];
  Wide<3> bottom[10];
  pair_minors<5>(x, 0, 1, top);
  pair_minors<5>(x, 3, 4, rows34);
  bottom_triples5(x, rows34, bottom);
  return laplace5(top, bottom);
}

// The 6 x 6 spatial determinant of rows 0 .. 5 of x, by Laplace along rows (0, 1), and each
// 4 x 4 minor of rows 2 .. 5 along rows (2, 3) (as laplace4): 105 products, where a table as
// below takes 192 (and more instructions on a 6D grid). 2 x 2 minors below 2^125,
// 4 x 4 ones below 2^252.6, the sum below 2^381.5.
Wide<6> spatial6(const std::int64_t (*x)[kMaxColumns]) {
  Wide<2> top[15], middle[15], bottom[15];
  pair_minors<6>(x, 0, 1, top);
  pair_minors<6>(x, 2, 3, middle);
  pair_minors<6>(x, 4, 5, bottom);
  const auto at = [](const Wide<2>(&m)[15], int a, int b) -> const Wide<2>& { return m[pair_index(a, b, 6)]; };
  Wide<6> det = Wide<6>::from(0);
#pragma GCC unroll 6
  for (int p = 0; p < 6; ++p) {
#pragma GCC unroll 6
    for (int q = p + 1; q < 6; ++q) {
      int c[4], n = 0;
      for (int k = 0; k < 6; ++k)
        if (k != p && k != q) c[n++] = k;
      const Wide<4> minor = at(middle, c[0], c[1]) * at(bottom, c[2], c[3]) - at(middle, c[0], c[2]) * at(bottom, c[1], c[3]) +
                            at(middle, c[0], c[3]) * at(bottom, c[1], c[2]) + at(middle, c[1], c[2]) * at(bottom, c[0], c[3]) -
                            at(middle, c[1], c[3]) * at(bottom, c[0], c[2]) + at(middle, c[2], c[3]) * at(bottom, c[0], c[1]);
      const Wide<6> term = at(top, p, q) * minor;
      det = ((p + q) & 1) ? det + term : det - term;
    }
  }
  return det;
}

// Tables of minors over column sets, for the 6D and 7D lifted cofactors and the 7 x 7
// orientation: the m x m minors of the first m of the rows, for every set of m of the C columns
// (with kLift, the last column is the rows' lift), each along its last row from the
// (m - 1) x (m - 1) minors below it (Laplace), for m = 1 .. the row count. (First rows first: a
// facet's levels then serve each of its candidates, whose row comes last.) Products, levels 2
// and up: 6D lifted 434, 7D lifted 1 008, the 7 x 7 orientation 441. Written once for any size
// instead of expansions written out.
//
// The limbs of an m x m minor: m! terms of m entries, each below 2^62 but for one lift where
// the table has a lift column (below 2^126.9 up to 7D: 7 squares below 2^124), plus a sign bit.
constexpr int minor_limbs(int m, bool lift = true) {
  int factorial = 1, log = 0;
  for (int i = 2; i <= m; ++i) factorial *= i;
  while ((1 << log) < factorial) ++log;
  return (62 * m + (lift ? 65 : 0) + log + 1 + 63) / 64;
}

template <int C, int M, bool kLift>
using MinorLevel = Wide<minor_limbs(M, kLift)>[1 << C];

constexpr int binomial(int n, int k) { return k == 0 ? 1 : binomial(n - 1, k - 1) * n / k; }

// The sets of M of C columns, as bit masks, laid out at compile time (__builtin_popcount is a
// libgcc call on plain x86-64: counting at run time is a large share of a 6D grid's run).
template <int C, int M>
struct ColumnSets {
  unsigned mask[binomial(C, M)];
  constexpr ColumnSets() : mask() {
    int n = 0;
    for (unsigned m = 0; m < (1u << C); ++m)
      if (bit_count(m) == M) mask[n++] = m;
  }
};

// Level M (rows 0 .. M - 1) from level M - 1, along row M - 1, `row` (with kLift, `lift` is its
// entry in column C - 1): the sign of column j is (-1)^(M - 1 + its position in the set).
template <int C, int M, bool kLift>
void next_minors(const std::int64_t* row, Int128 lift, const MinorLevel<C, M - 1, kLift>& below, MinorLevel<C, M, kLift>& out) {
  constexpr int L = minor_limbs(M, kLift);
  static constexpr ColumnSets<C, M> kSets;
  for (const unsigned mask : kSets.mask) {
    Wide<L> sum = Wide<L>::from(0);
    int position = 0;
#pragma GCC unroll 8
    for (int j = 0; j < C; ++j) {
      if ((mask & (1u << j)) == 0) continue;
      const auto& minor = below[mask & ~(1u << j)];
      const Wide<L> term =
          kLift && j == C - 1 ? resize<L>(Wide<2>::from(lift) * minor) : resize<L>(Wide<1>::from(row[j]) * minor);
      sum = ((M - 1 + position) & 1) ? sum - term : sum + term;
      ++position;
    }
    out[mask] = sum;
  }
}

// Levels M .. R of the table of rows 0 .. R - 1 (level m over the first m rows), from level
// M - 1; level R into `out`.
template <int C, int R, int M, bool kLift>
void next_levels(const std::int64_t (*x)[kMaxColumns], const Int128* lift, const MinorLevel<C, M - 1, kLift>& below,
                 MinorLevel<C, R, kLift>& out) {
  const int row = M - 1;
  const Int128 entry = kLift ? lift[row] : 0;
  if constexpr (M == R) {
    next_minors<C, M, kLift>(x[row], entry, below, out);
  } else {
    MinorLevel<C, M, kLift> level;
    next_minors<C, M, kLift>(x[row], entry, below, level);
    next_levels<C, R, M + 1, kLift>(x, lift, level, out);
  }
}

// The R x R minors of rows 0 .. R - 1 of x (with kLift, of [x | lift]) over the sets of R of
// the C columns.
template <int C, int R, bool kLift>
void table_of_minors(const std::int64_t (*x)[kMaxColumns], const Int128* lift, MinorLevel<C, R, kLift>& out) {
  MinorLevel<C, 1, kLift> one;
  using Entry = Wide<minor_limbs(1, kLift)>;
  for (int j = 0; j < C; ++j)
    one[1u << j] = kLift && j == C - 1 ? Entry::from(lift[0]) : Entry::from(x[0][j]);
  next_levels<C, R, 2, kLift>(x, lift, one, out);
}

// The 7 x 7 spatial determinant of rows 0 .. 6 of x: 5 040 terms below 2^434, the sum below
// 2^446.3.
Wide<minor_limbs(7, false)> spatial7(const std::int64_t (*x)[kMaxColumns]) {
  MinorLevel<7, 7, false> minors;
  table_of_minors<7, 7, false>(x, nullptr, minors);
  return minors[0x7f];
}

// The cofactors of x's row, the last of D + 1, from the D x D minors of the rows above it (a
// table's level D over D + 1 columns, the lift last): the cofactor of column c has the sign
// (-1)^(D + c), + at the lift (column D), and is the minor without that column.
template <int D, int L>
void cofactors_from(const MinorLevel<D + 1, D, true>& minors, Wide<L> (&spatial)[D], Wide<L>& lift_cofactor) {
  static_assert(L == minor_limbs(D), "the table's top level");
  constexpr unsigned kAll = (1u << (D + 1)) - 1;
  for (int c = 0; c < D; ++c) spatial[c] = ((D + c) & 1) ? -minors[kAll & ~(1u << c)] : minors[kAll & ~(1u << c)];
  lift_cofactor = minors[kAll & ~(1u << D)];
}

}  // namespace

std::optional<int> wide_orientation(const Frame& f, const double* const* points) {
  const int k = f.k;
  if (k < 1 || k > kMaxColumns) return std::nullopt;
  CommonUnit unit;
  for (int c = 0; c < k; ++c) {
    unit.include(f.base[f.axis(c)]);
    for (int r = 0; r < k; ++r) unit.include(points[r][f.axis(c)]);
  }
  const double inverse = unit.inverse();
  if (inverse == 0.0) return std::nullopt;
  std::int64_t a[kMaxColumns][kMaxColumns];
  for (int c = 0; c < k; ++c)
    for (int r = 0; r < k; ++r)
      if (!difference(points[r][f.axis(c)], f.base[f.axis(c)], inverse, a[r][c])) return std::nullopt;
  if (k == 1) return (a[0][0] > 0) - (a[0][0] < 0);
  if (k == 2) {
    const Int128 det = minor2(a[0][0], a[0][1], a[1][0], a[1][1]);
    return (det > 0) - (det < 0);
  }
  if (k == 4) return spatial4(a, 0, 1, 2, 3).sign();
  if (k == 5) return spatial5(a).sign();
  if (k == 6) return spatial6(a).sign();
  if (k == 7) return spatial7(a).sign();
  // Along the last row: each term below 2^187, the sum below 2^189.
  const Wide<3> det = Wide<1>::from(a[2][0]) * Wide<2>::from(minor2(a[0][1], a[0][2], a[1][1], a[1][2])) -
                      Wide<1>::from(a[2][1]) * Wide<2>::from(minor2(a[0][0], a[0][2], a[1][0], a[1][2])) +
                      Wide<1>::from(a[2][2]) * Wide<2>::from(minor2(a[0][0], a[0][1], a[1][0], a[1][1]));
  return det.sign();
}

std::optional<int> wide_lifted_sign(const Frame& f, const double* const* points) {
  const int k = f.k, n = k + 1;
  if (k < 2 || k > kMaxColumns || f.dim > kMaxColumns) return std::nullopt;
  if (k >= 5) {
    // 5D to 7D: the cofactors along the last row, then its dot product with them.
    WideLiftedCofactors cofactors;
    if (!cofactors.prepare(f, points)) return std::nullopt;
    return cofactors.sign_with(points[k]);
  }
  CommonUnit unit;
  for (int c = 0; c < f.dim; ++c) {
    unit.include(f.base[c]);
    for (int r = 0; r < n; ++r) unit.include(points[r][c]);
  }
  // Rows [pi(p_r - base), |p_r - base|^2]: the lift below dim 2^124 <= 2^126.
  const double inverse = unit.inverse();
  if (inverse == 0.0) return std::nullopt;
  // Up to 4 x 4 spatial minors, the bounds below hold for lifts below 2^126 (6D).
  if (f.dim > 6) return std::nullopt;
  std::int64_t x[kMaxColumns + 1][kMaxColumns];
  Int128 lift[kMaxColumns + 1];
  if (!lifted_rows(f, inverse, points, n, x, lift)) return std::nullopt;
  if (k == 4) {
    // Along the lift column: det = sum_r (-1)^r L_r S_r, S_r the spatial 4 x 4 minor without
    // row r (below 2^253); each product below 2^379, the sum below 2^382.
    const Wide<6> det = Wide<2>::from(lift[0]) * spatial4(x, 1, 2, 3, 4) - Wide<2>::from(lift[1]) * spatial4(x, 0, 2, 3, 4) +
                        Wide<2>::from(lift[2]) * spatial4(x, 0, 1, 3, 4) - Wide<2>::from(lift[3]) * spatial4(x, 0, 1, 2, 4) +
                        Wide<2>::from(lift[4]) * spatial4(x, 0, 1, 2, 3);
    return det.sign();
  }
  if (k == 2) {
    // Along the lift column: minors below 2^125, lifts below 2^126, the sum below 2^253.
    const Wide<4> det = Wide<2>::from(lift[0]) * Wide<2>::from(minor2(x[1][0], x[1][1], x[2][0], x[2][1])) -
                        Wide<2>::from(lift[1]) * Wide<2>::from(minor2(x[0][0], x[0][1], x[2][0], x[2][1])) +
                        Wide<2>::from(lift[2]) * Wide<2>::from(minor2(x[0][0], x[0][1], x[1][0], x[1][1]));
    return det.sign();
  }
  // k = 3: along the lift column, det = sum_r (-1)^(r + 1) L_r S_r, S_r the spatial 3 x 3 minor
  // without row r, each along its last row from the 2 x 2 minors of rows (0, 1), (0, 2) and
  // (1, 2): 2 x 2 minors below 2^125, S_r below 2^189, each product below 2^315.
  Wide<2> m[3][3];
  pair_minors3(x, m);
  // The 3 x 3 minor of rows (pair, t) along row t.
  const auto spatial3 = [&](int p, int t) {
    return Wide<1>::from(x[t][0]) * m[p][0] - Wide<1>::from(x[t][1]) * m[p][1] + Wide<1>::from(x[t][2]) * m[p][2];
  };
  const Wide<5> det = Wide<2>::from(lift[3]) * spatial3(0, 2) - Wide<2>::from(lift[2]) * spatial3(0, 3) +
                      Wide<2>::from(lift[1]) * spatial3(1, 3) - Wide<2>::from(lift[0]) * spatial3(2, 3);
  return det.sign();
}

bool WideLiftedCofactors::prepare(const Frame& f, const double* const* points) {
  if (!(f.k == f.dim && f.axes == nullptr)) return false;
  dim_ = f.dim;
  if (f.dim == 3) return prepare_fixed<3>(f, points);
  if (f.dim == 4) return prepare_fixed<4>(f, points);
  if (f.dim == 5) return prepare_fixed<5>(f, points);
  if (f.dim == 6) return prepare_fixed<6>(f, points);
  if (f.dim == 7) return prepare_fixed<7>(f, points);
  return false;
}

template <int D>
bool WideLiftedCofactors::prepare_from_facet(const Frame& f, const double* const* points) {
  MinorLevel<D + 1, D - 1, true>& facet = [this]() -> MinorLevel<D + 1, D - 1, true>& {
    if constexpr (D == 7) return facet7_;
    else if constexpr (D == 6) return facet6_;
    else return facet5_;
  }();
  // The facet's base and rows by value (a caller may reuse a row's memory for other points).
  const auto row_of = [&](int r) { return r == 0 ? f.base : points[r - 1]; };
  bool same = facet_dim_ == D;
  for (int r = 0; same && r < D; ++r)
    for (int c = 0; c < D; ++c) same = same && facet_key_[r][c] == row_of(r)[c];
  if (!same) {
    facet_dim_ = D;
    for (int r = 0; r < D; ++r)
      for (int c = 0; c < D; ++c) facet_key_[r][c] = row_of(r)[c];
    CommonUnit unit;
    for (int c = 0; c < D; ++c) {
      unit.include(f.base[c]);
      for (int r = 0; r + 1 < D; ++r) unit.include(points[r][c]);
    }
    facet_unit_ = unit.unit();
    facet_inverse_ = unit.inverse();
    std::int64_t x[kMaxColumns][kMaxColumns];
    Int128 lift[kMaxColumns];
    facet_fits_ = facet_inverse_ != 0.0 && lifted_rows(f, facet_inverse_, points, D - 1, x, lift);
    if (facet_fits_) table_of_minors<D + 1, D - 1, true>(x, lift, facet);
  }
  if (!facet_fits_) return false;
  // The candidate, row D - 1, in the facet's unit: the table's top level along its row.
  const double* p = points[D - 1];
  CommonUnit unit;
  for (int c = 0; c < D; ++c) unit.include(p[c]);
  if (unit.unit() < facet_unit_) return false;
  std::int64_t row[kMaxColumns];
  Int128 lift = 0;
  for (int c = 0; c < D; ++c) {
    if (!difference(p[c], f.base[c], facet_inverse_, row[c])) return false;
    lift += product(row[c], row[c]);
  }
  unit_ = facet_unit_;
  inverse_ = facet_inverse_;
  for (int c = 0; c < D; ++c) base_[c] = f.base[c];
  MinorLevel<D + 1, D, true> minors;
  next_minors<D + 1, D, true>(row, lift, facet, minors);
  if constexpr (D == 7) cofactors_from<7>(minors, spatial7_, lift7_);
  else if constexpr (D == 6) cofactors_from<6>(minors, spatial6_, lift6_);
  else cofactors_from<5>(minors, spatial5_, lift5_);
  return true;
}

template <int D>
bool WideLiftedCofactors::prepare_fixed(const Frame& f, const double* const* points) {
  if constexpr (D >= 5)
    if (prepare_from_facet<D>(f, points)) return true;
  CommonUnit unit;
  for (int c = 0; c < D; ++c) {
    unit.include(f.base[c]);
    for (int r = 0; r < D; ++r) unit.include(points[r][c]);
  }
  unit_ = unit.unit();
  inverse_ = unit.inverse();
  if (inverse_ == 0.0) return false;
  for (int c = 0; c < D; ++c) base_[c] = f.base[c];
  std::int64_t x[kMaxColumns][kMaxColumns];
  Int128 lift[kMaxColumns];
  if (!lifted_rows(f, inverse_, points, D, x, lift)) return false;
  if constexpr (D == 7) {
    table_cofactors<7>(x, lift, spatial7_, lift7_);
  } else if constexpr (D == 6) {
    table_cofactors<6>(x, lift, spatial6_, lift6_);
  } else if constexpr (D == 5) {
    prepare5(x, lift);
  } else if constexpr (D == 4) {
    prepare4(x, lift);
  } else {
    // x's row is the fourth of four: cofactor signs -, +, -, + along it. The minor without
    // column c, along the lift column, from the 2 x 2 spatial minors of the row pairs.
    Wide<2> m[3][3];
    pair_minors3(x, m);
    for (int c = 0; c < 3; ++c) {
      // Rows 0, 1, 2 over the two spatial columns other than c and the lift: along the lift
      // column, L_0 m(rows 1, 2) - L_1 m(rows 0, 2) + L_2 m(rows 0, 1), the minors without c.
      const Wide<4> minor = Wide<2>::from(lift[0]) * m[2][c] - Wide<2>::from(lift[1]) * m[1][c] + Wide<2>::from(lift[2]) * m[0][c];
      spatial3_[c] = (c & 1) ? minor : -minor;
    }
    lift3_ = Wide<1>::from(x[2][0]) * m[0][0] - Wide<1>::from(x[2][1]) * m[0][1] + Wide<1>::from(x[2][2]) * m[0][2];
  }
  return true;
}

template <int D, int L>
void WideLiftedCofactors::table_cofactors(const std::int64_t (*x)[kMaxDim], const Int128* lift, Wide<L> (&spatial)[D],
                                          Wide<L>& lift_cofactor) {
  MinorLevel<D + 1, D, true> minors;
  table_of_minors<D + 1, D, true>(x, lift, minors);
  cofactors_from<D>(minors, spatial, lift_cofactor);
}

void WideLiftedCofactors::prepare4(const std::int64_t (*x)[kMaxDim], const Int128* lift) {
  // x's row is the fifth of five: cofactor signs +, -, +, -, + along it. The minor without
  // spatial column c is the 4 x 4 determinant of rows 0 .. 3 over the columns i < j < k other
  // than c and the lift L, by Laplace along rows (0, 1) against rows (2, 3) (as laplace4):
  //   + T(i,j) B(k,L) - T(i,k) B(j,L) + T(i,L) B(j,k) + T(j,k) B(i,L) - T(j,L) B(i,k) + T(k,L) B(i,j),
  // T and B the 2 x 2 minors of the top and bottom row pairs. Spatial ones below 2^125; those
  // with the lift, x_r L_s - L_r x_s, below 2^189; each product below 2^314, the sum below 2^317.
  // (Expanding along the lift column instead, as 3 x 3 minors times lifts, takes 16 products of
  // products where this takes 6 per column.)
  Wide<2> top[6], bottom[6];
  pair_minors<4>(x, 0, 1, top);
  pair_minors<4>(x, 2, 3, bottom);
  Wide<3> top_lift[4], bottom_lift[4];
  for (int a = 0; a < 4; ++a) {
    top_lift[a] = lift_minor(x, lift, 0, 1, a);
    bottom_lift[a] = lift_minor(x, lift, 2, 3, a);
  }
#pragma GCC unroll 4
  for (int c = 0; c < 4; ++c) {
    const int i = c == 0 ? 1 : 0, j = c <= 1 ? 2 : 1, k = c <= 2 ? 3 : 2;
    const Wide<5> minor = top[pair_index(i, j)] * bottom_lift[k] - top[pair_index(i, k)] * bottom_lift[j] +
                          bottom[pair_index(j, k)] * top_lift[i] + top[pair_index(j, k)] * bottom_lift[i] -
                          bottom[pair_index(i, k)] * top_lift[j] + bottom[pair_index(i, j)] * top_lift[k];
    spatial4_[c] = (c & 1) ? -minor : minor;
  }
  lift4_ = laplace4(top, bottom);  // the spatial determinant of rows 0 .. 3
}

void WideLiftedCofactors::prepare5(const std::int64_t (*x)[kMaxDim], const Int128* lift) {
  // x's row is the sixth of six: cofactor signs -, +, -, +, - along its spatial entries, + at
  // its lift. The minor without spatial column c is the 5 x 5 determinant of rows 0 .. 4 over
  // the spatial columns s_0 < .. < s_3 other than c and the lift L, by Laplace along rows
  // (0, 1) (as laplace5) over the position pairs p < q of (s_0, .., s_3, L):
  //   q < 4: top(s_p, s_q), a spatial 2 x 2 minor below 2^125, times the 3 x 3 minor of rows
  //          2, 3, 4 over the other two spatial columns and L, along L: sum of 3 lifts (below
  //          2^126.4, 5D) times spatial 2 x 2 minors, below 2^253;
  //   q = 4: top(s_p, L) = x_0 L_1 - L_0 x_1, below 2^189.4, times the spatial 3 x 3 minor of
  //          rows 2, 3, 4 over the other three, below 2^188.6.
  // Each product below 2^378, the ten below 2^381.4.
  Wide<2> top[10], rows34[10], rows24[10], rows23[10];
  pair_minors<5>(x, 0, 1, top);
  pair_minors<5>(x, 3, 4, rows34);
  pair_minors<5>(x, 2, 4, rows24);
  pair_minors<5>(x, 2, 3, rows23);
  Wide<3> bottom[10];  // spatial 3 x 3 minors of rows 2, 3, 4, by the column pair left out
  bottom_triples5(x, rows34, bottom);
  Wide<4> bottom_lift[10];  // rows 2, 3, 4 over columns u < v and L, by (u, v)
#pragma GCC unroll 10
  for (int i = 0; i < 10; ++i)
    bottom_lift[i] = Wide<2>::from(lift[2]) * rows34[i] - Wide<2>::from(lift[3]) * rows24[i] + Wide<2>::from(lift[4]) * rows23[i];
  Wide<3> top_lift[5];
#pragma GCC unroll 10
  for (int a = 0; a < 5; ++a)
    top_lift[a] = lift_minor(x, lift, 0, 1, a);
#pragma GCC unroll 10
  for (int c = 0; c < 5; ++c) {
    int col[4], n = 0;
#pragma GCC unroll 10
    for (int k = 0; k < 5; ++k)
      if (k != c) col[n++] = k;
    Wide<6> minor = Wide<6>::from(0);
#pragma GCC unroll 10
    for (int p = 0; p < 4; ++p) {
#pragma GCC unroll 10
      for (int q = p + 1; q < 4; ++q) {
        int other[2], m = 0;
#pragma GCC unroll 10
        for (int t = 0; t < 4; ++t)
          if (t != p && t != q) other[m++] = col[t];
        const Wide<6> term = top[pair_index(col[p], col[q], 5)] * bottom_lift[pair_index(other[0], other[1], 5)];
        minor = ((p + q) & 1) ? minor + term : minor - term;  // (-1)^(p + q + 1)
      }
      const int a = std::min(c, col[p]), b = std::max(c, col[p]);
      const Wide<6> term = top_lift[col[p]] * bottom[pair_index(a, b, 5)];
      minor = (p & 1) ? minor + term : minor - term;  // (-1)^(p + 4 + 1)
    }
    spatial5_[c] = (c & 1) ? minor : -minor;
  }
  lift5_ = resize<6>(laplace5(top, bottom));  // the spatial determinant of rows 0 .. 4
}

std::optional<int> WideLiftedCofactors::sign_with(const double* point) const {
  switch (dim_) {
    case 3: return sign_with_fixed<3>(point);
    case 4: return sign_with_fixed<4>(point);
    case 5: return sign_with_fixed<5>(point);
    case 6: return sign_with_fixed<6>(point);
    default: return sign_with_fixed<7>(point);
  }
}

template <int D>
std::optional<int> WideLiftedCofactors::sign_with_fixed(const double* point) const {
  CommonUnit unit;
  for (int c = 0; c < D; ++c) unit.include(point[c]);
  if (unit.unit() < unit_) return std::nullopt;  // a lower set bit than the rows' unit
  std::int64_t x[D];
  Int128 lift = 0;
  for (int c = 0; c < D; ++c) {
    if (!difference(point[c], base_[c], inverse_, x[c])) return std::nullopt;
    lift += product(x[c], x[c]);
  }
  if constexpr (D == 7) {
    // The 8 x 8 determinant: each product below 2^126.9 2^446.3 (the lift's) and 2^62 2^511.1
    // (the spatial ones'), the sum of eight below 2^576.2; held in 640 bits.
    Wide<10> det = resize<10>(Wide<2>::from(lift) * lift7_);
    for (int c = 0; c < 7; ++c) det = det + resize<10>(Wide<1>::from(x[c]) * spatial7_[c]);
    return det.sign();
  } else if constexpr (D == 6) {
    // The 7 x 7 determinant: 7! terms of six differences and a lift, below 2^510.9; held in
    // 576 bits, for a margin.
    Wide<9> det = resize<9>(Wide<2>::from(lift) * lift6_);
    for (int c = 0; c < 6; ++c) det = det + resize<9>(Wide<1>::from(x[c]) * spatial6_[c]);
    return det.sign();
  } else if constexpr (D == 5) {
    // Each product below 2^443.4 (the lift's) and 2^443.3 (the spatial ones'), the sum below
    // 2^446.1: held in 512 bits, for a margin.
    Wide<8> det = resize<8>(Wide<2>::from(lift) * lift5_);
    for (int c = 0; c < 5; ++c) det = det + resize<8>(Wide<1>::from(x[c]) * spatial5_[c]);
    return det.sign();
  } else if constexpr (D == 4) {
    // Each product below 2^379, the sum below 2^381.
    Wide<6> det = Wide<2>::from(lift) * lift4_;
    for (int c = 0; c < 4; ++c) det = det + Wide<1>::from(x[c]) * spatial4_[c];
    return det.sign();
  } else {
    // Each product below 2^315, the sum below 2^317.
    Wide<5> det = Wide<2>::from(lift) * lift3_;
    for (int c = 0; c < 3; ++c) det = det + Wide<1>::from(x[c]) * spatial3_[c];
    return det.sign();
  }
}

bool WideOrientationCofactors::prepare(const Frame& f, const double* const* points) {
  if (!(f.k == f.dim && f.axes == nullptr)) return false;
  dim_ = f.dim;
  if (f.dim == 6) return prepare_fixed<6>(f, points);
  if (f.dim == 7) return prepare_fixed<7>(f, points);
  return false;
}

template <int D>
bool WideOrientationCofactors::prepare_fixed(const Frame& f, const double* const* points) {
  CommonUnit unit;
  for (int c = 0; c < D; ++c) {
    unit.include(f.base[c]);
    for (int r = 0; r < D - 1; ++r) unit.include(points[r][c]);
  }
  unit_ = unit.unit();
  inverse_ = unit.inverse();
  if (inverse_ == 0.0) return false;
  std::int64_t x[kMaxColumns][kMaxColumns];
  for (int c = 0; c < D; ++c) {
    base_[c] = f.base[c];
    for (int r = 0; r < D - 1; ++r)
      if (!difference(points[r][c], f.base[c], inverse_, x[r][c])) return false;
  }
  // x's row is the last of D: the cofactor of column c has the sign (-1)^(D - 1 + c), and is
  // the minor of rows 0 .. D - 2 without column c.
  constexpr unsigned kAll = (1u << D) - 1;
  MinorLevel<D, D - 1, false> minors;
  table_of_minors<D, D - 1, false>(x, nullptr, minors);
  for (int c = 0; c < D; ++c) {
    const Wide<7> minor = resize<7>(minors[kAll & ~(1u << c)]);
    cofactors_[c] = ((D - 1 + c) & 1) ? -minor : minor;
  }
  return true;
}

std::optional<int> WideOrientationCofactors::sign_with(const double* point) const {
  CommonUnit unit;
  for (int c = 0; c < dim_; ++c) unit.include(point[c]);
  if (unit.unit() < unit_) return std::nullopt;  // a lower set bit than the rows' unit
  // Each product below 2^62 2^381.5, the sum of seven below 2^446.3: held in 512 bits.
  Wide<8> det = Wide<8>::from(0);
  for (int c = 0; c < dim_; ++c) {
    std::int64_t x = 0;
    if (!difference(point[c], base_[c], inverse_, x)) return std::nullopt;
    det = det + Wide<1>::from(x) * cofactors_[c];
  }
  return det.sign();
}

}  // namespace drange::geometry
