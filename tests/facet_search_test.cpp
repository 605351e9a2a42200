// tests/facet_search_test.cpp: the search compiled for a fixed d (facet_search.cpp, d = 2..8)
// against its compilation for any d, facet by facet, and both against the triangulation.
//
// For every facet of a simplex, the search on the simplex's side finds the simplex's own
// opposite vertex, and the search on the other side finds the neighbour's (or -1 on the hull).
// Both kernels must give the same answer on both sides, with the search variants that change
// the kernel's path, on random points and on integer points (grids, and small integer ranges
// in d = 7, 8, where a full grid is too slow: ties on many spheres, so the exact fallback and
// the perturbation run).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "delaunay/facet_search.hpp"
#include "delaunay/prepare_points.hpp"
#include "delaunay/team.hpp"
#include "drange/delaunay.hpp"
#include "drange/generate.hpp"
#include "oracle.hpp"

namespace {

using drange::PointCloud;
using drange::engine::FacetSearch;

// A triangulation of `points`, the engine's store of the same points, and the facets of (up to
// 100 of) its simplices in the engine's sorted ids.
struct SampledFacets {
  SampledFacets(const PointCloud& points, int leaf_size)
      : t(drange::delaunay(points)), d(points.dim), store(prepare(points, leaf_size)), id_of(points.size(), -1) {
    for (std::int32_t id = 0; id < store.size; ++id) id_of[static_cast<std::size_t>(store.input_index[static_cast<std::size_t>(id)])] = id;
  }
  static drange::engine::PointStore prepare(const PointCloud& points, int leaf_size) {
    drange::engine::Team team(1);
    std::vector<drange::Duplicate> duplicates;
    return drange::engine::prepare_points(points, leaf_size, duplicates, team);
  }
  // Calls visit(s, opposite, facet, own) for facet `opposite` of sampled simplex s: its sorted
  // ids, and `own`, the id of the simplex's vertex off the facet. Returns the simplices visited.
  template <class Visit>
  std::size_t for_each(Visit visit) const {
    const std::size_t stride = std::max<std::size_t>(1, t.size() / 100);
    std::size_t visited = 0;
    for (std::size_t s = 0; s < t.size(); s += stride, ++visited) {
      const std::int32_t* simplex = &t.simplices[s * static_cast<std::size_t>(d + 1)];
      for (int opposite = 0; opposite <= d; ++opposite) {
        std::vector<std::int32_t> facet;
        for (int i = 0; i <= d; ++i)
          if (i != opposite) facet.push_back(id_of[static_cast<std::size_t>(simplex[i])]);
        std::sort(facet.begin(), facet.end());
        visit(s, opposite, facet, id_of[static_cast<std::size_t>(simplex[opposite])]);
      }
    }
    return visited;
  }

