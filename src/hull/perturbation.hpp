// hull/perturbation.hpp: the orientation of d+1 points under the convex hull's symbolic
// perturbation, never zero.
//
// The perturbation. With O a fixed point strictly inside the hull and q_i = a_i - O, point i
// moves to P_i = O + q_i / t_i with t_i = 1 - eps w_i - eta_i, w_i = |q_i|^2, and infinitesimals
// 1 >> eps >> eta_(first) >> eta_(second) >> ... ordered by the points' ranks (lexicographic
// order of coordinates; exact copies by index). Every point moves outward along its ray from O.
// Because w is strictly convex, the eps term lifts a point inside a face of the hull less than
// the face's corners around it: only extreme points become vertices, and the faces are
// triangulated by their corners (the upper hull of a convex lift). The eta terms decide what eps
// leaves tied (corners on one sphere within their face, exact copies).
//
// The sign. The orientation of P_0..P_d is that of the (d+1)x(d+1) determinant [q_i, t_i]
// times (-1)^d (t_i > 0 does not change it). That determinant is linear in its last column:
//   det[q_i, 1] - eps det[q_i, w_i] - sum_i eta_i (-1)^(i+d) det[q_k : k != i],
// so the first nonzero of these decides, in this order:
//   1. the unperturbed orientation det[a_1 - a_0; ...; a_d - a_0];
//   2. (-1)^(d+1) times the lifted determinant det[a_i - O, |a_i - O|^2] (in-sphere in a flat);
//   3. for i by increasing rank: (-1)^(i+1) times det[a_k - O : k != i].
// All of them vanish only when the d+1 points and O lie in one hyperplane through O, which the
// Quickhull never asks: a facet's hyperplane keeps O strictly inside.
#pragma once

#include <cstdint>
#include <vector>

namespace drange::hull {

// O is the centroid of the first simplex. Where it rounds to a double strictly inside that
// simplex (on every input but extremely thin ones), stages 2 and 3 are the library's predicates
// about that double; otherwise they are evaluated about the exact centroid, in integers (GMP).
class Perturbation {
 public:
  // `coords`: n*d coordinates, row-major; `simplex`: the first simplex's d+1 ids; `interior`:
  // the centroid rounded to doubles when that is strictly inside, else empty.
  Perturbation(const double* coords, int d, std::vector<std::int32_t> simplex, std::vector<double> interior)
      : coords_(coords), d_(d), simplex_(std::move(simplex)), interior_(std::move(interior)) {}

  // The perturbed sign of det[a_1 - a_0; ...; a_d - a_0] for the d+1 ids `a` (distinct ids),
  // given that the unperturbed sign is `unperturbed` (the caller has it exactly); throws
  // InternalError when every stage vanishes.
  int sign(const std::int32_t* a, int unperturbed) const;
  // The unperturbed sign, exactly.
  int unperturbed(const std::int32_t* a) const;

  const double* point(std::int32_t id) const { return coords_ + static_cast<std::size_t>(id) * static_cast<std::size_t>(d_); }
  // Lexicographic order of the coordinates, then of the ids: the ranks of stage 3.
  bool before(std::int32_t a, std::int32_t b) const;

 private:
  // Stage 2's determinant det[p_i - O, |p_i - O|^2] for the d+1 points `p`, and stage 3's
  // det[p_k - O] for d points: signs, exactly.
  int lifted_about_interior(const double* const* p) const;
  int orientation_about_interior(const double* const* p) const;
  // The same about the exact centroid: rows (d+1) p_i - sum of the simplex's vertices, in
  // integers after one common power-of-two scaling (positive factors: the signs are kept).
  int exact_about_centroid(const double* const* p, int rows, bool lifted) const;

  const double* coords_;
  int d_;
  std::vector<std::int32_t> simplex_;
  std::vector<double> interior_;
};

}  // namespace drange::hull
