// geometry/facet_plane_test.hpp: the facet-plane predicate of the search, "is x on the open
// side of facet F": sigma O(x) > 0 with O(x) = det[f_1 - f_0; ...; f_{d-1} - f_0; x - f_0].
//
// Contract: set_facet() with the facet's d affinely independent vertices and its orientation
// sign sigma; then open_side(x) is exact: true exactly when sigma O(x) > 0. A point on the
// hyperplane (O = 0, the facet's own vertices included) is never on the open side, whatever
// the perturbation: the triangulation's simplices are not flat.
//
// The stages, cheapest first, each certain of the sign it returns:
//   1. the floating-point filter: O(x) = a . (x - f_0), a the facet's (d-1)-minors computed once
//      per facet, with its error bound (error_bound.hpp);
//   2. static exactness: with dyadic points, a value whose absolute tree is below its limit
//      was computed without rounding (static_exactness.hpp);
//   3. flat axes: a facet whose vertices agree on an axis (a terrain's plateau) has x on its
//      hyperplane exactly when x agrees too;
//   4. the known ties: points an exact stage already proved on this facet's hyperplane;
//   5. fixed-width integers (the facet's cofactors from 6D on) or double-double cofactors,
//      whichever the recent outcomes favour (ties: the integers decide them, double-double
//      never does), then GMP.
// A box [lo, hi] is on the closed side when the largest sigma O over it is certified negative
// (box_on_closed_side): the kd-tree's pruning of the closed side (paper, 2.4.1).
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
class FacetPlaneTest {
 public:
  static constexpr int kMaxRow = kMaxDimension + 1;

  // `filters_hold`: every value the filters see is free of overflow and of underflow beyond
  // kUnderflowError (the search's scaled points); else only the exact stages decide.
  FacetPlaneTest(int d, std::int32_t points, bool filters_hold, bool remember_ties, const StaticExactness& exactness)
      : d_(d),
        filters_hold_(filters_hold),
        remember_ties_(remember_ties),
        orient_gamma_(gamma_bound(laplace_roundings(d, 1))),
        // The factor of a box's largest sigma O. That sum takes each term at the box's corner
        // that the *computed* coefficient a_k's sign picks: the value of O at that corner,
        // within orient_gamma_ of its absolute tree. Where a_k's sign is wrong, the exact A_k
        // is no larger than a_k's error, gamma_c |a|_k (gamma_c: the (d-1)-minor's factor), and
        // the other corner is larger by |A_k| (hi_k - lo_k) <= 2.01 gamma_c |a|_k max(|lo_k -
        // f0_k|, |hi_k - f0_k|): the box's largest O is within orient_gamma_ + 2.01 gamma_c of
        // the absolute tree above the computed sum.
        box_gamma_(orient_gamma_ + 2.01 * gamma_bound(laplace_roundings(d - 1, 1))),
        minor_gamma_(gamma_bound(laplace_roundings(d - 1, 1))),
        exact_limit_(exactness.limit(d)),
        ties_(d, points) {}

  // The facet: its sorted vertex ids, sigma, f_0 and the rows f_1 .. f_{d-1}; `minors` the
  // (d-1)-minors of its rows relative to f_0 (the spatial columns 0 .. d-1 are read);
  // `exact`: every spatial minor was computed exactly (StaticExactness::facet_minors).
  void set_facet(const std::int32_t* ids, int sigma, const double* f0, const double* const* rows, const MinorTable& minors,
                 bool exact) {
    const int d = dim();
    ids_ = ids;
    sigma_ = sigma;
    f0_ = f0;
    for (int i = 0; i + 1 < d; ++i) rows_[static_cast<std::size_t>(i)] = rows[i];
    exact_ = exact;
    flat_axes_ = kFlatAxesUnknown;
    refined_ready_ = wide_ready_ = false;
    // O(x) = det[f_1 - f_0; ...; x - f_0]: Laplace along the last row over the spatial columns.
    const std::uint32_t spatial = (std::uint32_t{1} << d) - 1;
    for (int j = 0; j < d; ++j) {
      const double sign = ((d - 1 + j) & 1) ? -1.0 : 1.0;
      a_[static_cast<std::size_t>(j)] = sigma * sign * minors.minor(spatial & ~(std::uint32_t{1} << j));
      a_abs_[static_cast<std::size_t>(j)] = minors.abs_minor(spatial & ~(std::uint32_t{1} << j));
    }
  }

