// geometry/exact.hpp: exact rational values for the few places that need a value, not a sign
// (the validator's volume sums).
#pragma once

#include <gmpxx.h>

namespace drange::geometry {

// Converts a finite double to the exact rational it represents.
mpq_class exact_rational(double x);

// det[s_1 - s_0, ..., s_d - s_0] exactly: d! times the signed volume of the simplex.
mpq_class simplex_volume_times_factorial(int dim, const double* const* simplex);

}  // namespace drange::geometry
