// tests/hull_edges_test.cpp: the clean hull edges of 2D point sets (delaunay/hull_edges.cpp)
// against a brute-force oracle, and the search that skips their outer sides
// (SearchOptions::known_hull_facets).
//
// A pair (f0, f1) is a clean hull edge when every other point lies strictly on one side of its
// line (exact rational orientations, tests/oracle.hpp); outer_sigma must then name the other
// side, and 0 for every other pair. The families put points exactly on hull edges (integer
// grids, a square's boundary, a triangle's sides), in convex position (circles, a regular
// polygon), near the hull within rounding, and inside; the filter of the octagon and the two
// chains must get every one of them right.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "delaunay/hull_edges.hpp"
#include "delaunay/hull_triangles.hpp"
#include "delaunay/point_store.hpp"
#include "delaunay/prepare_points.hpp"
#include "delaunay/team.hpp"
#include "drange/check.hpp"
#include "drange/delaunay.hpp"
#include "drange/generate.hpp"
#include "oracle.hpp"

namespace {

using drange::PointCloud;
using drange::engine::HullEdges;
using drange::engine::PointStore;

PointStore store_of(const PointCloud& points, int leaf_size) {
  std::vector<drange::Duplicate> duplicates;
  drange::engine::Team team(1);
  return drange::engine::prepare_points(points, leaf_size, duplicates, team);
}

// The sign of det[b - a; c - a]: in long double where it is far from 0 (a margin a million
// times its rounding), else exactly (GMP rationals, tests/oracle.hpp), which is slow.
int orientation(const double* a, const double* b, const double* c) {
  const long double left = (static_cast<long double>(b[0]) - a[0]) * (static_cast<long double>(c[1]) - a[1]);
  const long double right = (static_cast<long double>(b[1]) - a[1]) * (static_cast<long double>(c[0]) - a[0]);
  const long double det = left - right, margin = 1e-12L * (std::fabs(left) + std::fabs(right));
  if (det > margin) return 1;
  if (det < -margin) return -1;
  return drange::test::reference_orientation(2, {a, b, c});
}

// The outer side's sigma of every pair of ids, by definition: -1 when every other point has
// O(x) = det[f1 - f0; x - f0] > 0, +1 when every other has O(x) < 0, else 0.
int outer_sigma_by_definition(const PointStore& store, std::int32_t f0, std::int32_t f1) {
  bool all_positive = true, all_negative = true;
  for (std::int32_t x = 0; x < store.size && (all_positive || all_negative); ++x) {
    if (x == f0 || x == f1) continue;
    const int sign = orientation(store.point(f0), store.point(f1), store.point(x));
    all_positive = all_positive && sign > 0;
    all_negative = all_negative && sign < 0;
  }
  return all_positive ? -1 : all_negative ? 1 : 0;
}

// Checks every ordered pair; returns the number of clean edges seen.
std::size_t expect_matches_definition(const PointCloud& points, const std::string& what) {
  std::size_t clean = 0;
  for (const int leaf_size : {8, 64}) {
    const PointStore store = store_of(points, leaf_size);
    const HullEdges hull(store, 0, 1u << 30);  // kept whatever its size
    clean = 0;
    for (std::int32_t f0 = 0; f0 < store.size; ++f0)
      for (std::int32_t f1 = 0; f1 < store.size; ++f1) {
        if (f0 == f1) continue;
        const int expected = outer_sigma_by_definition(store, f0, f1);
        if (hull.outer_sigma(f0, f1) != expected) {
          ADD_FAILURE() << what << ", leaf size " << leaf_size << ", ids " << f0 << " " << f1 << ": outer sigma "
                        << hull.outer_sigma(f0, f1) << ", expected " << expected;
          return clean;
        }
        clean += expected == -1;
      }
    EXPECT_EQ(hull.clean_edges(), clean) << what;
  }
  return clean;
}

PointCloud cloud(std::vector<double> coords) { return PointCloud{2, std::move(coords)}; }

PointCloud circle(std::size_t n, double radius, std::uint64_t seed) {
  drange::test::TestRandom random(seed);
  PointCloud points{2, {}};
  for (std::size_t i = 0; i < n; ++i) {
    const double t = 2 * M_PI * random.uniform();
    points.coords.insert(points.coords.end(), {radius * std::cos(t), radius * std::sin(t)});
  }
  return points;
}

TEST(HullEdges, MatchTheDefinitionOnConvexPosition) {
  EXPECT_EQ(expect_matches_definition(circle(60, 1.0, 1), "circle"), 60u);
  EXPECT_EQ(expect_matches_definition(circle(40, 1e-3, 2), "small circle"), 40u);
  PointCloud polygon{2, {}};
  for (int i = 0; i < 24; ++i) polygon.coords.insert(polygon.coords.end(), {std::cos(M_PI * i / 12), std::sin(M_PI * i / 12)});
  EXPECT_EQ(expect_matches_definition(polygon, "regular 24-gon"), 24u);
  EXPECT_EQ(expect_matches_definition(cloud({0, 0, 1, 0, 0, 1}), "triangle"), 3u);
}

TEST(HullEdges, LeaveEdgesWithPointsOnThemToTheSearch) {
  // An integer grid: every side of its hull holds grid points, so no edge is clean.
  EXPECT_EQ(expect_matches_definition(drange::generate_points(drange::Distribution::Grid, 49, 2, 1), "7 x 7 grid"), 0u);
  // A square's boundary with one side's midpoint, and points inside: three sides clean.
  EXPECT_EQ(expect_matches_definition(cloud({0, 0, 2, 0, 2, 2, 0, 2, 1, 0, 1, 1, 0.5, 1.5}), "square, one side split"), 3u);
  // A triangle with points on two sides and a vertical side (the chains' ends).
  EXPECT_EQ(expect_matches_definition(cloud({0, 0, 0, 4, 4, 0, 0, 1, 0, 3, 2, 2, 1, 1}), "triangle, two sides split"), 1u);
  // Points within rounding of the side x + y = 1: in binary, 0.1 + 0.9 is not 1, and each
  // such point lies just inside or just outside, as the exact orientation (not the filter)
  // says; the sides on the axes stay clean.
  EXPECT_GE(expect_matches_definition(cloud({0, 0, 1, 0, 0, 1, 0.1, 0.9, 0.2, 0.8, 0.3, 0.7, 0.4, 0.6, 0.7, 0.3, 0.9, 0.1, 0.25, 0.25}),
                                      "near the side x + y = 1"),
            2u);
}

TEST(HullEdges, MatchTheDefinitionOnRandomAndMixedInput) {
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    expect_matches_definition(drange::generate_points(drange::Distribution::Uniform, 150, 2, seed), "uniform");
    // A circle around a uniform interior, and a circle with a few points outside it.
    PointCloud mixed = circle(80, 1.0, seed);
    const PointCloud inside = drange::generate_points(drange::Distribution::Uniform, 60, 2, seed + 10);
    for (const double c : inside.coords) mixed.coords.push_back(c - 0.5);
    expect_matches_definition(mixed, "circle around uniform");
    mixed.coords.insert(mixed.coords.end(), {3.0, 0.0, 0.0, -3.0, 2.9, 0.1});
    expect_matches_definition(mixed, "circle and outliers");
  }
}

