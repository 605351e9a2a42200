// voronoi/circumcentre.hpp: circumcentres, the Voronoi vertices (paper, section 2.5).
//
// Accuracy: the centre is solved relative to the first vertex (so a cluster far from the
// origin loses no digits), with partial pivoting, in long double (64-bit significand on
// x86-64), and rounded to double once at the end. A sliver's ill-conditioned system thus
// keeps about 11 more bits than a double solve would; past a Hadamard ratio of 1e4 (rare:
// the slivers of nearly coplanar points) the centre is solved exactly with GMP instead.
#pragma once

namespace drange::diagram {

// The circumcentre of a full-dimensional simplex (dim+1 vertices) written to `centre`.
// Returns the Hadamard ratio  prod_i |v_i - v_0| / |det[v_1 - v_0, ..., v_d - v_0]|  (>= 1):
// how close the simplex is to flat, which bounds how much the solve can amplify rounding.
// Returns +infinity for a flat simplex (then `centre` is not set). Past a ratio of 1e4 the
// centre is solved exactly (GMP) and rounded once, so it is accurate whatever the ratio; a
// simplex too flat for the long double solve but not flat returns the largest double.
double simplex_circumcentre(int dim, const double* const* vertices, double* centre);

}  // namespace drange::diagram
