// hull/initial_simplex.hpp: Quickhull's first simplex and the interior point of the perturbation.
//
// The simplex is chosen from the coordinates alone, so that any input order gives the same one
// (and so the same interior point and the same perturbation): the lexicographically least
// point, then d times the point farthest (in floating point) from the affine hull of those
// chosen, ties to the lexicographically least. Each choice is confirmed exactly (GMP); a
// choice that rounding made wrongly falls back to an exact scan.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "drange/points.hpp"

namespace drange::hull {

struct InitialSimplex {
  std::vector<std::int32_t> ids;  // d+1 affinely independent points
  // Their centroid rounded to doubles when that is strictly inside the simplex (exactly
  // checked); empty otherwise (a simplex thinner than the doubles' spacing there).
  std::vector<double> interior;
};

// Throws DegenerateInputError, naming the dimension of the points' affine hull and what needs
// them to span E^d (`structure`), when they do not.
InitialSimplex initial_simplex(PointsView points, const std::string& structure = "a convex hull");

}  // namespace drange::hull
