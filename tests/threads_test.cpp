// Tests of Options::threads: the triangulation, simplex numbers and neighbours included, and
// the statistics are the same for every thread count, on general and degenerate inputs; the
// progress callback runs on the calling thread and may cancel a threaded run; exceptions on
// helper threads reach the caller.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "delaunay/team.hpp"
#include "drange/check.hpp"
#include "drange/delaunay.hpp"
#include "drange/errors.hpp"
#include "drange/generate.hpp"
#include "oracle.hpp"
#include "spatial/kdtree.hpp"

namespace {

using drange::Distribution;
using drange::PointCloud;
using drange::Triangulation;

const int kThreadCounts[] = {2, 3, 4, 7};

// The integer grid {0..k-1}^d.
PointCloud grid(int d, int k) {
  return drange::generate_points(Distribution::Grid, static_cast<std::size_t>(std::pow(k, d)), d, 1);
}

Triangulation run(const PointCloud& points, int threads, bool seeds = true) {
  drange::Options options;
  options.threads = threads;
  options.variant = seeds ? "full" : "no-seed";
  return drange::delaunay(points, options);
}

// Every thread count gives the serial run's arrays, byte for byte, and the statistics of the
// result (points, simplices, hull facets); the serial result is valid. From 4D on, where the
// searches run ahead on the threads of one serial loop, the statistics of the work agree too
// (all but the times, the thread count and the wasted searches), except that the seed
// candidates (variant no-seed leaves them out) come from the recent searches of all threads,
// in the order the threads happened to make them, so with them the work counters (calls,
// points tested, candidates, exact fallbacks) depend on the timing. In 2D and 3D the search
// runs in blocks, more for more threads (block_search.hpp): the work and the largest
// frontier depend on the cut.
void expect_same_for_every_thread_count(const std::string& name, const PointCloud& points, bool seeds);

void expect_same_for_every_thread_count(const std::string& what, const PointCloud& points) {
  for (const bool seeds : {true, false}) expect_same_for_every_thread_count(what, points, seeds);
}

void expect_same_for_every_thread_count(const std::string& name, const PointCloud& points, bool seeds) {
  const std::string what = name + (seeds ? "" : ", no seeds");
  const Triangulation serial = run(points, 1, seeds);
  EXPECT_EQ(serial.stats.threads, 1u) << what;
  EXPECT_EQ(serial.stats.debug.wasted_searches, 0u) << what;
  const drange::CheckReport report = drange::check_triangulation(points, serial.simplices);
  EXPECT_TRUE(report.valid) << what << ": " << (report.problems.empty() ? "" : report.problems.front());
  for (const int threads : kThreadCounts) {
    const Triangulation t = run(points, threads, seeds);
    const std::string at = what + ", threads=" + std::to_string(threads);
    EXPECT_EQ(t.stats.threads, static_cast<std::size_t>(threads)) << at;
    EXPECT_TRUE(t.simplices == serial.simplices) << at << ": simplices differ";
    EXPECT_TRUE(t.neighbors == serial.neighbors) << at << ": neighbours differ";
    ASSERT_EQ(t.duplicates.size(), serial.duplicates.size()) << at;
    for (std::size_t i = 0; i < t.duplicates.size(); ++i) {
      EXPECT_EQ(t.duplicates[i].index, serial.duplicates[i].index) << at;
      EXPECT_EQ(t.duplicates[i].original, serial.duplicates[i].original) << at;
    }
    const drange::Statistics& a = t.stats;
    const drange::Statistics& b = serial.stats;
    EXPECT_EQ(a.points, b.points) << at;
    EXPECT_EQ(a.distinct_points, b.distinct_points) << at;
    EXPECT_EQ(a.simplices, b.simplices) << at;
    EXPECT_EQ(a.hull_facets, b.hull_facets) << at;
    if (points.dim <= 3) continue;
    EXPECT_EQ(a.debug.max_open_facets, b.debug.max_open_facets) << at;
    if (seeds) continue;
    EXPECT_EQ(a.search_calls, b.search_calls) << at;
    EXPECT_EQ(a.debug.points_tested, b.debug.points_tested) << at;
    EXPECT_EQ(a.debug.candidates, b.debug.candidates) << at;
    EXPECT_EQ(a.debug.exact_fallbacks, b.debug.exact_fallbacks) << at;
  }
}

TEST(ThreadsTest, UniformInputsInTwoToFourDimensions) {
  expect_same_for_every_thread_count("uniform 2D 20000", drange::generate_points(Distribution::Uniform, 20000, 2, 1));
  expect_same_for_every_thread_count("uniform 3D 5000", drange::generate_points(Distribution::Uniform, 5000, 3, 2));
  expect_same_for_every_thread_count("uniform 4D 2000", drange::generate_points(Distribution::Uniform, 2000, 4, 3));
}

// Large enough for the parallel sort, kd-tree and first-facet scans (more than one chunk).
TEST(ThreadsTest, InputLargeEnoughForEveryParallelPhase) {
  expect_same_for_every_thread_count("uniform 2D 70000", drange::generate_points(Distribution::Uniform, 70000, 2, 4));
}

TEST(ThreadsTest, IntegerGrids) {
  expect_same_for_every_thread_count("grid 100x100", grid(2, 100));
  expect_same_for_every_thread_count("grid 12^3", grid(3, 12));
  // Its hull side x = 0 holds points from several first-facet chunks.
  expect_same_for_every_thread_count("grid 260x260", grid(2, 260));
}

TEST(ThreadsTest, CosphericalInputs) {
  // 800, not more: the search on a sphere costs O(n^2).
  expect_same_for_every_thread_count("sphere 3D 800", drange::generate_points(Distribution::Sphere, 800, 3, 5));
  // The 108 integer points on the circle of radius 1105 = 5 * 13 * 17, its centre, and integer
  // points inside: every triangle among the circle's points is a tie the perturbation breaks.
  PointCloud circle = drange::test::integer_circle_points(1105);
  ASSERT_EQ(circle.size(), 108u);
  circle.coords.insert(circle.coords.end(), {0.0, 0.0});
  std::mt19937_64 rng(6);
  std::uniform_int_distribution<long> coordinate(-700, 700);
  for (int i = 0; i < 200; ++i) circle.coords.insert(circle.coords.end(), {double(coordinate(rng)), double(coordinate(rng))});
  expect_same_for_every_thread_count("integer circle", circle);
}

TEST(ThreadsTest, Duplicates) {
  PointCloud points = drange::generate_points(Distribution::Uniform, 5000, 3, 7);
  std::mt19937_64 rng(8);
  for (int i = 0; i < 700; ++i) {
    const std::size_t j = rng() % 5000;
    points.coords.insert(points.coords.end(), points.point(j), points.point(j) + 3);
  }
  expect_same_for_every_thread_count("uniform 3D with 700 duplicates", points);
}

TEST(ThreadsTest, ZeroMeansEveryHardwareThreadAndNegativeIsAnError) {
  const PointCloud points = drange::generate_points(Distribution::Uniform, 500, 2, 9);
  const unsigned hardware = std::thread::hardware_concurrency();
  EXPECT_EQ(run(points, 0).stats.threads, hardware > 0 ? hardware : 1u);
  EXPECT_EQ(drange::Options{}.threads, 0);  // the default uses every core
  try {
    run(points, -2);
    FAIL() << "threads = -2 accepted";
  } catch (const drange::UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("-2"), std::string::npos) << e.what();
  }
}

