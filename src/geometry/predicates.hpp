// geometry/predicates.hpp: exact geometric predicates on double coordinates.
//
// Every predicate returns the exact sign of a determinant of the input doubles: a fast
// floating-point evaluation whose error bound is derived (see error_bound.hpp), then, only when
// that bound cannot decide, an exact evaluation in integers: fixed-width ones up to 5 x 5 where
// the values fit (wide_determinant.hpp), GMP's otherwise. Between the two, up to 6 x 6,
// the same evaluation in double-double arithmetic (refined_sign.hpp) decides the near-ties of
// points within rounding of a sphere or of a hyperplane. A zero never reaches the
// algorithm where it would matter: `lifted_sign_perturbed` breaks every tie by a symbolic
// perturbation of the lifted coordinate (Edelsbrunner and Muecke's Simulation of Simplicity,
// in the form Devillers and Teillaud give for Delaunay triangulations).
//
// Frames. A predicate works in a Frame: `k` of the `dim` ambient axes, relative to a base
// point. Row i of a determinant is the projection of (p_i - base) onto those axes, optionally
// followed by the *ambient* squared distance |p_i - base|^2 (the lifted coordinate). For a
// point set that lies in a k-flat projecting one-to-one onto the chosen axes, these
// determinants decide orientation and in-sphere within that flat, because the ambient
// squared norm restricted to the flat is a positive definite quadratic plus an affine term.
#pragma once

#include <cstdint>
#include <optional>

namespace drange::geometry {

struct Frame {
  int dim = 0;                  // ambient dimension: every point has `dim` coordinates
  int k = 0;                    // number of axes used
  const int* axes = nullptr;    // the axes (k of them); nullptr means 0..k-1
  const double* base = nullptr; // the base point (ambient coordinates)

  int axis(int i) const { return axes ? axes[i] : i; }
};

// Sign of det [pi(p_1 - base); ...; pi(p_k - base)]  (k rows, k columns).
// For frame.k == dim and base = p_0 this is the orientation of the simplex (p_0, ..., p_k).
int orientation(const Frame& frame, const double* const* points);
// orientation in two parts, for a caller that can learn a zero from elsewhere before it pays
// for the exact stages (delaunay/known_ties.hpp): the floating-point filters and the exactness
// proofs (nullopt when they cannot decide), then the exact stages alone (double-double, then
// integers: fixed-width or GMP).
std::optional<int> filtered_orientation(const Frame& frame, const double* const* points);
int exact_orientation(const Frame& frame, const double* const* points);
// The exact stage's fixed-width part alone (wide_determinant.hpp: k <= 4, when the points'
// differences fit), before the double-double stage, for a caller that meets mostly ties;
// nullopt when it does not apply.
std::optional<int> small_integer_orientation(const Frame& frame, const double* const* points);
// exact_orientation's last stage alone (integers: fixed-width, else GMP), for a caller that ran
// the double-double stage its own way (RefinedCofactors::prepare_orientation, refined_sign.hpp).
int integer_orientation(const Frame& frame, const double* const* points);

// Sign of the (k+1)x(k+1) determinant with rows [pi(p_i - base), |p_i - base|^2], i = 1..k+1.
// Unperturbed: zero when the k+2 points (base and the k+1 given) are cospherical.
int lifted_sign(const Frame& frame, const double* const* points);

// The same determinant under the symbolic perturbation |p|^2 -> |p|^2 + eps^(N - rank(p)):
// never zero as long as the k+2 points (base first, then the k+1 in `points`) span the
// k-flat. `ranks[0]` is the base's rank, `ranks[1..k+1]` those of `points`; a larger rank
// is perturbed more. Ranks must be distinct.
int lifted_sign_perturbed(const Frame& frame, const double* const* points, const std::int64_t* ranks);
// lifted_sign_perturbed for a caller that has proved the unperturbed determinant exactly zero
// (facet_search.cpp does, on dyadic points): the perturbation alone decides. `known`, when not
// 0, is the sign that the caller knows of both orientations of the base and the points without
// the last one and without the next to last one (a facet search: its candidate and the tested
// point are strictly on the facet's open side): when either of those two points is the most
// perturbed, that sign decides, without an orientation.
int lifted_tie_sign(const Frame& frame, const double* const* points, const std::int64_t* ranks, int known = 0);
// lifted_sign_perturbed without the double filter, for a caller whose own filter of the same
// determinant just failed: near-ties, which the generic filter would not decide either (on
// points on a sphere it decided none). The double-double and integer stages decide.
// (facet_search.cpp takes these stages one by one, exact_beats, to consult its known ties
// between them.)
int exact_lifted_sign_perturbed(const Frame& frame, const double* const* points, const std::int64_t* ranks);
// lifted_sign's last stage alone (integers: fixed-width, else GMP), unperturbed, for a caller
// that ran the double-double stage its own way (RefinedCofactors, refined_sign.hpp) and breaks
// the ties itself with lifted_tie_sign.
int integer_lifted_sign(const Frame& frame, const double* const* points);
// Its first part alone: the exact value in fixed-width integers (wide_determinant.hpp), for k
// = 2 to 4 in up to 4 dimensions when the points' differences fit; nullopt otherwise. About
// as cheap as the double-double stage for a candidate's cofactors and several times cheaper
// than GMP: a caller that meets mostly exact ties asks it first.
std::optional<int> small_integer_lifted_sign(const Frame& frame, const double* const* points);

// The lifted determinant det[r_1; ...; r_k; r_x] (frame.k == frame.dim, rows relative to
// frame.base as in lifted_sign) as a function of its last point x, written around a centre g
// and a constant rho:
//   det = b . (x - g) + lift (|x - g|^2 - rho) + constant,
// an identity for any g and rho. The coefficients are computed exactly, then each truncated to
// a double (within a relative 2^-52 of the exact value; zero exactly). For points near the
// sphere |x - g|^2 = rho every term is small, so a filter of this form decides what the
// Laplace form, with its large cancelling terms, cannot (facet_search.cpp, sphere_shell.hpp).
// False, outputs unspecified, when a nonzero coefficient is outside the normal range.
bool exact_lifted_form(const Frame& frame, const double* const* points, const double* g, double rho, double* b,
                       double* lift, double* constant);

// Convenience for full-dimensional simplices (frame = all axes, base = simplex[0]):
// sign of det[s_1 - s_0, ..., s_d - s_0].
int simplex_orientation(int dim, const double* const* simplex);
// +1 if q is strictly inside the circumsphere of the simplex (d+1 points, either orientation,
// nonzero volume), 0 if on it, -1 if outside. Unperturbed.
int in_sphere(int dim, const double* const* simplex, const double* q);

// Counts one exact evaluation that a caller made with a stage of its own (facet_search.cpp:
// WideLiftedCofactors, wide_determinant.hpp), for exact_evaluations().
void count_exact_evaluation();

// Counts of how often the floating-point filters and the double-double stage failed and the
// integer stage decided (fixed-width or GMP; for statistics; thread-local, never reset by the
// library).
std::uint64_t exact_evaluations();

}  // namespace drange::geometry
