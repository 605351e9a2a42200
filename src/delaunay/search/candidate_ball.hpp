// delaunay/search/candidate_ball.hpp: the query region of a search, from its candidate's
// sphere: the paper's box [c - R, c + R] (2.4.3), and the ball itself, each enlarged by a bound
// on the rounding error of the centre and radius, so that no point that may win is missed.
//
// Invariant: every point x strictly inside the sphere through the facet and the candidate, or
// on it, lies in the box, and (when ball() is true) has a computed squared distance to centre()
// not above reach2(). With no trustworthy sphere (reset), the box is all space.
#pragma once

#include <array>
#include <cmath>
#include <limits>

#include "drange/points.hpp"
#include "geometry/error_bound.hpp"

namespace drange::engine {

template <int D>
class CandidateBall {
 public:
  static constexpr int kMaxRow = kMaxDimension + 1;
  static constexpr double kInfinity = std::numeric_limits<double>::infinity();

  explicit CandidateBall(int d) : d_(d) {}

  // No candidate, or none whose sphere can be trusted: the box is all space, no ball.
  void reset() {
    for (int k = 0; k < dim(); ++k) {
      lower_[static_cast<std::size_t>(k)] = -kInfinity;
      upper_[static_cast<std::size_t>(k)] = kInfinity;
    }
    ball_ = false;
  }

  // The sphere {x : sigma I(p, x) = w . r_x = 0} (r_x = (x - f0, |x - f0|^2)), each w_j within
  // error(j) of its exact value. false when w's lift coefficient is not certainly away from 0
  // (no trustworthy box) or the reach is not finite; then centre() may have changed but the
  // box and the ball have not, and the caller sets another or resets. `use_ball`: also
  // query the ball, not only its box (else ball() stays false).
  template <class Error>
  [[gnu::always_inline]] inline bool set(const double* w, const Error& error, const double* f0, bool use_ball) {
    const int d = dim();
    // I(p, x) / O(p) is the power of x, so the centre is f0 - w_spatial / (2 w_lift) and the
    // sphere passes through f0.
    const double wd = w[d], ewd = error(d);
    if (!(std::fabs(wd) > 2 * ewd) || !std::isfinite(wd)) return false;
    double radius2 = 0.0, centre_error = 0.0, magnitude = 0.0;
    // Two divisions, then products: a reciprocal's rounding adds u to the centre's relative
    // error, which the reach's 8 (d + 4) u of slack below covers, and to its error's, which the
    // factor 1 + 1e-6 does.
    const double minus_half_over_wd = -1 / (2 * wd), half_over_margin = 1 / (2 * (std::fabs(wd) - ewd));
    for (int k = 0; k < d; ++k) {
      const double dc = w[k] * minus_half_over_wd;
      const double err = (error(k) + 2 * std::fabs(dc) * ewd) * half_over_margin;
      centre_[static_cast<std::size_t>(k)] = f0[k] + dc;
      radius2 += dc * dc;
      centre_error += err;  // the 1-norm of the centre's error: at least its length, without a root
      magnitude = std::max(magnitude, std::fabs(centre_[static_cast<std::size_t>(k)]));
    }
    const double radius = std::sqrt(radius2);
    // Twice the centre's error (the radius moves by at most as much), plus the roundings of
    // computing the centre, the radius and the box bounds, and what underflow can take from the
    // smallest of them (a radius below 2^-511 may lose its squares: at most sqrt(d) 2^-537; a
    // ball needs a reach above 2^-400 anyway).
    const double reach = radius + 2 * centre_error * (1 + 1e-6) +
                         8 * (d + 4) * geometry::kUnitRoundoff * (magnitude + radius) + 0x1p-500;
    if (!std::isfinite(reach)) return false;
    for (int k = 0; k < d; ++k) {
      lower_[static_cast<std::size_t>(k)] = centre_[static_cast<std::size_t>(k)] - reach;
      upper_[static_cast<std::size_t>(k)] = centre_[static_cast<std::size_t>(k)] + reach;
    }
    // A squared distance computed in floating point is within a relative (d + 2) u of the true
    // one (differences, squares and a sum of positive terms; an underflowing term only makes it
    // smaller), so comparing with reach^2 (1 + 1e-10) never drops a point of the ball. Far
    // below 1 (the points are scaled to magnitudes near 1), reach^2 itself could underflow: no
    // ball then. Nor when it overflows: the leaf blocks' empty lanes, at infinity, must stay
    // out of every ball.
    reach2_ = reach * reach * (1 + 1e-10);
    reach_ = reach;
    ball_ = use_ball && reach > 0x1p-400 && reach2_ < kInfinity;
    return true;
  }

  bool ball() const { return ball_; }
  const double* centre() const { return centre_.data(); }
  double reach() const { return reach_; }
  double reach2() const { return reach2_; }
  const double* lower() const { return lower_.data(); }
  const double* upper() const { return upper_.data(); }

  // Whether x is in the query region: the ball when there is one, else the box.
  bool holds(const double* x) const {
    const int d = dim();
    if (ball_) {
      double distance2 = 0.0;
      for (int k = 0; k < d; ++k) {
        const double delta = x[k] - centre_[static_cast<std::size_t>(k)];
        distance2 += delta * delta;
      }
      return !(distance2 > reach2_);
    }
    for (int k = 0; k < d; ++k)
      if (x[k] < lower_[static_cast<std::size_t>(k)] || x[k] > upper_[static_cast<std::size_t>(k)]) return false;
    return true;
  }

 private:
  int dim() const { return D > 0 ? D : d_; }
  int d_;
  std::array<double, kMaxRow> centre_{}, lower_{}, upper_{};
  double reach2_ = 0.0, reach_ = 0.0;
  bool ball_ = false;
};

}  // namespace drange::engine