TEST(ThreadsTest, ProgressIsCalledOnTheCallingThreadWithTheSerialCounts) {
  const PointCloud points = drange::generate_points(Distribution::Uniform, 100000, 2, 10);
  std::vector<std::size_t> serial_counts;
  drange::Options options;
  options.threads = 1;
  options.progress = [&](std::size_t found) { serial_counts.push_back(found); };
  drange::delaunay(points, options);

  const std::thread::id caller = std::this_thread::get_id();
  std::vector<std::size_t> counts;
  bool elsewhere = false;
  options.threads = 4;
  options.progress = [&](std::size_t found) {
    elsewhere = elsewhere || std::this_thread::get_id() != caller;
    counts.push_back(found);
  };
  drange::delaunay(points, options);
  EXPECT_FALSE(elsewhere);
  EXPECT_EQ(counts, serial_counts);
}

TEST(ThreadsTest, ThrowingProgressCancelsAThreadedRun) {
  struct Cancelled {
    std::size_t at;
  };
  const PointCloud points = drange::generate_points(Distribution::Uniform, 300000, 2, 11);
  for (const int threads : {2, 4}) {
    drange::Options options;
    options.threads = threads;
    options.progress = [](std::size_t found) { throw Cancelled{found}; };
    const auto start = std::chrono::steady_clock::now();
    try {
      drange::delaunay(points, options);
      FAIL() << "the run went on";
    } catch (const Cancelled& cancelled) {
      EXPECT_EQ(cancelled.at, drange::kProgressInterval);
    }
    // The run stops at the first report, a small part of the whole (600 000 triangles).
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
  }
}

TEST(ThreadsTest, TeamRethrowsAHelpersExceptionAfterStoppingTheOthers) {
  drange::engine::Team team(4);
  std::atomic<bool> stop{false};
  std::atomic<int> finished{0};
  try {
    team.run(
        4,
        [&](int rank) {
          if (rank == 2) throw std::runtime_error("helper 2 failed");
          while (!stop.load()) std::this_thread::yield();  // waits for the others, like the search pipeline
          ++finished;
        },
        [&] { stop = true; });
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "helper 2 failed");
  }
  EXPECT_EQ(finished.load(), 3);  // every other thread returned and was joined

  std::atomic<int> tasks_run{0};
  EXPECT_THROW(team.for_each(100,
                             [&](std::size_t i) {
                               ++tasks_run;
                               if (i == 10) throw std::bad_alloc();
                             }),
               std::bad_alloc);
  EXPECT_LE(tasks_run.load(), 100);
}

}  // namespace
