// voronoi/vertex_classes.hpp: which Delaunay simplices share one Voronoi vertex.
//
// Simplices whose circumspheres coincide (cospherical points: the cells of an integer grid,
// a regular polygon) must give one Voronoi vertex, not several copies a rounding error apart.
// Two neighbouring simplices have the same circumsphere exactly when the far vertex of one
// lies on the sphere of the other, and the simplices of one empty sphere triangulate a convex
// polytope, so they are connected through such facets: the classes are the connected
// components of the "cospherical neighbours" relation, decided by the exact in-sphere
// predicate (no tolerance).
//
// The same is done at infinity: every hull facet is an unbounded direction of the diagram
// (the infinite vertex -1), and neighbouring hull facets in one hyperplane (a hull face
// holding more than d points) form one infinite class. Infinite classes are not Voronoi
// vertices; they are needed to decide which pairs of cells share a (d-1)-face (ridges.hpp).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "delaunay/team.hpp"
#include "drange/delaunay.hpp"
#include "drange/points.hpp"
#include "drange/voronoi.hpp"

namespace drange::diagram {

struct VertexClasses {
  int dim = 0;
  std::int32_t finite = 0;                   // finite classes: ids 0 .. finite-1, the Voronoi vertices
  std::int32_t total = 0;                    // finite + infinite classes; infinite ids are finite .. total-1
  std::vector<std::int32_t> of_simplex;      // class of each simplex
  // The hull facets (neighbour -1), as keys s*(d+1)+k sorted, each with its class; a sorted
  // list rather than an m x (d+1) array, since the hull holds few of the facets.
  std::vector<std::int64_t> hull_facet_keys;
  std::vector<std::int32_t> hull_facet_class;
  std::vector<double> vertices;              // finite x dim: the centre of each finite class
  // The vertex sets of classes that are not a single simplex (merged or infinite): the
  // sorted input indices of their points. set_of[c] is the row in `sets`, -1 for a class
  // that is one simplex (its vertices are that simplex's).
  std::vector<std::int32_t> set_of;
  IndexLists sets;
  std::vector<std::int32_t> simplex_of;      // for single-simplex finite classes: that simplex

  bool is_infinite(std::int32_t c) const { return c >= finite; }

  // The class of the facet opposite vertex k of simplex s when it is a hull facet, else -1.
  std::int32_t hull_class(const Triangulation& t, std::size_t s, int k) const {
    const std::size_t key = s * static_cast<std::size_t>(dim + 1) + static_cast<std::size_t>(k);
    if (t.neighbors[key] >= 0) return -1;
    const auto it = std::lower_bound(hull_facet_keys.begin(), hull_facet_keys.end(), static_cast<std::int64_t>(key));
    return hull_facet_class[static_cast<std::size_t>(it - hull_facet_keys.begin())];
  }
};

// Classifies the simplices and hull facets of a triangulation of `points` (its neighbours
// must be present).
// The exact tests and the circumcentres run on the team's threads; the result does not depend
// on their count.
VertexClasses classify_vertices(PointsView points, const Triangulation& triangulation, engine::Team& team);

}  // namespace drange::diagram
