// geometry/refined_sign.hpp: the second stage of the lifted and orientation predicates, between
// the double filter and GMP: the same determinant in double-double arithmetic with its error
// bound.
//
// Why: points within rounding of a sphere that is not the input's one sphere (the insides of
// two concentric spheres, of small bubbles, of the rings of a cylinder) make the search test
// each point near a candidate's sphere, and the double filter cannot decide those tests: a
// point that lies within 2^-50 of the sphere, relative to the determinant's terms, is beyond
// its reach. Such a point is rarely within 2^-100, though, unless it is exactly on it, and the
// double-double evaluation decides it without GMP's integer scaling and Bareiss on several
// limbs (on two concentric spheres the whole run takes far fewer instructions). Exact ties
// still go to GMP, and then to the perturbation.
#pragma once

#include <optional>

#include "geometry/double_double.hpp"
#include "geometry/predicates.hpp"

namespace drange::geometry {

// Up to this many rows (frame.k + 1 lifted, frame.k oriented): the Laplace expansion's minors
// grow as 2^n. Six, for 5D's lifted determinants (points rounded to 0.1 in 5D would otherwise
// send millions of near-ties to GMP).
constexpr int kRefinedMaxRows = 6;

// The sign of lifted_sign's determinant when the double-double evaluation proves it; nullopt
// when the bound does not decide, frame.k + 1 > kRefinedMaxRows, or an operation underflowed
// or overflowed.
std::optional<int> refined_lifted_sign(const Frame& frame, const double* const* points);

// The same for orientation's determinant (frame.k rows of differences, 2 <= frame.k <=
// kRefinedMaxRows): points within rounding of a hyperplane but not on it, as the radial lines of
// a grid in cylindrical coordinates, which GMP decides at thousands of instructions each.
std::optional<int> refined_orientation(const Frame& frame, const double* const* points);

// Whether this stage computes its exact products by fused multiply-adds (2 operations instead of
// Dekker's 17; the same bits, so the same signs): by default where the processor has them.
// set_refined_fma(false) selects the other code, as on processors without them (tests run both);
// set_refined_fma(true) takes the processor's choice again. Not to be called while another
// thread triangulates.
bool refined_fma();
void set_refined_fma(bool on);

// The same stage for many points x against the same first frame.k points: the cofactors along
// x's row are computed once (prepare), and each test (sign_with) is then a dot product of
// double-double numbers. The value and bound are those of refined_lifted_sign on the rows with
// x's first and the frame.k-th point's next (the candidate's, whose row the cofactors expand
// last), so it decides the same cases. (A search tests many points against one candidate's
// sphere: on 100 rings of 200 points on a cylinder, 44 near-ties per candidate.)
class RefinedCofactors {
 public:
  // `points`: the first frame.k of lifted_sign's frame.k + 1 points.
  void prepare(const Frame& frame, const double* const* points);
  // The same in two steps, for many candidates of one facet: prepare_facet with the first
  // frame.k - 1 points (the minors of their rows, 1 << (frame.k + 1) of them, kept), then
  // prepare_candidate with the frame.k-th for each candidate (its cofactors from those minors:
  // in 4D 20 double-double products instead of 70; on 4D points rounded to 0.05 a facet
  // prepares more than one candidate on average). `frame` the same throughout.
  void prepare_facet(const Frame& frame, const double* const* points);
  void prepare_candidate(const Frame& frame, const double* candidate);
  // The same for orientation's determinant (frame.k rows of differences, 2 <= frame.k <=
  // kRefinedMaxRows): `points` the first frame.k - 1 of its frame.k points, and sign_with then
  // refined_orientation's sign with x as the last (a facet's hyperplane, asked about many
  // points within rounding of it: points of a decimal lattice's hyperplane in 4D). Not for
  // quick_sign_with and linear_form, which then decline.
  void prepare_orientation(const Frame& frame, const double* const* points);
  // lifted_sign's determinant with x as the last point, when proved; nullopt as
  // refined_lifted_sign, or when prepare could not (too many rows, or under- or overflow).
  // `frame` must be prepare's.
  std::optional<int> sign_with(const Frame& frame, const double* x) const;
  // The same sign from the cofactors' high parts and x's row in plain doubles, when a bound
  // proves it: a fraction of sign_with's instructions, and as decisive except where x is
  // within rounding of the sphere. For candidates within rounding of the facet's hyperplane (points
  // that a decimal lattice puts on one plane): their double cofactors are noise, so that the
  // search's own filter decides none of the tests against them, and these do. Only for points
  // scaled below 1 in magnitude (PointStore::scaled), where kUnderflowError bounds underflow.
  std::optional<int> quick_sign_with(const Frame& frame, const double* x) const;
  // The determinant with x as the last row as a linear form in x's lifted row r (frame.k
  // spatial entries on the frame's axes, then the lift): det = sum_c exact_c r_c, where
  // |coefficient[c] - exact_c| <= slack[c]; n = frame.k + 1 entries each. false when prepare
  // could not.
  bool linear_form(double* coefficient, double* slack) const;

 private:
  // s, the sign of the determinant the cofactors expand ([x; candidate; p_1; ...] lifted,
  // [x; p_1; ...] oriented), as that of the points in their order with x last: the lifted rows
  // are 2n - 3 transpositions away (x to the end, then the candidate after the p's), the
  // oriented n - 1.
  int to_points_order(int s) const { return lifted_ || n_ % 2 == 0 ? -s : s; }

  int n_ = 0;
  bool usable_ = false;
  bool lifted_ = true;  // prepare's determinant, else prepare_orientation's
  bool facet_usable_ = false;  // prepare_facet's minors were computed without under- or overflow
  DoubleDouble facet_minor_[1 << kRefinedMaxRows];
  double facet_tree_[1 << kRefinedMaxRows] = {};
  DoubleDouble cofactor_[kRefinedMaxRows];
  double tree_[kRefinedMaxRows] = {};
  // Bounds on |cofactor_[c] - the exact cofactor| (hi + lo against the exact value).
  double error_[kRefinedMaxRows] = {};
  double quick_gamma_ = 0.0;  // gamma_bound(n + dim + 1), for quick_sign_with
};

}  // namespace drange::geometry
