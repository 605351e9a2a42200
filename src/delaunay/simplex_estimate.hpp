// delaunay/simplex_estimate.hpp: how many simplices to make room for before the search, and
// how many there can be at most.
//
// The simplices and their neighbours are appended to two vectors. Growing a vector by doubling
// copies it once more and, for the moment of the copy, holds the old and the new block: in high
// dimensions that moment sets the peak memory, and room made up front lowers it. Making room
// only takes address space: the pages are committed as simplices are written, so an estimate
// that is too high costs no memory, and one that is too low only lets the vectors grow by
// doubling past it.
#pragma once

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>

namespace drange::engine {

// Simplices per point of uniform points, above what was measured (bench/RESULTS.md: 4D 100k
// 30.7, 5D 20k 161, 6D 5k 834, 7D 4 500 4 955 and 7 000 5 400, 8D 300 / 600 / 1 000 / 1 500
// 7 385 / 12 280 / 16 600 / 20 470: from 6D on the count per point grows with n, so the
// figure is well above the measured ones). 2D: at most 2n - 5 triangles; 3D: about 6.8n.
// Beyond 8D nothing was measured: no room is made.
inline std::size_t expected_simplices(int d, std::size_t n) {
  constexpr double kPerPoint[] = {0, 0, 2, 6.8, 32, 170, 1200, 7000, 25000};
  if (d < 2 || d >= static_cast<int>(std::size(kPerPoint))) return 0;
  return static_cast<std::size_t>(kPerPoint[d] * static_cast<double>(n));
}

// The room for `simplices` simplices of `ints_per_simplex` ints in each of `arrays` vectors,
// at most a quarter of the physical memory in all (a larger reservation of address space may
// be refused by the kernel's overcommit heuristics).
inline std::size_t reservable_simplices(std::size_t simplices, std::size_t ints_per_simplex, std::size_t arrays) {
  const long pages = sysconf(_SC_PHYS_PAGES), page_size = sysconf(_SC_PAGESIZE);
  if (pages <= 0 || page_size <= 0) return 0;
  const std::size_t budget = static_cast<std::size_t>(pages) / 4 * static_cast<std::size_t>(page_size);
  return std::min(simplices, budget / (ints_per_simplex * arrays * sizeof(int)));
}

// The most simplices a Delaunay triangulation of n distinct points in E^d can have: it is the
// lower hull of the points lifted to E^(d+1), perturbed symbolically into general position, so a
// simplicial (d+1)-polytope with at most n vertices, and by McMullen's upper bound theorem it
// has at most as many facets as the cyclic polytope C(n, d+1):
//   d + 1 = 2m even:  n / (n - m) * C(n - m, m);     d + 1 = 2m + 1 odd:  2 C(n - m - 1, m)
// (2D: 2n - 4; 3D: n (n - 3) / 2). The driver stops with an InternalError past it (frontier.hpp):
// a search that returns a wrong apex makes simplices overlap, and their facets, never matched,
// would keep the search going while memory lasts. Computed in floating point and rounded up
// generously (the bound only has to stay above the true count); saturates at SIZE_MAX.
inline std::size_t simplex_upper_bound(int d, std::size_t n) {
  if (n < static_cast<std::size_t>(d) + 2) return 1;  // d + 1 points at most: one simplex
  const int m = (d + 1) / 2;
  const double points = static_cast<double>(n);
  // C(top, m) as a product of m ratios, each exact to a relative 2^-52 or so.
  const auto binomial = [m](double top) {
    double c = 1.0;
    for (int i = 1; i <= m; ++i) c = c * (top - m + i) / i;
    return c;
  };
  const double facets = (d + 1) % 2 == 0 ? points / (points - m) * binomial(points - m) : 2 * binomial(points - m - 1);
  const double bound = std::ceil(facets * (1 + 1e-9)) + 1;
  if (!(bound < 0x1p63)) return std::numeric_limits<std::size_t>::max();
  return static_cast<std::size_t>(bound);
}

}  // namespace drange::engine
