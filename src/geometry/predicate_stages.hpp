// geometry/predicate_stages.hpp: the stages of the exact predicates one by one, for the
// predicate objects that run them in an order of their own (facet_plane_test.hpp,
// lifted_sphere_test.hpp: they consult their known ties between stages, and put the
// fixed-width integers first where the recent tests were mostly ties). Every other caller
// asks predicates.hpp's entry points, which run all the stages.
//
// Each stage returns an exact sign or, for the partial ones (std::optional), nothing when it
// cannot decide; none of them perturbs unless it says so.
#pragma once

#include <algorithm>
#include <cstdint>
#include <optional>

#include "geometry/predicates.hpp"

namespace drange::geometry {

// orientation in two parts, for a caller that can learn a zero from elsewhere before it pays
// for the exact stages (known_ties.hpp): the floating-point filters and the exactness
// proofs (nullopt when they cannot decide), then the exact stages alone (double-double, then
// integers: fixed-width or GMP).
std::optional<int> filtered_orientation(const Frame& frame, const double* const* points);
int exact_orientation(const Frame& frame, const double* const* points);
// The exact stage's fixed-width part alone (wide_determinant.hpp: its sizes, when the points'
// differences fit), before the double-double stage, for a caller that meets mostly ties;
// nullopt when it does not apply.
std::optional<int> small_integer_orientation(const Frame& frame, const double* const* points);
// exact_orientation's last stage alone (integers: fixed-width, else GMP), for a caller that ran
// the double-double stage its own way (RefinedCofactors::prepare_orientation, refined_sign.hpp).
int integer_orientation(const Frame& frame, const double* const* points);

// lifted_sign_perturbed for a caller that has proved the unperturbed determinant exactly zero
// (lifted_sphere_test.hpp does, on dyadic points): the perturbation alone decides. `known`, when not
// 0, is the sign that the caller knows of both orientations of the base and the points without
// the last one and without the next to last one (a facet search: its candidate and the tested
// point are strictly on the facet's open side): when either of those two points is the most
// perturbed, that sign decides, without an orientation.
int lifted_tie_sign(const Frame& frame, const double* const* points, const std::int64_t* ranks, int known = 0);
// lifted_sign_perturbed without the double filter, for a caller whose own filter of the same
// determinant just failed: near-ties, which the generic filter would not decide either (on
// points on a sphere it decided none). The double-double and integer stages decide.
int exact_lifted_sign_perturbed(const Frame& frame, const double* const* points, const std::int64_t* ranks);
// lifted_sign's last stage alone (integers: fixed-width, else GMP), unperturbed, for a caller
// that ran the double-double stage its own way (RefinedCofactors, refined_sign.hpp) and breaks
// the ties itself with lifted_tie_sign.
int integer_lifted_sign(const Frame& frame, const double* const* points);
// Its first part alone: the exact value in fixed-width integers (wide_determinant.hpp, for the
// sizes it covers) when the points' differences fit; nullopt otherwise. About
// as cheap as the double-double stage for a candidate's cofactors and several times cheaper
// than GMP: a caller that meets mostly exact ties asks it first.
std::optional<int> small_integer_lifted_sign(const Frame& frame, const double* const* points);

// Counts one exact evaluation that a caller made with a stage of its own (the predicate objects:
// WideLiftedCofactors, wide_determinant.hpp), for exact_evaluations().
void count_exact_evaluation();

// Ties minus near-ties among a predicate object's recent exact tests, within +-kLimit: while
// positive, its fixed-width integer stage goes before the double-double one (the integers
// decide ties and near-ties alike; double-double never decides a tie). It orders the stages
// only: every stage's sign is exact.
class TieBalance {
 public:
  bool mostly_ties() const { return balance_ > 0; }
  void note(bool tie) { balance_ = tie ? std::min(balance_ + 1, kLimit) : std::max(balance_ - 1, -kLimit); }

 private:
  static constexpr int kLimit = 16;
  int balance_ = 0;
};

}  // namespace drange::geometry
