// tests/check_test.cpp: drange::check_triangulation accepts correct triangulations (built by
// hand, or by the brute-force oracle in d = 2..5, in either orientation) and rejects each kind
// of defect with the problem message that names it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "drange/check.hpp"
#include "drange/errors.hpp"
#include "oracle.hpp"

namespace drange::test {
namespace {

PointCloud cloud_of(int dim, const std::vector<double>& coords) {
  PointCloud c;
  c.dim = dim;
  c.coords = coords;
  return c;
}

std::string describe(const CheckReport& report) {
  std::string text = "valid=" + std::to_string(report.valid) + " problems=" + std::to_string(report.problem_count) + "\n";
  for (const std::string& p : report.problems) text += "  " + p + "\n";
  return text;
}

void expect_valid(const PointCloud& points, const std::vector<std::int32_t>& simplices) {
  const CheckReport report = check_triangulation(points, simplices);
  EXPECT_TRUE(report.valid) << describe(report);
  EXPECT_EQ(report.problem_count, 0u) << describe(report);
  EXPECT_EQ(report.simplices, simplices.size() / static_cast<std::size_t>(points.dim + 1));
}

// Expects the report to be invalid with some problem containing `fragment`.
CheckReport expect_problem(const PointCloud& points, const std::vector<std::int32_t>& simplices,
                           const std::string& fragment) {
  const CheckReport report = check_triangulation(points, simplices);
  EXPECT_FALSE(report.valid) << describe(report);
  EXPECT_GE(report.problem_count, report.problems.size());
  const bool found = std::any_of(report.problems.begin(), report.problems.end(),
                                 [&](const std::string& p) { return p.find(fragment) != std::string::npos; });
  EXPECT_TRUE(found) << "expected a problem containing \"" << fragment << "\"\n" << describe(report);
  return report;
}

// The unit square with its centre (point 4), in four triangles.
PointCloud square_with_centre() { return cloud_of(2, {0, 0, 1, 0, 1, 1, 0, 1, 0.5, 0.5}); }
std::vector<std::int32_t> square_fan() { return {0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4}; }

// The unit cube's corners, corner i = (i & 1, (i >> 1) & 1, (i >> 2) & 1).
PointCloud cube() {
  std::vector<double> coords;
  for (int i = 0; i < 8; ++i)
    for (int k = 0; k < 3; ++k) coords.push_back((i >> k) & 1);
  return cloud_of(3, coords);
}

// Kuhn's triangulation: one tetrahedron per order of the axes, along the diagonal 0 -> 7.
std::vector<std::int32_t> cube_kuhn() {
  std::vector<std::int32_t> result;
  int axes[3] = {0, 1, 2};
  do {
    int corner = 0;
    result.push_back(corner);
    for (int a : axes) result.push_back(corner |= 1 << a);
  } while (std::next_permutation(axes, axes + 3));
  return result;
}

// Four corners cut off and the regular tetrahedron (0, 3, 5, 6) in the middle.
std::vector<std::int32_t> cube_five() { return {0, 3, 5, 6, 1, 0, 3, 5, 2, 0, 3, 6, 4, 0, 5, 6, 7, 3, 5, 6}; }

TEST(CheckTest, SquareWithCentre) {
  const CheckReport report = check_triangulation(square_with_centre(), square_fan());
  EXPECT_TRUE(report.valid) << describe(report);
  EXPECT_EQ(report.simplices, 4u);
  EXPECT_EQ(report.interior_facets, 4u);
  EXPECT_EQ(report.boundary_facets, 4u);
}

TEST(CheckTest, CubeSplitsAreDelaunayForCosphericalCorners) {
  // All eight corners lie on one sphere: no point is strictly inside any circumsphere, so
  // every triangulation of the cube is a Delaunay triangulation.
  expect_valid(cube(), cube_kuhn());
  expect_valid(cube(), cube_five());
  const CheckReport report = check_triangulation(cube(), cube_kuhn());
  EXPECT_EQ(report.boundary_facets, 12u);
  EXPECT_EQ(report.interior_facets, 6u);
}

TEST(CheckTest, PerturbedCubeHasOneDelaunayTriangulation) {
  // Perturbed corners are in general position: the oracle's triangulation is accepted, and the
  // two hand-made splits, whenever they differ from it, are rejected.
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    SCOPED_TRACE("seed=" + std::to_string(seed));
    PointCloud points = cube();
    TestRandom random(seed);
    for (double& x : points.coords) x += 1e-3 * (random.uniform() - 0.5);
    const std::vector<Simplex> delaunay = brute_force_delaunay(points);
    expect_valid(points, flatten(delaunay));
    for (const auto& split : {cube_kuhn(), cube_five()}) {
      if (canonical(split, 3) == delaunay) continue;
      EXPECT_FALSE(check_triangulation(points, split).valid);
    }
  }
}

TEST(CheckTest, OracleTriangulationsAreAcceptedInDimensionsTwoToFive) {
  for (int d = 2; d <= 5; ++d) {
    const int max_n = d <= 3 ? 12 : (d == 4 ? 10 : 9);
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
      const std::size_t n = static_cast<std::size_t>(d + 2 + static_cast<int>(seed % static_cast<std::uint64_t>(max_n - d - 1)));
      SCOPED_TRACE("d=" + std::to_string(d) + " n=" + std::to_string(n) + " seed=" + std::to_string(seed));
      const PointCloud points = random_points(n, d, seed);
      const std::vector<Simplex> delaunay = brute_force_delaunay(points);
      ASSERT_FALSE(delaunay.empty());
      expect_valid(points, flatten(delaunay));
    }
  }
}

