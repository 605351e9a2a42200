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

class Perturbation {
 public:
  // `coords`: n*d coordinates, row-major; `interior`: O, d coordinates.
  Perturbation(const double* coords, int d, std::vector<double> interior) : coords_(coords), d_(d), interior_(std::move(interior)) {}

  // The perturbed sign of det[a_1 - a_0; ...; a_d - a_0] for the d+1 ids `a` (distinct ids),
  // given that the unperturbed sign is `unperturbed` (the caller has it exactly); throws
  // InternalError when every stage vanishes.
  int sign(const std::int32_t* a, int unperturbed) const;
  // The unperturbed sign, exactly.
  int unperturbed(const std::int32_t* a) const;

  const double* point(std::int32_t id) const { return coords_ + static_cast<std::size_t>(id) * static_cast<std::size_t>(d_); }
  const std::vector<double>& interior() const { return interior_; }
  // Lexicographic order of the coordinates, then of the ids: the ranks of stage 3.
  bool before(std::int32_t a, std::int32_t b) const;

 private:
  const double* coords_;
  int d_;
  std::vector<double> interior_;
};

}  // namespace drange::hull
