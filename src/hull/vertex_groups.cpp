// hull/vertex_groups.cpp: the dual hull's facets grouped by the vertex of the halfspace
// intersection they stand for, exactly on the halfspaces (drange/hull.hpp).
#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "drange/errors.hpp"
#include "drange/hull.hpp"
#include "geometry/predicates.hpp"
#include "util/union_find.hpp"

namespace drange {

std::vector<std::int32_t> vertex_groups(PointsView halfspaces, const ConvexHull& dual) {
  const int d = dual.dim;
  if (halfspaces.dim != d + 1 || halfspaces.n != dual.num_points)
    throw UsageError("the halfspaces (" + std::to_string(halfspaces.n) + " rows of " + std::to_string(halfspaces.dim) +
                     ") are not those of the dual hull (" + std::to_string(dual.num_points) + " points in " +
                     std::to_string(d) + "D)");
  util::UnionFind groups(dual.size());
  // det[[A_i, b_i]] over d+1 halfspaces: the d of a facet (independent: their dual points span
  // a hyperplane that misses the origin) and one more, which passes through their common point
  // exactly when the determinant vanishes.
  const std::array<double, kMaxDimension + 1> origin{};
  const geometry::Frame frame{d + 1, d + 1, nullptr, origin.data()};
  std::array<const double*, kMaxDimension + 1> rows{};
  for (std::size_t f = 0; f < dual.size(); ++f) {
    const std::int32_t* v = dual.facet(f);
    for (int k = 0; k < d; ++k) {
      const auto g = static_cast<std::size_t>(dual.neighbors[f * static_cast<std::size_t>(d) + static_cast<std::size_t>(k)]);
      if (g < f) continue;  // each pair once
      const std::int32_t* w = dual.facet(g);
      std::int32_t extra = -1;  // g's halfspace that is not f's
      for (int j = 0; j < d; ++j)
        if (std::find(v, v + d, w[j]) == v + d) extra = w[j];
      for (int r = 0; r < d; ++r) rows[static_cast<std::size_t>(r)] = halfspaces.point(static_cast<std::size_t>(v[r]));
      rows[static_cast<std::size_t>(d)] = halfspaces.point(static_cast<std::size_t>(extra));
      if (geometry::orientation(frame, rows.data()) == 0) groups.unite(f, g);
    }
  }
  std::vector<std::int32_t> result(dual.size());
  for (std::size_t f = 0; f < dual.size(); ++f) result[f] = static_cast<std::int32_t>(groups.find(f));
  return result;
}

}  // namespace drange
