// delaunay/shell/shell_arithmetic.cpp: float_form (shell_arithmetic.hpp), the lifted form about
// a sphere's centre in floating point with its error bounds, for d = 2 to 8; each d compiled
// with loops of fixed length, and from 4D the facet's minors computed once per facet.
#include "delaunay/shell/shell_arithmetic.hpp"

#include <cmath>

#include "geometry/error_bound.hpp"

namespace drange::engine {

namespace {

// The determinant of the K x K submatrix of `a` on `rows` and `columns` by Laplace expansion
// along its first row, and the same expansion on absolute values (its error bound's tree:
// within gamma(laplace_roundings(K, 1)) of it when each entry carries one rounding).
template <int N, int K>
void minor_of(const double (&a)[N][N], const int* rows, const int* columns, double& value, double& tree) {
  if constexpr (K == 1) {
    value = a[rows[0]][columns[0]];
    tree = std::fabs(value);
  } else {
    value = tree = 0.0;
    for (int j = 0; j < K; ++j) {
      int rest[K - 1];
      for (int t = 0, o = 0; t < K; ++t)
        if (t != j) rest[o++] = columns[t];
      double v = 0.0, t = 0.0;
      minor_of<N, K - 1>(a, rows + 1, rest, v, t);
      const double entry = a[rows[0]][columns[j]];
      value += (j % 2 ? -entry : entry) * v;
      tree += std::fabs(entry) * t;
    }
  }
}

// The index of the column pair {c, j}, c < j, among the d (d - 1) / 2 pairs.
constexpr int pair_index(int d, int c, int j) { return c * (2 * d - c - 1) / 2 + (j - c - 1); }

// The Laplace expansion along `row` (d entries) of a minor without column c, over `sub`, its
// minors without columns c and t (by pair_index): minor_of's value and tree for the minor's
// rows taken `row` first. Inlined, for d = N: out of line, with d at run time, it costs
// measurably over a whole run.
template <int N>
[[gnu::always_inline]] inline void expand_along(const double* row, const double (*sub)[2], int c, double& value, double& tree) {
  constexpr int d = N;
  value = tree = 0.0;
  for (int t = 0, position = 0; t < d; ++t) {
    if (t == c) continue;
    const double* m = sub[c < t ? pair_index(d, c, t) : pair_index(d, t, c)];
    value += (position % 2 ? -row[t] : row[t]) * m[0];
    tree += std::fabs(row[t]) * m[1];
    ++position;
  }
}

// FacetMinors for the facet rows a[0..d-2]: the (d - 2)-minors without row i and columns c < j,
// then the (d - 1)-minors without column c, expanded along row 0 over the former (so each is
// minor_of's value for rows 0..d-2, bit for bit).
template <int N>
void fill_facet_minors(const double (&a)[N][N], FacetMinors& minors) {
  constexpr int d = N;
  for (int i = 0; i < d - 1; ++i) {
    int rows_left[N - 2];
    for (int t = 0, r = 0; t < d - 1; ++t)
      if (t != i) rows_left[r++] = t;
    for (int c = 0; c < d; ++c)
      for (int j = c + 1; j < d; ++j) {
        int columns_left[N - 2];
        for (int t = 0, k = 0; t < d; ++t)
          if (t != c && t != j) columns_left[k++] = t;
        double* m = minors.sub[i][pair_index(d, c, j)];
        minor_of<N, N - 2>(a, rows_left, columns_left, m[0], m[1]);
      }
  }
  for (int c = 0; c < d; ++c) expand_along<N>(a[0], minors.sub[0], c, minors.top[c][0], minors.top[c][1]);
  minors.ready = true;
}

// float_form for d = N: loops of fixed length (with d at run time the form is markedly
// slower). Up to 8D: the Laplace expansions grow as (d - 1)!, but with the facet's minors made
// once per facet (FacetMinors), the floating form still beats GMP's Bareiss there.
template <int N>
bool float_form_fixed(const ShellSphere& sphere, const double* f0, double s0, const double* const* rows, const double* row_offsets,
                      FloatForm& form, FacetMinors* minors) {
  constexpr int d = N;
  // With S_x = |x - g|^2 - rho, |x - f0|^2 = (S_x - S_0) - 2 (f0 - g) . (x - f0): the lift
  // column less a combination of the spatial ones, so the lifted determinant is
  //   det[p_i - f0, S_i - S_0 (i = 1..d); x - f0, S_x - S_0].
  // Along its last row, with A the d x d matrix of the p_i - f0 and s_i = S_i - S_0:
  //   b = -adj(A) s,  lift = det A,  constant = -b . (f0 - g) - lift S_0.
  // On points near the sphere the s_i are tiny and b is computed to a few units of its own
  // terms, where the exact form's cofactors cancel. (The stored offsets' errors, u |s| + eta,
  // are a few hundred units of an offset: far below what the shell's tests resolve.)
  // Error bounds, each against the exact coefficients (exact points and offsets):
  //   the entries a = fl(p - f0) are within u |a| (1 + u); an adjugate entry alpha (a
  //   (d - 1)-minor by Laplace expansion) within gamma(m) of its absolute tree tau, m =
  //   laplace_roundings(d - 1, 1);
  //   e_i >= |fl(s_i - s_0) - (S_i - S_0)| = 1.01 u |s^_i| + u (|s_i| + |s_0|) + 2 eta;
  //   |B_c - b_c| <= gamma(d + m + 2) sum tau |s^| + (1 + gamma(m + 2)) sum tau e;
  //   |W - lift| <= gamma(laplace_roundings(d, 1)) sum |a| tau over the candidate's row (W is
  //   A's Laplace expansion along that row);
  //   K: the sum's roundings, the b and y0 errors, W's error and the offset S_0's error.
  // Each bound is evaluated with a margin for its own roundings.
  constexpr double u = geometry::kUnitRoundoff;
  const double eta = sphere.eta;
  double a[N][N], sh[N], e[N];
  for (int i = 0; i < d; ++i) {
    const double* p = rows[i];
    for (int c = 0; c < d; ++c) a[i][c] = p[c] - f0[c];
    const double si = row_offsets[i];
    sh[i] = si - s0;
    e[i] = (1.01 * u * std::fabs(sh[i]) + u * (std::fabs(si) + std::fabs(s0)) + 2 * eta) * (1 + 8 * u);
  }
  double alpha[N][N], tau[N][N];  // adj(A)[c][i] = cofactor (i, c)
  if constexpr (N == 2) {
    alpha[0][0] = a[1][1], alpha[0][1] = -a[0][1], alpha[1][0] = -a[1][0], alpha[1][1] = a[0][0];
    for (int c = 0; c < 2; ++c)
      for (int i = 0; i < 2; ++i) tau[c][i] = std::fabs(alpha[c][i]);
  } else if constexpr (N == 3) {  // the cofactors by cyclic indices (the sign comes with them)
    for (int c = 0; c < 3; ++c)
      for (int i = 0; i < 3; ++i) {
        const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, c1 = (c + 1) % 3, c2 = (c + 2) % 3;
        alpha[c][i] = a[i1][c1] * a[i2][c2] - a[i1][c2] * a[i2][c1];
        tau[c][i] = std::fabs(a[i1][c1]) * std::fabs(a[i2][c2]) + std::fabs(a[i1][c2]) * std::fabs(a[i2][c1]);
      }
  } else {  // d = 4 to 8: the cofactors as (d - 1) x (d - 1) minors
    // Without the candidate's row (i = d - 1): a minor of the facet's rows. With it, the
    // minor's rows are taken candidate first (d - 2 swaps: the sign (-1)^d), and its Laplace
    // expansion along that row runs over (d - 2)-minors of the facet's rows. Either way the
    // value is minor_of's for those rows (the bound below holds for any row order: the tree
    // is the same), and the facet's minors are computed once per facet (FacetMinors).
    FacetMinors local;
    if (minors == nullptr) minors = &local;
    if (!minors->ready) fill_facet_minors<N>(a, *minors);
    for (int c = 0; c < d; ++c) {
      for (int i = 0; i < d - 1; ++i) {
        double value = 0.0, tree = 0.0;
        expand_along<N>(a[d - 1], minors->sub[i], c, value, tree);
        if (d % 2) value = -value;
        alpha[c][i] = (i + c) % 2 ? -value : value;
        tau[c][i] = tree;
      }
      const double value = minors->top[c][0];
      alpha[c][d - 1] = (d - 1 + c) % 2 ? -value : value;
      tau[c][d - 1] = minors->top[c][1];
    }
  }
  const int m = geometry::laplace_roundings(d - 1, 1);
  const double margin = 1 + geometry::gamma_bound(4 * d + 4);
  double b_sum = 0.0, b_err_sum = 0.0;
  for (int c = 0; c < d; ++c) {
    double v = 0.0, t = 0.0, r = 0.0;
    for (int i = 0; i < d; ++i) {
      v += alpha[c][i] * sh[i];
      t += tau[c][i] * std::fabs(sh[i]);
      r += tau[c][i] * e[i];
    }
    form.b[c] = -v;
    const double err = (geometry::gamma_bound(d + m + 2) * t + (1 + geometry::gamma_bound(m + 2)) * r) * margin;
    form.b_err[c] = err;
    b_sum += std::fabs(v);
    b_err_sum += err;
  }
  double w = 0.0, w_tree = 0.0;
  for (int c = 0; c < d; ++c) {
    w += a[d - 1][c] * alpha[c][d - 1];
    w_tree += std::fabs(a[d - 1][c]) * tau[c][d - 1];
  }
  const double w_err = geometry::gamma_bound(geometry::laplace_roundings(d, 1)) * w_tree * margin;
  const double* g = sphere.centre;
  double k = -w * s0, k_tree = std::fabs(w) * std::fabs(s0), k_err = 0.0;
  for (int c = 0; c < d; ++c) {
    const double y0 = f0[c] - g[c];
    const double b = form.b[c];
    k -= b * y0;
    k_tree += std::fabs(b) * std::fabs(y0);
    k_err += (form.b_err[c] + 1.01 * u * (std::fabs(b) + form.b_err[c])) *
             std::fabs(y0) * (1 + 2 * u);
  }
  k_err = (k_err + geometry::gamma_bound(d + 3) * k_tree + w_err * std::fabs(s0) + (std::fabs(w) + w_err) * (u * std::fabs(s0) + eta)) * margin;
  if (!(k_tree + k_err < geometry::kFilterOverflow && std::fabs(w) + b_sum < geometry::kFilterOverflow)) return false;
  constexpr double kSmall = 0x1p-30;  // the bounds' share of their terms that keeps the shell's tests sharp
  if (!(w_err <= kSmall * std::fabs(w) && b_err_sum <= kSmall * b_sum && k_err <= kSmall * (k_tree + std::fabs(k)))) return false;
  form.lift = w;
  form.constant = k;
  form.lift_err = w_err;
  form.constant_err = k_err;
  form.b_err_sum = b_err_sum;
  return true;
}
}  // namespace

bool float_form(const ShellSphere& sphere, int d, const double* f0, double s0, const double* const* rows, const double* row_offsets,
                FloatForm& form, FacetMinors* minors) {
  switch (d) {
    case 2: return float_form_fixed<2>(sphere, f0, s0, rows, row_offsets, form, minors);
    case 3: return float_form_fixed<3>(sphere, f0, s0, rows, row_offsets, form, minors);
    case 4: return float_form_fixed<4>(sphere, f0, s0, rows, row_offsets, form, minors);
    case 5: return float_form_fixed<5>(sphere, f0, s0, rows, row_offsets, form, minors);
    case 6: return float_form_fixed<6>(sphere, f0, s0, rows, row_offsets, form, minors);
    case 7: return float_form_fixed<7>(sphere, f0, s0, rows, row_offsets, form, minors);
    case 8: return float_form_fixed<8>(sphere, f0, s0, rows, row_offsets, form, minors);
    default: return false;
  }
}

}  // namespace drange::engine
