// hull/quickhull.hpp: Quickhull (Barber, Dobkin and Huhdanpaa) in E^d with exact orientations
// under the perturbation of perturbation.hpp, which makes every orientation nonzero, so the
// construction never meets a tie and builds the hull of the perturbed points: a simplicial
// polytope whose vertices are the extreme input points.
//
// Invariants, after each added point:
//   - the live facets are the boundary of the perturbed hull of the points added so far, each
//     with its vertices ordered so that the facet's orientation O(x) = det[v1 - v0; ...;
//     v(d-1) - v0; x - v0] is positive outside (a new facet keeps its visible predecessor's
//     order with the apex in the place of the vertex it replaces, which keeps that sign);
//   - neighbour k of a facet is the facet across the ridge opposite its vertex k;
//   - every point not yet decided is in the outside set of exactly one facet it lies above;
//   - every decided point that lies on the boundary of the unperturbed hull so far, and is not
//     a vertex, is in the coplanar set of exactly one facet whose hyperplane holds it, and no
//     other point is in a coplanar set. (When a facet dies, its coplanar points, its outside
//     points that end inside and its vertices that leave the hull are on the new boundary
//     exactly when a new facet's hyperplane holds them: the part of the old boundary that
//     stays, near such a point, is covered by new facets through the horizon.)
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "geometry/error_bound.hpp"
#include "geometry/minors.hpp"
#include "hull/initial_simplex.hpp"
#include "hull/perturbation.hpp"

namespace drange::hull {

struct HullFacets {
  std::vector<std::int32_t> vertices;   // d per facet, O(x) > 0 outside
  std::vector<std::int32_t> neighbors;  // d per facet, compact facet numbers
  std::vector<std::vector<std::int32_t>> coplanar;  // per facet, the coplanar points
};

class Quickhull {
 public:
  // `coords`: n*d coordinates; `filters`: the floating-point filter's bound holds for them
  // (coordinates scaled below 1 in magnitude), else every sign is exact from the start.
  Quickhull(const double* coords, std::int32_t n, int d, bool filters, InitialSimplex simplex);

  HullFacets run();

 private:
  struct Sets {
    // Undecided points above the facet, d+1 doubles each: the id, then a copy of the
    // coordinates, so that the passes over a dead facet's points read memory in order (reading
    // them by id would make most of a run's cache misses).
    std::vector<double> outside;
    std::vector<std::int32_t> coplanar;  // decided points on the facet's hyperplane
    std::int32_t farthest = -1;
    double height = 0.0;
    bool alive = true;
  };

  const double* point(std::int32_t id) const { return coords_ + static_cast<std::size_t>(id) * static_cast<std::size_t>(d_); }
  std::int32_t* vertices(std::int32_t f) { return vertices_.data() + static_cast<std::size_t>(f) * static_cast<std::size_t>(d_); }
  std::int32_t* neighbors(std::int32_t f) { return neighbors_.data() + static_cast<std::size_t>(f) * static_cast<std::size_t>(d_); }