TEST(HullEdges, AreKeptOnlyForLargeHulls) {
  const PointStore uniform = store_of(drange::generate_points(drange::Distribution::Uniform, 20000, 2, 3), 64);
  EXPECT_FALSE(HullEdges(uniform).active());
  EXPECT_GT(HullEdges(uniform).clean_edges(), 5u);
  EXPECT_LT(HullEdges(uniform).candidates(), 2000u) << "the octagon should leave few interior points";
  const PointStore ring = store_of(circle(2000, 1.0, 4), 64);
  const HullEdges on_circle(ring);
  EXPECT_TRUE(on_circle.active());
  EXPECT_EQ(on_circle.clean_edges(), 2000u);
  EXPECT_FALSE(HullEdges(store_of(drange::generate_points(drange::Distribution::Uniform, 500, 3, 5), 64)).active());
}

drange::Triangulation triangulate(const PointCloud& points, const char* variant, int threads) {
  drange::Options options;
  options.variant = variant;
  options.threads = threads;
  return drange::delaunay(points, options);
}

// With the hull's facets known and without: the same valid triangulation, on one thread and on
// three, with fewer kd-tree calls.
void expect_same_with_fewer_calls(const PointCloud& points) {
  const drange::Triangulation with = triangulate(points, "full", 1), without = triangulate(points, "no-hull", 1);
  EXPECT_EQ(with.simplices, without.simplices);
  EXPECT_EQ(with.neighbors, without.neighbors);
  EXPECT_EQ(with.stats.hull_facets, without.stats.hull_facets);
  EXPECT_LT(with.stats.search_calls, without.stats.search_calls);
  EXPECT_TRUE(drange::check_triangulation(points, with.simplices).valid);
  EXPECT_EQ(triangulate(points, "full", 3).simplices, with.simplices) << "3 threads";
}