TEST(CheckTest, EitherOrientationOfEverySimplexIsAccepted) {
  for (int d = 2; d <= 4; ++d) {
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
      SCOPED_TRACE("d=" + std::to_string(d) + " seed=" + std::to_string(seed));
      const PointCloud points = random_points(static_cast<std::size_t>(d + 6), d, seed + 100);
      std::vector<std::int32_t> flat = flatten(brute_force_delaunay(points));
      const CheckReport reference = check_triangulation(points, flat);
      ASSERT_TRUE(reference.valid) << describe(reference);
      TestRandom random(seed);
      const std::size_t width = static_cast<std::size_t>(d + 1);
      for (std::size_t s = 0; s < flat.size(); s += width) {
        if (random.next() & 1) std::swap(flat[s], flat[s + 1]);  // reverses the orientation
        std::rotate(flat.begin() + static_cast<std::ptrdiff_t>(s), flat.begin() + static_cast<std::ptrdiff_t>(s + random.next() % width),
                    flat.begin() + static_cast<std::ptrdiff_t>(s + width));
      }
      const CheckReport report = check_triangulation(points, flat);
      EXPECT_TRUE(report.valid) << describe(report);
      EXPECT_EQ(report.interior_facets, reference.interior_facets);
      EXPECT_EQ(report.boundary_facets, reference.boundary_facets);
    }
  }
}

TEST(CheckTest, ExactDuplicatesMayBeLeftOut) {
  PointCloud points = square_with_centre();
  for (int k = 0; k < 2; ++k) points.coords.push_back(points.coords[2 * 2 + k]);  // a copy of point 2
  expect_valid(points, square_fan());
}

// ---- Defects. ----

TEST(CheckTest, RejectsIndexOutOfRange) {
  std::vector<std::int32_t> simplices = square_fan();
  simplices[4] = 7;
  expect_problem(square_with_centre(), simplices, "simplex 1 (1 7 4): vertex index 7 is out of range");
  simplices[4] = -1;
  expect_problem(square_with_centre(), simplices, "vertex index -1 is out of range");
}

TEST(CheckTest, RejectsRepeatedVertex) {
  std::vector<std::int32_t> simplices = square_fan();
  simplices[5] = 1;
  expect_problem(square_with_centre(), simplices, "simplex 1 (1 2 1): vertex 1 is repeated");
}

TEST(CheckTest, RejectsFlatSimplex) {
  // Points 0, 1, 2 are collinear; (0, 1, 3), (1, 2, 3) triangulate them with 3, and the flat
  // triangle (0, 1, 2) is extra.
  const PointCloud points = cloud_of(2, {0, 0, 1, 0, 2, 0, 1, 1});
  expect_valid(points, {0, 1, 3, 1, 2, 3});
  expect_problem(points, {0, 1, 3, 1, 2, 3, 0, 1, 2}, "simplex 2 (0 1 2): flat (zero volume)");
}

TEST(CheckTest, RejectsMissingCornerSimplex) {
  // Without the triangle (1, 2, 4) the edges from the centre face a notch.
  std::vector<std::int32_t> simplices = square_fan();
  simplices.erase(simplices.begin() + 3, simplices.begin() + 6);
  expect_problem(square_with_centre(), simplices, "does not support the hull");
}

