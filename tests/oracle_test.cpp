// tests/oracle_test.cpp: the brute-force oracle on cases known by hand, and the engine
// (drange::delaunay) against it on tiny random inputs in general position, d = 2..5.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "drange/check.hpp"
#include "drange/delaunay.hpp"
#include "oracle.hpp"

namespace drange::test {
namespace {

TEST(OracleTest, FourPointsInConvexPosition) {
  PointCloud points;
  points.dim = 2;
  points.coords = {0, 0, 2, -0.2, 4, 0, 2, 3};
  EXPECT_EQ(brute_force_delaunay(points), (std::vector<Simplex>{{0, 1, 3}, {1, 2, 3}}));
}

TEST(OracleTest, CosphericalPointsGiveNoSimplexThrough) {
  // The square's corners are cocircular: no triangle has an empty open-and-closed circle, so
  // the oracle (which requires general position) returns nothing. This pins its definition.
  PointCloud points;
  points.dim = 2;
  points.coords = {0, 0, 1, 0, 1, 1, 0, 1};
  EXPECT_TRUE(brute_force_delaunay(points).empty());
}

TEST(OracleTest, CanonicalSortsRowsAndTuples) {
  EXPECT_EQ(canonical({4, 1, 2, 0, 3, 1}, 2), (std::vector<Simplex>{{0, 1, 3}, {1, 2, 4}}));
  EXPECT_EQ(flatten({{0, 1, 3}, {1, 2, 4}}), (std::vector<std::int32_t>{0, 1, 3, 1, 2, 4}));
}

TEST(OracleTest, RandomGeneratorIsFixed) {
  TestRandom random(42);
  const std::uint64_t first = random.next();
  TestRandom again(42);
  EXPECT_EQ(again.next(), first);
  EXPECT_NE(TestRandom(43).next(), first);
  for (int i = 0; i < 1000; ++i) {
    const double u = random.uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
  }
}

TEST(OracleTest, EngineMatchesBruteForceOnTinyInputs) {
  for (int d = 2; d <= 5; ++d) {
    const int max_n = d <= 3 ? 12 : (d == 4 ? 10 : 9);
    for (std::uint64_t seed = 1; seed <= 8; ++seed) {
      const std::size_t n = static_cast<std::size_t>(d + 2 + static_cast<int>(seed % static_cast<std::uint64_t>(max_n - d - 1)));
      SCOPED_TRACE("d=" + std::to_string(d) + " n=" + std::to_string(n) + " seed=" + std::to_string(seed + 1000));
      const PointCloud points = random_points(n, d, seed + 1000);
      const std::vector<Simplex> expected = brute_force_delaunay(points);
      const Triangulation result = delaunay(points);
      EXPECT_EQ(canonical(result.simplices, d), expected);
      EXPECT_TRUE(check_triangulation(points, result.simplices).valid);
    }
  }
}

}  // namespace
}  // namespace drange::test
