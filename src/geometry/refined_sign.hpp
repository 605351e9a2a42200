// geometry/refined_sign.hpp: the second stage of the lifted predicate, between the double
// filter and GMP: the same determinant in double-double arithmetic with its error bound.
//
// Why: points within rounding of a sphere that is not the input's one sphere (the insides of
// two concentric spheres, of small bubbles, of the rings of a cylinder) make the search test
// each point near a candidate's sphere, and the double filter cannot decide those tests: a
// point that lies within 2^-50 of the sphere, relative to the determinant's terms, is beyond
// its reach. Such a point is rarely within 2^-100, though, unless it is exactly on it, and the
// double-double evaluation decides it without GMP's integer scaling and Bareiss on several
// limbs (two concentric spheres of 2 500 points in 3D: callgrind instructions -53% for the
// whole run). Exact ties still go to GMP, and then to the perturbation.
#pragma once

#include <optional>

#include "geometry/predicates.hpp"

namespace drange::geometry {

// Up to this many rows (frame.k + 1): the Laplace expansion's minors grow as 2^n.
constexpr int kRefinedMaxRows = 5;

// The sign of lifted_sign's determinant when the double-double evaluation proves it; nullopt
// when the bound does not decide, frame.k + 1 > kRefinedMaxRows, or an operation underflowed
// or overflowed.
std::optional<int> refined_lifted_sign(const Frame& frame, const double* const* points);

}  // namespace drange::geometry
