// Tests of the engine (src/delaunay, src/spatial): brute-force oracles on tiny inputs, the
// exact validator on every generated family, degenerate families, permutation invariance,
// duplicates, the search variants, adjacency, and every error with its message.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cmath>
#include <functional>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "delaunay/simplex_estimate.hpp"
#include "drange/check.hpp"
#include "drange/delaunay.hpp"
#include "drange/errors.hpp"
#include "drange/generate.hpp"
#include "geometry/predicates.hpp"
#include "geometry/refined_sign.hpp"
#include "oracle.hpp"
#include "triangulation_checks.hpp"

namespace {

using drange::Distribution;
using drange::PointCloud;
using drange::Triangulation;
using drange::test::Simplex;
using namespace drange::test::checks;

PointCloud cloud(int d, std::vector<double> coords) { return PointCloud{d, std::move(coords)}; }


TEST(DelaunayOracle, RandomTinyInputsMatchBruteForce) {
  for (int d = 2; d <= 5; ++d)
    for (std::uint64_t seed = 1; seed <= 12; ++seed) {
      const std::size_t n = static_cast<std::size_t>(d + 4 + (seed % 5));
      const PointCloud points = drange::generate_points(Distribution::Uniform, n, d, seed);
      const Triangulation t = drange::delaunay(points);
      EXPECT_EQ(canonical(t), perturbed_oracle(points)) << "d=" << d << " seed=" << seed;
    }
}

TEST(DelaunayOracle, DegenerateTinyInputsMatchPerturbedBruteForce) {
  std::vector<std::pair<std::string, PointCloud>> cases = {
      {"grid 4x4", grid(2, 4)},
      {"grid 3x3x3", grid(3, 3)},
      {"grid 2^4", grid(4, 2)},
      {"integer circle", cloud(2, {5, 0, -5, 0, 0, 5, 0, -5, 3, 4, -3, 4, 3, -4, -3, -4, 4, 3, -4, 3, 4, -3, -4, -3})},
      {"square and centre", cloud(2, {0, 0, 1, 0, 0, 1, 1, 1, 0.5, 0.5})},
      {"cube corners and centre", cloud(3, {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1, 0.5, 0.5, 0.5})},
      {"collinear on the hull", cloud(2, {0, 0, 1, 0, 2, 0, 3, 0, 1.5, 1, 1.5, -2})},
      // Products underflowing to zero inside the filter, then multiplied by 1e100: a filter
      // blind to underflow gives overlapping triangles here (an unscaled input: it spans
      // 5e-324 to 1e100).
      {"underflowing products", cloud(2, {0, 0, 1e-135, 0, 1, 1e-190, 1e100, 1e-130, -1e100, 5e-324})},
      // Scaled inputs (below 1 in magnitude) whose facet and candidate minors underflow inside
      // the cluster: the search reads no floating-point flag (kUnderflowError).
      {"unit square beside a 1e-100 cluster",
       cloud(2, {1, 0, 0, 1, -1, 0, 0, -1, 3e-100, 1e-100, 1e-100, 2e-100, -2e-100, 1e-100, 0, -3e-100, 2e-100, -1e-100})},
      {"unit octahedron beside a 1e-80 cluster",
       cloud(3, {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 3e-80, 1e-80, 2e-80, -1e-80, 2e-80, 1e-80,
                 1e-80, -3e-80, 2e-80, -2e-80, 1e-80, -1e-80, 1e-80, 1e-80, -3e-80})},
  };
  // Distinct points rounded to 0.1 (as from a CSV file): in binary their lattice's planes and
  // spheres are within rounding, so candidates on a facet's lattice plane get their ball from
  // the double-double cofactors, and their near-ties are decided there; the oracle is exact.
  std::mt19937_64 rng(23);
  for (const auto& [d, n] : {std::pair{2, 30}, std::pair{3, 24}, std::pair{4, 15}}) {
    std::set<std::vector<double>> distinct;
    while (distinct.size() < static_cast<std::size_t>(n)) {
      std::vector<double> p(static_cast<std::size_t>(d));
      for (double& x : p) x = static_cast<double>(rng() % 6) / 10;
      distinct.insert(p);
    }
    PointCloud c{d, {}};
    for (const auto& p : distinct) c.coords.insert(c.coords.end(), p.begin(), p.end());
    cases.emplace_back("rounded to 0.1 in " + std::to_string(d) + "D", c);
  }
  for (const auto& [name, points] : cases) {
    const Triangulation t = drange::delaunay(points);
    EXPECT_EQ(canonical(t), perturbed_oracle(points)) << name;
    expect_valid(points, t, name);
  }
}

// Every `step`-th (in lexicographic order) integer point at distance `radius` from the origin
// in d dimensions: exactly cospherical.
PointCloud integer_sphere_points(int d, std::int64_t radius, std::size_t step) {
  PointCloud out{d, {}};
  std::vector<std::int64_t> x(static_cast<std::size_t>(d));
  std::size_t seen = 0;
  std::function<void(int, std::int64_t)> place = [&](int axis, std::int64_t left) {  // left: radius^2 still to place
    if (axis == d - 1) {
      const auto last = static_cast<std::int64_t>(std::llround(std::sqrt(static_cast<double>(left))));
      if (last * last != left) return;
      for (const std::int64_t v : {-last, last}) {
        if (v == last && last == 0) break;  // zero once
        x.back() = v;
        if (seen++ % step == 0)
          for (const std::int64_t c : x) out.coords.push_back(static_cast<double>(c));
      }
      return;
    }
    for (std::int64_t v = -radius; v <= radius; ++v) {
      if (v * v > left) continue;
      x[static_cast<std::size_t>(axis)] = v;
      place(axis + 1, left - v * v);
    }
  };
  place(0, radius * radius);
  return out;
}

// Exactly cospherical integer points: every closing search meets ties, which the search
// decides in double precision when its minors provably did not round (small radii) and by
// GMP when they might have (radii near 2^12 to 2^15: products beyond 2^53 units). Either way
// the result must be the perturbed Delaunay triangulation.
TEST(DelaunayOracle, CosphericalIntegerPointsGiveThePerturbedTriangulation) {
  std::vector<std::pair<std::string, PointCloud>> cases = {
      {"circle 1105", drange::test::integer_circle_points(1105)},
      {"circle 32045", drange::test::integer_circle_points(32045)},
      {"sphere 45", integer_sphere_points(3, 45, 4)},
      {"sphere 4095", integer_sphere_points(3, 4095, 466)},
      {"4-sphere 15", integer_sphere_points(4, 15, 60)},
  };
  PointCloud with_centre = integer_sphere_points(3, 65, 3);
  with_centre.coords.insert(with_centre.coords.end(), {0, 0, 0, 1, 2, 3});
  cases.emplace_back("sphere 65 and two inside", with_centre);
  for (const auto& [name, points] : cases) {
    const Triangulation t = drange::delaunay(points);
    expect_valid(points, t, name);
    expect_perturbed_empty(points, t, name);
  }
}

struct Family {
  Distribution distribution;
  std::size_t n;
};

TEST(DelaunayValidator, EveryFamilyInDimensionsTwoToSix) {
  const std::vector<Family> families = {{Distribution::Uniform, 0}, {Distribution::Ball, 0},   {Distribution::Sphere, 0},
                                        {Distribution::Gaussian, 0}, {Distribution::Clustered, 0}, {Distribution::Grid, 0}};
  const std::size_t sizes[] = {0, 0, 4000, 2000, 600, 200, 80};  // by d: sphere inputs cost O(n^2)
  for (int d = 2; d <= 6; ++d)
    for (const Family& f : families) {
      std::size_t n = sizes[d] / (f.distribution == Distribution::Sphere ? 2 : 1);
      if (f.distribution == Distribution::Grid) {  // a full grid k^d, so that it spans E^d
        std::size_t k = d <= 5 ? 3 : 2;  // three per side: cospherical ties everywhere
        while (static_cast<std::size_t>(std::pow(k + 1, d)) <= n) ++k;
        n = static_cast<std::size_t>(std::pow(k, d));
      }
      const PointCloud points = drange::generate_points(f.distribution, n, d, 77);
      const auto start = std::chrono::steady_clock::now();
      const Triangulation t = drange::delaunay(points);
      std::printf("d=%d family=%d n=%zu: %.3fs\n", d, static_cast<int>(f.distribution), n,
                  std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      const std::string what = "d=" + std::to_string(d) + " family=" + std::to_string(static_cast<int>(f.distribution));
      expect_valid(points, t, what);
      expect_consistent_adjacency(points, t);
    }
}

TEST(DelaunayValidator, DimensionEight) {
  const PointCloud points = drange::generate_points(Distribution::Uniform, 40, 8, 8);
  const Triangulation t = drange::delaunay(points);
  expect_valid(points, t, "d=8");
  expect_consistent_adjacency(points, t);
}

TEST(DelaunayRobustness, HardFamilies) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<std::pair<std::string, PointCloud>> cases;
  {
    PointCloud c{3, {}};  // a circle in 3D and two poles
    for (int i = 0; i < 24; ++i) c.coords.insert(c.coords.end(), {std::cos(i * M_PI / 12), std::sin(i * M_PI / 12), 0.0});
    c.coords.insert(c.coords.end(), {0, 0, 1, 0, 0, -1});
    cases.emplace_back("circle in 3D", c);
  }
  {
    PointCloud c{3, {}};  // a hull face full of coplanar grid points
    for (int i = 0; i < 1500; ++i) c.coords.insert(c.coords.end(), {u(rng), u(rng), u(rng)});
    for (int i = 0; i < 300; ++i) c.coords.insert(c.coords.end(), {0.0, std::round(u(rng) * 20) / 20, std::round(u(rng) * 20) / 20});
    cases.emplace_back("coplanar hull face", c);
  }
  {
    PointCloud c{2, {}};  // huge offset
    for (int i = 0; i < 2000; ++i) c.coords.insert(c.coords.end(), {1e9 + u(rng), 1e9 + u(rng)});
    cases.emplace_back("offset 1e9", c);
  }
  {
    PointCloud c{3, {}};  // a tiny cluster
    for (int i = 0; i < 2000; ++i) c.coords.insert(c.coords.end(), {1e-9 * u(rng), 1e-9 * u(rng), 1e-9 * u(rng)});
    cases.emplace_back("cluster 1e-9", c);
  }
  for (const double scale : {1e-60, 1e-100, 1e-200}) {
    // Unit points beside a cluster so small that its minors underflow (the lifted ones from
    // 1e-60 in 3D, all of them at 1e-200), in one scaled input.
    for (int d = 2; d <= 3; ++d) {
      PointCloud c{d, {}};
      for (int i = 0; i < 300; ++i)
        for (int k = 0; k < d; ++k) c.coords.push_back(u(rng) - 0.5);
      for (int i = 0; i < 300; ++i)
        for (int k = 0; k < d; ++k) c.coords.push_back(scale * (u(rng) - 0.5));
      std::ostringstream name;
      name << "unit points beside a cluster of " << scale << " in " << d << "D";
      cases.emplace_back(name.str(), c);
    }
  }
  {
    PointCloud c{2, {}};  // collinear subsets inside and on the hull
    for (int i = 0; i < 400; ++i) c.coords.insert(c.coords.end(), {u(rng), u(rng)});
    for (int i = 0; i <= 40; ++i) c.coords.insert(c.coords.end(), {i / 40.0, i / 40.0, i / 40.0, 0.0});
    cases.emplace_back("collinear subsets", c);
  }
  {
    PointCloud c{4, {}};  // 4D integer grid 5^4
    c = grid(4, 5);
    cases.emplace_back("grid 5^4", c);
  }
  {
    std::normal_distribution<double> gauss;  // nearly cospherical: a sphere moved by one ulp
    PointCloud c{3, {}};
    for (int i = 0; i < 300; ++i) {
      double v[3], r = 0;
      for (double& x : v) {
        x = gauss(rng);
        r += x * x;
      }
      for (double& x : v) c.coords.push_back(std::nextafter(x / std::sqrt(r), (rng() & 1) ? 2.0 : -2.0));
    }
    cases.emplace_back("sphere moved by one ulp", c);
  }
  for (const double scale : {1e-300, 1e150}) {  // lifts that would underflow or overflow
    PointCloud c = grid(3, 5);
    for (double& x : c.coords) x *= scale;
    cases.emplace_back("grid scaled by " + std::to_string(scale), c);
  }
  {
    PointCloud c = grid(2, 20);  // integer grid far from the origin
    for (double& x : c.coords) x += 1e15;
    cases.emplace_back("grid at offset 1e15", c);
  }
  {
    // Magnitudes from 1e-300 to 1e300: no power-of-two scaling fits, the generic predicates decide.
    PointCloud c{2, {0, 0, 1e300, 0, 0, 1e300, 1e300, 1e300, 1e-300, 1e-300, 3e-300, 1e-300, 2e-300, 4e-300}};
    for (int i = 0; i < 30; ++i) c.coords.insert(c.coords.end(), {1e300 * u(rng), 1e300 * u(rng)});
    cases.emplace_back("magnitudes 1e-300 to 1e300", c);
  }
  {
    // Every coordinate below 2^-1022: the scale factor 2^-exponent is then infinite, and the
    // values must be shifted instead (a product with it traps with SIGFPE).
    PointCloud c{2, {1e-310, 0, 0, 1e-310, 0, 0}};
    for (int i = 0; i < 40; ++i) c.coords.insert(c.coords.end(), {1e-310 * u(rng), 1e-310 * u(rng)});
    cases.emplace_back("all coordinates denormal", c);
  }
  {
    PointCloud c = grid(3, 6);  // a grid jittered below the filters' resolution
    for (double& x : c.coords) x += 1e-13 * u(rng);
    cases.emplace_back("grid with 1e-13 jitter", c);
  }
  for (const auto& [name, points] : cases) {
    const Triangulation t = drange::delaunay(points);
    expect_valid(points, t, name);
    expect_consistent_adjacency(points, t);
  }
}

TEST(DelaunayRobustness, DecimalInputsGiveTheSameTriangulationOnEveryProductCode) {
  // Coordinates with two decimals (a CSV file's) and a grid of 0.1 k: their decimal ties are
  // near-ties in binary, which the double-double stage decides. Its products by fused
  // multiply-add and by Dekker's splitting must give the same, valid, triangulation.
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<std::pair<std::string, PointCloud>> cases;
  for (int d = 2; d <= 4; ++d) {
    PointCloud c{d, {}};
    for (int i = 0; i < (d == 4 ? 600 : 3000); ++i)
      for (int k = 0; k < d; ++k) c.coords.push_back(std::round(u(rng) * 100) / 100);
    cases.emplace_back("rounded to 0.01 in " + std::to_string(d) + "D", c);
  }
  {
    PointCloud c{5, {}};  // 5D, whose lifted rows the double-double stage takes since it has six
    for (int i = 0; i < 300 * 5; ++i) c.coords.push_back(std::round(u(rng) * 10) / 10);
    cases.emplace_back("rounded to 0.1 in 5D", c);
  }
  {
    PointCloud c = grid(3, 9);
    for (double& x : c.coords) x *= 0.1;
    cases.emplace_back("grid of 0.1 k", c);
  }
  drange::geometry::set_refined_fma(true);
  if (!drange::geometry::refined_fma()) GTEST_SKIP() << "SKIPPED: this CPU has no FMA: the FMA products were NOT tested";
  for (const auto& [name, points] : cases) {
    drange::geometry::set_refined_fma(false);
    const Triangulation dekker = drange::delaunay(points);
    drange::geometry::set_refined_fma(true);
    const Triangulation fma = drange::delaunay(points);
    expect_valid(points, fma, name);
    EXPECT_EQ(dekker.simplices, fma.simplices) << name;
  }
}

TEST(DelaunayInvariance, PermutedInputGivesTheSameSimplices) {
  std::mt19937_64 rng(11);
  const std::vector<PointCloud> inputs = {drange::generate_points(Distribution::Uniform, 3000, 2, 3), grid(2, 25), grid(3, 7),
                                          drange::generate_points(Distribution::Sphere, 300, 3, 4),
                                          drange::generate_points(Distribution::Grid, 200, 4, 5)};
  for (const PointCloud& points : inputs) {
    const std::size_t n = points.size();
    std::vector<std::size_t> perm(n);
    std::iota(perm.begin(), perm.end(), 0);
    std::shuffle(perm.begin(), perm.end(), rng);
    PointCloud shuffled{points.dim, {}};
    for (std::size_t i : perm) shuffled.coords.insert(shuffled.coords.end(), points.point(i), points.point(i) + points.dim);
    EXPECT_EQ(geometric(drange::delaunay(points), points), geometric(drange::delaunay(shuffled), shuffled))
        << "d=" << points.dim << " n=" << n;
  }
}

TEST(DelaunayDuplicates, ReportedLeftOutAndHarmless) {
  PointCloud points = drange::generate_points(Distribution::Uniform, 500, 3, 9);
  PointCloud with_copies = points;
  for (std::size_t i = 0; i < 50; ++i)  // point 500 + i copies point 7 * i
    with_copies.coords.insert(with_copies.coords.end(), points.point(7 * i), points.point(7 * i) + 3);
  with_copies.coords.insert(with_copies.coords.end(), points.point(0), points.point(0) + 3);  // a second copy of 0
  const Triangulation t = drange::delaunay(with_copies);
  ASSERT_EQ(t.duplicates.size(), 51u);
  EXPECT_EQ(t.duplicates[3].index, 503);
  EXPECT_EQ(t.duplicates[3].original, 21);
  EXPECT_EQ(t.duplicates.back().index, 550);
  EXPECT_EQ(t.duplicates.back().original, 0);
  EXPECT_EQ(t.stats.distinct_points, 500u);
  for (std::int32_t v : t.simplices) EXPECT_LT(v, 500) << "a duplicate was used as a vertex";
  EXPECT_EQ(canonical(t), canonical(drange::delaunay(points)));
  expect_valid(with_copies, t, "duplicates");
}

TEST(DelaunayVariants, EveryVariantGivesTheSameTriangulation) {
  const std::vector<PointCloud> inputs = {drange::generate_points(Distribution::Uniform, 2000, 2, 21), grid(3, 6),
                                          drange::generate_points(Distribution::Gaussian, 300, 4, 22)};
  for (const PointCloud& points : inputs) {
    const auto reference = canonical(drange::delaunay(points));
    for (const char* name : {"scan", "kdtree", "no-prune", "no-order", "paper", "no-bottom-up", "no-seed", "no-ball", "no-shell", "no-tie-memory", "no-hull", "fifo", "spatial"}) {
      drange::Options options;
      options.variant = name;
      const Triangulation t = drange::delaunay(points, options);
      EXPECT_EQ(canonical(t), reference) << name << " d=" << points.dim;
      EXPECT_GT(t.stats.search_calls, 0u);
    }
  }
  drange::Options unknown;
  unknown.variant = "fast";
  try {
    drange::delaunay(inputs[0], unknown);
    ADD_FAILURE() << "no exception for an unknown variant";
  } catch (const drange::UsageError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("'fast'"), std::string::npos) << message;
    EXPECT_NE(message.find(drange::variant_names()), std::string::npos) << message;
  }
}

