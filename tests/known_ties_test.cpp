// The remembered ties (geometry/known_ties.hpp): what a set answers, how it grows, and that a
// triangulation whose ties are exact but not dyadic is the same with them and without, with far
// fewer exact evaluations.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "geometry/known_ties.hpp"
#include "drange/check.hpp"
#include "drange/delaunay.hpp"
#include "oracle.hpp"

namespace {

using drange::geometry::KnownTies;

TEST(KnownTies, AnswersOnlyWhatWasRecorded) {
  KnownTies ties(3, 100);  // hyperplanes in 3D: three points define one
  const std::int32_t facet[] = {4, 9, 2};
  EXPECT_FALSE(ties.holds(facet, 7));
  ties.record(facet, 7);
  EXPECT_TRUE(ties.holds(facet, 7));
  EXPECT_FALSE(ties.holds(facet, 8));
  // Any three of the set define the same plane, in any order: 2 is on the plane of 7, 9, 4.
  const std::int32_t other[] = {7, 9, 4};
  EXPECT_TRUE(ties.holds(other, 2));
  // A simplex with a point outside the set says nothing, even about the set's points.
  const std::int32_t outside[] = {7, 9, 8};
  EXPECT_FALSE(ties.holds(outside, 4));
}

TEST(KnownTies, GrowsTheSetOfItsSimplex) {
  KnownTies ties(3, 100);
  const std::int32_t first[] = {1, 2, 3};
  ties.record(first, 4);
  // Learned through another simplex of the same set: the same plane, so the same set.
  const std::int32_t second[] = {2, 3, 4};
  ties.record(second, 5);
  EXPECT_TRUE(ties.holds(first, 5));
  const std::int32_t third[] = {1, 4, 5};
  EXPECT_TRUE(ties.holds(third, 3));
  // A simplex that shares only two points starts a set of its own.
  const std::int32_t apart[] = {1, 2, 6};
  ties.record(apart, 7);
  EXPECT_TRUE(ties.holds(apart, 7));
  EXPECT_FALSE(ties.holds(first, 7));
  EXPECT_FALSE(ties.holds(apart, 3));
}

TEST(KnownTies, ForgetsWhenFullAndLearnsAgain) {
  // Far more facts than links: the sets are forgotten and the latest facts kept.
  KnownTies ties(2, 1 << 20);
  const std::int32_t sets = static_cast<std::int32_t>((KnownTies::kMinLinks + KnownTies::kLinksPerPoint * (1 << 20)) / 3 + 10);
  for (std::int32_t s = 0; s < sets; ++s) {
    const std::int32_t pair[] = {3 * s % (1 << 20), (3 * s + 1) % (1 << 20)};
    ties.record(pair, (3 * s + 2) % (1 << 20));
  }
  const std::int32_t last[] = {3 * (sets - 1) % (1 << 20), (3 * (sets - 1) + 1) % (1 << 20)};
  EXPECT_TRUE(ties.holds(last, (3 * (sets - 1) + 2) % (1 << 20)));
  const std::int32_t first[] = {0, 1};
  EXPECT_FALSE(ties.holds(first, 2));
}

// A grid in cylindrical coordinates: any two of its vertical lines lie in one plane and any
// four corners of a vertical face on one circle, exactly, but the coordinates (r cos t, r sin t)
// are not dyadic, so no filter decides those ties.
drange::PointCloud cylindrical_grid(int rings, int angles, int levels) {
  drange::PointCloud points{3, {}};
  const double pi = std::acos(-1.0);
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < angles; ++j)
      for (int k = 0; k < levels; ++k) {
        const double r = 1.0 + i / (rings - 1.0), t = 2 * pi * j / angles;
        points.coords.insert(points.coords.end(), {r * std::cos(t), r * std::sin(t), k / (levels - 1.0)});
      }
  return points;
}

drange::Triangulation triangulate(const drange::PointCloud& points, const char* variant, int threads = 1) {
  drange::Options options;
  options.variant = variant;
  options.threads = threads;
  return drange::delaunay(points, options);
}

TEST(KnownTies, CylindricalGridTheSameWithFewerExactEvaluations) {
  const drange::PointCloud points = cylindrical_grid(5, 16, 10);
  const drange::Triangulation with = triangulate(points, "full"), without = triangulate(points, "no-tie-memory");
  EXPECT_EQ(drange::test::canonical(with.simplices, 3), drange::test::canonical(without.simplices, 3));
  EXPECT_EQ(drange::test::canonical(triangulate(points, "full", 2).simplices, 3), drange::test::canonical(with.simplices, 3));
  const drange::CheckReport report = drange::check_triangulation(points, with.simplices);
  EXPECT_TRUE(report.valid) << (report.problems.empty() ? "" : report.problems.front());
  // With the memory, well under two thirds of the exact evaluations made without it, and a
  // smaller share still on larger grids of this kind. (The fixed-width stage, asked first
  // where ties dominate, decides some ties without the memory that it would have known.)
  EXPECT_GT(without.stats.debug.exact_fallbacks, 10000u);
  EXPECT_LT(with.stats.debug.exact_fallbacks * 3, without.stats.debug.exact_fallbacks * 2);
}

}  // namespace