  drange::Triangulation t;
  int d;
  drange::engine::PointStore store;
  std::vector<std::int32_t> id_of;  // input index -> the engine's point id
};

// The two kernels' apexes for both sides of every facet of (up to 100 of) the simplices of
// the triangulation of `points`.
void expect_kernels_agree(const PointCloud& points, const std::string& what) {
  const SampledFacets sample(points, drange::engine::search_leaf_size(points.dim));
  const int d = points.dim;
  for (const char* variant : {"full", "paper", "no-ball"}) {
    const drange::engine::SearchOptions options = drange::engine::search_variant(variant);
    FacetSearch fixed(sample.store, options, FacetSearch::KernelChoice::FixedDimension);
    FacetSearch any(sample.store, options, FacetSearch::KernelChoice::AnyDimension);
    drange::engine::SearchCounters fixed_counters, any_counters;
    std::size_t own_apex_found = 0;
    const std::size_t checked = sample.for_each([&](std::size_t s, int opposite, const std::vector<std::int32_t>& facet, std::int32_t own) {
      for (int sigma : {1, -1}) {
        const std::int32_t a = fixed.find_apex(facet.data(), sigma, fixed_counters);
        const std::int32_t b = any.find_apex(facet.data(), sigma, any_counters);
        ASSERT_EQ(a, b) << what << " variant " << variant << " simplex " << s << " facet " << opposite << " side " << sigma;
        if (a == own) ++own_apex_found;
      }
    });
    // Exactly one side of each facet is the simplex's own.
    EXPECT_EQ(own_apex_found, checked * static_cast<std::size_t>(d + 1)) << what << " variant " << variant;
    EXPECT_EQ(fixed_counters.points_tested, any_counters.points_tested) << what << " variant " << variant;
  }
}

TEST(FacetSearch, FixedDimensionKernelsMatchTheAnyDimensionKernelOnRandomPoints) {
  const std::array<std::size_t, 9> sizes = {0, 0, 300, 200, 100, 60, 40, 30, 25};
  for (int d = 2; d <= 8; ++d)
    expect_kernels_agree(drange::generate_points(drange::Distribution::Uniform, sizes[static_cast<std::size_t>(d)], d, 5),
                         "uniform d=" + std::to_string(d));
}

TEST(FacetSearch, FixedDimensionKernelsMatchTheAnyDimensionKernelOnIntegerPoints) {
  for (int d = 2; d <= 6; ++d) {  // full grids: 3^d, then 2^d from d = 4 on
    const std::size_t side = d <= 3 ? 3 : 2;
    std::size_t n = 1;
    for (int k = 0; k < d; ++k) n *= side;
    expect_kernels_agree(drange::generate_points(drange::Distribution::Grid, n, d, 1), "grid d=" + std::to_string(d));
  }
  for (int d = 7; d <= 8; ++d)
    for (std::uint64_t seed : {1, 2})
      expect_kernels_agree(drange::test::random_integer_points(30, d, 0, 2, seed),
                           "integers in [0, 2] d=" + std::to_string(d) + " seed=" + std::to_string(seed));
}

// The kd-tree search (both kernels, every variant that uses the tree) against the scan of
// every point, for both sides of every facet of (up to 100 of) the simplices, with the tree
// built for `leaf_size`: leaves larger than LeafBlocks' blocks (8 points), and larger than
// one group of blocks (64 points) when leaf_size is, so that the block scan skips blocks and
// groups by their boxes.
void expect_tree_search_matches_scan(const PointCloud& points, int leaf_size, const std::string& what) {
  const SampledFacets sample(points, leaf_size);
  FacetSearch scan(sample.store, drange::engine::search_variant("scan"), FacetSearch::KernelChoice::AnyDimension);
  for (const char* variant : {"full", "no-seed", "no-bottom-up", "no-prune"}) {
    const drange::engine::SearchOptions options = drange::engine::search_variant(variant);
    FacetSearch fixed(sample.store, options, FacetSearch::KernelChoice::FixedDimension);
    FacetSearch any(sample.store, options, FacetSearch::KernelChoice::AnyDimension);
    drange::engine::SearchCounters counters;
    sample.for_each([&](std::size_t s, int opposite, const std::vector<std::int32_t>& facet, std::int32_t) {
      for (int sigma : {1, -1}) {
        const std::int32_t expected = scan.find_apex(facet.data(), sigma, counters);
        ASSERT_EQ(fixed.find_apex(facet.data(), sigma, counters), expected)
            << what << " leaf size " << leaf_size << " variant " << variant << " simplex " << s << " facet " << opposite
            << " side " << sigma;
        ASSERT_EQ(any.find_apex(facet.data(), sigma, counters), expected)
            << what << " leaf size " << leaf_size << " variant " << variant << " simplex " << s << " facet " << opposite
            << " side " << sigma << " (any d)";
      }
    });
  }
}

TEST(FacetSearch, TreeSearchFindsTheScansPointWithSmallAndLargeLeaves) {
  const std::array<std::size_t, 9> sizes = {0, 0, 600, 400, 300, 200, 120, 90, 80};
  for (int d = 2; d <= 8; ++d) {
    const PointCloud points = drange::generate_points(drange::Distribution::Uniform, sizes[static_cast<std::size_t>(d)], d, 7);
    for (int leaf_size : {drange::engine::search_leaf_size(d), 13, 200})
      expect_tree_search_matches_scan(points, leaf_size, "uniform d=" + std::to_string(d));
  }
  for (int d = 2; d <= 4; ++d) {  // grids: cospherical points, ties broken by the perturbation
    const std::size_t side = d == 2 ? 12 : d == 3 ? 5 : 3;
    std::size_t n = 1;
    for (int k = 0; k < d; ++k) n *= side;
    const PointCloud points = drange::generate_points(drange::Distribution::Grid, n, d, 1);
    for (int leaf_size : {drange::engine::search_leaf_size(d), 200})
      expect_tree_search_matches_scan(points, leaf_size, "grid d=" + std::to_string(d));
  }
}

// The leaf scan's vector loops at both widths: the same apex for both sides of
// every sampled facet, and the same work, point for point (the same doubles in every lane).
// Skipped where the CPU has no AVX2: both would run the two-double loops.
TEST(FacetSearch, WideVectorLoopsMatchTheTwoDoubleOnes) {
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
  if (!__builtin_cpu_supports("avx2")) GTEST_SKIP() << "SKIPPED: this CPU has no AVX2: the AVX2 lane loops were NOT tested";
#else
  GTEST_SKIP() << "SKIPPED: not x86-64: there are no AVX2 lane loops to test";
#endif
  const std::array<std::size_t, 9> sizes = {0, 0, 3000, 1500, 600, 400, 200, 120, 90};
  for (int d = 2; d <= 8; ++d) {
    const PointCloud points = drange::generate_points(drange::Distribution::Uniform, sizes[static_cast<std::size_t>(d)], d, 11);
    for (int leaf_size : {drange::engine::search_leaf_size(d), 13, 200}) {
      const SampledFacets sample(points, leaf_size);
      for (const auto choice : {FacetSearch::KernelChoice::FixedDimension, FacetSearch::KernelChoice::AnyDimension}) {
        const drange::engine::SearchOptions options = drange::engine::search_variant("full");
        FacetSearch wide(sample.store, options, choice, FacetSearch::VectorWidth::Widest);
        FacetSearch narrow(sample.store, options, choice, FacetSearch::VectorWidth::TwoDoubles);
        drange::engine::SearchCounters wide_counters, narrow_counters;
        sample.for_each([&](std::size_t s, int opposite, const std::vector<std::int32_t>& facet, std::int32_t) {
          for (int sigma : {1, -1})
            ASSERT_EQ(wide.find_apex(facet.data(), sigma, wide_counters), narrow.find_apex(facet.data(), sigma, narrow_counters))
                << "d=" << d << " leaf size " << leaf_size << " simplex " << s << " facet " << opposite << " side " << sigma;
        });
        EXPECT_EQ(wide_counters.calls, narrow_counters.calls) << "d=" << d << " leaf size " << leaf_size;
        EXPECT_EQ(wide_counters.points_tested, narrow_counters.points_tested) << "d=" << d << " leaf size " << leaf_size;
        EXPECT_EQ(wide_counters.candidates, narrow_counters.candidates) << "d=" << d << " leaf size " << leaf_size;
      }
    }
  }
}

}  // namespace
