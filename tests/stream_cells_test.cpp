// Tests of drange::stream_clipped_cells (src/voronoi/stream_cells.cpp) and the text cells
// (append_cell_text): every distinct point gets one cell, equal to clip_cells' cell of the whole
// diagram up to rounding; the text is the same for every thread count; bad arguments are refused
// and an exception from `write` stops the stream. tests/cells/cells_stream_agreement.py checks
// the CLI against the whole diagram's cells and voro++.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "drange/errors.hpp"
#include "drange/formats.hpp"
#include "drange/generate.hpp"
#include "drange/voronoi.hpp"

namespace {

using drange::Box;
using drange::ClippedCells;
using drange::Distribution;
using drange::PointCloud;

struct Streamed {
  std::string text;
  std::map<std::int32_t, double> volume;  // by input point
  drange::CellStreamReport report;
};

Streamed stream(const PointCloud& points, const Box& box, int threads) {
  Streamed out;
  drange::Options options;
  options.threads = threads;
  out.report = drange::stream_clipped_cells(
      points, box, options,
      [](const ClippedCells& cell, std::int32_t point, std::string& text) {
        drange::append_cell_text(text, cell, 0, point, true);
      },
      [&](const std::string& text) { out.text += text; });
  std::istringstream lines(out.text);
  std::string line;
  while (std::getline(lines, line)) {
    std::istringstream fields(line);
    std::int32_t point;
    double volume;
    fields >> point >> volume;
    EXPECT_EQ(out.volume.count(point), 0u) << "point " << point << " has two cells";
    out.volume[point] = volume;
  }
  return out;
}

void expect_whole_diagram_cells(const PointCloud& points) {
  const Box box = drange::default_clip_box(points);
  const drange::Voronoi diagram = drange::voronoi(points);
  const ClippedCells whole = drange::clip_cells(points, diagram, box);
  const Streamed streamed = stream(points, box, 1);
  ASSERT_EQ(streamed.volume.size(), whole.size());
  for (std::size_t c = 0; c < whole.size(); ++c) {
    const std::int32_t point = diagram.region_point[c];
    ASSERT_EQ(streamed.volume.count(point), 1u) << "no cell for point " << point;
    EXPECT_NEAR(streamed.volume.at(point), whole.volumes[c], 1e-9 * std::fabs(whole.volumes[c]) + 1e-15)
        << "point " << point;
  }
}

TEST(StreamCells, EqualTheWholeDiagramsCells) {
  for (const int d : {2, 3})
    for (const Distribution distribution : {Distribution::Uniform, Distribution::Clustered, Distribution::Grid}) {
      SCOPED_TRACE("d = " + std::to_string(d) + ", distribution " + std::to_string(static_cast<int>(distribution)));
      expect_whole_diagram_cells(drange::generate_points(distribution, 1500, d, 7));
    }
}

TEST(StreamCells, SameTextForEveryThreadCount) {
  // More points than one batch holds, so that threads take several batches.
  const PointCloud points = drange::generate_points(Distribution::Uniform, 40000, 2, 3);
  const Box box = drange::default_clip_box(points);
  const Streamed one = stream(points, box, 1), three = stream(points, box, 3);
  EXPECT_GT(one.report.batches, 1u);
  EXPECT_EQ(one.text, three.text);
  EXPECT_EQ(one.volume.size(), 40000u);
  double total = 0;
  for (const auto& [point, volume] : one.volume) total += volume;
  EXPECT_NEAR(total, (box.upper[0] - box.lower[0]) * (box.upper[1] - box.lower[1]), 1e-9);
}

TEST(StreamCells, DuplicatesShareTheirOriginalsCell) {
  PointCloud points = drange::generate_points(Distribution::Uniform, 200, 3, 5);
  for (const std::size_t copied : {4u, 9u, 4u})
    for (int k = 0; k < 3; ++k) points.coords.push_back(points.coords[copied * 3 + static_cast<std::size_t>(k)]);
  const Streamed streamed = stream(points, drange::default_clip_box(points), 2);
  EXPECT_EQ(streamed.report.duplicates.size(), 3u);
  EXPECT_EQ(streamed.volume.size(), 200u);
  for (const std::int32_t copy : {200, 201, 202}) EXPECT_EQ(streamed.volume.count(copy), 0u);
}

TEST(StreamCells, TextLines) {
  // The unit square's four corners clipped to it: four quarter squares, corners counter-clockwise.
  const PointCloud points{2, {0, 0, 1, 0, 0, 1, 1, 1}};
  const Streamed streamed = stream(points, Box{{0, 0}, {1, 1}}, 1);
  EXPECT_EQ(streamed.volume.size(), 4u);
  for (const auto& [point, volume] : streamed.volume) EXPECT_EQ(volume, 0.25);
  EXPECT_NE(streamed.text.find("0 0.25 4 0 0 0.5 0 0.5 0.5 0 0.5\n"), std::string::npos) << streamed.text;
  // A cell that misses the box: "point 0 0".
  const PointCloud outside{2, {0, 0, 1, 0, 0, 1, 5, 5}};
  EXPECT_NE(stream(outside, Box{{0, 0}, {1, 1}}, 1).text.find("3 0 0\n"), std::string::npos);
}

TEST(StreamCells, RefusesBadArguments) {
  const PointCloud points = drange::generate_points(Distribution::Uniform, 100, 3, 1);
  const auto format = [](const ClippedCells&, std::int32_t, std::string&) {};
  const auto write = [](const std::string&) {};
  drange::Options options;
  EXPECT_THROW(drange::stream_clipped_cells(points, Box{{0, 0}, {1, 1}}, options, format, write), drange::UsageError);
  EXPECT_THROW(drange::stream_clipped_cells(points, Box{{0, 0, 0}, {1, 0, 1}}, options, format, write), drange::UsageError);
  const PointCloud four = drange::generate_points(Distribution::Uniform, 100, 4, 1);
  EXPECT_THROW(drange::stream_clipped_cells(four, Box{{0, 0, 0, 0}, {1, 1, 1, 1}}, options, format, write),
               drange::UsageError);
  options.threads = -1;
  EXPECT_THROW(drange::stream_clipped_cells(points, Box{{0, 0, 0}, {1, 1, 1}}, options, format, write), drange::UsageError);
}

TEST(StreamCells, AFailedWriteStopsTheStream) {
  const PointCloud points = drange::generate_points(Distribution::Uniform, 40000, 2, 2);
  drange::Options options;
  options.threads = 2;
  int writes = 0;
  EXPECT_THROW(drange::stream_clipped_cells(
                   points, drange::default_clip_box(points), options,
                   [](const ClippedCells&, std::int32_t, std::string& text) { text += 'x'; },
                   [&](const std::string&) {
                     ++writes;
                     throw std::runtime_error("disk full");
                   }),
               std::runtime_error);
  EXPECT_EQ(writes, 1);
}

}  // namespace
