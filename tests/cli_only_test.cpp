// tests/cli_only_test.cpp: `drange delaunay --only IDS`: the stars written equal the whole
// triangulation's simplices at those points; every bad id is named, exits 2 and writes nothing.
// And `--furthest-site`, which like --only writes another set of simplices than the default.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "cli_runner.hpp"
#include "drange/incremental.hpp"
#include "drange/io.hpp"
#include "temp_dir.hpp"

namespace drange {
namespace {

using testing::CliRun;
using testing::contains;
using testing::read_text;
using testing::run_cli;
using testing::TempDir;
using testing::write_text;

std::set<std::vector<std::int32_t>> vertex_sets(const std::string& path, int vertices, const std::set<std::int32_t>& at) {
  const std::vector<std::int32_t> flat = read_simplices(path, vertices);
  std::set<std::vector<std::int32_t>> sets;
  for (std::size_t i = 0; i < flat.size(); i += static_cast<std::size_t>(vertices)) {
    std::vector<std::int32_t> v(flat.begin() + static_cast<long>(i), flat.begin() + static_cast<long>(i) + vertices);
    std::sort(v.begin(), v.end());
    if (std::any_of(v.begin(), v.end(), [&](std::int32_t x) { return at.empty() || at.count(x) != 0; })) sets.insert(v);
  }
  return sets;
}

std::set<std::vector<std::int32_t>> vertex_sets_of(const Triangulation& t) {
  std::set<std::vector<std::int32_t>> sets;
  for (std::size_t s = 0; s < t.size(); ++s) {
    std::vector<std::int32_t> v(t.simplex(s), t.simplex(s) + t.dim + 1);
    std::sort(v.begin(), v.end());
    sets.insert(v);
  }
  return sets;
}

TEST(CliOnly, StarsEqualTheWholeTriangulationsSimplices) {
  TempDir dir;
  for (const auto& [distribution, count, dim] : std::vector<std::tuple<std::string, std::string, int>>{
           {"grid", "125", 3}, {"uniform", "2000", 2}, {"uniform", "400", 4}}) {
    const std::string points = dir.file("p.txt");
    ASSERT_EQ(run_cli(dir, {"generate", distribution, count, std::to_string(dim), "-o", points}).code, 0);
    ASSERT_EQ(run_cli(dir, {"delaunay", points, "-o", dir.file("full.txt"), "--algorithm", "direct"}).code, 0);
    write_text(dir.file("ids.txt"), "0\n 62, 7\n" + std::to_string(std::stoi(count) - 1) + "\n");
    const std::set<std::int32_t> ids{0, 62, 7, std::stoi(count) - 1};
    const auto expected = vertex_sets(dir.file("full.txt"), dim + 1, ids);
    for (const std::string& list : {std::string("0,62,7,") + std::to_string(std::stoi(count) - 1), "@" + dir.file("ids.txt")}) {
      const CliRun run = run_cli(dir, {"delaunay", points, "--only", list, "-o", dir.file("stars.txt"), "--neighbors", dir.file("n.txt")});
      ASSERT_EQ(run.code, 0) << run.err;
      EXPECT_EQ(vertex_sets(dir.file("stars.txt"), dim + 1, {}), expected) << distribution << " " << list;
      const std::string neighbours = read_text(dir.file("n.txt"));  // the count, then a row per simplex
      EXPECT_EQ(neighbours.substr(0, neighbours.find('\n')), std::to_string(expected.size()));
      EXPECT_EQ(static_cast<std::size_t>(std::count(neighbours.begin(), neighbours.end(), '\n')), expected.size() + 1);
    }
    ASSERT_EQ(run_cli(dir, {"delaunay", points, "--only", "7", "-o", dir.file("stars.json")}).code, 0);
    EXPECT_TRUE(contains(read_text(dir.file("stars.json")), "\"neighbors\"")) << distribution;
  }
}

TEST(CliOnly, BadIdsAreNamedAndWriteNothing) {
  TempDir dir;
  write_text(dir.file("p.txt"), testing::kSquareWithCentre);
  write_text(dir.file("out.txt"), "untouched");
  write_text(dir.file("bad_ids.txt"), "1\n2 two\n");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"1,5", "point id 5 is out of range"},  {"2,3,2", "point id 2 is given twice"},
      {"1,x", "'x' in '1,x' is not a point id"}, {"-1", "'-1' in '-1' is not a point id"},
      {"1,,2", "an empty point id"},           {"", "--only needs at least one point id"},
      {"@" + dir.file("bad_ids.txt"), "'two' in " + dir.file("bad_ids.txt") + ", line 2"},
  };
  for (const auto& [ids, message] : cases) {
    const CliRun run = run_cli(dir, {"delaunay", dir.file("p.txt"), "--only", ids, "-o", dir.file("out.txt")});
    EXPECT_EQ(run.code, 2) << ids;
    EXPECT_TRUE(contains(run.err, message)) << ids << ": " << run.err;
    EXPECT_EQ(read_text(dir.file("out.txt")), "untouched") << ids;
  }
  const CliRun missing = run_cli(dir, {"delaunay", dir.file("p.txt"), "--only", "@" + dir.file("none.txt"), "-o", dir.file("out.txt")});
  EXPECT_EQ(missing.code, 3);
  EXPECT_TRUE(contains(missing.err, "cannot read")) << missing.err;
}

TEST(CliOnly, TheCentreOfASquareHasEveryTriangle) {
  TempDir dir;
  write_text(dir.file("p.txt"), testing::kSquareWithCentre);
  ASSERT_EQ(run_cli(dir, {"delaunay", dir.file("p.txt"), "--only", "4", "-o", dir.file("s.txt")}).code, 0);
  EXPECT_EQ(read_simplices(dir.file("s.txt"), 3).size(), 12u);
  ASSERT_EQ(run_cli(dir, {"delaunay", dir.file("p.txt"), "--only", "0", "-o", dir.file("s.txt")}).code, 0);
  EXPECT_EQ(read_simplices(dir.file("s.txt"), 3).size(), 6u);  // the corner's two triangles
}

TEST(CliFurthestSite, WritesTheFurthestSiteTriangulation) {
  testing::TempDir dir;
  const std::string points = dir.file("p.txt");
  ASSERT_EQ(testing::run_cli(dir, {"generate", "uniform", "300", "3", "-o", points}).code, 0);
  const testing::CliRun run = testing::run_cli(dir, {"delaunay", points, "--furthest-site", "-o", dir.file("f.txt")});
  ASSERT_EQ(run.code, 0) << run.err;
  const PointCloud cloud = read_points(points);
  const Triangulation expected = IncrementalDelaunay(cloud, true).triangulation();
  EXPECT_EQ(vertex_sets(dir.file("f.txt"), 4, {}), vertex_sets_of(expected));
  const testing::CliRun mixed = testing::run_cli(dir, {"delaunay", points, "--furthest-site", "--only", "3", "-o", dir.file("g.txt")});
  EXPECT_EQ(mixed.code, 2);
  EXPECT_TRUE(testing::contains(mixed.err, "--furthest-site")) << mixed.err;
}

}  // namespace
}  // namespace drange
