// Tests of simplex_other_facets (delaunay/simplex_facets.hpp) against the definition: remove
// vertex f from the recorded simplex, sort the rest counting transpositions, and move the
// removed vertex to the end.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "delaunay/simplex_facets.hpp"

namespace {

// The open-side sign by definition (the driver's former code): sort the facet by adjacent
// transpositions, then the removed vertex's move from place f to the end.
int open_side_by_sorting(std::vector<std::int32_t> facet, int f, int d) {
  int parity = 1;
  for (int i = 1; i < d; ++i)
    for (int j = i; j > 0 && facet[j - 1] > facet[j]; --j) {
      std::swap(facet[j - 1], facet[j]);
      parity = -parity;
    }
  const int to_end = ((d - f) & 1) ? -1 : 1;
  return -parity * to_end;
}

TEST(SimplexFacets, MatchSortingInEveryDimensionAndApexPlace) {
  std::mt19937 rng(7);
  for (int d = 2; d <= 11; ++d)
    for (int trial = 0; trial < 400; ++trial) {
      std::set<std::int32_t> distinct;
      while (static_cast<int>(distinct.size()) < d + 1) distinct.insert(static_cast<std::int32_t>(rng() % 40));
      std::vector<std::int32_t> all(distinct.begin(), distinct.end());
      std::shuffle(all.begin(), all.end(), rng);
      const std::int32_t x = all.back();  // anywhere among the facet's ids, first and last included
      std::vector<std::int32_t> a(all.begin(), all.end() - 1);
      std::sort(a.begin(), a.end());
      const bool swapped = (trial & 1) != 0;
      std::vector<std::int32_t> v = a;  // the simplex as recorded
      v.push_back(x);
      if (swapped) std::swap(v[0], v[1]);

      std::vector<std::int32_t> ids(static_cast<std::size_t>(d * d)), open_side(static_cast<std::size_t>(d));
      drange::engine::simplex_other_facets(a.data(), d, x, swapped, ids.data(), open_side.data());
      for (int f = 0; f < d; ++f) {
        std::vector<std::int32_t> facet;
        for (int i = 0; i <= d; ++i)
          if (i != f) facet.push_back(v[static_cast<std::size_t>(i)]);
        const int expected_side = open_side_by_sorting(facet, f, d);
        std::sort(facet.begin(), facet.end());
        const std::vector<std::int32_t> got(ids.begin() + f * d, ids.begin() + (f + 1) * d);
        ASSERT_EQ(got, facet) << "d=" << d << " trial=" << trial << " f=" << f;
        ASSERT_EQ(open_side[static_cast<std::size_t>(f)], expected_side) << "d=" << d << " trial=" << trial << " f=" << f;
      }
    }
}

}  // namespace