  // sigma O(x) > 0, exactly, for the point `id` at x with row = x - f_0 (its first d entries).
  bool open_side(std::int32_t id, const double* x, const double* row) {
    const int d = dim();
    double o = 0.0, o_abs = 0.0;
    for (int k = 0; k < d; ++k) {
      o += a_[static_cast<std::size_t>(k)] * row[k];
      o_abs += a_abs_[static_cast<std::size_t>(k)] * std::fabs(row[k]);
    }
    int s = sign_of(o, o_abs, orient_gamma_);
    if (s == 0) s = exact_sign(id, x);
    return s > 0;
  }

  // Whether every point of the box [lo, hi] is certainly on the closed side (sigma O <= 0).
  // `box_abs` receives the absolute tree of the box's largest sigma O, which the accelerators'
  // closed-side tests (box_gamma() times it) take as the coefficients' error.
  bool box_on_closed_side(const double* lo, const double* hi, double& box_abs) {
    const int d = dim();
    // The largest value of sigma O over the box, at the corner that maximises each term
    // (rounding is monotonic: a * dhi >= a * dlo in floating point too when a >= 0).
    double m = 0.0, m_abs = 0.0;
    for (int k = 0; k < d; ++k) {
      const double a = a_[static_cast<std::size_t>(k)];
      const double dlo = lo[k] - f0_[k], dhi = hi[k] - f0_[k];
      m += a * (a >= 0 ? dhi : dlo);
      m_abs += a_abs_[static_cast<std::size_t>(k)] * std::max(std::fabs(dlo), std::fabs(dhi));
    }
    box_abs = m_abs;
    return sign_of(m, m_abs, box_gamma_) < 0 || flat_closed_side(lo, hi);
  }

  // sigma O(x) = coefficients() . (x - f_0) in floating point, each coefficient within
  // orient_gamma() of abs_coefficients() (the lane filters of the leaf scan, the accelerators).
  const double* coefficients() const { return a_.data(); }
  const double* abs_coefficients() const { return a_abs_.data(); }
  double orient_gamma() const { return orient_gamma_; }
  double box_gamma() const { return box_gamma_; }

 private:
  static constexpr unsigned kFlatAxesUnknown = ~0u;
  int dim() const { return D > 0 ? D : d_; }

  // The sign of sigma O over the computed value, when certified with the bound factor `gamma`
  // or proved exact; else 0. An exact 0 counts as the closed side, like negative values.
  int sign_of(double value, double abs_tree, double gamma) const {
    const int s = filters_hold_ ? certified_sign_with(value, abs_tree, gamma) : 0;
    if (s != 0 || !exact_ || !(abs_tree < exact_limit_)) return s;
    return value > 0 ? 1 : -1;
  }

  // The sign of sigma O(x) whose filter failed, exactly: stages 3 to 5.
  int exact_sign(std::int32_t id, const double* x) {
    const int d = dim();
    rows_[static_cast<std::size_t>(d - 1)] = x;
    if (flat_axes_ == kFlatAxesUnknown) flat_axes_ = flat_axes();
    for (unsigned axes = flat_axes_; axes != 0; axes &= axes - 1) {
      const int k = __builtin_ctz(axes);
      if (x[k] == f0_[k]) return 0;  // a zero column
    }
    const Frame frame{d, d, nullptr, f0_};
    // The generic filters only where the search's own did not run (points not scaled): where
    // it did, they filter the same expansion with the same exactness proof.
    if (!filters_hold_)
      if (const std::optional<int> s = filtered_orientation(frame, rows_.data())) return sigma_ * *s;
    if (!remember_ties_) return sigma_ * exact_orientation(frame, rows_.data());
    // Looked up before the double-double stage, unlike the spheres' ties: a facet's search asks
    // about its one hyperplane many times, and on grids half the points that reach here lie on it.
    if (ties_.holds(ids_, id)) return 0;
    std::optional<int> small;
    if (tie_balance_.mostly_ties()) small = fixed_width_sign(frame, x);
    if (!small) {
      // The double-double stage as the facet's cofactors, computed at its first near-tie: each
      // point then costs a dot product.
      if (!refined_ready_) {
        refined_.prepare_orientation(frame, rows_.data());
        refined_ready_ = true;
      }
      small = refined_.sign_with(frame, x);
    }
    const int s = small ? *small : integer_orientation(frame, rows_.data());
    tie_balance_.note(s == 0);
    if (s == 0) ties_.record(ids_, id);
    return sigma_ * s;
  }

