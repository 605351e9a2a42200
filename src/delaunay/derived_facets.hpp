// delaunay/derived_facets.hpp: the other facets of a simplex just found, packed in one block
// of ints with their open sides and hashes, as the search's side hands them to the side that
// records the simplex. Apart from the driver because three parts share the block's layout: the
// searches write it (triangulate.cpp's serial loops, the helper threads), the frontier reads it
// when it records the simplex, and the closure predictor reads it to remember the simplex.
#pragma once

#include <cstddef>
#include <cstdint>

#include "delaunay/facet_table.hpp"
#include "delaunay/simplex_facets.hpp"

namespace drange::engine {

// The other facets of the simplex found for a facet, derived apart from the shared state (with
// threads, by the thread that found the apex, so that the calling thread only probes the table
// and writes): a block of d (d + 2) ints, d facets of d sorted ids (simplex_facets.hpp), their
// open sides, their hashes.
inline std::size_t derived_block_size(int d) { return static_cast<std::size_t>(d) * static_cast<std::size_t>(d + 2); }
inline void derive_in(const std::int32_t* facet, int sigma, std::int32_t apex, int d, std::int32_t* block) {
  engine::simplex_other_facets(facet, d, apex, sigma < 0, block, block + d * d);
  for (int f = 0; f < d; ++f) block[d * d + d + f] = static_cast<std::int32_t>(engine::facet_hash(block + f * d, d));
}
// Not inlined: inlined into the driver's serial loop, it made the whole search measurably
// slower (3D, one thread), so it stays a call.
[[gnu::noinline]] inline void derive_other_facets(const std::int32_t* facet, int sigma, std::int32_t apex, int d, std::int32_t* block) {
  // With d a constant (the search kernels' dimensions) the compiler unrolls the short loops.
  // From 4D too: the unrolled cases take far fewer instructions than the generic loop, enough
  // to show in the whole run.
  switch (d) {
    case 2: derive_in(facet, sigma, apex, 2, block); return;
    case 3: derive_in(facet, sigma, apex, 3, block); return;
    case 4: derive_in(facet, sigma, apex, 4, block); return;
    case 5: derive_in(facet, sigma, apex, 5, block); return;
    case 6: derive_in(facet, sigma, apex, 6, block); return;
    case 7: derive_in(facet, sigma, apex, 7, block); return;
    case 8: derive_in(facet, sigma, apex, 8, block); return;
    default: derive_in(facet, sigma, apex, d, block); return;
  }
}

}  // namespace drange::engine
