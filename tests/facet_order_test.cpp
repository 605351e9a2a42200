// Tests of engine::SearchOptions::facet_order (the order in which open facets take their turns,
// triangulate.cpp): the spatial order gives the FIFO order's simplices, in another order, on
// general and degenerate inputs in 2D to 4D; its output is byte for byte the same for 1 to 4
// threads; `automatic` picks it by dimension; and it keeps the 3D frontier smaller.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <utility>
#include <vector>

#include "delaunay/search_options.hpp"
#include "delaunay/triangulate.hpp"
#include "drange/check.hpp"
#include "drange/delaunay.hpp"
#include "drange/generate.hpp"
#include "oracle.hpp"

namespace {

using drange::Distribution;
using drange::engine::FacetOrder;
using drange::engine::SearchOptions;
using drange::PointCloud;
using drange::Triangulation;

Triangulation run(const PointCloud& points, FacetOrder order, int threads = 1) {
  drange::Options options;
  options.threads = threads;
  SearchOptions search;
  search.facet_order = order;
  return drange::engine::triangulate(points, options, search);
}

PointCloud grid(int d, int k) {
  return drange::generate_points(Distribution::Grid, static_cast<std::size_t>(std::pow(k, d)), d, 1);
}

// Uniform points with copies of some of them.
PointCloud with_duplicates(int d, std::size_t n, unsigned seed) {
  PointCloud points = drange::generate_points(Distribution::Uniform, n, d, seed);
  std::mt19937_64 rng(seed);
  for (std::size_t i = 0; i < n / 5; ++i) {
    const std::size_t j = rng() % n;
    points.coords.insert(points.coords.end(), points.point(j), points.point(j) + d);
  }
  return points;
}

// Every integer point of the circle x^2 + y^2 = 1105^2 (108 of them, cospherical exactly), its
// centre and integer points inside.
PointCloud integer_circle() {
  PointCloud circle = drange::test::integer_circle_points(1105);
  circle.coords.insert(circle.coords.end(), {0.0, 0.0});
  std::mt19937_64 rng(6);
  std::uniform_int_distribution<long> coordinate(-700, 700);
  for (int i = 0; i < 300; ++i) circle.coords.insert(circle.coords.end(), {double(coordinate(rng)), double(coordinate(rng))});
  return circle;
}

std::vector<std::pair<std::string, PointCloud>> inputs() {
  return {
      {"uniform 2D 20000", drange::generate_points(Distribution::Uniform, 20000, 2, 1)},
      {"uniform 3D 6000", drange::generate_points(Distribution::Uniform, 6000, 3, 2)},
      {"uniform 4D 1500", drange::generate_points(Distribution::Uniform, 1500, 4, 3)},
      {"gaussian 3D 4000", drange::generate_points(Distribution::Gaussian, 4000, 3, 4)},
      {"grid 2D 60x60", grid(2, 60)},
      {"grid 3D 12^3", grid(3, 12)},
      {"grid 4D 5^4", grid(4, 5)},
      {"duplicates 2D", with_duplicates(2, 5000, 5)},
      {"duplicates 3D", with_duplicates(3, 3000, 6)},
      {"duplicates 4D", with_duplicates(4, 800, 7)},
      {"sphere 3D 600", drange::generate_points(Distribution::Sphere, 600, 3, 8)},
      {"sphere 2D 1000", drange::generate_points(Distribution::Sphere, 1000, 2, 9)},
      {"integer circle", integer_circle()},
  };
}

TEST(FacetOrder, SpatialGivesTheFifoSimplicesInAnotherOrder) {
  for (const auto& [name, points] : inputs()) {
    const Triangulation fifo = run(points, FacetOrder::fifo);
    const Triangulation spatial = run(points, FacetOrder::spatial);
    EXPECT_EQ(drange::test::canonical(spatial.simplices, spatial.dim), drange::test::canonical(fifo.simplices, fifo.dim)) << name;
    const drange::CheckReport report = drange::check_triangulation(points, spatial.simplices);
    EXPECT_TRUE(report.valid) << name << ": " << (report.problems.empty() ? "" : report.problems.front());
    EXPECT_EQ(spatial.stats.hull_facets, fifo.stats.hull_facets) << name;
    EXPECT_EQ(spatial.duplicates.size(), fifo.duplicates.size()) << name;
    // The order is in effect: the simplices are numbered differently.
    EXPECT_NE(spatial.simplices, fifo.simplices) << name << ": the spatial order gave the FIFO order";
  }
}

// The spatial order depends on a fixed window of facets taken ahead, never on the thread
// count: every count gives the serial run's arrays and statistics (but the times, the thread
// count and the wasted searches; with the seed candidates, the work counters depend on which
// thread searched what, as in threads_test.cpp).
TEST(FacetOrder, SpatialIsTheSameForEveryThreadCount) {
  for (const auto& [name, points] : inputs()) {
    const Triangulation serial = run(points, FacetOrder::spatial, 1);
    for (const int threads : {2, 3, 4}) {
      const Triangulation t = run(points, FacetOrder::spatial, threads);
      const std::string at = name + ", threads=" + std::to_string(threads);
      EXPECT_TRUE(t.simplices == serial.simplices) << at << ": simplices differ";
      EXPECT_TRUE(t.neighbors == serial.neighbors) << at << ": neighbours differ";
      EXPECT_EQ(t.stats.simplices, serial.stats.simplices) << at;
      EXPECT_EQ(t.stats.hull_facets, serial.stats.hull_facets) << at;
      EXPECT_EQ(t.stats.debug.max_open_facets, serial.stats.debug.max_open_facets) << at;
      EXPECT_EQ(t.stats.threads, static_cast<std::size_t>(threads)) << at;
    }
  }
}

// Large enough that the window (1024 facets) is full for most of the run, and without seed
// candidates, so that the work counters must agree too.
TEST(FacetOrder, SpatialWorkCountersAreTheSameForEveryThreadCount) {
  const PointCloud points = drange::generate_points(Distribution::Uniform, 30000, 3, 10);
  drange::Options options;
  options.threads = 1;
  SearchOptions search;
  search.facet_order = FacetOrder::spatial;
  search.seed_candidate = false;
  const Triangulation serial = drange::engine::triangulate(points, options, search);
  for (const int threads : {2, 4}) {
    options.threads = threads;
    const Triangulation t = drange::engine::triangulate(points, options, search);
    EXPECT_TRUE(t.simplices == serial.simplices) << threads;
    EXPECT_EQ(t.stats.search_calls, serial.stats.search_calls) << threads;
    EXPECT_EQ(t.stats.debug.points_tested, serial.stats.debug.points_tested) << threads;
    EXPECT_EQ(t.stats.debug.candidates, serial.stats.debug.candidates) << threads;
    EXPECT_EQ(t.stats.debug.exact_fallbacks, serial.stats.debug.exact_fallbacks) << threads;
  }
}

TEST(FacetOrder, AutomaticIsBlocksUpTo3DSpatialIn4DAnd5DAndFifoElsewhere) {
  for (const int d : {2, 3}) {
    // In 2D and 3D the automatic order is the blocks' canonical one (block_search.hpp): the
    // same simplices as either fixed order, listed otherwise.
    const PointCloud points = drange::generate_points(Distribution::Uniform, 5000, d, 11);
    const Triangulation automatic = run(points, FacetOrder::automatic);
    EXPECT_EQ(drange::test::canonical(automatic.simplices, d), drange::test::canonical(run(points, FacetOrder::fifo).simplices, d)) << d;
    EXPECT_NE(automatic.simplices, run(points, FacetOrder::fifo).simplices) << d;
    EXPECT_NE(automatic.simplices, run(points, FacetOrder::spatial).simplices) << d;
  }
  const PointCloud six = drange::generate_points(Distribution::Uniform, 150, 6, 14);
  EXPECT_EQ(run(six, FacetOrder::automatic).simplices, run(six, FacetOrder::fifo).simplices);
  EXPECT_NE(run(six, FacetOrder::spatial).simplices, run(six, FacetOrder::fifo).simplices);
  for (const int d : {4, 5}) {
    const PointCloud points = drange::generate_points(Distribution::Uniform, d == 5 ? 600 : 3000, d, 12);
    EXPECT_EQ(run(points, FacetOrder::automatic).simplices, run(points, FacetOrder::spatial).simplices) << d;
  }
  EXPECT_EQ(drange::Options{}.variant, "full");
  EXPECT_EQ(SearchOptions{}.facet_order, FacetOrder::automatic);
  EXPECT_EQ(drange::engine::search_variant("full").facet_order, FacetOrder::automatic);
  EXPECT_EQ(drange::engine::search_variant("fifo").facet_order, FacetOrder::fifo);
  EXPECT_EQ(drange::engine::search_variant("paper").facet_order, FacetOrder::fifo);
  EXPECT_EQ(drange::engine::search_variant("spatial").facet_order, FacetOrder::spatial);
}

// What the order is for: in 3D the FIFO frontier grows as a ball's surface, the spatial one
// sweeps through space (a count, not a time: deterministic).
TEST(FacetOrder, SpatialKeepsTheThreeDimensionalFrontierSmall) {
  const PointCloud points = drange::generate_points(Distribution::Uniform, 50000, 3, 13);
  const std::size_t fifo = run(points, FacetOrder::fifo).stats.debug.max_open_facets;
  const std::size_t spatial = run(points, FacetOrder::spatial).stats.debug.max_open_facets;
  EXPECT_LT(spatial * 2, fifo) << "spatial " << spatial << ", fifo " << fifo;
}

}  // namespace