  // The fixed-width stage: the facet's cofactors from 6D, else the whole determinant.
  std::optional<int> fixed_width_sign(const Frame& frame, const double* x) {
    if (dim() >= WideOrientationCofactors::kMinDim) {
      if (!wide_ready_) {
        wide_usable_ = wide_.prepare(frame, rows_.data());
        wide_ready_ = true;
      }
      if (wide_usable_) {
        const std::optional<int> s = wide_.sign_with(x);
        if (s) {
          count_exact_evaluation();
          return s;
        }
      }
    }
    return small_integer_orientation(frame, rows_.data());
  }

  // The axes on which all the facet's vertices agree, as a bit mask.
  unsigned flat_axes() const {
    const int d = dim();
    unsigned axes = 0;
    for (int k = 0; k < d; ++k) {
      bool flat = true;
      for (int i = 1; i < d && flat; ++i) flat = rows_[static_cast<std::size_t>(i - 1)][k] == f0_[k];
      if (flat) axes |= 1u << k;
    }
    return axes;
  }

  // Whether the box is wholly on the closed side of a facet flat on an axis (a horizontal
  // facet of a terrain's plateau), exactly: its largest O is 0 on the plateau's points, which
  // the filter cannot certify negative. One flat axis k at most (the vertices are affinely
  // independent), and the hyperplane is x_k = f0_k: every other coefficient of a_ is a minor
  // with a zero column, computed as an exact 0, so sigma O(x) = a_k (x_k - f0_k) exactly where
  // a_k's sign is right, which its own filter certifies (a_k is a (d-1)-minor).
  bool flat_closed_side(const double* lo, const double* hi) {
    if (flat_axes_ == kFlatAxesUnknown) flat_axes_ = flat_axes();
    if (flat_axes_ == 0) return false;
    const int k = __builtin_ctz(flat_axes_);
    const int s = certified_sign_with(a_[static_cast<std::size_t>(k)], a_abs_[static_cast<std::size_t>(k)], minor_gamma_);
    return s > 0 ? hi[k] <= f0_[k] : s < 0 && lo[k] >= f0_[k];
  }

  int d_;
  bool filters_hold_, remember_ties_;
  double orient_gamma_, box_gamma_, minor_gamma_;
  double exact_limit_;  // O(x) is exact below this absolute tree when exact_ (dyadic points)

  // Per facet.
  const std::int32_t* ids_ = nullptr;
  int sigma_ = 1;
  const double* f0_ = nullptr;
  std::array<const double*, kMaxRow> rows_{};  // f_1, ..., f_{d-1}, x for the exact stages
  std::array<double, kMaxRow> a_{}, a_abs_{};  // sigma O(x) = a . (x - f0), and its absolute tree
  bool exact_ = false;
  unsigned flat_axes_ = kFlatAxesUnknown;  // computed at the facet's first need
  TieBalance tie_balance_;
  KnownTies ties_;  // points proved on a facet's hyperplane, for the neighbouring facets' searches
  RefinedCofactors refined_;  // the facet's double-double cofactors, at its first near-tie
  bool refined_ready_ = false;
  // The facet's fixed-width cofactors (from 6D), at their first use; large, so last.
  WideOrientationCofactors wide_;
  bool wide_ready_ = false, wide_usable_ = false;
};

}  // namespace drange::geometry
