// voronoi/star.hpp: the simplices around a point of a triangulation, as flat arrays: the
// point-to-simplex incidence, and walks around a point (2D) or an edge (3D) through the
// neighbour links, which give Voronoi regions and ridges their cyclic order.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "drange/delaunay.hpp"

namespace drange::diagram {

// simplices[offsets[p] .. offsets[p+1]) are the simplices having input point p as a vertex.
// `order` lists the points that have simplices in the order of their first simplex: the
// engine emits simplices in a spatially coherent order, so visiting points in this order
// keeps the simplices and neighbours being read in cache (input order would jump at random).
struct Incidence {
  std::vector<std::int64_t> offsets;
  std::vector<std::int32_t> simplices;
  std::vector<std::int32_t> order;

  const std::int32_t* begin(std::size_t p) const { return simplices.data() + offsets[p]; }
  const std::int32_t* end(std::size_t p) const { return simplices.data() + offsets[p + 1]; }
};

Incidence point_incidence(const Triangulation& t);

// on_hull[p] != 0 when input point p is a vertex of a hull facet (a facet without neighbour):
// its Voronoi cell is unbounded.
std::vector<char> hull_points(const Triangulation& t);

// The position of input point v in simplex s (v must be a vertex of s).
inline int position_in(const Triangulation& t, std::size_t s, std::int32_t v) {
  const std::int32_t* row = t.simplex(s);
  int k = 0;
  while (row[k] != v) ++k;
  return k;
}

// The triangles around point p of a 2D triangulation in counter-clockwise order, starting
// from `start` (a triangle having p). When p is on the hull the list starts at the triangle
// after the hull edge met clockwise and ends at the one before it; `closed` tells which.
std::vector<std::int32_t> triangles_around(const Triangulation& t, std::int32_t p, std::int32_t start, bool& closed);

// The tetrahedra around the edge pq of a 3D triangulation, in rotational order, starting from
// `start` (a tetrahedron having p and q). When the edge is on the hull the list runs from one
// hull facet to the other; `closed` tells which.
std::vector<std::int32_t> tetrahedra_around(const Triangulation& t, std::int32_t p, std::int32_t q, std::int32_t start,
                                            bool& closed);

}  // namespace drange::diagram
