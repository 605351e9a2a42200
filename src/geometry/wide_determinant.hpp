// geometry/wide_determinant.hpp: the exact stage of the small predicates in fixed-width
// integers (wide_integer.hpp), before GMP.
//
// Coordinates that no small power of two divides (0.1 k, the decimal grids of most real data;
// the cosines of a cylindrical grid) pass every floating-point filter at each tie, and GMP
// then costs several thousand instructions per determinant, mostly in calls, sizes and
// Bareiss' exact divisions. Here the same exact value (every coordinate an integer in the
// points' common unit, as in exact_matrix.hpp) is expanded by minors in integers whose widths
// the formula fixes: 64-bit differences, 128-bit 2 x 2 minors and lifts, 192 to 640 bits above
// them (up to the 8 x 8 lifted determinant of 7D; the 5D to 7D lifted cofactors and the 6D and
// 7D orientation cofactors come from tables of minors over column sets, the rest from
// expansions written out). 8D stays with GMP: its lifts, 8 squares below 2^124, would not fit
// 128 bits. That needs each difference from the base point below 2^62 in the common unit (the
// points of a determinant are near each other: 0.01 k near 5 differ by about 2^55 units of
// 0.01's last bit), and 2^-unit a normal double. The signs are exact:
// tests/wide_determinant_test.cpp checks them against GMP's.
#pragma once

#include <optional>

#include "geometry/predicates.hpp"
#include "geometry/wide_integer.hpp"

namespace drange::geometry {

// The sign of orientation's determinant (predicates.hpp) for k <= 7, exactly; nullopt when a
// difference is too large in the common unit (or k > 7).
std::optional<int> wide_orientation(const Frame& frame, const double* const* points);
// The sign of lifted_sign's determinant, unperturbed, for k = 2 to 4 in at most 6 ambient
// dimensions and for k = dim = 5 to 7, exactly; nullopt otherwise.
std::optional<int> wide_lifted_sign(const Frame& frame, const double* const* points);

// wide_lifted_sign in 3D to 7D for many last points x against the same first dim rows (a
// candidate's sphere, tested against each point that its filters leave): the cofactors along
// x's row computed once, in the rows' common unit, then each x is a dot product. (In 2D the
// whole 3 x 3 determinant costs less than the cofactors, as measured on a 2D decimal grid.)
class WideLiftedCofactors {
 public:
  static constexpr int kMaxDim = 7;
  // The cofactors of the first dim of the dim + 1 rows that `points` will hold, frame.base
  // included (frame.dim = frame.k = 3 to 7, all axes); false when they do not fit or in
  // another frame.
  bool prepare(const Frame& frame, const double* const* points);
  // The sign with x as the last row, the same as wide_lifted_sign's; nullopt when x needs a
  // finer unit than the rows (a lower set bit) or its difference does not fit.
  std::optional<int> sign_with(const double* x) const;

 private:
  template <int D>
  bool prepare_fixed(const Frame& frame, const double* const* points);
  // 6D and 7D: from a table of minors over column sets.
  template <int D, int L>
  static void table_cofactors(const std::int64_t (*x)[kMaxDim], const Int128* lift, Wide<L> (&spatial)[D], Wide<L>& lift_cofactor);
  // 5D to 7D: the same from the facet's levels (the first dim - 1 rows), kept for the next
  // candidate of the same facet; false where the candidate needs a finer unit than the facet's
  // rows (then the whole table, or prepare5, in the common unit).
  template <int D>
  bool prepare_from_facet(const Frame& frame, const double* const* points);
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
  Wide<6> lift5_ = {};  // in 6 limbs as spatial5_, so that a table's level fills both
  Wide<7> spatial6_[6] = {};
  Wide<7> lift6_ = {};
  // In 7D below 2^511.1 and 2^446.3.
  Wide<9> spatial7_[7] = {};
  Wide<9> lift7_ = {};
  // prepare_from_facet's facet: its base and rows' coordinates, unit, and the table's level
  // dim - 1 over its rows (uninitialised: large, and read only once written). facet_dim_ 0:
  // none yet.
  int facet_dim_ = 0;
  double facet_key_[kMaxDim][kMaxDim] = {};
  bool facet_fits_ = false;
  int facet_unit_ = 0;
  double facet_inverse_ = 1.0;
  Wide<7> facet7_[1 << 8];  // 7D: the 6 x 6 minors over 8 columns
  Wide<6> facet6_[1 << 7];  // 6D: the 5 x 5 minors over 7 columns
  Wide<5> facet5_[1 << 6];  // 5D: the 4 x 4 minors over 6 columns
};

// wide_orientation in 6D and 7D for many last points x against the same first dim - 1 rows (a
// facet's hyperplane, tested against each point that its filters leave, which on a grid's
// hyperplanes are many): the cofactors along x's row computed once, from a table of minors,
// then each x is a dot product. (The perturbation's orientations share rows too: predicates.cpp
// keeps their cofactors in a small cache.)
class WideOrientationCofactors {
 public:
  static constexpr int kMinDim = 6, kMaxDim = 7;
  // The cofactors of the first dim - 1 rows of `points`, frame.base included (frame.dim =
  // frame.k = 6 or 7, all axes); false when they do not fit or in another frame.
  bool prepare(const Frame& frame, const double* const* points);
  // The sign with x as the last row, the same as wide_orientation's; nullopt when x needs a
  // finer unit than the rows or its difference does not fit.
  std::optional<int> sign_with(const double* x) const;

 private:
  template <int D>
  bool prepare_fixed(const Frame& frame, const double* const* points);

  int dim_ = 0;
  int unit_ = 0;
  double base_[kMaxDim] = {};
  double inverse_ = 1.0;  // 2^-unit_
  // The cofactor of x's entry c, its sign folded in: (dim - 1) x (dim - 1) minors, in 7D below
  // 6! 2^372 < 2^381.5.
  Wide<7> cofactors_[kMaxDim] = {};
};

}  // namespace drange::geometry
