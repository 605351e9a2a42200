// geometry/predicates.cpp: orientation and lifted (in-sphere) determinants, filtered then
// exact, and the symbolic perturbation that breaks lifted ties.
#include "geometry/predicate_stages.hpp"
#include "geometry/predicates.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <vector>

#include "drange/errors.hpp"
#include "geometry/error_bound.hpp"
#include "geometry/exact.hpp"
#include "geometry/exact_matrix.hpp"
#include "geometry/wide_determinant.hpp"
#include "geometry/minors.hpp"
#include "geometry/refined_sign.hpp"

namespace drange::geometry {
namespace {

thread_local std::uint64_t exact_count = 0;

double squared_distance(int dim, const double* p, const double* q) {
  double s = 0.0;
  for (int c = 0; c < dim; ++c) s += (p[c] - q[c]) * (p[c] - q[c]);
  return s;
}

// The largest power of two dividing every coordinate of the points (as an exponent), or
// INT_MAX when all are zero.
int common_unit_exponent(int dim, const double* base, const double* const* points, int count) {
  int e = std::numeric_limits<int>::max();
  for (int c = 0; c < dim; ++c)
    if (base[c] != 0.0) e = std::min(e, lowest_bit_exponent(base[c]));
  for (int i = 0; i < count; ++i)
    for (int c = 0; c < dim; ++c)
      if (points[i][c] != 0.0) e = std::min(e, lowest_bit_exponent(points[i][c]));
  return e;
}

// A static proof that the floating-point evaluation was exact: every coordinate is a multiple
// of 2^unit, so every entry of a spatial column is a multiple of 2^unit, of the lift column a
// multiple of 2^(2 unit), and a minor over columns S a multiple of the product of its columns'
// units. An integer multiple of a power of two below 2^53 of them is a double, and every partial
// sum and product of the expansion is bounded by the absolute-value tree of its minor. So if
// every minor's absolute tree is below 2^53 of its unit, no operation rounded: the value is
// exact, zero included. This is what decides the ties of integer grids without GMP.
template <class UnitOf>
bool evaluation_is_exact(const MinorTable& minors, int n, int lift_column, UnitOf unit_of) {
  const int unit = unit_of();
  if (unit == std::numeric_limits<int>::max()) return true;  // all coordinates zero
  // The limit of a minor by its number of columns, the lift column counting twice. 2^52, not
  // 2^53: a computed bound just below the limit cannot hide a true value above it.
  std::array<double, SubsetTable::kMaxColumns + 2> limit;
  for (int columns = 0; columns <= n + 1; ++columns) limit[static_cast<std::size_t>(columns)] = power_of_two_limit(52 + unit * columns);
  for (std::uint32_t mask = 1; mask < (std::uint32_t{1} << n); ++mask) {
    const bool lift = lift_column >= 0 && (mask >> lift_column & 1u);
    const int columns = bit_count(mask) + (lift ? 1 : 0);
    if (!(minors.abs_minor(mask) < limit[static_cast<std::size_t>(columns)])) return false;
  }
  return true;
}

// The filter: the sign of the determinant of the rows built by `fill_row` when the error bound
// certifies it, or when the evaluation provably did not round; nullopt otherwise. `unit_of`
// gives the common unit exponent of the points (common_unit_exponent), needed only when the
// error bound does not decide.
template <class FillRow, class UnitOf>
std::optional<int> filtered_sign(int n, int entry_roundings, int lift_column, UnitOf unit_of, FillRow fill_row) {
  if (n > SubsetTable::kMaxColumns) return std::nullopt;
  MinorTable minors(n);
  std::array<double, SubsetTable::kMaxColumns> row;
  const FloatingPointWatch watch;
  for (int r = 0; r < n; ++r) {
    fill_row(r, row.data());
    minors.set_row(r, row.data());
  }
  // An underflow anywhere (entries, products, sums) voids both the error bound and the
  // exactness proof: only the integer stages may decide then.
  if (!watch.clean()) return std::nullopt;
  const std::uint32_t all = (std::uint32_t{1} << n) - 1;
  const double value = minors.minor(all);
  const int s = certified_sign(value, minors.abs_minor(all), laplace_roundings(n, entry_roundings));
  if (s != 0) return s;
  if (evaluation_is_exact(minors, n, lift_column, unit_of)) return (value > 0) - (value < 0);
  return std::nullopt;
}

IntegerScale scale_of(int dim, const double* base, const double* const* points, int count) {
  IntegerScale scale;
  for (int c = 0; c < dim; ++c) scale.include(base[c]);
  for (int i = 0; i < count; ++i)
    for (int c = 0; c < dim; ++c) scale.include(points[i][c]);
  return scale;
}

// The exact evaluations' integers, kept per thread: GMP integers keep their limbs from call to
// call, so inputs that need millions of exact tests (points within rounding of a sphere)
// allocate nothing after the first ones (on points on a sphere, malloc and free would
// otherwise take much of the time).
// Each integer starts with room for kReservedBits: Bareiss swaps its scratch integer with the
// matrix's entries, so a small one would travel from entry to entry and be enlarged again and
// again (on a cylindrical grid's ties, realloc and free would show in the profile).
constexpr mp_bitcnt_t kReservedBits = 2048;
struct ExactScratch {
  std::vector<mpz_class> matrix, base, delta;
  mpz_class lift, square, pivot;
  ExactScratch() {
    for (mpz_class* z : {&lift, &square, &pivot}) mpz_realloc2(z->get_mpz_t(), kReservedBits);
  }
  // v.resize(n), the new integers with their room.
  static void resize(std::vector<mpz_class>& v, std::size_t n) {
    const std::size_t old = v.size();
    v.resize(n);
    for (std::size_t i = old; i < n; ++i) mpz_realloc2(v[i].get_mpz_t(), kReservedBits);
  }
};
ExactScratch& exact_scratch() {
  thread_local ExactScratch scratch;
  return scratch;
}

}  // namespace

std::optional<int> small_integer_orientation(const Frame& f, const double* const* points) {
  const std::optional<int> s = wide_orientation(f, points);
  if (s) ++exact_count;
  return s;
}

int integer_orientation(const Frame& f, const double* const* points) {
  if (const std::optional<int> s = small_integer_orientation(f, points)) return *s;
  ++exact_count;
  const IntegerScale scale = scale_of(f.dim, f.base, points, f.k);
  ExactScratch& x = exact_scratch();
  ExactScratch::resize(x.matrix, static_cast<std::size_t>(f.k * f.k));
  ExactScratch::resize(x.base, static_cast<std::size_t>(f.k));
  for (int c = 0; c < f.k; ++c) scale.assign_integer(f.base[f.axis(c)], x.base[static_cast<std::size_t>(c)]);
  for (int r = 0; r < f.k; ++r)
    for (int c = 0; c < f.k; ++c) {
      mpz_class& entry = x.matrix[static_cast<std::size_t>(r * f.k + c)];
      scale.assign_integer(points[r][f.axis(c)], entry);
      entry -= x.base[static_cast<std::size_t>(c)];
    }
  return bareiss_in_place(x.matrix, f.k, x.pivot) * sgn(x.matrix[static_cast<std::size_t>(f.k * f.k - 1)]);
}

namespace {

// The integer lifted rows of `count` points in `scale`'s units (spatial entries in 2^shift,
// the lift in 2^(2 shift)): row r is [pi(p_r - base), |p_r - base|^2], f.k + 1 entries, into
// `rows` (x.base and x.delta are scratch). Leaves base's integers in x.base.
void integer_lifted_rows(const Frame& f, const IntegerScale& scale, const double* const* points, int count,
                         ExactScratch& x, std::vector<mpz_class>& rows) {
  const int width = f.k + 1;
  ExactScratch::resize(x.base, static_cast<std::size_t>(f.dim));
  ExactScratch::resize(x.delta, static_cast<std::size_t>(f.dim));
  ExactScratch::resize(rows, static_cast<std::size_t>(count * width));
  for (int c = 0; c < f.dim; ++c) scale.assign_integer(f.base[c], x.base[static_cast<std::size_t>(c)]);
  for (int r = 0; r < count; ++r) {
    x.lift = 0;
    for (int c = 0; c < f.dim; ++c) {
      mpz_class& delta = x.delta[static_cast<std::size_t>(c)];
      scale.assign_integer(points[r][c], delta);
      delta -= x.base[static_cast<std::size_t>(c)];
      mpz_mul(x.square.get_mpz_t(), delta.get_mpz_t(), delta.get_mpz_t());
      x.lift += x.square;
    }
    for (int c = 0; c < f.k; ++c) rows[static_cast<std::size_t>(r * width + c)] = x.delta[static_cast<std::size_t>(f.axis(c))];
    rows[static_cast<std::size_t>(r * width + f.k)] = x.lift;
  }
}

}  // namespace

std::optional<int> small_integer_lifted_sign(const Frame& f, const double* const* points) {
  const std::optional<int> s = wide_lifted_sign(f, points);
  if (s) ++exact_count;
  return s;
}

int integer_lifted_sign(const Frame& f, const double* const* points) {
  if (const std::optional<int> s = small_integer_lifted_sign(f, points)) return *s;
  ++exact_count;
  const int n = f.k + 1;
  const IntegerScale scale = scale_of(f.dim, f.base, points, n);
  ExactScratch& x = exact_scratch();
  integer_lifted_rows(f, scale, points, n, x, x.matrix);
  return bareiss_in_place(x.matrix, n, x.pivot) * sgn(x.matrix[static_cast<std::size_t>(n * n - 1)]);
}

// The exact signs: proved by the double-double evaluation when it can be (refined_sign.hpp),
// else computed in integers (fixed-width, else GMP), which alone count as exact evaluations.
int exact_orientation(const Frame& f, const double* const* points) {
  if (const std::optional<int> s = refined_orientation(f, points)) return *s;
  return integer_orientation(f, points);
}

namespace {

int exact_lifted_sign(const Frame& f, const double* const* points) {
  if (const std::optional<int> s = refined_lifted_sign(f, points)) return *s;
  return integer_lifted_sign(f, points);
}

// Orientation for k <= 3 written out: the sign when a filter certifies it or the evaluation
// provably did not round, else nullopt (the generic path decides). k = 1: the sign of a
// difference of doubles is exact in round to nearest. k = 2, 3: the Laplace expansion along
// the last row, with its absolute-value tree and the same error bound as the generic filter
// (laplace_roundings(k, 1) over-counts these short expressions), under a watch for underflow.
// When the bound does not decide, the static proof of evaluation_is_exact on the expansion's
// own terms: the 2x2 minors (k = 3) and the whole, each below 2^52 of its unit. The entries
// need no bound of their own: each is multiplied by a nonzero factor of at least one unit,
// whose product the bounds cover, or by an exact zero, which hides its rounding. That decides
// the exactly flat subsets of integer grids, which the symbolic perturbation meets at every
// tie, without a minor table.
std::optional<int> small_orientation(const Frame& f, const double* const* points) {
  const double* b = f.base;
  if (f.k == 1) {
    const double x = points[0][f.axis(0)], y = b[f.axis(0)];
    return (x > y) - (x < y);
  }
  const FloatingPointWatch watch;
  double value = 0.0, abs_tree = 0.0, largest_pair = 0.0;
  if (f.k == 2) {
    const int x = f.axis(0), y = f.axis(1);
    const double a00 = points[0][x] - b[x], a01 = points[0][y] - b[y];
    const double a10 = points[1][x] - b[x], a11 = points[1][y] - b[y];
    value = a00 * a11 - a01 * a10;
    abs_tree = std::fabs(a00) * std::fabs(a11) + std::fabs(a01) * std::fabs(a10);
  } else {
    const int x = f.axis(0), y = f.axis(1), z = f.axis(2);
    const double a00 = points[0][x] - b[x], a01 = points[0][y] - b[y], a02 = points[0][z] - b[z];
    const double a10 = points[1][x] - b[x], a11 = points[1][y] - b[y], a12 = points[1][z] - b[z];
    const double a20 = points[2][x] - b[x], a21 = points[2][y] - b[y], a22 = points[2][z] - b[z];
    const double m12 = a01 * a12 - a02 * a11, m02 = a00 * a12 - a02 * a10, m01 = a00 * a11 - a01 * a10;
    const double n12 = std::fabs(a01) * std::fabs(a12) + std::fabs(a02) * std::fabs(a11);
    const double n02 = std::fabs(a00) * std::fabs(a12) + std::fabs(a02) * std::fabs(a10);
    const double n01 = std::fabs(a00) * std::fabs(a11) + std::fabs(a01) * std::fabs(a10);
    value = a20 * m12 - a21 * m02 + a22 * m01;
    abs_tree = std::fabs(a20) * n12 + std::fabs(a21) * n02 + std::fabs(a22) * n01;
    largest_pair = std::max({n12, n02, n01});
  }
  if (!watch.clean()) return std::nullopt;
  const int s = certified_sign(value, abs_tree, laplace_roundings(f.k, 1));
  if (s != 0) return s;
  const int unit = common_unit_exponent(f.dim, f.base, points, f.k);
  if (unit == std::numeric_limits<int>::max()) return 0;  // all coordinates zero
  const bool exact = largest_pair < power_of_two_limit(52 + 2 * unit) &&
                     abs_tree < power_of_two_limit(52 + f.k * unit);
  if (exact) return (value > 0) - (value < 0);
  return std::nullopt;
}

// Orientation for k = 4 to 7, the Laplace expansion laid out at compile time (every minor
// of the last m rows by column set, each along its first row, as refined_sign.cpp's minors_of
// in double-double), with filtered_sign's bound and evaluation_is_exact's proof (every minor's
// absolute tree below 2^52 of its unit). The generic filter's table of minors, with its
// run-time loops, is a large share of an integer grid's triangulation from 4D on (the
// symbolic perturbation's orientations, several per tie); this form takes far fewer
// instructions there, for the same output, and is level on uniform points. The mask loop must
// unroll in full (127 masks for k = 7), so that each mask's size and columns are constants.
template <int K>
std::optional<int> fixed_orientation(const Frame& f, const double* const* points) {
  const FloatingPointWatch watch;
  double entry[K][K];
  for (int r = 0; r < K; ++r)
    for (int c = 0; c < K; ++c) entry[r][c] = points[r][f.axis(c)] - f.base[f.axis(c)];
  double minor[1 << K], tree[1 << K];
  double largest[K + 1] = {};  // the largest absolute tree by number of columns
#pragma GCC unroll 128
  for (int mask = 1; mask < (1 << K); ++mask) {
    const int m = bit_count(static_cast<std::uint32_t>(mask));
    const int r = K - m;
    double value = 0.0, t = 0.0;
    int position = 0;
#pragma GCC unroll 8
    for (int c = 0; c < K; ++c) {
      if (!(mask & (1 << c))) continue;
      const int rest = mask & ~(1 << c);
      if (rest == 0) {
        value = entry[r][c];
        t = std::fabs(value);
        break;
      }
      const double term = entry[r][c] * minor[rest];
      value += position % 2 ? -term : term;
      t += std::fabs(entry[r][c]) * tree[rest];
      ++position;
    }
    minor[mask] = value;
    tree[mask] = t;
    largest[m] = std::max(largest[m], t);
  }
  if (!watch.clean()) return std::nullopt;
  constexpr int kAll = (1 << K) - 1;
  const int s = certified_sign(minor[kAll], tree[kAll], laplace_roundings(K, 1));
  if (s != 0) return s;
  const int unit = common_unit_exponent(f.dim, f.base, points, K);
  if (unit == std::numeric_limits<int>::max()) return 0;  // all coordinates zero
  for (int m = 1; m <= K; ++m)
    if (!(largest[m] < power_of_two_limit(52 + m * unit))) return std::nullopt;
  return (minor[kAll] > 0) - (minor[kAll] < 0);
}

}  // namespace

namespace {
// lifted_tie_sign's orientations in 6D and 7D, each with the k - 1 rows and base it shares with
// many others (a tie's facet and candidate, all but the point left out and the tested point):
// each such set's orientation cofactors (WideOrientationCofactors) kept in a small direct-mapped
// cache, indexed by the rows' addresses and checked by their coordinates, so that a repeated set
// costs a dot product where the whole 7 x 7 determinant takes 441 products. On grids, most of
// these orientations repeat one of the last few sets.
class OrientationCache {
 public:
  // The sign of the orientation of `points` in `f`, from the cached cofactors of all but the
  // last row; nullopt where the frame is not 6D or 7D with all axes, or the values do not fit.
  std::optional<int> sign(const Frame& f, const double* const* points) {
    const int k = f.k;
    if (k != f.dim || f.axes != nullptr || k < WideOrientationCofactors::kMinDim || k > WideOrientationCofactors::kMaxDim)
      return std::nullopt;
    const auto row = [&](int r) { return r == 0 ? f.base : points[r - 1]; };  // base, then rows
    std::uint64_t hash = 0;
    for (int r = 0; r < k; ++r) hash = (hash + reinterpret_cast<std::uintptr_t>(row(r))) * 0x9E3779B97F4A7C15ull;
    Entry& e = entries_[hash >> (64 - kBits)];
    bool same = e.dim == k;
    for (int r = 0; same && r < k; ++r)
      for (int c = 0; same && c < k; ++c) same = e.key[r][c] == row(r)[c];
    if (!same) {
      e.dim = k;
      for (int r = 0; r < k; ++r)
        for (int c = 0; c < k; ++c) e.key[r][c] = row(r)[c];
      e.usable = e.cofactors.prepare(f, points);
    }
    return e.usable ? e.cofactors.sign_with(points[k - 1]) : std::nullopt;
  }

