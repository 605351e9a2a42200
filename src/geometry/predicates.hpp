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
// These are the entry points: each runs every stage. The stages one by one, for the search's
// predicate objects that order them themselves, are in predicate_stages.hpp.
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

// Sign of the (k+1)x(k+1) determinant with rows [pi(p_i - base), |p_i - base|^2], i = 1..k+1.
// Unperturbed: zero when the k+2 points (base and the k+1 given) are cospherical.
int lifted_sign(const Frame& frame, const double* const* points);

// The same determinant under the symbolic perturbation |p|^2 -> |p|^2 + eps^(N - rank(p)):
// never zero as long as the k+2 points (base first, then the k+1 in `points`) span the
// k-flat. `ranks[0]` is the base's rank, `ranks[1..k+1]` those of `points`; a larger rank
// is perturbed more. Ranks must be distinct.
int lifted_sign_perturbed(const Frame& frame, const double* const* points, const std::int64_t* ranks);

// The lifted determinant det[r_1; ...; r_k; r_x] (frame.k == frame.dim, rows relative to
// frame.base as in lifted_sign) as a function of its last point x, written around a centre g
// and a constant rho:
//   det = b . (x - g) + lift (|x - g|^2 - rho) + constant,
// an identity for any g and rho. The coefficients are computed exactly, then each truncated to
// a double (within a relative 2^-52 of the exact value; zero exactly). For points near the
// sphere |x - g|^2 = rho every term is small, so a filter of this form decides what the
// Laplace form, with its large cancelling terms, cannot (the sphere shell: delaunay/search/shell_pruner.hpp).
// False, outputs unspecified, when a nonzero coefficient is outside the normal range.
bool exact_lifted_form(const Frame& frame, const double* const* points, const double* g, double rho, double* b,
                       double* lift, double* constant);

// Convenience for full-dimensional simplices (frame = all axes, base = simplex[0]):
// sign of det[s_1 - s_0, ..., s_d - s_0].
int simplex_orientation(int dim, const double* const* simplex);
// +1 if q is strictly inside the circumsphere of the simplex (d+1 points, either orientation,
// nonzero volume), 0 if on it, -1 if outside. Unperturbed.
int in_sphere(int dim, const double* const* simplex, const double* q);

// Counts of how often the floating-point filters and the double-double stage failed and the
// integer stage decided (fixed-width or GMP; for statistics; thread-local, never reset by the
// library).
std::uint64_t exact_evaluations();

}  // namespace drange::geometry