TEST(HullEdges, TheSearchFindsTheSameValidTriangulationWithFewerCalls) {
  PointCloud two_circles = circle(3000, 1.0, 6);
  const PointCloud inner = circle(1000, 0.5, 7);
  two_circles.coords.insert(two_circles.coords.end(), inner.coords.begin(), inner.coords.end());
  expect_same_with_fewer_calls(circle(3000, 1.0, 5));
  expect_same_with_fewer_calls(two_circles);
}

}  // namespace

// ---- 3D: the clean hull facets (delaunay/hull_triangles.cpp). ----

namespace {

using drange::engine::HullTriangles;

int orientation3(const double* a, const double* b, const double* c, const double* x) {
  long double u[3], v[3], w[3];
  for (int k = 0; k < 3; ++k) {
    u[k] = static_cast<long double>(b[k]) - a[k];
    v[k] = static_cast<long double>(c[k]) - a[k];
    w[k] = static_cast<long double>(x[k]) - a[k];
  }
  const long double t0 = u[0] * (v[1] * w[2] - v[2] * w[1]), t1 = u[1] * (v[2] * w[0] - v[0] * w[2]),
                    t2 = u[2] * (v[0] * w[1] - v[1] * w[0]);
  const long double det = t0 + t1 + t2, margin = 1e-12L * (std::fabs(t0) + std::fabs(t1) + std::fabs(t2));
  if (det > margin) return 1;
  if (det < -margin) return -1;
  return drange::test::reference_orientation(3, {a, b, c, x});
}

// -1 when every other point has O(x) = det[f1 - f0; f2 - f0; x - f0] > 0, +1 when every other
// has O(x) < 0, else 0.
int outer_sigma_3d_by_definition(const PointStore& store, const std::int32_t* f) {
  bool all_positive = true, all_negative = true;
  for (std::int32_t x = 0; x < store.size && (all_positive || all_negative); ++x) {
    if (x == f[0] || x == f[1] || x == f[2]) continue;
    const int sign = orientation3(store.point(f[0]), store.point(f[1]), store.point(f[2]), store.point(x));
    all_positive = all_positive && sign > 0;
    all_negative = all_negative && sign < 0;
  }
  return all_positive ? -1 : all_negative ? 1 : 0;
}

// Every sorted triple against the definition; with `general` (no four points coplanar on the
// hull) the hull must be kept, else it may give up (then it keeps nothing). Returns the clean
// facets by definition.
std::size_t expect_3d_matches_definition(const PointCloud& points, bool general, const std::string& what) {
  const PointStore store = store_of(points, 8);
  const HullTriangles hull(store, 1u << 30, 0);  // no sample, kept whatever its size
  EXPECT_TRUE(hull.built()) << what;
  if (general) EXPECT_TRUE(hull.active()) << what;
  std::size_t clean = 0;
  for (std::int32_t a = 0; a < store.size; ++a)
    for (std::int32_t b = a + 1; b < store.size; ++b)
      for (std::int32_t c = b + 1; c < store.size; ++c) {
        const std::int32_t f[3] = {a, b, c};
        const int expected = outer_sigma_3d_by_definition(store, f);
        clean += expected != 0;
        if (!hull.active()) continue;
        if (hull.outer_sigma(f) != expected) {
          ADD_FAILURE() << what << ", ids " << a << " " << b << " " << c << ": outer sigma " << hull.outer_sigma(f)
                        << ", expected " << expected;
          return clean;
        }
      }
  if (hull.active()) EXPECT_EQ(hull.clean_facets(), clean) << what;
  return clean;
}

PointCloud sphere_points(std::size_t n, const double (&axes)[3], std::uint64_t seed) {
  drange::test::TestRandom random(seed);
  PointCloud points{3, {}};
  for (std::size_t i = 0; i < n; ++i) {
    const double z = 2 * random.uniform() - 1, t = 2 * M_PI * random.uniform(), r = std::sqrt(1 - z * z);
    points.coords.insert(points.coords.end(), {axes[0] * r * std::cos(t), axes[1] * r * std::sin(t), axes[2] * z});
  }
  return points;
}

TEST(HullTriangles, MatchTheDefinitionInGeneralPosition) {
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const PointCloud sphere = sphere_points(40, {1, 1, 1}, seed);
    EXPECT_EQ(expect_3d_matches_definition(sphere, true, "sphere"), 2 * 40u - 4);
    expect_3d_matches_definition(sphere_points(40, {1, 0.7, 0.4}, seed + 10), true, "ellipsoid");
    // A sphere around a uniform interior, and a uniform cube (a small hull).
    PointCloud mixed = sphere_points(30, {1, 1, 1}, seed + 20);
    const PointCloud inside = drange::generate_points(drange::Distribution::Uniform, 20, 3, seed + 30);
    for (const double c : inside.coords) mixed.coords.push_back(c - 0.5);
    expect_3d_matches_definition(mixed, true, "sphere around uniform");
    expect_3d_matches_definition(drange::generate_points(drange::Distribution::Uniform, 50, 3, seed), true, "uniform");
  }
}

