// delaunay/simplex_estimate.hpp: how many simplices to make room for before the search.
//
// The simplices and their neighbours are appended to two vectors. Growing a vector by doubling
// copies it once more and, for the moment of the copy, holds the old and the new block: the
// peak memory of high dimensions was set there (8D 300 points: 405 MiB, against 365 with room
// made up front). Making room only takes address space: the pages are committed as simplices
// are written, so an estimate that is too high costs no memory, and one that is too low only
// lets the vectors grow as before.
#pragma once

#include <unistd.h>

#include <algorithm>
#include <cstddef>
#include <iterator>

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

}  // namespace drange::engine
