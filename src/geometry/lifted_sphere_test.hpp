// geometry/lifted_sphere_test.hpp: the in-sphere predicate of the search, "does x beat the
// candidate p of facet F": is x strictly inside the sphere through F and p.
//
// With r_x = (x - f_0, |x - f_0|^2) the lifted row of x relative to f_0,
// I(p, x) = det[r_f1; ...; r_f{d-1}; r_p; r_x], and sigma the facet's orientation sign (its
// open side is sigma O > 0), x beats p exactly when sigma I(p, x) < 0.
//
// Contract: set_facet() with the facet's d affinely independent vertices; set_candidate() with
// a point strictly on its open side; then beats(x) is exact, with ties (x on the sphere) broken
// by the symbolic perturbation of the lifted coordinates in the points' lexicographic ranks, so
// that the result does not depend on the input order. The facet's vertices and the candidate
// lie on every candidate's sphere: the caller does not ask about them.
//
// I(p, x) is bilinear in r_p and r_x: set_facet computes the (d-1)-minors of the facet's lifted
// rows once (owned here, and read by FacetPlaneTest for their spatial part); set_candidate turns
// them into w with sigma I(p, x) = w . r_x, so each test costs a dot product.
// The stages, each certain of the sign it returns:
//   1. the floating-point filter on w . r_x with its error bound;
//   2. `hint`, the caller's own certified sign (an accelerator's form, e.g. the sphere shell's);
//   3. static exactness (dyadic points): an exact value, and a tie broken by the perturbation;
//   4. fixed-width integers first where the recent outcomes were mostly ties (they decide ties,
//      double-double never does), else double-double cofactors of the candidate; then the known
//      ties, then GMP, then the perturbation.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>

#include "drange/points.hpp"
#include "geometry/error_bound.hpp"
#include "geometry/known_ties.hpp"
#include "geometry/minors.hpp"
#include "geometry/predicate_stages.hpp"
#include "geometry/predicates.hpp"
#include "geometry/refined_sign.hpp"
#include "geometry/static_exactness.hpp"
#include "geometry/wide_determinant.hpp"

namespace drange::geometry {

template <int D>  // D = 2..8: loops of fixed length; D = 0: any d, read at run time
class LiftedSphereTest {
 public:
  static constexpr int kMaxRow = kMaxDimension + 1;

  // `ranks`: each point id's rank in the lexicographic order (the perturbation's order).
  // `filters_hold` as FacetPlaneTest's.
  LiftedSphereTest(int d, std::int32_t points, const std::int32_t* ranks, bool filters_hold, bool remember_ties,
                   const StaticExactness& exactness)
      : d_(d),
        ranks_of_(ranks),
        filters_hold_(filters_hold),
        remember_ties_(remember_ties),
        gamma_(gamma_bound(laplace_roundings(d + 1, lifted_entry_roundings(d)))),
        exactness_(exactness),
        minors_(d + 1),
        ties_(d + 1, points) {}

  // The facet: sorted vertex ids, sigma, its vertices' coordinates `vertices[0..d-1]`.
  void set_facet(const std::int32_t* ids, int sigma, const double* const* vertices) {
    const int d = dim();
    ids_ = ids;
    sigma_ = sigma;
    f0_ = vertices[0];
    refined_facet_ready_ = false;
    std::array<double, kMaxRow> row{};
    for (int i = 1; i < d; ++i) {
      const double* f = vertices[i];
      rows_[static_cast<std::size_t>(i - 1)] = f;
      double lift = 0.0;
      for (int k = 0; k < d; ++k) {
        row[static_cast<std::size_t>(k)] = f[k] - f0_[k];
        lift += row[static_cast<std::size_t>(k)] * row[static_cast<std::size_t>(k)];
      }
      row[static_cast<std::size_t>(d)] = lift;
      // The fixed-d kernels expand the minors with their terms laid out at compile time.
      if constexpr (D > 0) minors_.set_row_fixed<D + 1>(i - 1, row.data());
      else minors_.set_row(i - 1, row.data());
    }
    exact_ = exactness_.facet_minors(minors_, d);
    // I(p, x) = det[...; r_p; r_x]: Laplace along the last row over all d+1 columns; its
    // d-minors (all but column j), by Laplace along p's row (row d - 1) over the (d-1)-minors,
    // with their signs and sigma folded in (negation is exact).
    const std::uint32_t all = (std::uint32_t{2} << d) - 1;
#pragma GCC unroll 12
    for (int j = 0; j <= d; ++j) {
      const double sign = sigma * (((d + j) & 1) ? -1.0 : 1.0);
      const std::uint32_t mask = all & ~(std::uint32_t{1} << j);
      int position = 0;  // of column c within mask: the cofactor sign (-1)^(d - 1 + position)
#pragma GCC unroll 12
      for (int c = 0; c <= d; ++c) {
        if (c == j) continue;
        const std::uint32_t sub = mask & ~(std::uint32_t{1} << c);
        const double cofactor = ((d - 1 + position) & 1) ? -sign : sign;
        k_[static_cast<std::size_t>(j)][static_cast<std::size_t>(c)] = cofactor * minors_.minor(sub);
        k_abs_[static_cast<std::size_t>(j)][static_cast<std::size_t>(c)] = minors_.abs_minor(sub);
        ++position;
      }
    }
  }
  // The facet's lifted minors and which of them are exact (for FacetPlaneTest::set_facet).
  const MinorTable& minors() const { return minors_; }
  bool orientation_exact() const { return exact_.orientation; }