 private:
  static constexpr int kBits = 6;
  struct Entry {
    int dim = 0;  // 0: empty
    bool usable = false;
    double key[WideOrientationCofactors::kMaxDim][WideOrientationCofactors::kMaxDim];
    WideOrientationCofactors cofactors;
  };
  Entry entries_[1 << kBits];
};
thread_local OrientationCache orientation_cache;

// The fixed-width stage of lifted_tie_sign's orientations: the cache, else the whole determinant.
std::optional<int> tie_orientation(const Frame& g, const double* const* points) {
  if (const std::optional<int> s = orientation_cache.sign(g, points)) {
    ++exact_count;
    return s;
  }
  return small_integer_orientation(g, points);
}
}  // namespace

// The sign that the symbolic perturbation gives a lifted determinant that is exactly zero.
// The relative determinant I equals (-1)^(k+1) det M, where M has the homogeneous rows
// [x_i, |x_i|^2, 1] of (base, p_1, ..., p_{k+1}). Perturbing the lifts by eps_i makes
// det M(eps) = det M + sum_i eps_i (-1)^(i+k) H_i, with H_i the homogeneous orientation of the
// other k+1 points. det M = 0 here, so the most perturbed point whose H_i is nonzero decides:
// sign I(eps) = -(-1)^i (-1)^k sign(orientation of the others, based at the first of them).
// The points are taken by decreasing rank without sorting, and the others live on the stack
// up to kInlinePoints: grids reach this once per tie.
int lifted_tie_sign(const Frame& f, const double* const* points, const std::int64_t* ranks, int known) {
  constexpr int kInlinePoints = 16;
  const int count = f.k + 2;
  std::array<const double*, kInlinePoints> inline_others;
  std::vector<const double*> heap_others;
  const double** others = inline_others.data();
  if (count - 1 > kInlinePoints) {
    heap_others.resize(static_cast<std::size_t>(count - 1));
    others = heap_others.data();
  }
  const auto point = [&](int j) { return j == 0 ? f.base : points[j - 1]; };
  std::int64_t below = std::numeric_limits<std::int64_t>::max();  // ranks already tried are >= below
  for (int tried = 0; tried < count; ++tried) {
    int i = -1;
    for (int j = 0; j < count; ++j)
      if (ranks[j] < below && (i < 0 || ranks[j] > ranks[i])) i = j;
    below = ranks[i];
    const int parity = ((i + f.k) & 1) ? -1 : 1;
    // Points k and k + 1 (the last two) left out: the others' orientation is the caller's.
    if (known != 0 && i >= f.k) return -parity * known;
    for (int j = 0, o = 0; j < count; ++j)
      if (j != i) others[o++] = point(j);
    Frame g = f;
    g.base = others[0];
    // A tie's points are often coplanar by fours (the grids whose ties these are): a zero,
    // which the double-double stage never decides, so the fixed-width stage goes first.
    std::optional<int> h = filtered_orientation(g, others + 1);
    if (!h) h = tie_orientation(g, others + 1);
    if (!h) h = exact_orientation(g, others + 1);
    if (*h != 0) return -parity * *h;
  }
  // Only reachable when the k+2 points do not span the k-flat: a caller's bug.
  throw InternalError("lifted_sign_perturbed: the points do not span their flat");
}

// Whether a spatial column of the matrix of the `count` points is zero: every point has the
// base's coordinate on that axis, exactly (points in an axis-parallel hyperplane: a planar set
// embedded in 3D, the faces of a grid). The orientation and lifted determinants are then
// exactly zero, which no filter certifies: without this, each such test went to GMP (20 000
// points on a circle in the plane z = 0 with the two poles of its sphere: 3.6 M exact
// evaluations).
bool has_zero_column(const Frame& f, const double* const* points, int count) {
  for (int c = 0; c < f.k; ++c) {
    const int axis = f.axis(c);
    bool zero = true;
    for (int r = 0; r < count && zero; ++r) zero = points[r][axis] == f.base[axis];
    if (zero) return true;
  }
  return false;
}

std::optional<int> filtered_orientation(const Frame& f, const double* const* points) {
  // First: k^2 comparisons, where the filters below certify nothing on such points (and would
  // cost much of the time on inputs full of them).
  if (has_zero_column(f, points, f.k)) return 0;
  // For k <= 3, where small_orientation declines, the generic filter below, with the same
  // error bound and exactness proof, would decline too: only the exact stages decide, and
  // skipping that filter spares its work on coplanar points (a cylindrical grid's).
  if (f.k <= 3 && f.k >= 1) return small_orientation(f, points);
  switch (f.k) {
    case 4: return fixed_orientation<4>(f, points);
    case 5: return fixed_orientation<5>(f, points);
    case 6: return fixed_orientation<6>(f, points);
    case 7: return fixed_orientation<7>(f, points);
    default: break;
  }
  const auto unit = [&] { return common_unit_exponent(f.dim, f.base, points, f.k); };
  return filtered_sign(f.k, 1, -1, unit, [&](int r, double* row) {
    for (int c = 0; c < f.k; ++c) row[c] = points[r][f.axis(c)] - f.base[f.axis(c)];
  });
}

int orientation(const Frame& f, const double* const* points) {
  const std::optional<int> s = filtered_orientation(f, points);
  return s ? *s : exact_orientation(f, points);
}

int lifted_sign(const Frame& f, const double* const* points) {
  const auto unit = [&] { return common_unit_exponent(f.dim, f.base, points, f.k + 1); };
  const std::optional<int> s = filtered_sign(f.k + 1, lifted_entry_roundings(f.dim), f.k, unit, [&](int r, double* row) {
    for (int c = 0; c < f.k; ++c) row[c] = points[r][f.axis(c)] - f.base[f.axis(c)];
    row[f.k] = squared_distance(f.dim, points[r], f.base);
  });
  if (s) return *s;
  return has_zero_column(f, points, f.k + 1) ? 0 : exact_lifted_sign(f, points);
}

namespace {
// z 2^unit_exponent truncated to a double; false when not zero and outside the normal range.
bool truncated_double(const mpz_class& z, long unit_exponent, double& out) {
  if (sgn(z) == 0) {
    out = 0.0;
    return true;
  }
  long exponent = 0;
  const double mantissa = mpz_get_d_2exp(&exponent, z.get_mpz_t());  // |mantissa| in [0.5, 1), truncated
  const long e = exponent + unit_exponent;
  if (e > 1023 || e < -1021) return false;
  out = std::ldexp(mantissa, static_cast<int>(e));
  return true;
}
}  // namespace

bool exact_lifted_form(const Frame& f, const double* const* points, const double* g, double rho, double* b,
                       double* lift, double* constant) {
  const int k = f.k;
  if (k != f.dim || f.axes != nullptr) return false;
  // One scale for everything: every coordinate, g and rho are integer multiples of 2^shift.
  IntegerScale scale = scale_of(f.dim, f.base, points, k);
  for (int c = 0; c < k; ++c) scale.include(g[c]);
  scale.include(rho);
  const long unit = scale.shift();
  ExactScratch& x = exact_scratch();
  // The integer lifted rows (spatial entries in units of 2^unit, the lift in 2^(2 unit)), and
  // the cofactors of the last row: C_j = (-1)^(k + j) times the minor without column j, in
  // units of 2^(unit (k + 1)) for j < k and 2^(unit k) for the lift column.
  thread_local std::vector<mpz_class> rows, cofactor, e;
  thread_local mpz_class term, sum, rho_lift;
  integer_lifted_rows(f, scale, points, k, x, rows);
  cofactor.resize(static_cast<std::size_t>(k + 1));
  e.resize(static_cast<std::size_t>(k));
  ExactScratch::resize(x.matrix, static_cast<std::size_t>(k * k));
  for (int j = 0; j <= k; ++j) {
    for (int r = 0; r < k; ++r)
      for (int c = 0, out = 0; c <= k; ++c)
        if (c != j) x.matrix[static_cast<std::size_t>(r * k + out++)] = rows[static_cast<std::size_t>(r * (k + 1) + c)];
    const int parity = bareiss_in_place(x.matrix, k, x.pivot);
    mpz_class& cj = cofactor[static_cast<std::size_t>(j)];
    if (parity == 0) {
      cj = 0;
    } else {
      cj = x.matrix[static_cast<std::size_t>(k * k - 1)];
      if ((parity < 0) != (((k + j) & 1) != 0)) cj = -cj;
    }
  }
  // e = base - g (units 2^unit); rho in lift units 2^(2 unit): rho = m 2^p with p >= unit.
  for (int c = 0; c < k; ++c) {
    scale.assign_integer(g[c], term);
    e[static_cast<std::size_t>(c)] = x.base[static_cast<std::size_t>(c)] - term;
  }
  scale.assign_integer(rho, rho_lift);  // rho / 2^unit
  if (unit > 0) return false;           // not an integer in lift units (never for scaled points)
  mpz_mul_2exp(rho_lift.get_mpz_t(), rho_lift.get_mpz_t(), static_cast<mp_bitcnt_t>(-unit));
  // With y = x - g: |x - base|^2 = |y|^2 - 2 e . y + |e|^2, so
  //   det = sum_c (C_c - 2 C_k e_c) y_c + C_k (|y|^2 - rho) + C_k (rho + |e|^2) - sum_c C_c e_c.
  const mpz_class& ck = cofactor[static_cast<std::size_t>(k)];
  sum = rho_lift;
  for (int c = 0; c < k; ++c) {
    const mpz_class& ec = e[static_cast<std::size_t>(c)];
    term = ck * ec;
    term *= 2;
    term = cofactor[static_cast<std::size_t>(c)] - term;  // units 2^(unit (k + 1))
    if (!truncated_double(term, unit * (k + 1), b[c])) return false;
    term = ec * ec;
    sum += term;
  }
  term = ck * sum;  // units 2^(unit (k + 2))
  for (int c = 0; c < k; ++c) {
    sum = cofactor[static_cast<std::size_t>(c)] * e[static_cast<std::size_t>(c)];
    term -= sum;
  }
  return truncated_double(term, unit * (k + 2), *constant) && truncated_double(ck, unit * k, *lift);
}

int exact_lifted_sign_perturbed(const Frame& f, const double* const* points, const std::int64_t* ranks) {
  const int unperturbed = exact_lifted_sign(f, points);
  return unperturbed != 0 ? unperturbed : lifted_tie_sign(f, points, ranks);
}

int lifted_sign_perturbed(const Frame& f, const double* const* points, const std::int64_t* ranks) {
  const int unperturbed = lifted_sign(f, points);
  return unperturbed != 0 ? unperturbed : lifted_tie_sign(f, points, ranks);
}

int simplex_orientation(int dim, const double* const* simplex) {
  const Frame f{dim, dim, nullptr, simplex[0]};
  return orientation(f, simplex + 1);
}

int in_sphere(int dim, const double* const* simplex, const double* q) {
  const int o = simplex_orientation(dim, simplex);
  if (o == 0) throw std::invalid_argument("in_sphere: the simplex is flat");
  std::vector<const double*> rows(simplex + 1, simplex + 1 + dim);
  rows.push_back(q);
  const Frame f{dim, dim, nullptr, simplex[0]};
  // With O(simplex) > 0, q is strictly inside exactly when the lifted determinant is negative.
  return -lifted_sign(f, rows.data()) * o;
}

std::uint64_t exact_evaluations() { return exact_count; }

void count_exact_evaluation() { ++exact_count; }

mpq_class exact_rational(double x) { return mpq_class(x); }

mpq_class simplex_volume_times_factorial(int dim, const double* const* simplex) {
  const IntegerScale scale = scale_of(dim, simplex[0], simplex + 1, dim);
  std::vector<mpz_class> a(static_cast<std::size_t>(dim * dim));
  for (int r = 0; r < dim; ++r)
    for (int c = 0; c < dim; ++c)
      a[static_cast<std::size_t>(r * dim + c)] = scale.integer(simplex[r + 1][c]) - scale.integer(simplex[0][c]);
  mpq_class det(bareiss_determinant(a, dim));
  // Every entry was scaled by 2^-shift, the determinant by 2^(-shift * dim).
  const long exponent = scale.shift() * dim;
  if (exponent >= 0) mpq_mul_2exp(det.get_mpq_t(), det.get_mpq_t(), static_cast<mp_bitcnt_t>(exponent));
  else mpq_div_2exp(det.get_mpq_t(), det.get_mpq_t(), static_cast<mp_bitcnt_t>(-exponent));
  return det;
}

}  // namespace drange::geometry
