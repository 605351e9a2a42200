// hull/initial_simplex.cpp: the first simplex by farthest points, confirmed exactly.
#include "hull/initial_simplex.hpp"

#include <gmpxx.h>

#include <array>
#include <cmath>
#include <string>

#include "drange/errors.hpp"
#include "geometry/predicates.hpp"

namespace drange::hull {
namespace {

bool lexicographically_less(const double* x, const double* y, int d) {
  for (int k = 0; k < d; ++k)
    if (x[k] != y[k]) return x[k] < y[k];
  return false;
}

// Exact affine independence of points, by elimination over the rationals: an echelon basis of
// the differences from the first point.
class ExactSpan {
 public:
  ExactSpan(const double* origin, int d) : origin_(origin), d_(d) {}
  // Whether x is off the affine hull of the points so far; adds it when it is.
  bool add_if_independent(const double* x) {
    std::vector<mpq_class> v(static_cast<std::size_t>(d_));
    for (int k = 0; k < d_; ++k) v[static_cast<std::size_t>(k)] = mpq_class(x[k]) - mpq_class(origin_[k]);
    for (std::size_t b = 0; b < basis_.size(); ++b) {
      const auto c = static_cast<std::size_t>(pivots_[b]);
      if (v[c] == 0) continue;
      const mpq_class factor = v[c] / basis_[b][c];
      for (std::size_t k = 0; k < v.size(); ++k) v[k] -= factor * basis_[b][k];
    }
    for (int k = 0; k < d_; ++k)
      if (v[static_cast<std::size_t>(k)] != 0) {
        pivots_.push_back(k);
        basis_.push_back(std::move(v));
        return true;
      }
    return false;
  }
  int rank() const { return static_cast<int>(basis_.size()); }

 private:
  const double* origin_;
  int d_;
  std::vector<std::vector<mpq_class>> basis_;
  std::vector<int> pivots_;
};

// The squared distance of x from the affine hull of the chosen points, in floating point:
// the residual of x - origin after its components along the orthonormal `directions`.
double residual2(const double* x, const double* origin, const std::vector<std::vector<double>>& directions, int d,
                 double* residual) {
  for (int k = 0; k < d; ++k) residual[k] = x[k] - origin[k];
  for (const std::vector<double>& u : directions) {
    double dot = 0.0;
    for (int k = 0; k < d; ++k) dot += u[static_cast<std::size_t>(k)] * residual[k];
    for (int k = 0; k < d; ++k) residual[k] -= dot * u[static_cast<std::size_t>(k)];
  }
  double sum = 0.0;
  for (int k = 0; k < d; ++k) sum += residual[k] * residual[k];
  return sum;
}

// Whether `interior` is strictly inside the simplex: on the same side of each facet as the
// vertex opposite it.
bool strictly_inside(PointsView points, const std::vector<std::int32_t>& ids, const double* interior, int orientation) {
  const int d = points.dim;
  for (int i = 0; i <= d; ++i) {
    std::array<const double*, kMaxDimension + 1> rows{};
    for (int k = 0; k <= d; ++k) rows[static_cast<std::size_t>(k)] = k == i ? interior : points.point(static_cast<std::size_t>(ids[static_cast<std::size_t>(k)]));
    if (geometry::orientation(geometry::Frame{d, d, nullptr, rows[0]}, rows.data() + 1) != orientation) return false;
  }
  return true;
}

}  // namespace

InitialSimplex initial_simplex(PointsView points, const std::string& structure) {
  const int d = points.dim;
  const auto n = static_cast<std::int32_t>(points.n);
  const auto at = [&](std::int32_t id) { return points.point(static_cast<std::size_t>(id)); };
  std::int32_t first = 0;
  for (std::int32_t id = 1; id < n; ++id)
    if (lexicographically_less(at(id), at(first), d)) first = id;
  InitialSimplex simplex;
  simplex.ids.push_back(first);
  ExactSpan span(at(first), d);
  std::vector<std::vector<double>> directions;
  std::vector<double> residual(static_cast<std::size_t>(d));
  while (span.rank() < d) {
    std::int32_t best = -1;
    double best_distance = 0.0;
    for (std::int32_t id = 0; id < n; ++id) {
      const double distance = residual2(at(id), at(first), directions, d, residual.data());
      if (distance > best_distance || (distance == best_distance && best >= 0 && distance > 0 &&
                                       lexicographically_less(at(id), at(best), d))) {
        best = id;
        best_distance = distance;
      }
    }
    if (best < 0 || !span.add_if_independent(at(best))) {
      // Rounding chose a point in the span, or saw every point in it: scan exactly.
      best = -1;
      for (std::int32_t id = 0; id < n && best < 0; ++id)
        if (span.add_if_independent(at(id))) best = id;
      if (best < 0)
        throw DegenerateInputError("all " + std::to_string(points.n) + " points lie in an affine subspace of dimension " +
                                   std::to_string(span.rank()) + "; " + structure + " in " + std::to_string(d) +
                                   " dimensions needs points that span " + std::to_string(d) + " dimensions");
    }
    simplex.ids.push_back(best);
    residual2(at(best), at(first), directions, d, residual.data());
    double norm = 0.0;
    for (const double r : residual) norm += r * r;
    norm = std::sqrt(norm);
    for (double& r : residual) r /= norm;
    directions.push_back(residual);
  }
  // The interior point: the centroid, when rounding leaves it strictly inside.
  std::array<const double*, kMaxDimension + 1> rows{};
  for (int k = 0; k <= d; ++k) rows[static_cast<std::size_t>(k)] = at(simplex.ids[static_cast<std::size_t>(k)]);
  const int orientation = geometry::orientation(geometry::Frame{d, d, nullptr, rows[0]}, rows.data() + 1);
  simplex.interior.assign(static_cast<std::size_t>(d), 0.0);
  for (int k = 0; k < d; ++k) {
    double sum = 0.0;
    for (int i = 0; i <= d; ++i) sum += rows[static_cast<std::size_t>(i)][k];
    simplex.interior[static_cast<std::size_t>(k)] = sum / (d + 1);
  }
  if (!strictly_inside(points, simplex.ids, simplex.interior.data(), orientation)) simplex.interior.clear();
  return simplex;
}

}  // namespace drange::hull
