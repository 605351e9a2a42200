// Agreement with Qhull (`qdelaunay`, Debian's qhull-bin) on random points in general position,
// where the Delaunay triangulation is unique: the same simplices, as sets of input indices.
// Skipped, loudly, when qdelaunay is not installed (test.sh installs it).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "drange/delaunay.hpp"
#include "drange/generate.hpp"
#include "drange/io.hpp"

namespace {

using Simplex = std::vector<std::int32_t>;

std::set<Simplex> canonical(const std::vector<std::int32_t>& flat, int d) {
  std::set<Simplex> out;
  for (std::size_t s = 0; s + static_cast<std::size_t>(d) < flat.size(); s += static_cast<std::size_t>(d + 1)) {
    Simplex v(flat.begin() + static_cast<std::ptrdiff_t>(s), flat.begin() + static_cast<std::ptrdiff_t>(s) + d + 1);
    std::sort(v.begin(), v.end());
    out.insert(v);
  }
  return out;
}

bool have_qdelaunay() { return std::system("command -v qdelaunay >/dev/null 2>&1") == 0; }

struct Case {
  drange::Distribution distribution;
  std::size_t n;
  int d;
};

std::string describe(const Case& c) {
  static const char* const names[] = {"uniform", "ball", "sphere", "gaussian", "clustered", "grid"};
  return std::string(names[static_cast<int>(c.distribution)]) + "_d" + std::to_string(c.d) + "_n" + std::to_string(c.n);
}
std::string case_name(const ::testing::TestParamInfo<Case>& info) { return describe(info.param); }
void PrintTo(const Case& c, std::ostream* os) { *os << describe(c); }

class QhullAgreement : public ::testing::TestWithParam<Case> {};

TEST_P(QhullAgreement, SameSimplicesAsQdelaunay) {
  if (!have_qdelaunay()) GTEST_SKIP() << "qdelaunay not installed (Debian qhull-bin): Qhull agreement NOT tested";
  const Case c = GetParam();
  const std::uint64_t seed = 1000 + c.n + static_cast<std::uint64_t>(c.d);
  const drange::PointCloud points = drange::generate_points(c.distribution, c.n, c.d, seed);
  const std::string dir = ::testing::TempDir();
  const std::string in = dir + "qhull_in_" + describe(c) + ".txt";
  const std::string out = in + ".tri";
  drange::write_file_atomically(in, [&](std::ostream& o) { drange::write_points(o, points); });
  // Qt: triangulated output, as scipy uses; on points in general position it is the unique triangulation.
  const std::string command = "qdelaunay i Qt < '" + in + "' > '" + out + "'";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const std::vector<std::int32_t> theirs = drange::read_simplices(out, c.d + 1);
  const drange::Triangulation ours = drange::delaunay(points);
  EXPECT_EQ(canonical(ours.simplices, c.d), canonical(theirs, c.d)) << "seed " << seed;
  std::remove(in.c_str());
  std::remove(out.c_str());
}

INSTANTIATE_TEST_SUITE_P(
    RandomInputs, QhullAgreement,
    ::testing::Values(Case{drange::Distribution::Uniform, 5000, 2}, Case{drange::Distribution::Gaussian, 5000, 2},
                      Case{drange::Distribution::Uniform, 3000, 3}, Case{drange::Distribution::Ball, 3000, 3},
                      Case{drange::Distribution::Uniform, 800, 4}, Case{drange::Distribution::Uniform, 300, 5},
                      Case{drange::Distribution::Gaussian, 120, 6}),
    case_name);

}  // namespace