// The bottom-up walk, the seeds and the ball query change the order in which points are met,
// or skip points that cannot win, never the point found: on the degenerate families, where ties are decided by the perturbation and
// many points sit exactly on query boxes and spheres, every switch gives the same simplices.
TEST(DelaunayVariants, BottomUpAndSeedsChangeNothingOnDegenerateInputs) {
  std::vector<std::pair<std::string, PointCloud>> cases = {
      {"grid 2D 30x30", grid(2, 30)},
      {"grid 3D 8^3", grid(3, 8)},
      {"grid 4D 4^4", grid(4, 4)},
      {"sphere 3D", drange::generate_points(Distribution::Sphere, 400, 3, 31)},
      {"sphere 2D", drange::generate_points(Distribution::Sphere, 500, 2, 32)},
  };
  {
    // Every integer point of the circle x^2 + y^2 = 5^4 * 13^2 (cospherical, exactly), and its centre.
    PointCloud c{2, {0, 0}};
    const long r2 = 625L * 169L;
    for (long x = -325; x <= 325; ++x)
      for (long y = -325; y <= 325; ++y)
        if (x * x + y * y == r2) c.coords.insert(c.coords.end(), {double(x), double(y)});
    cases.emplace_back("integer circle", c);
  }
  {
    PointCloud c = grid(3, 5);  // duplicates of every third grid point
    const std::size_t n = c.size();
    for (std::size_t i = 0; i < n; i += 3) c.coords.insert(c.coords.end(), c.point(i), c.point(i) + 3);
    cases.emplace_back("grid with duplicates", c);
  }
  for (const auto& [name, points] : cases) {
    const auto reference = canonical(drange::delaunay(points));
    for (const char* variant : {"paper", "no-bottom-up", "no-seed", "no-ball", "no-shell", "scan", "fifo", "spatial"}) {
      drange::Options options;
      options.variant = variant;
      EXPECT_EQ(canonical(drange::delaunay(points, options)), reference) << name << ", " << variant;
    }
  }
}

