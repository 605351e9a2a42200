// Tests of the incremental kernel (src/delaunay/incremental) against the direct algorithm and
// the oracles: both constructions must give the one perturbed Delaunay triangulation, on tiny
// inputs by brute force, on degenerate families by the exact validator and the perturbed
// emptiness of every simplex, and always the same set of simplices as each other.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "drange/delaunay.hpp"
#include "drange/errors.hpp"
#include "drange/generate.hpp"
#include "oracle.hpp"
#include "triangulation_checks.hpp"

namespace {

using namespace drange::test::checks;

Triangulation triangulate(const PointCloud& points, const char* algorithm, int threads = 1) {
  drange::Options options;
  options.algorithm = algorithm;
  options.threads = threads;
  return drange::delaunay(points, options);
}

PointCloud cloud(int d, std::vector<double> coords) { return PointCloud{d, std::move(coords)}; }

// Points on the faces of a cube: exactly on them (a grid of each face, every face's points
// coplanar and cocircular by fours) or within `offset` of them inside, as Qhull's rbox W.
PointCloud cube_faces(std::size_t n, double offset, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-0.5, 0.5), inward(0.0, offset);
  PointCloud out{3, {}};
  for (std::size_t i = 0; i < n; ++i) {
    const int axis = static_cast<int>(rng() % 3);
    const double side = rng() % 2 ? 0.5 : -0.5;
    double p[3] = {u(rng), u(rng), u(rng)};
    p[axis] = side - (side > 0 ? inward(rng) : -inward(rng));
    out.coords.insert(out.coords.end(), p, p + 3);
  }
  return out;
}

// A cylinder's grid: rings of points at equal heights, each four of a face's corners cocircular.
PointCloud cylinder_grid(int rings, int per_ring) {
  PointCloud out{3, {}};
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < per_ring; ++j) {
      const double a = 2 * 3.141592653589793 * j / per_ring;
      out.coords.insert(out.coords.end(), {std::cos(a), std::sin(a), i / 10.0});
    }
  return out;
}

// Random integer points without their duplicates (which the validator's references, taking
// every input point, would count as inside).
PointCloud distinct_integer_points(std::size_t n, int d, std::int64_t lo, std::int64_t hi, std::uint64_t seed) {
  const PointCloud all = drange::test::random_integer_points(n, d, lo, hi, seed);
  std::set<std::vector<double>> seen;
  PointCloud out{d, {}};
  for (std::size_t i = 0; i < all.size(); ++i)
    if (seen.insert(std::vector<double>(all.point(i), all.point(i) + d)).second)
      out.coords.insert(out.coords.end(), all.point(i), all.point(i) + d);
  return out;
}

TEST(Incremental, TinyInputsMatchBruteForce) {
  for (int d = 2; d <= 5; ++d)
    for (std::uint64_t seed = 1; seed <= 12; ++seed) {
      const std::size_t n = static_cast<std::size_t>(d + 4 + (seed % 5));
      const PointCloud points = drange::generate_points(Distribution::Uniform, n, d, seed);
      EXPECT_EQ(canonical(triangulate(points, "incremental")), perturbed_oracle(points)) << "d=" << d << " seed=" << seed;
    }
  const std::vector<std::pair<std::string, PointCloud>> degenerate = {
      {"grid 4x4", grid(2, 4)},
      {"grid 3x3x3", grid(3, 3)},
      {"grid 2^4", grid(4, 2)},
      {"integer circle", cloud(2, {5, 0, -5, 0, 0, 5, 0, -5, 3, 4, -3, 4, 3, -4, -3, -4, 4, 3, -4, 3, 4, -3, -4, -3})},
      {"square and centre", cloud(2, {0, 0, 1, 0, 0, 1, 1, 1, 0.5, 0.5})},
      {"collinear on the hull", cloud(2, {0, 0, 1, 0, 2, 0, 3, 0, 1.5, 1, 1.5, -2})},
      {"cube corners and centre", cloud(3, {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1, 0.5, 0.5, 0.5})},
      {"cube faces", cube_faces(14, 0.0, 3)},
  };
  for (const auto& [name, points] : degenerate)
    EXPECT_EQ(canonical(triangulate(points, "incremental")), perturbed_oracle(points)) << name;
}

// Inputs whose ties and hull hyperplanes full of points exercise every case of the conflict
// test: cospherical points, points on a hull facet's hyperplane inside or outside its
// circumsphere, near-ties within rounding.
std::vector<std::pair<std::string, PointCloud>> degenerate_families() {
  std::vector<std::pair<std::string, PointCloud>> out = {
      {"grid 2D 25x25", grid(2, 25)},
      {"grid 3D 7^3", grid(3, 7)},
      {"grid 4D 4^4", grid(4, 4)},
      {"sphere 2D", drange::generate_points(Distribution::Sphere, 400, 2, 31)},
      {"sphere 3D", drange::generate_points(Distribution::Sphere, 400, 3, 32)},
      {"integer circle", drange::test::integer_circle_points(1105)},
      {"cube faces exactly", cube_faces(600, 0.0, 4)},
      {"cube faces within 1e-10", cube_faces(600, 1e-10, 5)},
      {"cylinder grid", cylinder_grid(8, 24)},
      {"integer points 3D", distinct_integer_points(500, 3, 0, 6, 7)},
      {"integer points 5D", distinct_integer_points(150, 5, 0, 2, 8)},
      {"uniform 4D", drange::generate_points(Distribution::Uniform, 300, 4, 9)},
      {"clustered 3D", drange::generate_points(Distribution::Clustered, 800, 3, 10)},
  };
  return out;
}

