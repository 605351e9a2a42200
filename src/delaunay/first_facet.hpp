// delaunay/first_facet.hpp: the first open facet (paper, section 2.2), exact on every input.
//
// Gift wrapping finds d points spanning a supporting hyperplane H of the point set: start from
// the lexicographically smallest point and the hyperplane orthogonal to the first axis, then
// rotate it about the points found so far until it meets one more point (the paper's
// "consistent hyperplanes"). Angles are never computed: one rotation is better than another
// exactly when an orientation determinant says so.
//
// When H holds more than d points (a side of an integer grid, a face of a cube) the facet must
// be a Delaunay facet among them, under the same perturbation. The points on H lie in a
// (d-1)-flat: the same construction runs inside it (in the coordinates of d-1 axes onto which
// H projects one-to-one, with the ambient squared norm as lift), recursively, and each level
// closes its facet into a simplex of its flat by an exact scan for the Delaunay point.
#pragma once

#include <cstdint>
#include <vector>

#include "delaunay/point_store.hpp"
#include "delaunay/team.hpp"

namespace drange::engine {

struct FirstFacet {
  std::vector<std::int32_t> ids;  // d point ids, increasing
  int sigma = 1;                  // the open side (the hull's interior) is where sigma O(x) > 0
};

// Throws DegenerateInputError when the points do not span E^d (the message gives the
// dimension of their affine hull). The scans over all points use the team's threads; the
// facet, and the predicates evaluated, are the same for every thread count.
FirstFacet find_first_facet(const PointStore& points, Team& team);

}  // namespace drange::engine
