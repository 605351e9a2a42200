// geometry/wide_determinant.hpp: the exact stage of the small predicates in fixed-width
// integers (wide_integer.hpp), before GMP.
//
// Coordinates that no small power of two divides (0.1 k, the decimal grids of most real data;
// the cosines of a cylindrical grid) pass every floating-point filter at each tie, and GMP
// then costs several thousand instructions per determinant, mostly in calls, sizes and
// Bareiss' exact divisions. Here the same exact value (every coordinate an integer in the
// points' common unit, as in exact_matrix.hpp) is expanded by minors in integers whose widths
// the formula fixes: 64-bit differences, 128-bit 2 x 2 minors and lifts, 192 to 576 bits above
// them (up to the 7 x 7 lifted determinant of 6D; from 6D the minors come from a table over
// column sets, up to 5D from expansions written out). That needs each difference from the base
// point below 2^62 in the common unit (the points of a determinant are near each other: 0.01 k
// near 5 differ by about 2^55 units of 0.01's last bit), and 2^-unit a normal double. The
// signs are exact: tests/wide_determinant_test.cpp checks them against GMP's.
#pragma once

#include <optional>

#include "geometry/predicates.hpp"
#include "geometry/wide_integer.hpp"

namespace drange::geometry {

// The sign of orientation's determinant (predicates.hpp) for k <= 6, exactly; nullopt when a
// difference is too large in the common unit (or k > 6).
std::optional<int> wide_orientation(const Frame& frame, const double* const* points);
// The sign of lifted_sign's determinant, unperturbed, for k = 2 to 6 in at most 6 ambient
// dimensions, exactly; nullopt otherwise.
std::optional<int> wide_lifted_sign(const Frame& frame, const double* const* points);

// wide_lifted_sign in 3D to 6D for many last points x against the same first dim rows (a
// candidate's sphere, tested against each point that its filters leave): the cofactors along
// x's row computed once, in the rows' common unit, then each x is a dot product. (In 2D the
// whole 3 x 3 determinant costs less than the cofactors: measured, a 2D decimal grid +6%.)
class WideLiftedCofactors {
 public:
  static constexpr int kMaxDim = 6;
  // The cofactors of the first dim of the dim + 1 rows that `points` will hold, frame.base
  // included (frame.dim = frame.k = 3 to 6, all axes); false when they do not fit or in
  // another frame.
  bool prepare(const Frame& frame, const double* const* points);
  // The sign with x as the last row, the same as wide_lifted_sign's; nullopt when x needs a
  // finer unit than the rows (a lower set bit) or its difference does not fit.
  std::optional<int> sign_with(const double* x) const;

 private:
  template <int D>
  bool prepare_fixed(const Frame& frame, const double* const* points);
  void prepare4(const std::int64_t (*x)[kMaxDim], const Int128* lift);
  void prepare5(const std::int64_t (*x)[kMaxDim], const Int128* lift);
  template <int D>
  std::optional<int> sign_with_fixed(const double* x) const;

  int dim_ = 0;
  int unit_ = 0;
  double base_[kMaxDim] = {};
  double inverse_ = 1.0;  // 2^-unit_
  // The cofactors of x's spatial entries and of its lift, signs folded in: det = sum_c x_c
  // spatial_[c] + |x - base|^2 lift_. In 3D below 2^253 and 2^189, in 4D below 2^317 and 2^253.
  Wide<4> spatial3_[3] = {};
  Wide<3> lift3_ = {};
  Wide<5> spatial4_[4] = {};
  Wide<4> lift4_ = {};
  // In 5D below 2^382 and 2^318; in 6D below 2^446.1 and 2^381.5.
  Wide<6> spatial5_[5] = {};
  Wide<5> lift5_ = {};
  Wide<7> spatial6_[6] = {};
  Wide<7> lift6_ = {};
};

}  // namespace drange::geometry
