// delaunay/hull_triangles.hpp: the clean facets of a 3D point set's convex hull (ours,
// SearchOptions::known_hull_facets, the 3D counterpart of hull_edges.hpp; see known_hull.hpp).
//
// Why: on points sampled from a convex surface (an ellipsoid, a scan of a convex object) a
// third of the facets lie on the hull, and each of their searches proves the open side empty
// along a boundary that every kd-tree box near the facet crosses: a large share of the search
// time on points on an ellipsoid.
//
// How: Quickhull (Barber, Dobkin and Huhdanpaa) with exact orientations, over the points that
// may be on the hull. A hull facet is clean when no other point lies on its plane: every other
// point is then strictly inside, whatever the symbolic perturbation, and its outer side has no
// apex. The construction gives up (keeps nothing) at the first exact zero it meets, or when a
// hull edge is not strictly convex: inputs with coplanar points (grids, a terrain's plateau)
// keep their searches. A point that Quickhull discards lies strictly inside the hull at that
// moment, and the hull only grows, so no discarded point lies on a final facet's plane; the
// hull's own vertices are checked by the convexity of every edge.
//
// Only when the hull is large: a Quickhull over a sample of the points says first whether most
// of them are on the hull (uniform input: a few percent, and the full hull is not built).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace drange::engine {

struct PointStore;

class HullTriangles {
 public:
  HullTriangles() = default;
  // The clean hull facets of `points` (3D; any other dimension keeps none). `sample` points
  // (spread over the ids) are tried first; the full hull is built only when more than three in
  // four of them are hull vertices of the sample (a torus: about half, and its hull facets are
  // a small part of its search), and kept when it has at least `least_facets` clean facets
  // (the tests lower both).
  explicit HullTriangles(const PointStore& points, std::size_t sample = kSample, std::size_t least_facets = kLeastFacets);

  // The sign sigma for which the facet (f0 < f1 < f2)'s open side, sigma O(x) > 0 with
  // O(x) = det[f1 - f0; f2 - f0; x - f0], is the outside of the hull, when it is a clean hull
  // facet; 0 otherwise.
  int outer_sigma(const std::int32_t* sorted) const {
    if (first_.empty()) return 0;
    const auto f0 = static_cast<std::size_t>(sorted[0]);
    for (std::int32_t e = first_[f0]; e < first_[f0 + 1]; ++e) {
      const Entry& entry = entries_[static_cast<std::size_t>(e)];
      if (entry.f1 == sorted[1] && entry.f2 == sorted[2]) return entry.sigma;
    }
    return 0;
  }
  bool active() const { return !first_.empty(); }
  std::size_t clean_facets() const { return entries_.size(); }
  // Whether the full hull was built (the sample said most points are on it).
  bool built() const { return built_; }

  static constexpr std::size_t kSample = 1024;
  static constexpr std::size_t kLeastFacets = 512;

 private:
  struct Entry {
    std::int32_t f1, f2;
    int sigma;
  };
  // The clean facets by their least id: entries_[first_[f0] .. first_[f0 + 1]).
  std::vector<std::int32_t> first_;
  std::vector<Entry> entries_;
  bool built_ = false;
};

}  // namespace drange::engine