TEST(Incremental, DegenerateFamiliesGiveTheDirectSimplices) {
  for (const auto& [name, points] : degenerate_families()) {
    const Triangulation incremental = triangulate(points, "incremental");
    EXPECT_EQ(canonical(incremental), canonical(triangulate(points, "direct"))) << name;
    expect_valid(points, incremental, name);
    expect_consistent_adjacency(points, incremental);
  }
}

// The same, with each simplex's perturbed emptiness checked against every point by the
// rational reference (slow: small inputs).
TEST(Incremental, SmallDegenerateInputsAreEmptyUnderThePerturbation) {
  const std::vector<std::pair<std::string, PointCloud>> cases = {
      {"grid 3D 4^3", grid(3, 4)},
      {"cube faces exactly", cube_faces(120, 0.0, 4)},
      {"cube faces within 1e-10", cube_faces(120, 1e-10, 5)},
      {"cylinder grid", cylinder_grid(4, 12)},
      {"integer points 3D", distinct_integer_points(100, 3, 0, 4, 7)},
      {"integer points 4D", distinct_integer_points(60, 4, 0, 2, 8)},
  };
  for (const auto& [name, points] : cases) {
    const Triangulation incremental = triangulate(points, "incremental");
    EXPECT_EQ(canonical(incremental), canonical(triangulate(points, "direct"))) << name;
    expect_perturbed_empty(points, incremental, name);
  }
}

TEST(Incremental, ResultDependsOnTheCoordinatesOnly) {
  // The insertion order comes from the points' ranks and kd-tree: a permuted input gives the
  // same simplices (as coordinates), and the threads change nothing.
  for (const auto& [name, points] : degenerate_families()) {
    std::vector<std::size_t> order(points.size());
    std::iota(order.begin(), order.end(), 0);
    std::shuffle(order.begin(), order.end(), std::mt19937_64(17));
    PointCloud shuffled{points.dim, {}};
    for (std::size_t i : order) shuffled.coords.insert(shuffled.coords.end(), points.point(i), points.point(i) + points.dim);
    const Triangulation a = triangulate(points, "incremental"), b = triangulate(shuffled, "incremental");
    EXPECT_EQ(geometric(a, points), geometric(b, shuffled)) << name;
    EXPECT_EQ(triangulate(points, "incremental", 3).simplices, a.simplices) << name;
  }
}

TEST(Incremental, UniformInputsGiveTheDirectSimplices) {
  for (int d = 2; d <= 6; ++d) {
    const PointCloud points = drange::generate_points(Distribution::Uniform, d <= 3 ? 5000 : 800, d, 40 + d);
    const Triangulation incremental = triangulate(points, "incremental");
    EXPECT_EQ(canonical(incremental), canonical(triangulate(points, "direct"))) << "d=" << d;
    expect_consistent_adjacency(points, incremental);
  }
}

TEST(Incremental, AlgorithmNamesAreChecked) {
  const PointCloud points = drange::generate_points(Distribution::Uniform, 50, 2, 1);
  drange::Options unknown;
  unknown.algorithm = "quick";
  try {
    drange::delaunay(points, unknown);
    ADD_FAILURE() << "no exception for an unknown algorithm";
  } catch (const drange::UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("'quick'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(drange::algorithm_names()), std::string::npos) << e.what();
  }
  drange::Options mixed;
  mixed.algorithm = "incremental";
  mixed.variant = "paper";
  EXPECT_THROW(drange::delaunay(points, mixed), drange::UsageError);
  // A flat input is refused as by the direct algorithm.
  EXPECT_THROW(triangulate(cloud(2, {0, 0, 1, 1, 2, 2, 3, 3}), "incremental"), drange::DegenerateInputError);
}

TEST(Incremental, ProgressKeepsItsContract) {
  const PointCloud points = drange::generate_points(Distribution::Uniform, 60000, 2, 3);
  std::vector<std::size_t> calls;
  drange::Options options;
  options.algorithm = "incremental";
  options.progress = [&](std::size_t found) { calls.push_back(found); };
  const Triangulation t = drange::delaunay(points, options);
  ASSERT_GE(calls.size(), 2u);
  for (std::size_t i = 0; i + 1 < calls.size(); ++i) {
    EXPECT_EQ(calls[i] % drange::kProgressInterval, 0u);
    EXPECT_LT(calls[i], calls[i + 1]);
  }
  EXPECT_EQ(calls.back(), t.size());
}

}  // namespace

namespace {

// Options::algorithm "auto": a count-based probe, so its choice is the same everywhere. Points
// near a cube's faces make the sample's direct search exceed its budget; uniform points stay
// below the limit; either way the simplices are the direct search's.
TEST(Incremental, AutoChoosesByTheSearchsWorkOnASample) {
  const std::vector<std::pair<PointCloud, const char*>> cases = {
      {cube_faces(20000, 1e-10, 6), "incremental"},
      {drange::generate_points(Distribution::Uniform, 20000, 3, 7), "direct"},
      {drange::generate_points(Distribution::Uniform, 20000, 2, 8), "direct"},
      {cube_faces(5000, 1e-10, 9), "direct"},  // below the probe's smallest input
  };
  for (const auto& [points, expected] : cases) {
    const Triangulation chosen = triangulate(points, "auto");
    EXPECT_EQ(chosen.stats.algorithm, expected) << points.size() << " points in " << points.dim << "D";
    EXPECT_EQ(canonical(chosen), canonical(triangulate(points, "direct")));
  }
}

}  // namespace