TEST(CheckTest, RejectsInteriorHole) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    SCOPED_TRACE("seed=" + std::to_string(seed));
    const PointCloud points = random_points(12, 2, seed + 7);
    const std::vector<Simplex> delaunay = brute_force_delaunay(points);
    // Remove a simplex none of whose facets is on the boundary (all shared).
    const CheckReport full = check_triangulation(points, flatten(delaunay));
    ASSERT_TRUE(full.valid) << describe(full);
    for (std::size_t s = 0; s < delaunay.size(); ++s) {
      std::vector<Simplex> holed = delaunay;
      holed.erase(holed.begin() + static_cast<std::ptrdiff_t>(s));
      const CheckReport report = check_triangulation(points, flatten(holed));
      if (report.boundary_facets != full.boundary_facets + 3) continue;  // s touched the boundary
      expect_problem(points, flatten(holed), "does not support the hull");
      break;
    }
  }
}

TEST(CheckTest, RejectsOverlappingExtraSimplex) {
  std::vector<std::int32_t> simplices = square_fan();
  simplices.insert(simplices.end(), {0, 1, 2});
  expect_problem(square_with_centre(), simplices, "both lie on the same side of it (they overlap)");
}

TEST(CheckTest, RejectsNonDelaunayFlip2D) {
  // Four points in convex position: the Delaunay diagonal is (1, 3); (0, 2) is not.
  const PointCloud points = cloud_of(2, {0, 0, 2, -0.2, 4, 0, 2, 3});
  expect_valid(points, {0, 1, 3, 1, 2, 3});
  expect_problem(points, {0, 1, 2, 0, 2, 3}, "not Delaunay: point 3 (of simplex 1) is strictly inside the circumsphere of simplex 0");
}

TEST(CheckTest, RejectsNonDelaunayFlip3D) {
  // A flat bipyramid: apexes 3, 4 at height 1/2 over the triangle (0, 1, 2) on the unit
  // circle; the apex of one tetrahedron is inside the other's sphere, so the Delaunay
  // triangulation is the three tetrahedra around the axis (3, 4), not the two on the triangle.
  const double s = std::sqrt(3.0) / 2;
  const PointCloud points = cloud_of(3, {1, 0, 0, -0.5, s, 0, -0.5, -s, 0, 0, 0, 0.5, 0, 0, -0.5});
  expect_valid(points, {3, 4, 0, 1, 3, 4, 1, 2, 3, 4, 2, 0});
  EXPECT_EQ(canonical({3, 4, 0, 1, 3, 4, 1, 2, 3, 4, 2, 0}, 3), brute_force_delaunay(points));
  expect_problem(points, {0, 1, 2, 3, 0, 1, 2, 4}, "not Delaunay");
}

TEST(CheckTest, RejectsUnusedPoint) {
  PointCloud points = square_with_centre();
  points.coords.insert(points.coords.end(), {0.25, 0.5});
  expect_problem(points, square_fan(), "point 5 (0.25 0.5) is in no simplex");
  // Outside the hull, it is also beyond a boundary facet.
  points.coords.back() = -1;
  expect_problem(points, square_fan(), "is in no simplex");
  expect_problem(points, square_fan(), "point 5 is strictly beyond it");
}

TEST(CheckTest, RejectsFacetSharedThreeTimes) {
  // Edge (0, 1) under three triangles, two on one side.
  const PointCloud points = cloud_of(2, {0, 0, 1, 0, 0.5, 1, 0.5, -1, 0.5, 2});
  expect_problem(points, {0, 1, 2, 0, 1, 3, 0, 1, 4}, "facet (0 1) is shared by 3 simplices (0 1 2)");
}

