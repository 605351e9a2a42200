// delaunay/incremental/insertion_order.cpp: the rounds of the biased randomized insertion order.
#include "delaunay/incremental/insertion_order.hpp"

#include <array>

namespace drange::engine {
namespace {

// The last rounds are the large ones; beyond this many, a round would hold a handful of points.
constexpr int kRounds = 24;

// splitmix64's finaliser: a fixed bijection of 64-bit words whose low bits are independent
// enough to draw rounds from.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// Round 0 is the first inserted; a point's round is kRounds - 1 minus its hash's trailing
// zeros, so that half the points are in the last round.
int round_of(std::int64_t rank) {
  const std::uint64_t h = mix(static_cast<std::uint64_t>(rank));
  int zeros = 0;
  while (zeros < kRounds - 1 && ((h >> zeros) & 1u) == 0) ++zeros;
  return kRounds - 1 - zeros;
}

}  // namespace

std::vector<std::int32_t> insertion_order(const PointStore& points) {
  // A counting sort by round, ids increasing within each.
  std::array<std::size_t, kRounds + 1> start{};
  std::vector<std::uint8_t> round(static_cast<std::size_t>(points.size));
  for (std::int32_t id = 0; id < points.size; ++id) {
    const int r = round_of(points.rank(id));
    round[static_cast<std::size_t>(id)] = static_cast<std::uint8_t>(r);
    ++start[static_cast<std::size_t>(r) + 1];
  }
  for (int r = 0; r < kRounds; ++r) start[static_cast<std::size_t>(r) + 1] += start[static_cast<std::size_t>(r)];
  std::vector<std::int32_t> order(static_cast<std::size_t>(points.size));
  for (std::int32_t id = 0; id < points.size; ++id) order[start[round[static_cast<std::size_t>(id)]]++] = id;
  return order;
}

}  // namespace drange::engine