TEST(DelaunayVariants, BottomUpSeedsAndBallReduceTheWork) {
  for (int d : {2, 3}) {
    const PointCloud points = drange::generate_points(Distribution::Uniform, d == 2 ? 20000 : 5000, d, 24);
    auto stats = [&](const char* name) {
      drange::Options options;
      options.variant = name;
      return drange::delaunay(points, options).stats;
    };
    const drange::Statistics full = stats("full"), paper = stats("paper"), no_seed = stats("no-seed"),
                             no_bottom_up = stats("no-bottom-up");
    // The bottom-up walk enters far fewer nodes: it skips the descent from the root.
    EXPECT_LT(full.search_calls, no_bottom_up.search_calls) << "d=" << d;
    EXPECT_LT(no_seed.search_calls, paper.search_calls) << "d=" << d;
    // The seeds start the search with a good candidate: fewer improvements, fewer points tested.
    EXPECT_LT(full.debug.candidates, no_seed.debug.candidates) << "d=" << d;
    EXPECT_LT(full.debug.points_tested, no_seed.debug.points_tested) << "d=" << d;
    // The ball skips the corners of its bounding box: fewer points tested.
    EXPECT_LT(full.debug.points_tested, stats("no-ball").debug.points_tested) << "d=" << d;
  }
}