TEST(CheckTest, RejectsDoubleCoveringThatPassesEveryLocalTest) {
  // Two triangulations of the same nine points (a 2x2 square with its edge midpoints and
  // centre) that share no edge: a fan of the corners around the centre, and a diamond of the
  // midpoints with the four corner triangles. Their union pairs every facet correctly, every
  // boundary edge supports the hull (the midpoints lie on the corner fan's edges), every
  // interior edge is locally Delaunay, and the volume identity holds (twice the area, twice
  // the boundary). Only the centroid count sees that the hull is covered twice. (The centroid
  // (1, 1/3) of simplex 0 lies on the edge shared by simplices 4 and 7: three closed simplices.)
  const PointCloud points = cloud_of(2, {0, 0, 2, 0, 2, 2, 0, 2, 1, 0, 2, 1, 1, 2, 0, 1, 1, 1});
  const std::vector<std::int32_t> corner_fan = {8, 0, 1, 8, 1, 2, 8, 2, 3, 8, 3, 0};
  const std::vector<std::int32_t> diamond = {8, 4, 5, 8, 5, 6, 8, 6, 7, 8, 7, 4, 0, 4, 7, 1, 5, 4, 2, 6, 5, 3, 7, 6};
  expect_valid(points, diamond);
  std::vector<std::int32_t> both = corner_fan;
  both.insert(both.end(), diamond.begin(), diamond.end());
  const CheckReport report = expect_problem(points, both, "the centroid of simplex 0 lies in 3 simplices (0 4 7)");
  EXPECT_EQ(report.problem_count, 1u) << describe(report);
}

TEST(CheckTest, RejectsWindingTwiceAroundTheCentre) {
  // A pentagram fan around the centre of a regular pentagon: every edge from the centre is
  // shared from opposite sides, but the fan turns twice; its boundary edges (the pentagram's)
  // do not support the hull and the inner pentagon is covered twice.
  std::vector<double> coords = {0, 0};
  const double pi = std::acos(-1.0);
  for (int i = 0; i < 5; ++i) coords.insert(coords.end(), {std::cos(2 * pi * i / 5), std::sin(2 * pi * i / 5)});
  const PointCloud points = cloud_of(2, coords);
  expect_valid(points, {0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 5, 0, 5, 1});
  const std::vector<std::int32_t> star = {0, 1, 3, 0, 3, 5, 0, 5, 2, 0, 2, 4, 0, 4, 1};
  expect_problem(points, star, "lies in 2 simplices");
  expect_problem(points, star, "does not support the hull");
}

TEST(CheckTest, RejectsLocallyConvexBoundaryThatWindsTwice) {
  // The pentagram fan again, with its first triangle split by a point T near corner 1, so that
  // simplex 0 lies in a tip of the star, where the fan covers once: the centroid count is 1,
  // every facet pairs up, the boundary (the pentagram) turns the same way at every corner.
  // Only the test that the centroid is inside every boundary facet sends the validator to the
  // direct test, which finds corner 1 beyond the pentagram edge (2 5).
  std::vector<double> coords = {0, 0};
  const double pi = std::acos(-1.0);
  for (int i = 0; i < 5; ++i) coords.insert(coords.end(), {std::cos(2 * pi * i / 5), std::sin(2 * pi * i / 5)});
  const double t[2] = {0.7 * coords[2] + 0.2 * coords[6], 0.7 * coords[3] + 0.2 * coords[7]};
  coords.insert(coords.end(), {t[0], t[1]});  // point 6
  const PointCloud points = cloud_of(2, coords);
  const std::vector<std::int32_t> star = {0, 1, 6, 1, 3, 6, 3, 0, 6, 0, 3, 5, 0, 5, 2, 0, 2, 4, 0, 4, 1};
  const CheckReport report = expect_problem(points, star, "does not support the hull");
  for (const std::string& p : report.problems) EXPECT_EQ(p.find("centroid"), std::string::npos) << p;
}

