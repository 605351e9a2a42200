// util/check_points.hpp: the checks every entry point makes of the caller's points.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>

#include "drange/errors.hpp"
#include "drange/points.hpp"

namespace drange::util {

// Throws InputError for a dimension outside 2..kMaxDimension, 2^31 - 1 points or more (ids are
// 32-bit), or a coordinate that is NaN or infinite (naming the point and the coordinate).
// `what`: what drange does with them, for the dimension's message ("triangulates");
// `first_index`: the index of the first point among all, for the message.
inline void check_points(PointsView input, const char* what, std::size_t first_index = 0) {
  if (input.dim < 2 || input.dim > kMaxDimension)
    throw InputError("dimension " + std::to_string(input.dim) + " is not supported (drange " + what + " in 2 to " +
                     std::to_string(kMaxDimension) + " dimensions)");
  if (input.n >= static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
    throw InputError(std::to_string(input.n) + " points are more than drange's limit of 2^31 - 2");
  for (std::size_t i = 0; i < input.n; ++i)
    for (int k = 0; k < input.dim; ++k) {
      const double x = input.point(i)[k];
      if (!std::isfinite(x))
        throw InputError("point " + std::to_string(first_index + i) + ", coordinate " + std::to_string(k) + " is " +
                         (std::isnan(x) ? "NaN" : "infinite"));
    }
}

}  // namespace drange::util