TEST(DelaunayVariants, PruningAndOrderingReduceTheWork) {
  const PointCloud points = drange::generate_points(Distribution::Uniform, 20000, 2, 23);
  auto calls = [&](const char* name) {
    drange::Options options;
    options.variant = name;
    return drange::delaunay(points, options).stats.search_calls;
  };
  const auto full = calls("full");
  EXPECT_LT(full, calls("no-prune"));
  EXPECT_LT(full, calls("kdtree"));
  EXPECT_LT(full, calls("no-order"));
}

TEST(DelaunayVariants, GridHullFacetsPruneTheirHyperplane) {
  // The hull facets of a grid have every point of their face on their hyperplane; the search
  // prunes those kd-tree nodes only by proving their orientation exactly zero. The work counter
  // (deterministic, not a time) is more than twice the bound on this grid without that proof.
  const Triangulation t = drange::delaunay(grid(3, 20));
  EXPECT_LT(t.stats.calls_per_simplex(), 30.0);
}

TEST(DelaunayVariants, PlateauFacetsPruneTheirFlatSide) {
  // A terrain: half its points on a flat plateau at a height that is no dyadic fraction (no
  // filter or static proof decides them), half on a wavy surface above and below it. Facets in
  // the plateau have its points on their hyperplane, exactly; the search prunes those kd-tree
  // nodes by the flat axis. With the plateau flat on each axis in turn: the open side's
  // direction comes from the facet, and a wrong one loses simplices, which the validator sees.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int flat = 0; flat < 3; ++flat) {
    PointCloud terrain{3, {}};
    for (int i = 0; i < 10000; ++i) {
      const double x = u(rng), y = u(rng);
      const double z = x < 0.5 ? 0.3 : 0.3 + 0.2 * (x - 0.5) * std::sin(7 * y);
      double p[3];
      p[flat] = z;
      p[(flat + 1) % 3] = x;
      p[(flat + 2) % 3] = y;
      terrain.coords.insert(terrain.coords.end(), p, p + 3);
    }
    const Triangulation t = drange::delaunay(terrain);
    expect_valid(terrain, t, "plateau flat on axis " + std::to_string(flat));
    // Points tested per simplex (a deterministic work counter, not a time): well below the
    // bound with the flat axis, about three times as many without it, when every search from a
    // plateau facet visits the whole plateau before its first candidate; the gap grows with
    // the plateau.
    EXPECT_LT(double(t.stats.debug.points_tested) / double(t.stats.simplices), 8.0) << "flat axis " << flat;
  }
}

