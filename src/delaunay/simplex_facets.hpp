// delaunay/simplex_facets.hpp: the other facets of a simplex found from one facet (section 2.5).
//
// A simplex is recorded as its facet's sorted ids a[0..d-1], then the apex x, with a[0] and
// a[1] exchanged when that makes it positively oriented. Its facet f omits vertex f; the driver
// needs each one's ids sorted (the facet table's key) and the sign of its open side. Both follow
// from the order of a without sorting anything: x goes in once, at the place p of the first id
// above it, and the permutation's parity is a count of inversions.
#pragma once

#include <cstdint>

namespace drange::engine {

// For f = 0..d-1, writes facet f of the simplex (a with a[0] and a[1] exchanged when `swapped`,
// then x) sorted into ids + f*d, and into open_side[f] the sign s of its open side, the side of
// the simplex's other vertex v[f]: the search looks for points y with s O(facet, y) > 0.
//
// Why the sign: with the simplex positive, O(v without v[f], then v[f]) has the sign of moving
// v[f] from place f to the end, (-1)^(d - f), and sorting the rest of v multiplies by the
// parity of that permutation. v[f] lies on the closed side, so the open side gets the opposite
// sign. The parity counts inversions: x, last in v, passes the ids above it that remain (d - p,
// minus one when the omitted id a[j] is above x, j >= p); the exchange adds one when both a[0]
// and a[1] remain (f >= 2).
inline void simplex_other_facets(const std::int32_t* a, int d, std::int32_t x, bool swapped, std::int32_t* ids,
                                 std::int32_t* open_side) {
  int p = 0;
  while (p < d && a[p] < x) ++p;
  for (int f = 0; f < d; ++f) {
    const int j = (swapped && f < 2) ? 1 - f : f;  // the id that v[f] is
    std::int32_t* out = ids + f * d;
    for (int i = 0; i < d; ++i) {
      if (i == p) *out++ = x;
      if (i != j) *out++ = a[i];
    }
    if (p == d) *out = x;
    const int inversions = d - p - (j >= p ? 1 : 0) + ((swapped && f >= 2) ? 1 : 0);
    open_side[f] = ((1 + inversions + d - f) & 1) ? -1 : 1;
  }
}

}  // namespace drange::engine