// Points one rounding error away from a boundary edge, at coordinates near 1e9: the plane
// filter must not decide these in floating point.
TEST(CheckTest, HullEdgeDecidedExactlyAtLargeCoordinates) {
  int reflex_cases = 0;
  for (std::uint64_t seed = 1; seed <= 300; ++seed) {
    SCOPED_TRACE("seed=" + std::to_string(seed));
    TestRandom random(seed);
    std::vector<double> c(6);
    for (double& x : c) x = 1e9 * random.uniform();
    PointCloud points = cloud_of(2, {c[0], c[1], c[2], c[3], c[4], c[5], 0, 0});
    const double* a = points.point(0);
    const double* b = points.point(1);
    const int c_side = reference_orientation(2, corners(points, {0, 1, 2}));
    if (c_side == 0) continue;
    // P near the middle of AB, nudged one ulp at a time until it is strictly on C's side
    // (then the boundary A-P-B is reflex at P) or strictly on the other side.
    const bool reflex = seed % 2 == 0;
    const int wanted = reflex ? c_side : -c_side;
    double* p = &points.coords[6];
    p[0] = a[0] + 0.5 * (b[0] - a[0]);
    p[1] = a[1] + 0.5 * (b[1] - a[1]);
    // Nudge the coordinate with the larger lever: d orientation / d p_y = b_x - a_x, and
    // d orientation / d p_x = -(b_y - a_y).
    const bool move_y = std::fabs(b[0] - a[0]) >= std::fabs(b[1] - a[1]);
    const double lever = move_y ? b[0] - a[0] : -(b[1] - a[1]);
    double& moved = p[move_y ? 1 : 0];
    for (int step = 0; step < 64 && reference_orientation(2, corners(points, {0, 1, 3})) != wanted; ++step)
      moved = std::nextafter(moved, wanted * lever > 0 ? INFINITY : -INFINITY);
    ASSERT_EQ(reference_orientation(2, corners(points, {0, 1, 3})), wanted);
    const std::vector<std::int32_t> split = {0, 3, 2, 3, 1, 2};
    const CheckReport report = check_triangulation(points, split);
    const bool unsupported = std::any_of(report.problems.begin(), report.problems.end(), [](const std::string& line) {
      return line.find("does not support the hull") != std::string::npos;
    });
    EXPECT_EQ(unsupported, reflex) << describe(report);
    if (reflex) ++reflex_cases;
  }
  EXPECT_GT(reflex_cases, 100);
}

// The integer grid {0..5}^2, each unit square split by the same diagonal: every four corners
// of a square are cocircular, so it is a Delaunay triangulation (no point strictly inside).
PointCloud grid_points(int k) {
  PointCloud points;
  points.dim = 2;
  for (int y = 0; y < k; ++y)
    for (int x = 0; x < k; ++x) points.coords.insert(points.coords.end(), {double(x), double(y)});
  return points;
}

std::vector<std::int32_t> grid_triangles(int k) {
  std::vector<std::int32_t> result;
  for (int y = 0; y + 1 < k; ++y)
    for (int x = 0; x + 1 < k; ++x) {
      const std::int32_t a = y * k + x, b = a + 1, c = a + k, e = a + k + 1;
      result.insert(result.end(), {a, b, e, a, e, c});
    }
  return result;
}

TEST(CheckTest, GridWithCollinearHullPoints) {
  expect_valid(grid_points(6), grid_triangles(6));
  const CheckReport report = check_triangulation(grid_points(6), grid_triangles(6));
  EXPECT_EQ(report.boundary_facets, 20u);
  // A point left of the grid: the five collinear edges of the left side are one hull facet;
  // they are tested, and reported, once.
  PointCloud points = grid_points(6);
  points.coords.insert(points.coords.end(), {-1, 2.5});
  const CheckReport outside = expect_problem(points, grid_triangles(6), "point 36 is strictly beyond it (as beyond its 4 coplanar neighbours)");
  EXPECT_EQ(outside.problem_count, 2u) << describe(outside);
}

TEST(CheckTest, CapsMessagesButCountsEveryProblem) {
  PointCloud points = square_with_centre();
  for (int i = 0; i < 30; ++i) points.coords.insert(points.coords.end(), {0.1 + 0.01 * i, 0.3});
  const CheckReport report = check_triangulation(points, square_fan(), 5);
  EXPECT_FALSE(report.valid);
  EXPECT_EQ(report.problems.size(), 5u);
  EXPECT_EQ(report.problem_count, 30u) << describe(report);
}

TEST(CheckTest, NonFiniteCoordinateIsAProblemNotACrash) {
  PointCloud points = square_with_centre();
  points.coords[9] = std::numeric_limits<double>::quiet_NaN();
  expect_problem(points, square_fan(), "point 4 (0.5 nan) has a non-finite coordinate");
}

TEST(CheckTest, EmptyTriangulationOfPointsIsAProblem) {
  expect_problem(square_with_centre(), {}, "no simplices");
  const CheckReport nothing = check_triangulation(cloud_of(2, {}), {});
  EXPECT_TRUE(nothing.valid);
}

TEST(CheckTest, MismatchedDimensionsThrowUsageError) {
  EXPECT_THROW(check_triangulation(square_with_centre(), {0, 1, 4, 1}), UsageError);
  EXPECT_THROW(check_triangulation(cloud_of(1, {0, 1}), {0, 1}), UsageError);
}

}  // namespace
}  // namespace drange::test