TEST(DelaunayVariants, LongSearchesOnACylinderPruneTheClosedSide) {
  // Points on a cylinder: most Delaunay balls are centred near its axis and touch the surface
  // along a whole circle, so a search meets many kd-tree nodes, and whole subtrees near the
  // circle lie on the facet's closed side. After its first 32 inner nodes, a search with a
  // ball prunes them too.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> angle(0.0, 6.283185307179586), height(-1.0, 1.0);
  PointCloud cylinder{3, {}};
  for (int i = 0; i < 10000; ++i) {
    const double t = angle(rng);
    cylinder.coords.insert(cylinder.coords.end(), {std::cos(t), std::sin(t), height(rng)});
  }
  const Triangulation t = drange::delaunay(cylinder);
  expect_valid(cylinder, t, "cylinder");
  drange::Options no_prune;
  no_prune.variant = "no-prune";
  EXPECT_EQ(canonical(t), canonical(drange::delaunay(cylinder, no_prune)));
  // Nodes entered per simplex (a deterministic work counter, not a time): the bound lies between
  // the count with the closed side pruned only before the first ball and the lower one with it
  // pruned in long searches too.
  EXPECT_LT(t.stats.calls_per_simplex(), 105.0);
}

TEST(DelaunayVariants, TheBestPointOfABlockIsTriedFirstIn2D) {
  // Two concentric circles: the triangles between them join two neighbours on one circle to a
  // point of the other, and a leaf's points there follow the circle, each a better candidate
  // than the one before. Of the points of a block in the ball, the best by floating point is
  // tried first; the others then mostly fall outside its ball.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> angle(0.0, 6.283185307179586);
  PointCloud circles{2, {}};
  for (double radius : {1.0, 0.5})
    for (int i = 0; i < 3000; ++i) {
      const double t = angle(rng);
      circles.coords.insert(circles.coords.end(), {radius * std::cos(t), radius * std::sin(t)});
    }
  const Triangulation t = drange::delaunay(circles);
  expect_valid(circles, t, "two circles");
  drange::Options no_prune;
  no_prune.variant = "no-prune";
  EXPECT_EQ(canonical(t), canonical(drange::delaunay(circles, no_prune)));
  // Candidates per simplex (a deterministic work counter, not a time): the bound lies between
  // the count in index order and the lower one with the best first (one seed per point). The
  // count depends on the order of the searches too, through the seeds: measured in the
  // paper's FIFO order (the blocks' wrapping order makes a few more candidates).
  drange::Options fifo;
  fifo.variant = "fifo";
  const Triangulation in_fifo = drange::delaunay(circles, fifo);
  EXPECT_EQ(canonical(t), canonical(in_fifo));
  EXPECT_LT(double(in_fifo.stats.debug.candidates) / double(in_fifo.stats.simplices), 4.0);
}

