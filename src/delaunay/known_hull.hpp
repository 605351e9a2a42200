// delaunay/known_hull.hpp: the hull facets known before the search (ours,
// SearchOptions::known_hull_facets): the clean edges in 2D (hull_edges.hpp), the clean
// triangles in 3D (hull_triangles.hpp). At most one of them is kept for a point set.
#pragma once

#include <cstdint>

#include "delaunay/hull_edges.hpp"
#include "delaunay/hull_triangles.hpp"

namespace drange::engine {

struct KnownHull {
  HullEdges edges;          // 2D
  HullTriangles triangles;  // 3D

  bool active() const { return edges.active() || triangles.active(); }
  // The sign sigma whose open side is the hull's outside, when the facet (sorted ids) is a
  // clean hull facet; 0 otherwise.
  int outer_sigma(const std::int32_t* sorted) const {
    return edges.active() ? edges.outer_sigma(sorted[0], sorted[1]) : triangles.outer_sigma(sorted);
  }
};

}  // namespace drange::engine
