// tests/progress_test.cpp: Options::progress as the engine calls it (counts, the final call,
// abandoning a run by throwing), and the CLI's progress line (cli/progress.hpp) through its
// pure functions; whether stderr is a terminal is not testable here.
#include <unistd.h>

#include <cstddef>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "drange/delaunay.hpp"
#include "drange/generate.hpp"

// The CLI is an executable, not a library: its progress unit is compiled into the tests here.
#include "../cli/progress.cpp"  // NOLINT(bugprone-suspicious-include)

namespace drange {
namespace {

std::vector<std::size_t> reported_counts(const PointCloud& points) {
  std::vector<std::size_t> counts;
  Options options;
  options.progress = [&](std::size_t found) { counts.push_back(found); };
  const Triangulation t = delaunay(points, options);
  EXPECT_FALSE(counts.empty());
  if (!counts.empty()) {
    EXPECT_EQ(counts.back(), t.size());
  }
  return counts;
}

// About 200 000 triangles: three calls on the way, at multiples of the interval, then the total.
TEST(ProgressTest, EngineReportsIncreasingCountsEndingInTheTotal) {
  const std::vector<std::size_t> counts = reported_counts(generate_points(Distribution::Uniform, 100000, 2, 1));
  ASSERT_EQ(counts.size(), 4u);
  for (std::size_t i = 0; i + 1 < counts.size(); ++i) {
    EXPECT_EQ(counts[i], (i + 1) * kProgressInterval);
    EXPECT_LT(counts[i], counts[i + 1]);
  }
  EXPECT_NE(counts.back() % kProgressInterval, 0u);  // how a caller tells the final call
}

TEST(ProgressTest, SmallRunReportsOnlyItsTotal) {
  const std::vector<std::size_t> counts = reported_counts(generate_points(Distribution::Uniform, 100, 3, 1));
  EXPECT_EQ(counts.size(), 1u);
}

TEST(ProgressTest, ThrowingCallbackAbandonsTheRun) {
  struct Abandoned {
    std::size_t at;
  };
  Options options;
  options.progress = [](std::size_t found) { throw Abandoned{found}; };
  try {
    delaunay(generate_points(Distribution::Uniform, 50000, 2, 1), options);
    FAIL() << "the run went on";
  } catch (const Abandoned& abandoned) {
    EXPECT_EQ(abandoned.at, kProgressInterval);
  }
}

TEST(ProgressTest, ReporterIsEmptyWhenQuietOrNotATerminal) {
  EXPECT_FALSE(cli::make_progress_reporter(1000000, 3, true));
  if (!isatty(STDERR_FILENO)) {
    EXPECT_FALSE(cli::make_progress_reporter(1000000, 3, false));
  }
}

TEST(ProgressTest, LineShowsCountRateFractionAndTimeLeft) {
  // 1 234 567 of 2 000 000 in 4 s: 309k/s, 61%, 4 s * 765 433 / 1 234 567 = 2.5 s left.
  EXPECT_EQ(cli::progress_line(1234567, 2000000, 4.0), "1 234 567 simplices  309k/s  61%  about 3 s left");
  EXPECT_EQ(cli::progress_line(65536, 6553600, 10.0), "65 536 simplices  6554/s  1%  about 17 min left");
  EXPECT_EQ(cli::progress_line(65536, 65536000, 10.0), "65 536 simplices  6554/s  0%  about 2 h 47 min left");
  EXPECT_EQ(cli::progress_line(2400000, 0, 2.0), "2 400 000 simplices  1.2M/s");  // no estimate
  EXPECT_EQ(cli::progress_line(655360, 1000000, 0.0), "655 360 simplices  65%");  // no time yet
}

TEST(ProgressTest, FractionStopsAt99WhenTheEstimateIsTooLow) {
  EXPECT_EQ(cli::progress_line(3000000, 2000000, 3.0), "3 000 000 simplices  1.0M/s  99%");
}

TEST(ProgressTest, ExpectedSimplicesGrowWithTheDimension) {
  EXPECT_DOUBLE_EQ(cli::expected_simplices(1000, 2), 2000.0);
  EXPECT_NEAR(cli::expected_simplices(1000000, 3), 6.75e6, 0.05e6);  // README: 6 747 791
  for (int d = 3; d <= 11; ++d) EXPECT_GT(cli::expected_simplices(1000, d), cli::expected_simplices(1000, d - 1)) << d;
}

}  // namespace
}  // namespace drange