TEST(DelaunayVariants, CandidatesOnADecimalLatticePlaneGetABall) {
  // Points rounded to multiples of 0.04, a CSV file's kind of coordinates: four of them on one
  // lattice plane and one circle are within rounding of both in binary, so the candidate's
  // sphere through them is computed from noise in doubles and gives no ball; each such candidate
  // would send the search through every point on the facet's open side. The double-double
  // cofactors give it its ball.
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  PointCloud points{3, {}};
  for (int i = 0; i < 5000 * 3; ++i) points.coords.push_back(std::round(u(rng) * 25) / 25);
  const Triangulation t = drange::delaunay(points);
  expect_valid(points, t, "points rounded to 0.04");
  // Points tested per simplex (a deterministic work counter, not a time): well below the bound
  // with the double-double ball, several times above it without.
  EXPECT_LT(double(t.stats.debug.points_tested) / double(t.stats.simplices), 8.0);
}

TEST(DelaunayStatistics, CountsAreConsistent) {
  const PointCloud points = drange::generate_points(Distribution::Uniform, 10000, 2, 31);
  const Triangulation t = drange::delaunay(points);
  const drange::Statistics& s = t.stats;
  EXPECT_EQ(s.points, 10000u);
  EXPECT_EQ(s.distinct_points, 10000u);
  EXPECT_EQ(s.simplices, t.size());
  // Euler in the plane: triangles = 2n - 2 - h for n points, h of them on the hull.
  EXPECT_EQ(s.simplices, 2 * s.points - 2 - s.hull_facets);
  EXPECT_GT(s.calls_per_simplex(), 1.0);
  EXPECT_LT(s.calls_per_simplex(), 100.0);
  EXPECT_GT(s.peak_rss_bytes, 0u);
  EXPECT_GE(s.seconds_total, s.seconds_search);
  EXPECT_NE(s.summary().find("simplices=" + std::to_string(t.size())), std::string::npos);
}