  std::int32_t new_facet();          // a slot, reused from a dead facet when there is one
  // The filter's coefficients of O(x) for the d ids `v`: O(x) = a . (x - v0), and its absolute tree.
  void compute_normal(const std::int32_t* v, double* a, double* a_abs);
  void set_normal(std::int32_t f);   // compute_normal for a facet
  void set_row(int r, const double* row);  // row r of minors_
  // The filter's certified sign of O(x) = a . (x - v0) (0: undecided); `height` gets its
  // value. The construction's innermost loop: inline, of fixed length in 2D to 6D.
  int filter(const double* v0, const double* a, const double* a_abs, const double* p, double& height) const {
    double value = 0.0, abs_tree = 0.0;
    switch (d_) {
      case 2: dot<2>(v0, a, a_abs, p, value, abs_tree); break;
      case 3: dot<3>(v0, a, a_abs, p, value, abs_tree); break;
      case 4: dot<4>(v0, a, a_abs, p, value, abs_tree); break;
      case 5: dot<5>(v0, a, a_abs, p, value, abs_tree); break;
      case 6: dot<6>(v0, a, a_abs, p, value, abs_tree); break;
      default:
        for (int k = 0; k < d_; ++k) {
          const double delta = p[k] - v0[k];
          value += a[k] * delta;
          abs_tree += a_abs[k] * std::fabs(delta);
        }
    }
    height = value;
    return filters_ ? geometry::certified_sign_with(value, abs_tree, gamma_) : 0;
  }
  template <int D>
  static void dot(const double* v0, const double* a, const double* a_abs, const double* p, double& value, double& abs_tree) {
    for (int k = 0; k < D; ++k) {
      const double delta = p[k] - v0[k];
      value += a[k] * delta;
      abs_tree += a_abs[k] * std::fabs(delta);
    }
  }
  // The perturbed sign of O(x) for the ids v, never 0; `height` gets the filter's value, and
  // `on_plane` whether x is exactly on their hyperplane.
  // x's coordinates are at px.
  int tuple_side(const std::int32_t* v, const double* a, const double* a_abs, std::int32_t x, const double* px, double& height,
                 bool& on_plane);
  // tuple_side for facet f (+1 outside)
  int side(std::int32_t f, std::int32_t x, const double* px, double& height, bool& on_plane);
  bool on_plane(std::int32_t f, std::int32_t x);  // unperturbed O(x) == 0, exactly
  void add_outside(std::int32_t f, std::int32_t x, const double* px, double height);
  // Puts x in the outside set of the first of `facets` it lies above; else in the coplanar
  // set of the first whose hyperplane holds it; else nowhere (strictly inside).
  void assign(std::int32_t x, const double* px, const std::vector<std::int32_t>& facets);
  void keep_if_on_boundary(std::int32_t x, const std::vector<std::int32_t>& facets);
  void add_point(std::int32_t facet);
  // Places an outside point x of the dead facet `from` (an index into visible_facets_) without
  // testing it against every new facet, which in 5D and 6D are hundreds per point added.
  // Why it works: x and p both lie above `from`, so the segment from p to x misses the old
  // hull, and x is inside the new one exactly when the ray from p through x meets a visible
  // facet beyond x, i.e. when x is in the pyramid from p over some visible facet g. Seen from
  // p, the visible facets tile a convex region; the walk moves from facet to facet across the
  // ridges that x lies beyond (the hyperplane through p and the ridge), until x lies within
  // every ridge of g (inside: dropped), or beyond a horizon ridge, whose hyperplane is that of
  // the new facet on it (outside: put in its set). The ridges are tried from a random place
  // (a visibility walk can cycle in a triangulation that is not Delaunay); after as many steps
  // as there are visible facets, or at an exact tie (where coplanarity must be seen, and
  // where an inner ridge's hyperplane may pass through the interior point), it returns false
  // and the scan over the new facets decides.
  void index_horizon();  // walk_index_ and horizon_ for this addition
  bool walk(std::int32_t x, const double* px, std::int32_t from, std::int32_t p);
  void link_new_facets();  // the neighbours of created_ across the ridges through the apex

  const double* coords_;
  std::int32_t n_;
  int d_;
  bool filters_;
  double gamma_;
  InitialSimplex simplex_;
  Perturbation perturbation_;
  geometry::MinorTable minors_;

  // Per facet slot.
  std::vector<std::int32_t> vertices_, neighbors_;
  std::vector<double> normal_, normal_abs_;  // O(x) = normal . (x - v0), and its absolute tree
  std::vector<Sets> sets_;
  std::vector<std::int32_t> free_;
  std::vector<std::int32_t> pending_;  // facets that may have outside points, in the order made

  // add_point's marks and scratch, kept across its calls.
  std::uint32_t addition_ = 0;           // add_point's calls so far: a mark equal to it is current
  std::vector<std::uint32_t> seen_;      // per slot: tested during this addition
  std::vector<char> visible_;            // per slot: and found visible
  std::vector<std::uint32_t> in_cone_;   // per point: a vertex of a new facet of this addition
  std::vector<std::int32_t> visible_facets_, created_;
  std::vector<int> apex_place_;          // per new facet: the place of the apex among its vertices
  std::vector<std::int32_t> creator_;    // per new facet: its visible predecessor's index in visible_facets_
  std::vector<char> apex_on_plane_;      // per visible facet: the apex exactly on its hyperplane
  // The walks' data, per visible facet i and place k: the new facet on that ridge (-1 inside
  // the visible region), and the coefficients for the hyperplane through the apex and the
  // ridge, computed at their first use.
  std::vector<std::int32_t> walk_index_;  // per slot: its index among this addition's visible facets
  std::vector<std::int32_t> horizon_;
  std::vector<double> ridge_normal_, ridge_abs_;
  std::vector<char> ridge_ready_;
  std::vector<std::int32_t> tuple_;
  std::uint64_t random_ = 0x9e3779b97f4a7c15ull;  // xorshift: the walks' order of ridges
  std::vector<std::int32_t> ids_;        // a facet's vertices and a point, for the exact stages
};

}  // namespace drange::hull
