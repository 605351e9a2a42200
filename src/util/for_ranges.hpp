// util/for_ranges.hpp: a loop over [0, n) cut into consecutive ranges that a Team's threads
// share. The ranges depend on n and the thread count only; a caller whose output must not
// depend on the thread count writes each index's result in its own place, or one result per
// range that it joins in range order afterwards.
#pragma once

#include <algorithm>
#include <cstddef>

#include "delaunay/team.hpp"

namespace drange::util {

// Runs body(range, begin, end) over ranges covering [0, n) in order, on the team's threads when
// there are at least 2 * min_range indices (else one range on the calling thread); returns the
// number of ranges. Several ranges per thread even out ranges that take unequal times.
template <class Body>
std::size_t for_ranges(std::size_t n, engine::Team& team, Body body, std::size_t min_range = std::size_t{1} << 16) {
  const std::size_t ranges =
      std::max<std::size_t>(1, std::min(static_cast<std::size_t>(team.threads()) * 4, n / std::max<std::size_t>(1, min_range)));
  team.for_each(ranges, [&](std::size_t i) { body(i, n * i / ranges, n * (i + 1) / ranges); });
  return ranges;
}

}  // namespace drange::util