// scripts/ab_time.sh and bench/ read the --stats line by its keys: they stay, in this order,
// the debug counters included.
TEST(DelaunayStatistics, SummaryKeysAreFixed) {
  const PointCloud points = drange::generate_points(Distribution::Uniform, 2000, 3, 32);
  const drange::Statistics s = drange::delaunay(points).stats;
  std::vector<std::string> keys;
  std::istringstream line(s.summary());
  for (std::string pair; line >> pair;) keys.push_back(pair.substr(0, pair.find('=')));
  const std::vector<std::string> expected = {
      "points", "distinct", "simplices", "hull_facets", "calls_per_simplex", "tested_per_simplex",
      "candidates_per_simplex", "exact_fallbacks", "max_open_facets", "shell_spheres", "threads", "wasted_searches",
      "time_kdtree", "time_first_facet", "time_search", "time_total", "peak_rss", "algorithm", "time_choice",
      "time_busy", "time_critical"};
  EXPECT_EQ(keys, expected) << s.summary();
  // One busy time per thread of the search, the critical path at least the busiest one's.
  EXPECT_FALSE(s.seconds_busy.empty());
  for (const double busy : s.seconds_busy) EXPECT_LE(busy, s.seconds_critical_path + 1e-9);
  EXPECT_NE(s.summary().find(" max_open_facets=" + std::to_string(s.debug.max_open_facets) + " "), std::string::npos);
  EXPECT_NE(s.summary().find(" exact_fallbacks=" + std::to_string(s.debug.exact_fallbacks) + " "), std::string::npos);
}

