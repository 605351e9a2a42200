// Agreement with Qhull (`qdelaunay`, Debian's qhull-bin) on random points in general position,
// where the Delaunay triangulation is unique: the same simplices, as sets of input indices.
// Skipped, loudly, when qdelaunay is not installed (test.sh installs it).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "drange/check.hpp"
#include "drange/delaunay.hpp"
#include "oracle.hpp"
#include "peers/peer_case.hpp"
#include "drange/generate.hpp"
#include "drange/io.hpp"

namespace drange {
namespace {

bool have_qdelaunay() { return std::system("command -v qdelaunay >/dev/null 2>&1") == 0; }

class QhullAgreement : public ::testing::TestWithParam<test::PeerCase> {};

TEST_P(QhullAgreement, SameSimplicesAsQdelaunay) {
  if (!have_qdelaunay()) GTEST_SKIP() << "qdelaunay not installed (Debian qhull-bin): Qhull agreement NOT tested";
  const test::PeerCase c = GetParam();
  const std::uint64_t seed = 1000 + c.n + static_cast<std::uint64_t>(c.d);
  const PointCloud points = generate_points(c.distribution, c.n, c.d, seed);
  const std::string dir = ::testing::TempDir();
  const std::string in = dir + "qhull_in_" + test::describe(c) + ".txt";
  const std::string out = in + ".tri";
  write_file_atomically(in, [&](std::ostream& o) { write_points(o, points); });
  // Qt: triangulated output, as scipy uses; on points in general position it is the unique triangulation.
  const std::string command = "qdelaunay i Qt < '" + in + "' > '" + out + "'";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const std::vector<std::int32_t> theirs = read_simplices(out, c.d + 1);
  const Triangulation ours = delaunay(points);
  EXPECT_EQ(test::canonical(ours.simplices, c.d), test::canonical(theirs, c.d)) << "seed " << seed;
  // The validator works on another program's output (either orientation) too.
  const CheckReport report = check_triangulation(points, theirs);
  EXPECT_TRUE(report.valid) << (report.problems.empty() ? "" : report.problems.front());
  std::remove(in.c_str());
  std::remove(out.c_str());
}

INSTANTIATE_TEST_SUITE_P(
    RandomInputs, QhullAgreement,
    ::testing::Values(test::PeerCase{Distribution::Uniform, 5000, 2}, test::PeerCase{Distribution::Gaussian, 5000, 2},
                      test::PeerCase{Distribution::Uniform, 3000, 3}, test::PeerCase{Distribution::Ball, 3000, 3},
                      test::PeerCase{Distribution::Uniform, 800, 4}, test::PeerCase{Distribution::Uniform, 300, 5},
                      test::PeerCase{Distribution::Gaussian, 120, 6}),
    test::case_name);

}  // namespace
}  // namespace drange
