// `drange hull` against Qhull's `qconvex i Qt` (Debian's qhull-bin) on random points in general
// position, where the hull's facets are unique: the same facets as sets of input indices, and
// the command's other outputs. Skipped, loudly, when qconvex is not installed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "drange/generate.hpp"
#include "drange/hull.hpp"
#include "drange/io.hpp"
#include "oracle.hpp"

namespace drange {
namespace {

using testing::contains;
using testing::run_cli;
using testing::TempDir;

bool have_qconvex() { return std::system("command -v qconvex >/dev/null 2>&1") == 0; }

TEST(HullCommand, SameFacetsAsQconvex) {
  if (!have_qconvex()) GTEST_SKIP() << "qconvex not installed (Debian qhull-bin): Qhull agreement NOT tested";
  TempDir dir;
  const struct {
    Distribution distribution;
    std::size_t n;
    int d;
  } cases[] = {{Distribution::Uniform, 20000, 2}, {Distribution::Ball, 20000, 3}, {Distribution::Sphere, 3000, 3},
               {Distribution::Gaussian, 3000, 4}, {Distribution::Uniform, 2000, 5}};
  for (const auto& c : cases) {
    SCOPED_TRACE("n=" + std::to_string(c.n) + " d=" + std::to_string(c.d));
    const PointCloud points = generate_points(c.distribution, c.n, c.d, 77);
    const std::string in = dir.file("points.txt");
    write_file_atomically(in, [&](std::ostream& o) { write_points(o, points); });
    const std::string command = "qconvex i Qt < '" + in + "' > '" + dir.file("qconvex.txt") + "'";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
    const auto run = run_cli(dir, {"hull", in, "-o", dir.file("hull.txt"), "--stats"});
    ASSERT_EQ(run.code, 0) << run.err;
    EXPECT_TRUE(contains(run.err, "facets=")) << run.err;
    const std::vector<std::int32_t> theirs = read_simplices(dir.file("qconvex.txt"), c.d);
    const std::vector<std::int32_t> ours = read_simplices(dir.file("hull.txt"), c.d);
    EXPECT_EQ(test::canonical(ours, c.d - 1), test::canonical(theirs, c.d - 1));
  }
}

TEST(HullCommand, WritesNeighboursAndCoplanarPoints) {
  TempDir dir;
  // A square with a point on a side and a copy of a corner.
  const std::string in = dir.file("square.txt");
  testing::write_text(in, "2\n6\n0 0\n2 0\n2 2\n0 2\n1 0\n2 2\n");
  const auto run = run_cli(dir, {"hull", in, "--neighbors", dir.file("n.txt"), "--coplanar", dir.file("c.txt")});
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_EQ(read_simplices(dir.file("n.txt"), 2).size(), 8u);
  const std::vector<std::int32_t> coplanar = read_simplices(dir.file("c.txt"), 3);
  ASSERT_EQ(coplanar.size(), 6u);
  // The point on a side, and whichever copy of (2, 2) is not the vertex.
  std::vector<std::int32_t> points = {coplanar[0], coplanar[3]};
  std::sort(points.begin(), points.end());
  EXPECT_TRUE(points == (std::vector<std::int32_t>{2, 4}) || points == (std::vector<std::int32_t>{4, 5}));
  const auto flat = run_cli(dir, {"hull", in + ".flat"});
  EXPECT_EQ(flat.code, 3);  // no such file
  testing::write_text(in, "2\n3\n0 0\n1 1\n2 2\n");
  EXPECT_EQ(run_cli(dir, {"hull", in}).code, 4);  // collinear
}

}  // namespace
}  // namespace drange
