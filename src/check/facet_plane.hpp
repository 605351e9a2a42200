// check/facet_plane.hpp: the hyperplane of one facet, evaluated at many points: a
// floating-point filter with a proven error bound, then the exact predicate when the filter
// cannot decide.
//
// For a facet f_0, ..., f_{d-1} (d points in E^d) let D(x) = det[f_1 - f_0; ...;
// f_{d-1} - f_0; x - f_0], the orientation of the simplex (f_0, ..., f_{d-1}, x). D is affine
// in x: D(x) = sum_j C_j (x_j - f0_j) with C_j the cofactors of the last row. The cofactors are
// computed once per facet (Laplace expansion with memoised minors, geometry/minors.hpp), so a
// point costs O(d). The error bounds follow geometry/error_bound.hpp (Higham's model); the
// box bound is derived next to its code.
//
// Underflow. Each facet row f_i - f_0 is scaled by a power of two (exact; it multiplies D by a
// positive constant, so no sign changes) to make its largest entry lie in [1/2, 1). Then no
// intermediate value of the cofactors exceeds d!, an underflowing product errs by at most
// 2^-1074 and is never magnified afterwards, so the cofactors' absolute underflow error is far
// below 2^-1000; flooring their absolute trees at 2^-1000 folds it into the relative bound.
// The last level (products with x - f_0) is covered by certified_sign's refusal to decide
// when the absolute tree is below 2^-900.
#pragma once

#include <optional>
#include <vector>

#include "geometry/minors.hpp"

namespace drange::check {

class FacetPlane {
 public:
  explicit FacetPlane(int dim);

  // Sets the facet: `dim` points (the pointers are kept; the points must outlive the use).
  void set(const double* const* facet);

  // The exact sign of D(x).
  int side(const double* x);
  // The sign of D(x) if the filter proves it, else 0.
  int filtered_side(const double* x) const;
  // The exact sign of D at the average of `count` points (D is affine: the sign of the sum of
  // D(p_i)); used for centroids, which are rational, not double.
  int side_of_average(const double* const* p, int count);
  // False only if the filter proves that no x in the box [lo, hi] has outer * D(x) > 0.
  bool box_may_reach(const double* lo, const double* hi, int outer) const;

 private:
  // value = D(x) in floating point, abs_tree its absolute-value tree.
  void evaluate(const double* x, double& value, double& abs_tree) const;
  int exact_side(const double* x);

  int dim_;
  std::optional<geometry::MinorTable> minors_;  // absent when dim is too large for the filter
  bool filter_ = false;                         // the current facet's cofactors are usable
  std::vector<double> cofactor_;      // C_j, sign included
  std::vector<double> abs_cofactor_;  // the absolute-value tree of C_j
  std::vector<double> row_;
  std::vector<const double*> corners_;  // the facet's points, then one slot for the query point
};

}  // namespace drange::check