  // The candidate: its id, coordinates and lifted row r_p.
  void set_candidate(std::int32_t id, const double* p, const double* row) {
    const int d = dim();
    candidate_ = id;
    refined_ready_ = wide_ready_ = false;
    rows_[static_cast<std::size_t>(d - 1)] = p;
    // Unrolled for fixed d, the test c == j folds away.
#pragma GCC unroll 12
    for (int j = 0; j <= d; ++j) {
      double v = 0.0, a = 0.0;
#pragma GCC unroll 12
      for (int c = 0; c <= d; ++c) {
        if (c == j) continue;
        v += k_[static_cast<std::size_t>(j)][static_cast<std::size_t>(c)] * row[c];
        a += std::fabs(row[c]) * k_abs_[static_cast<std::size_t>(j)][static_cast<std::size_t>(c)];
      }
      w_[static_cast<std::size_t>(j)] = v;
      w_abs_[static_cast<std::size_t>(j)] = a;
    }
    // w_j is a d-minor over all columns but j: d units, plus one for the lift column (j < d).
    candidate_exact_ = exact_.lifted;
    for (int j = 0; candidate_exact_ && j <= d; ++j)
      candidate_exact_ = w_abs_[static_cast<std::size_t>(j)] < exactness_.limit(j < d ? d + 1 : d);
  }

  // sigma I(p, x) = w() . r_x in floating point; error(j) bounds w_j's error (its rounding and
  // what underflow adds), for the query ball.
  const double* w() const { return w_.data(); }
  double error(int j) const { return gamma_ * w_abs_[static_cast<std::size_t>(j)] + kUnderflowError; }
  // The same from the candidate's double-double cofactors, for a candidate whose doubles are
  // noise (within rounding of the facet's hyperplane); false when they give none.
  bool refined_form(double* w, double* error) {
    const int d = dim();
    prepare_refined();
    if (!refined_.linear_form(w, error)) return false;
    for (int j = 0; j <= d; ++j) {
      w[j] *= sigma_;
      error[j] += kUnderflowError;
    }
    return true;
  }
  // The rows f_1, ..., f_{d-1}, p (the sphere shell's exact form reads them).
  const double* const* rows() const { return rows_.data(); }

  // sigma I(p, x) < 0, exactly, for the point `id` at x with lifted row `row`. `hint(id)`: a
  // certified sign of sigma I(p, x) by the caller's means, or 0.
  template <class Hint>
  bool beats(std::int32_t id, const double* x, const double* row, const Hint& hint) {
    const int d = dim();
    double v = 0.0, v_abs = 0.0;
    for (int k = 0; k <= d; ++k) {
      v += w_[static_cast<std::size_t>(k)] * row[k];
      v_abs += w_abs_[static_cast<std::size_t>(k)] * std::fabs(row[k]);
    }
    int s = filters_hold_ ? certified_sign_with(v, v_abs, gamma_) : 0;
    if (s == 0) s = hint(id);
    if (s == 0) s = exact_sign(id, x, v, v_abs);
    return s < 0;
  }

 private:
  int dim() const { return D > 0 ? D : d_; }

  int exact_sign(std::int32_t id, const double* x, double v, double v_abs) {
    const int d = dim();
    rows_[static_cast<std::size_t>(d)] = x;
    // The ranks only the perturbation reads, looked up here: the filter decides nearly every
    // test, and the ranks are one more array that each candidate would touch.
    for (int i = 0; i < d; ++i) ranks_[static_cast<std::size_t>(i)] = ranks_of_[ids_[i]];
    ranks_[static_cast<std::size_t>(d)] = ranks_of_[candidate_];
    ranks_[static_cast<std::size_t>(d + 1)] = ranks_of_[id];
    const Frame frame{d, d, nullptr, f0_};
    // I(p, x) has d + 2 units (d spatial columns, the lift twice). Exact and zero: a tie
    // (cospherical points, as in every cell of a grid), which only the perturbation breaks.
    if (candidate_exact_ && v_abs < exactness_.limit(d + 2))
      return v != 0.0 ? (v > 0 ? 1 : -1) : sigma_ * lifted_tie_sign(frame, rows_.data(), ranks_.data(), sigma_);
    if (filters_hold_) return near_tie_sign(frame, id, x);  // the filter was sound and failed: a near-tie
    return sigma_ * lifted_sign_perturbed(frame, rows_.data(), ranks_.data());
  }