TEST(HullTriangles, GiveUpOrMatchOnCoplanarPoints) {
  // A cube's corners (square faces: no clean facet), a grid, and a tetrahedron with a point on
  // one face and one on an edge: either nothing is kept or every triple matches.
  expect_3d_matches_definition(drange::generate_points(drange::Distribution::Grid, 8, 3, 1), false, "cube");
  expect_3d_matches_definition(drange::generate_points(drange::Distribution::Grid, 27, 3, 1), false, "3 x 3 x 3 grid");
  expect_3d_matches_definition(PointCloud{3, {0, 0, 0, 4, 0, 0, 0, 4, 0, 0, 0, 4, 1, 1, 0, 0, 2, 2, 1, 1, 1}}, false,
                               "tetrahedron, points on a face and an edge");
  // An octahedron: clean facets, but four of its points in each coordinate plane, which
  // Quickhull's first facets meet (it may give up).
  EXPECT_EQ(expect_3d_matches_definition(PointCloud{3, {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0.1, 0.2, 0.05}},
                                         false, "octahedron"),
            8u);
}

TEST(HullTriangles, AreBuiltOnlyWhenMostPointsAreOnTheHull) {
  const PointStore uniform = store_of(drange::generate_points(drange::Distribution::Uniform, 20000, 3, 3), 128);
  EXPECT_FALSE(HullTriangles(uniform).built());
  const PointStore on_sphere = store_of(sphere_points(5000, {1, 0.8, 0.6}, 4), 128);
  const HullTriangles hull(on_sphere);
  EXPECT_TRUE(hull.built());
  EXPECT_TRUE(hull.active());
  EXPECT_EQ(hull.clean_facets(), 2 * 5000u - 4);
  EXPECT_FALSE(HullTriangles(store_of(circle(500, 1.0, 5), 64)).built());  // 2D
}

TEST(HullTriangles, TheSearchFindsTheSameValidTriangulationWithFewerCalls) {
  PointCloud ball = sphere_points(3000, {1, 0.7, 0.5}, 6);
  const PointCloud inside = drange::generate_points(drange::Distribution::Uniform, 500, 3, 7);
  for (const double c : inside.coords) ball.coords.push_back((c - 0.5) * 0.5);
  expect_same_with_fewer_calls(sphere_points(3000, {1, 0.7, 0.5}, 5));
  expect_same_with_fewer_calls(ball);
}

}  // namespace
