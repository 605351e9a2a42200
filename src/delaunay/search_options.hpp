// delaunay/search_options.hpp: the search's internal switches (paper, section 2.4, and ours),
// for measuring what each step gains. Users pick a named set of them with Options::variant
// (the CLI's --variant, Python's variant=); the tests set single switches through
// engine::triangulate (delaunay/triangulate.hpp).
#pragma once

#include <string>

namespace drange::engine {

// The order in which the open facets take their turns (paper, section 2.3: FIFO). It changes
// the simplices' numbering and order, never the set of simplices.
enum class FacetOrder {
  automatic,  // by dimension, where each was faster: spatial in 3D to 5D, FIFO in 2D and from 6D on
  fifo,       // the paper's queue
  // The facet whose smallest vertex is least in the kd-tree's point order (a space-filling
  // one) comes first, by blocks of points, FIFO within a block and in a fixed window of facets
  // taken ahead: the frontier sweeps through space and stays small.
  spatial,
};

// How the next simplex of an open facet is searched (paper, section 2.4), and which facet is
// searched next. The defaults are the full algorithm; the switches exist so that the gain of
// each step can be measured. The first three are the paper's; the next three are ours (they
// change the order in which points are met, never which point is found).
struct SearchOptions {
  bool use_kdtree = true;               // false: scan every point for every facet (the slow direct algorithm)
  bool prune_closed_side = true;        // 2.4.1: skip kd-tree nodes wholly on the closed side of the facet
  bool visit_facet_child_first = true;  // 2.4.2: descend first into the child that holds the facet
  // Walk the kd-tree bottom-up from the leaf of the facet's first vertex, climbing only until
  // the query box lies inside the subtree walked so far, instead of descending from the root.
  bool bottom_up = true;
  // Before the walk, try as candidates the points found by the last searches of facets that
  // share a vertex with this one (Delaunay neighbours of its vertices): the first query box is
  // then already small.
  bool seed_candidate = true;
  // Query the candidate's ball itself (enlarged by its error bound), not only its bounding box
  // (2.4 approximates the sphere by a hypercube, "the rougher the larger d is").
  bool ball_query = true;
  // On points near one sphere (cospherical up to rounding), or near a few concentric ones, or
  // near spheres about several centres (bubbles), also skip the kd-tree nodes whose points'
  // offsets from their sphere prove them outside the candidate's sphere, where the ball cannot
  // (every candidate's sphere is then the facet's sphere, within rounding), and decide points
  // by the exact form of the test around that sphere's centre instead of GMP.
  bool sphere_shell = true;
  // Remember the points that an exact evaluation proved on a facet's hyperplane or on a
  // candidate's sphere, and skip the exact evaluation when a later search meets a subset of them
  // again (ties that no floating-point filter decides: exactly cospherical points whose
  // coordinates are not dyadic, as in a grid in cylindrical coordinates).
  bool remember_ties = true;
  // Which open facet is searched next (ours too: it changes the simplices' order, not the set).
  FacetOrder facet_order = FacetOrder::automatic;
  // In 2D and 3D, find the convex hull's facets with no other point on their hyperplane
  // beforehand (exactly: a monotone chain in 2D, Quickhull in 3D), and skip the searches of
  // their outer sides, which hold no point (src/delaunay/known_hull.hpp). Pays on points in
  // convex position (a circle, an ellipsoid, a convex scan), where a third to a half of the
  // facets lie on the hull; kept only for large hulls.
  bool known_hull_facets = true;
};

// The options of a named variant (search_options.cpp's table; drange::variant_names() lists
// them): "full", each "no-X" with one step off, "paper" (the paper's three steps alone, FIFO),
// "scan" and "kdtree" (no tree; a tree and nothing else), "fifo" and "spatial" (full with that
// facet order in every dimension). Throws UsageError naming the unknown value and the names.
SearchOptions search_variant(const std::string& name);

}  // namespace drange::engine
