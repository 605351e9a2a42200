// delaunay/incremental/cell_predicates.hpp: the two exact questions the incremental kernel asks
// of a cell, in the perturbed geometry of the direct search, so that both give one triangulation.
//
// * Which side of a facet a point is on: the orientation of the cell with the point in place
//   of the facet's opposite vertex. Exact and unperturbed, as the search's open-side test.
// * Whether a point is in conflict with a cell: strictly inside a finite cell's circumsphere
//   under the symbolic perturbation of the lifted coordinate (lifted_sign_perturbed, the
//   search's own tie-breaking); for an infinite cell, strictly beyond its hull facet, or on
//   that facet's hyperplane and inside the facet's circumsphere within it. The last case is
//   asked of the finite cell across the hull facet: for a point q on the hyperplane H of a
//   facet F and any point a off H, the sphere through F and a meets H in F's circumsphere, and
//   the perturbed determinant of (F, a, q) has the sign of F and q's perturbed determinant
//   within H whatever a is (the term of a's perturbation has the coefficient
//   orientation(F, q) = 0). So a point on a hull hyperplane conflicts with the infinite cell
//   exactly when it conflicts with the finite cell across, and the cavity stays star-shaped.
//
// For the furthest-site triangulation (the upper hull of the lifted points, which is the lower
// hull of the points lifted by -|x|^2) the lifted determinant's sign is reversed: a point is in
// conflict with a finite cell when it is strictly outside its circumsphere. Everything else,
// the argument above included, holds with the lift negated.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "delaunay/incremental/cell_complex.hpp"
#include "delaunay/incremental/kernel_points.hpp"
#include "geometry/error_bound.hpp"
#include "geometry/predicates.hpp"
#include "geometry/refined_sign.hpp"

namespace drange::engine {

class CellPredicates {
 public:
  CellPredicates(const KernelPoints& points, const CellComplex& cells, bool furthest_site)
      : points_(points), cells_(cells), d_(points.dim), conflict_sign_(furthest_site ? 1 : -1),
        rows_(static_cast<std::size_t>(points.dim + 2)), ranks_(static_cast<std::size_t>(points.dim + 2)) {}

  // Sign of the orientation of finite cell c with q in place of vertex k: negative exactly when
  // q is strictly beyond the facet opposite vertex k.
  int side(std::int32_t c, int k, std::int32_t q) {
    const std::int32_t* v = cells_.vertices(c);
    for (int i = 0; i <= d_; ++i) rows_[static_cast<std::size_t>(i)] = points_.point(i == k ? q : v[i]);
    if (points_.scaled && d_ <= 3) {
      const int s = d_ == 2 ? filtered_orientation<2>() : filtered_orientation<3>();
      if (s != 0) return s;
    }
    ++unfiltered_;
    const geometry::Frame frame{d_, d_, nullptr, rows_[0]};
    // Double-double first: points within rounding of a hyperplane, not on it, are decided there.
    if (const std::optional<int> s = geometry::refined_orientation(frame, rows_.data() + 1)) return *s;
    return geometry::orientation(frame, rows_.data() + 1);
  }

  bool in_conflict(std::int32_t c, std::int32_t q) {
    const int infinite = cells_.infinite_position(c);
    if (infinite < 0) return finite_conflict(c, q);
    // q in kInfinite's place: positive when q is strictly beyond the hull facet.
    const int s = side(c, infinite, q);
    if (s != 0) return s > 0;
    return finite_conflict(cells_.neighbors(c)[infinite], q);
  }

  // Whether q is in conflict with finite cell c: strictly inside its circumsphere under the
  // perturbation (strictly outside for the furthest site). The cell is positively oriented, so
  // inside is a negative lifted determinant (geometry::in_sphere).
  bool finite_conflict(std::int32_t c, std::int32_t q) {
    const std::int32_t* v = cells_.vertices(c);
    for (int i = 0; i <= d_; ++i) rows_[static_cast<std::size_t>(i)] = points_.point(v[i]);
    rows_[static_cast<std::size_t>(d_ + 1)] = points_.point(q);
    if (points_.scaled && d_ <= 3) {
      const int s = d_ == 2 ? filtered_lifted_sign<2>() : filtered_lifted_sign<3>();
      if (s != 0) return s == conflict_sign_;
    }
    ++unfiltered_;
    const geometry::Frame frame{d_, d_, nullptr, rows_[0]};
    // Double-double first: points within rounding of a sphere, not on it (circles, spheres,
    // rings of a mesh), are decided there; ties go on to the exact stages and the perturbation.
    if (const std::optional<int> s = geometry::refined_lifted_sign(frame, rows_.data() + 1); s && *s != 0) return *s == conflict_sign_;
    // The ranks only now: the perturbation needs them, and each is a read far from the cell.
    for (int i = 0; i <= d_; ++i) ranks_[static_cast<std::size_t>(i)] = points_.rank(v[i]);
    ranks_[static_cast<std::size_t>(d_ + 1)] = points_.rank(q);
    return geometry::lifted_sign_perturbed(frame, rows_.data() + 1, ranks_.data()) == conflict_sign_;
  }

  // Tests that the fast filters did not decide (or that had none: d > 3, unscaled points),
  // left to the generic predicates' stages.
  std::uint64_t unfiltered() const { return unfiltered_; }