  // Stage 4, for a value the sound filter left undecided.
  int near_tie_sign(const Frame& frame, std::int32_t id, const double* x) {
    const int d = dim();
    // Where the recent exact tests were mostly ties (grids whose coordinates are not dyadic),
    // the fixed-width integer stage first: it decides ties and near-ties alike, for less than
    // the double-double stage spends on a candidate's cofactors, which decide no tie. The
    // candidate's cofactors in those integers serve its later tests.
    if (tie_balance_.mostly_ties()) {
      if (!wide_ready_) {
        wide_usable_ = wide_.prepare(frame, rows_.data());  // the sizes wide_determinant.hpp covers
        wide_ready_ = true;
      }
      std::optional<int> s = wide_usable_ ? wide_.sign_with(x) : std::nullopt;
      if (s) count_exact_evaluation();
      else s = small_integer_lifted_sign(frame, rows_.data());
      if (s) {
        tie_balance_.note(*s == 0);
        return sigma_ * (*s != 0 ? *s : lifted_tie_sign(frame, rows_.data(), ranks_.data(), sigma_));
      }
    }
    // The double-double stage first: it decides the near-ties, which are most, and never a tie,
    // so the known ties are looked up only for what it leaves. Its cofactors applied in doubles
    // first decide the tests that the filter left only because the candidate's cofactors in
    // doubles are noise (a candidate within rounding of the facet's hyperplane).
    prepare_refined();
    std::optional<int> refined = refined_.quick_sign_with(frame, x);
    if (!refined) refined = refined_.sign_with(frame, x);
    if (refined) {
      tie_balance_.note(false);
      return sigma_ * *refined;
    }
    tie_balance_.note(true);  // most likely a tie: the double-double stage decides no tie
    // The facet and the candidate, strictly on its open side, are affinely independent: they
    // define the candidate's sphere.
    std::array<std::int32_t, kMaxRow + 1> simplex;
    std::copy(ids_, ids_ + d, simplex.begin());
    simplex[static_cast<std::size_t>(d)] = candidate_;
    if (!remember_ties_ || !ties_.holds(simplex.data(), id)) {
      const int s = integer_lifted_sign(frame, rows_.data());
      if (s != 0) return sigma_ * s;
      if (remember_ties_) ties_.record(simplex.data(), id);
    }
    return sigma_ * lifted_tie_sign(frame, rows_.data(), ranks_.data(), sigma_);
  }

  // The candidate's double-double cofactors, once per candidate; the facet's part once per facet.
  void prepare_refined() {
    if (refined_ready_) return;
    const Frame frame{dim(), dim(), nullptr, f0_};
    if (!refined_facet_ready_) {
      refined_.prepare_facet(frame, rows_.data());
      refined_facet_ready_ = true;
    }
    refined_.prepare_candidate(frame, rows_[static_cast<std::size_t>(dim() - 1)]);
    refined_ready_ = true;
  }

  int d_;
  const std::int32_t* ranks_of_;
  bool filters_hold_, remember_ties_;
  double gamma_;  // the filter's error bound factor (error_bound.hpp)
  StaticExactness exactness_;

  // Per facet.
  const std::int32_t* ids_ = nullptr;
  int sigma_ = 1;
  const double* f0_ = nullptr;
  MinorTable minors_;
  StaticExactness::FacetMinors exact_{false, false};
  // sigma I(p, x) = w . r_x with w_j = sum_c k_[j][c] (r_p)_c (c != j).
  std::array<std::array<double, kMaxRow>, kMaxRow> k_{}, k_abs_{};
  TieBalance tie_balance_;

  // Per candidate.
  std::int32_t candidate_ = -1;
  std::array<double, kMaxRow> w_{}, w_abs_{};
  bool candidate_exact_ = false;  // w is exact, and so is I(p, x) below its limit
  std::array<const double*, kMaxRow + 1> rows_{};  // f_1, ..., f_{d-1}, p, x for the exact stages
  std::array<std::int64_t, kMaxRow + 1> ranks_{};  // ranks of f_0, ..., f_{d-1}, p, x
  KnownTies ties_;  // points proved on a candidate's sphere, for the neighbouring searches
  RefinedCofactors refined_;
  bool refined_ready_ = false, refined_facet_ready_ = false;
  // The candidate's fixed-width cofactors, at its first exact test that asks them; large, so last.
  WideLiftedCofactors wide_;
  bool wide_ready_ = false, wide_usable_ = false;
};

}  // namespace drange::geometry
