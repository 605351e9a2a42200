// geometry/wide_determinant.hpp: the exact stage of the small predicates in fixed-width
// integers (wide_integer.hpp), before GMP.
//
// Coordinates that no small power of two divides (0.1 k, the decimal grids of most real data;
// the cosines of a cylindrical grid) pass every floating-point filter at each tie, and GMP
// then costs several thousand instructions per determinant, mostly in calls, sizes and
// Bareiss' exact divisions. Here the same exact value (every coordinate an integer in the
// points' common unit, as in exact_matrix.hpp) is expanded by minors in integers whose widths
// the formula fixes: 64-bit differences, 128-bit 2 x 2 minors and lifts, 192 to 320 bits above
// them. That needs each difference from the base point below 2^62 in the common unit (the
// points are near each other in a determinant: 0.01 k near 5 differ by about 2^55 units of
// 0.01's last bit) and each coordinate below 2^125.
#pragma once

#include <optional>

#include "geometry/predicates.hpp"

namespace drange::geometry {

// The sign of orientation's determinant (predicates.hpp) for k <= 3, exactly; nullopt when a
// coordinate is too large in the common unit (or k > 3).
std::optional<int> wide_orientation(const Frame& frame, const double* const* points);
// The sign of lifted_sign's determinant, unperturbed, for k = 2 or 3 in at most 3 ambient
// dimensions, exactly; nullopt otherwise.
std::optional<int> wide_lifted_sign(const Frame& frame, const double* const* points);

}  // namespace drange::geometry
