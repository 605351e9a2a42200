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
//
// In 2D and 3D the ridges are known polygons (segments; cyclic polygons), so the cell is
// the union of the pyramids from p over its ridges: vol = (1/d) sum |pq|/2 * area(ridge),
// positive terms only, and much cheaper.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "voronoi/diagram_parts.hpp"

namespace drange::diagram {
namespace {

// Double suffices: every centre is an offset from its simplex's first vertex, so no digits
// go to a far origin (checked against an exact rational volume on far, huge 4D cells:
// 3e-13 relative), and x87 long double made this loop three times slower.
using Real = double;

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

// The (d-1)-measure of a bounded ridge: a segment's length (2D) or a planar polygon's area
// (3D; its vertices in cyclic order).
double ridge_measure(const Voronoi& v, std::size_t r) {
  const std::int32_t* ids = v.ridge_vertices.row(r);
  const std::size_t n = v.ridge_vertices.row_size(r);
  const double* o = v.vertex(static_cast<std::size_t>(ids[0]));
  if (v.dim == 2) {
    const double* a = v.vertex(static_cast<std::size_t>(ids[n - 1]));
    return std::hypot(a[0] - o[0], a[1] - o[1]);
  }
  Real normal[3] = {0, 0, 0};
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double* a = v.vertex(static_cast<std::size_t>(ids[i]));
    const double* b = v.vertex(static_cast<std::size_t>(ids[i + 1]));
    const Real u[3] = {(Real)a[0] - o[0], (Real)a[1] - o[1], (Real)a[2] - o[2]};
    const Real w[3] = {(Real)b[0] - o[0], (Real)b[1] - o[1], (Real)b[2] - o[2]};
    normal[0] += u[1] * w[2] - u[2] * w[1];
    normal[1] += u[2] * w[0] - u[0] * w[2];
    normal[2] += u[0] * w[1] - u[1] * w[0];
  }
  return static_cast<double>(std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]) / 2);
}

// 2D and 3D: pyramids from each point over its ridges.
std::vector<double> volumes_from_ridges(PointsView points, const Voronoi& v) {
  std::vector<double> volume(points.n, 0.0);
  for (std::size_t r = 0; r < v.num_ridges(); ++r) {
    const std::int32_t* ids = v.ridge_vertices.row(r);
    if (ids[0] < 0) continue;  // unbounded: both cells are unbounded
    const auto p = static_cast<std::size_t>(v.ridge_points[2 * r]);
    const auto q = static_cast<std::size_t>(v.ridge_points[2 * r + 1]);
    double distance2 = 0;
    for (int k = 0; k < v.dim; ++k) distance2 += (points.point(q)[k] - points.point(p)[k]) * (points.point(q)[k] - points.point(p)[k]);
    const double pyramid = std::sqrt(distance2) / 2 * ridge_measure(v, r) / v.dim;
    volume[p] += pyramid;
    volume[q] += pyramid;
  }
  return volume;
}

// The circumcentres of all faces of one simplex, as offsets from its first vertex. Built up face by face: adding
// vertex v to a face F moves F's centre along the unit vector e orthogonal to F's affine
// hull toward v, by t = (|c - v|^2 - |c - p0|^2) / (2 e.(v - p0)), which keeps it
// equidistant from F's vertices and makes it so from v; e extends F's orthonormal basis
// (Gram-Schmidt). O(d k) per face instead of a k x k solve.
class FaceCentres {
 public:
  explicit FaceCentres(int d)
      : d_(d), subsets_(std::size_t{1} << (d + 1)), centre_(subsets_ * static_cast<std::size_t>(d)),
        basis_(subsets_ * static_cast<std::size_t>(d * d)), corner_(static_cast<std::size_t>((d + 1) * d)) {}

  // centres()[mask * d + k]: coordinate k of the centre of the face made of the vertices in `mask`.
  const std::vector<Real>& centres() const { return centre_; }

