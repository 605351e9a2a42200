// geometry/double_bits.hpp: a double's integer significand and exponent, read from its bits.
//
// The exactness proofs and the exact evaluations take every coordinate apart this way; frexp
// and ldexp are library calls, and degenerate inputs (grids, points near a sphere) make
// millions of them.
#pragma once

#include <cstdint>
#include <cstring>

namespace drange::geometry {

// x = significand * 2^exponent, with |significand| < 2^53 (the IEEE significand with its
// implicit bit; x finite).
struct DoubleParts {
  std::int64_t significand;
  int exponent;
};

inline DoubleParts parts_of(double x) {
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  const int biased = static_cast<int>(bits >> 52 & 0x7ff);
  auto magnitude = static_cast<std::int64_t>(bits & ((std::uint64_t{1} << 52) - 1));
  if (biased != 0) magnitude |= std::int64_t{1} << 52;  // normal: the implicit leading bit
  return DoubleParts{(bits >> 63) ? -magnitude : magnitude, (biased != 0 ? biased : 1) - 1075};
}

}  // namespace drange::geometry