 private:
  // The orientation of rows_[0..D] in doubles (det[p_1 - p_0; ...; p_D - p_0]), for D = 2 and
  // 3, and its sign when the forward error bound certifies it, else 0. Only for scaled points.
  template <int D>
  int filtered_orientation() const {
    double a[D][D];
    const double* base = rows_[0];
    for (int r = 0; r < D; ++r)
      for (int c = 0; c < D; ++c) a[r][c] = rows_[static_cast<std::size_t>(r + 1)][c] - base[c];
    double value = 0.0, tree = 0.0;
    if constexpr (D == 2) {
      value = a[0][0] * a[1][1] - a[0][1] * a[1][0];
      tree = std::fabs(a[0][0] * a[1][1]) + std::fabs(a[0][1] * a[1][0]);
    } else {
      const double m0 = a[1][1] * a[2][2] - a[1][2] * a[2][1], n0 = std::fabs(a[1][1] * a[2][2]) + std::fabs(a[1][2] * a[2][1]);
      const double m1 = a[1][0] * a[2][2] - a[1][2] * a[2][0], n1 = std::fabs(a[1][0] * a[2][2]) + std::fabs(a[1][2] * a[2][0]);
      const double m2 = a[1][0] * a[2][1] - a[1][1] * a[2][0], n2 = std::fabs(a[1][0] * a[2][1]) + std::fabs(a[1][1] * a[2][0]);
      value = a[0][0] * m0 - a[0][1] * m1 + a[0][2] * m2;
      tree = std::fabs(a[0][0]) * n0 + std::fabs(a[0][1]) * n1 + std::fabs(a[0][2]) * n2;
    }
    constexpr double gamma = geometry::gamma_bound(geometry::laplace_roundings(D, 1));
    return geometry::certified_sign_with(value, tree, gamma);
  }

  // The lifted determinant of rows_ (base rows_[0], the others relative to it, the squared
  // distance last: geometry::lifted_sign's matrix) in doubles, for D = 2 and 3, and its sign
  // when the forward error bound certifies it (error_bound.hpp), else 0. Only for scaled
  // points, whose underflow the bound's floor absorbs (PointStore::scaled).
  template <int D>
  int filtered_lifted_sign() const {
    constexpr int N = D + 1;
    double a[N][N];
    const double* base = rows_[0];
    for (int r = 0; r < N; ++r) {
      const double* p = rows_[static_cast<std::size_t>(r + 1)];
      double lift = 0.0;
      for (int c = 0; c < D; ++c) {
        a[r][c] = p[c] - base[c];
        lift += a[r][c] * a[r][c];
      }
      a[r][D] = lift;
    }
    double value = 0.0, tree = 0.0;
    if constexpr (D == 2) {
      const double m0 = a[1][1] * a[2][2] - a[1][2] * a[2][1], n0 = std::fabs(a[1][1] * a[2][2]) + std::fabs(a[1][2] * a[2][1]);
      const double m1 = a[1][0] * a[2][2] - a[1][2] * a[2][0], n1 = std::fabs(a[1][0] * a[2][2]) + std::fabs(a[1][2] * a[2][0]);
      const double m2 = a[1][0] * a[2][1] - a[1][1] * a[2][0], n2 = std::fabs(a[1][0] * a[2][1]) + std::fabs(a[1][1] * a[2][0]);
      value = a[0][0] * m0 - a[0][1] * m1 + a[0][2] * m2;
      tree = std::fabs(a[0][0]) * n0 + std::fabs(a[0][1]) * n1 + std::fabs(a[0][2]) * n2;
    } else {
      // Laplace along the first two rows: each 2 x 2 minor of rows 0 and 1 times the
      // complementary minor of rows 2 and 3.
      const auto minor = [&](int r, int i, int j) { return a[r][i] * a[r + 1][j] - a[r][j] * a[r + 1][i]; };
      const auto tree2 = [&](int r, int i, int j) { return std::fabs(a[r][i] * a[r + 1][j]) + std::fabs(a[r][j] * a[r + 1][i]); };
      value = minor(0, 0, 1) * minor(2, 2, 3) - minor(0, 0, 2) * minor(2, 1, 3) + minor(0, 0, 3) * minor(2, 1, 2) +
              minor(0, 1, 2) * minor(2, 0, 3) - minor(0, 1, 3) * minor(2, 0, 2) + minor(0, 2, 3) * minor(2, 0, 1);
      tree = tree2(0, 0, 1) * tree2(2, 2, 3) + tree2(0, 0, 2) * tree2(2, 1, 3) + tree2(0, 0, 3) * tree2(2, 1, 2) +
             tree2(0, 1, 2) * tree2(2, 0, 3) + tree2(0, 1, 3) * tree2(2, 0, 2) + tree2(0, 2, 3) * tree2(2, 0, 1);
    }
    constexpr double gamma = geometry::gamma_bound(geometry::laplace_roundings(N, geometry::lifted_entry_roundings(D)));
    return geometry::certified_sign_with(value, tree, gamma);
  }

  const KernelPoints& points_;
  const CellComplex& cells_;
  int d_;
  int conflict_sign_;  // the lifted determinant's sign for a point in conflict with a finite cell
  std::vector<const double*> rows_;
  std::vector<std::int64_t> ranks_;
  std::uint64_t unfiltered_ = 0;
};

}  // namespace drange::engine
