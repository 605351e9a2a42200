// voronoi/cell_volumes.cpp: the volume of every bounded Voronoi cell, in any dimension.
//
// The cell of an interior point p is cut into simplices by its faces' "flags": for a
// Delaunay simplex S around p and an order v_1..v_d of S's other vertices, the faces
// F_0 = {p} < F_1 = {p, v_1} < ... < F_d = S have circumcentres c_0 = p, c_1, ..., c_d
// (c_k: the point of F_k's affine hull equidistant from its vertices), and the simplex
// [c_0, ..., c_d] is one piece. The steps u_k = c_k - c_{k-1} are mutually orthogonal, so the
// piece's volume is |u_1| ... |u_d| / d!, taken with the sign of u_k . (v_k - p) at each step:
// this is the pyramid formula vol(P) = (1/k) sum over P's facets of height * facet volume,
// applied recursively to the cell, its ridges, and so on down to the Voronoi edges, with
// signed heights so that a circumcentre outside its face still counts right. Summed over
// all flags of all simplices around p it is the cell's volume; on cospherical input the
// pieces of a degenerate face cancel (their heights have opposite signs).
//
// Per simplex: the circumcentres of all its 2^(d+1) faces, then for each interior vertex a
// sum over the subsets of the other vertices (2^d partial sums), not over the d! orders.
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "voronoi/circumcentre.hpp"
#include "voronoi/diagram_parts.hpp"

namespace drange::diagram {
namespace {

// Marks the points on the convex hull: those of a facet without neighbour.
std::vector<char> hull_points(const Triangulation& t) {
  std::vector<char> on_hull(t.num_points, 0);
  const int width = t.dim + 1;
  for (std::size_t s = 0; s < t.size(); ++s)
    for (int k = 0; k < width; ++k)
      if (t.neighbors[s * static_cast<std::size_t>(width) + static_cast<std::size_t>(k)] < 0)
        for (int j = 0; j < width; ++j)
          if (j != k) on_hull[static_cast<std::size_t>(t.simplex(s)[j])] = 1;
  return on_hull;
}

}  // namespace

void compute_cell_volumes(PointsView points, const Triangulation& t, Voronoi& out) {
  const int d = t.dim;
  const int width = d + 1;
  const std::size_t subsets = std::size_t{1} << width;
  const std::vector<char> on_hull = hull_points(t);

  double factorial = 1;
  for (int k = 2; k <= d; ++k) factorial *= k;

  std::vector<double> volume(t.num_points, 0.0);
  // The circumcentre of face `mask`, as an offset from the simplex's first vertex, and the
  // partial sums, in long double: the signed pieces of a far-reaching cell cancel.
  std::vector<long double> centre(subsets * static_cast<std::size_t>(d));
  std::vector<long double> partial(subsets);
  std::vector<const double*> corners(static_cast<std::size_t>(width)), face(static_cast<std::size_t>(width));

  for (std::size_t s = 0; s < t.size(); ++s) {
    const std::int32_t* row = t.simplex(s);
    bool any_interior = false;
    for (int k = 0; k < width; ++k) any_interior |= !on_hull[static_cast<std::size_t>(row[k])];
    if (!any_interior) continue;
    for (int k = 0; k < width; ++k) corners[static_cast<std::size_t>(k)] = points.point(static_cast<std::size_t>(row[k]));
    for (std::size_t mask = 1; mask < subsets; ++mask) {
      int n = 0;
      for (int k = 0; k < width; ++k)
        if (mask >> k & 1) face[static_cast<std::size_t>(n++)] = corners[static_cast<std::size_t>(k)];
      face_circumcentre(d, n - 1, face.data(), corners[0], centre.data() + mask * static_cast<std::size_t>(d));
    }
    for (int i = 0; i < width; ++i) {
      if (on_hull[static_cast<std::size_t>(row[i])]) continue;
      const long double* p = centre.data() + (std::size_t{1} << i) * static_cast<std::size_t>(d);
      std::fill(partial.begin(), partial.end(), 0.0);
      partial[std::size_t{1} << i] = 1;
      // Masks holding i, in increasing order: every subset comes before its supersets.
      for (std::size_t mask = std::size_t{1} << i; mask < subsets; ++mask) {
        if (!(mask >> i & 1) || partial[mask] == 0) continue;
        const long double* from = centre.data() + mask * static_cast<std::size_t>(d);
        for (int j = 0; j < width; ++j) {
          if (mask >> j & 1) continue;
          const std::size_t next = mask | std::size_t{1} << j;
          const long double* to = centre.data() + next * static_cast<std::size_t>(d);
          const long double* v = centre.data() + (std::size_t{1} << j) * static_cast<std::size_t>(d);
          long double length2 = 0, toward = 0;
          for (int k = 0; k < d; ++k) {
            const long double u = to[k] - from[k];
            length2 += u * u;
            toward += u * (v[k] - p[k]);
          }
          const long double height = toward >= 0 ? std::sqrt(length2) : -std::sqrt(length2);
          partial[next] += partial[mask] * height;
        }
      }
      volume[static_cast<std::size_t>(row[i])] += static_cast<double>(partial[subsets - 1] / factorial);
    }
  }

  out.volumes.resize(out.region_point.size());
  for (std::size_t r = 0; r < out.region_point.size(); ++r) {
    const auto p = static_cast<std::size_t>(out.region_point[r]);
    out.volumes[r] = on_hull[p] ? std::numeric_limits<double>::infinity() : volume[p];
  }
}

}  // namespace drange::diagram