  void compute(PointsView points, const std::int32_t* simplex) {
    const auto d = static_cast<std::size_t>(d_);
    const double* origin = points.point(static_cast<std::size_t>(simplex[0]));
    for (std::size_t i = 0; i <= d; ++i) {
      const double* p = points.point(static_cast<std::size_t>(simplex[i]));
      for (std::size_t k = 0; k < d; ++k) corner_[i * d + k] = p[k] - origin[k];
    }
    for (std::size_t mask = 1; mask < subsets_; ++mask) {
      Real* c = &centre_[mask * d];
      const int high = highest_bit(mask);
      const std::size_t rest = mask & ~(std::size_t{1} << high);
      const Real* v = &corner_[static_cast<std::size_t>(high) * d];
      if (rest == 0) {
        std::copy(v, v + d, c);
        continue;
      }
      const int rank = popcount(rest) - 1;  // rest's basis vectors
      const Real* c0 = &centre_[rest * d];
      const Real* p0 = &corner_[static_cast<std::size_t>(lowest_bit(rest)) * d];
      const Real* old_basis = &basis_[rest * d * d];
      Real* basis = &basis_[mask * d * d];
      std::copy(old_basis, old_basis + static_cast<std::size_t>(rank) * d, basis);
      Real* e = basis + static_cast<std::size_t>(rank) * d;
      for (std::size_t k = 0; k < d; ++k) e[k] = v[k] - p0[k];
      for (int b = 0; b < rank; ++b) {
        const Real* q = basis + static_cast<std::size_t>(b) * d;
        Real dot = 0;
        for (std::size_t k = 0; k < d; ++k) dot += e[k] * q[k];
        for (std::size_t k = 0; k < d; ++k) e[k] -= dot * q[k];
      }
      Real norm2 = 0;
      for (std::size_t k = 0; k < d; ++k) norm2 += e[k] * e[k];
      const Real norm = std::sqrt(norm2);
      for (std::size_t k = 0; k < d; ++k) e[k] /= norm;
      Real to_v = 0, to_p0 = 0;
      for (std::size_t k = 0; k < d; ++k) {
        to_v += (c0[k] - v[k]) * (c0[k] - v[k]);
        to_p0 += (c0[k] - p0[k]) * (c0[k] - p0[k]);
      }
      const Real step = (to_v - to_p0) / (2 * norm);
      for (std::size_t k = 0; k < d; ++k) c[k] = c0[k] + step * e[k];
    }
  }

 private:
  static int highest_bit(std::size_t x) { return 63 - __builtin_clzll(x); }
  static int lowest_bit(std::size_t x) { return __builtin_ctzll(x); }
  static int popcount(std::size_t x) { return __builtin_popcountll(x); }

  int d_;
  std::size_t subsets_;
  std::vector<Real> centre_, basis_, corner_;
};

}  // namespace

void compute_cell_volumes(PointsView points, const Triangulation& t, Voronoi& out) {
  if (t.dim <= 3) {
    const std::vector<char> on_hull = hull_points(t);
    const std::vector<double> volume = volumes_from_ridges(points, out);
    out.volumes.resize(out.region_point.size());
    for (std::size_t r = 0; r < out.region_point.size(); ++r) {
      const auto p = static_cast<std::size_t>(out.region_point[r]);
      out.volumes[r] = on_hull[p] ? std::numeric_limits<double>::infinity() : volume[p];
    }
    return;
  }
  const int d = t.dim;
  const int width = d + 1;
  const std::size_t subsets = std::size_t{1} << width;
  const std::vector<char> on_hull = hull_points(t);

  double factorial = 1;
  for (int k = 2; k <= d; ++k) factorial *= k;

  std::vector<double> volume(t.num_points, 0.0);
  FaceCentres faces(d);
  std::vector<Real> partial(subsets), height(subsets * static_cast<std::size_t>(width));

  for (std::size_t s = 0; s < t.size(); ++s) {
    const std::int32_t* row = t.simplex(s);
    bool any_interior = false;
    for (int k = 0; k < width; ++k) any_interior |= !on_hull[static_cast<std::size_t>(row[k])];
    if (!any_interior) continue;
    faces.compute(points, row);
    const std::vector<Real>& centre = faces.centres();
    // The signed height of each step mask -> mask + j. It does not depend on which vertex
    // of `mask` is the cell's point: u is orthogonal to mask's affine hull, so u.(v_j - x)
    // is the same for every x in it.
    for (std::size_t mask = 1; mask < subsets; ++mask) {
      const Real* from = centre.data() + mask * static_cast<std::size_t>(d);
      const Real* x = centre.data() + (std::size_t{1} << __builtin_ctzll(mask)) * static_cast<std::size_t>(d);
      for (int j = 0; j < width; ++j) {
        if (mask >> j & 1) continue;
        const Real* to = centre.data() + (mask | std::size_t{1} << j) * static_cast<std::size_t>(d);
        const Real* v = centre.data() + (std::size_t{1} << j) * static_cast<std::size_t>(d);
        Real length2 = 0, toward = 0;
        for (int k = 0; k < d; ++k) {
          const Real u = to[k] - from[k];
          length2 += u * u;
          toward += u * (v[k] - x[k]);
        }
        height[mask * static_cast<std::size_t>(width) + static_cast<std::size_t>(j)] =
            toward >= 0 ? std::sqrt(length2) : -std::sqrt(length2);
      }
    }
    for (int i = 0; i < width; ++i) {
      if (on_hull[static_cast<std::size_t>(row[i])]) continue;
      std::fill(partial.begin(), partial.end(), 0.0);
      partial[std::size_t{1} << i] = 1;
      // Masks holding i, in increasing order: every subset comes before its supersets.
      for (std::size_t mask = std::size_t{1} << i; mask < subsets; ++mask) {
        if (!(mask >> i & 1) || partial[mask] == 0) continue;
        for (int j = 0; j < width; ++j)
          if (!(mask >> j & 1))
            partial[mask | std::size_t{1} << j] += partial[mask] * height[mask * static_cast<std::size_t>(width) + static_cast<std::size_t>(j)];
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