// The room made for the simplices before the search (simplex_estimate.hpp) is address space
// only, so it may be generous, but never more than a quarter of the machine: a reservation
// beyond what the kernel would grant would fail the triangulation.
TEST(DelaunayStorage, RoomForTheSimplicesIsBoundedByTheMachine) {
  const std::size_t quarter =
      static_cast<std::size_t>(sysconf(_SC_PHYS_PAGES)) / 4 * static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
  const std::size_t huge = drange::engine::expected_simplices(8, std::size_t{1} << 40);
  EXPECT_GT(huge, std::size_t{1} << 50);
  EXPECT_LE(drange::engine::reservable_simplices(huge, 9, 2) * 9 * 2 * sizeof(int), quarter);
  EXPECT_EQ(drange::engine::reservable_simplices(1000, 9, 2), 1000u);
  EXPECT_EQ(drange::engine::expected_simplices(2, 1000), 2000u);
  EXPECT_EQ(drange::engine::expected_simplices(9, 1000), 0u);  // nothing measured beyond 8D
}

TEST(DelaunayNeighbors, CanBeLeftOut) {
  // Left out, they are not recorded at all (the frontier skips their writes), and the
  // simplices are the same, in the same order, on the FIFO queue (2D) and the spatial one (3D).
  for (int d : {2, 3})
    for (int threads : {1, 2}) {
      const PointCloud points = drange::generate_points(Distribution::Uniform, 3000, d, 41);
      drange::Options with, without;
      with.threads = without.threads = threads;
      without.compute_neighbors = false;
      const Triangulation all = drange::delaunay(points, with), simplices_only = drange::delaunay(points, without);
      EXPECT_TRUE(simplices_only.neighbors.empty()) << d << "D, " << threads << " threads";
      EXPECT_EQ(all.neighbors.size(), all.simplices.size()) << d << "D, " << threads << " threads";
      EXPECT_EQ(simplices_only.simplices, all.simplices) << d << "D, " << threads << " threads";
      EXPECT_EQ(simplices_only.stats.hull_facets, all.stats.hull_facets) << d << "D, " << threads << " threads";
    }
}

template <class E>
std::string message_of(const PointCloud& points) {
  try {
    drange::delaunay(points);
  } catch (const E& e) {
    return e.what();
  }
  return "no exception";
}

TEST(DelaunayErrors, NameTheProblem) {
  EXPECT_EQ(message_of<drange::DegenerateInputError>(cloud(2, {0, 0, 1, 1, 0, 0, 1, 1})),
            "only 2 distinct points; a triangulation in 2 dimensions needs at least 3");
  EXPECT_EQ(message_of<drange::DegenerateInputError>(cloud(2, {0, 0, 1, 1, 2, 2, 3, 3})),
            "all 4 distinct points lie in an affine subspace of dimension 1; a Delaunay triangulation in 2 dimensions "
            "needs points that span 2 dimensions");
  EXPECT_EQ(message_of<drange::DegenerateInputError>(cloud(3, {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 2, 3, 0})),
            "all 5 distinct points lie in an affine subspace of dimension 2; a Delaunay triangulation in 3 dimensions "
            "needs points that span 3 dimensions");
  EXPECT_EQ(message_of<drange::InputError>(cloud(2, {0, 0, 1, 0, 0, std::nan("")})), "point 2, coordinate 1 is NaN");
  EXPECT_EQ(message_of<drange::InputError>(cloud(2, {0, 0, HUGE_VAL, 0, 0, 1})), "point 1, coordinate 0 is infinite");
  EXPECT_EQ(message_of<drange::InputError>(cloud(1, {0, 1, 2})),
            "dimension 1 is not supported (drange triangulates in 2 to 11 dimensions)");
  EXPECT_EQ(message_of<drange::DegenerateInputError>(cloud(3, {})),
            "only 0 distinct points; a triangulation in 3 dimensions needs at least 4");
}

}  // namespace
