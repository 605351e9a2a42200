// tests/cli_voronoi_only_test.cpp: `drange voronoi --only IDS`: each asked-for cell written
// (json) equals the whole diagram's cell for that point, the other points have no region;
// bad ids and the layouts that need every cell are refused with exit 2, writing nothing.
#include <gtest/gtest.h>

#include <string>
#include <tuple>
#include <vector>

#include "cli_runner.hpp"
#include "python_check.hpp"
#include "temp_dir.hpp"

namespace drange {
namespace {

using testing::CliRun;
using testing::contains;
using testing::read_text;
using testing::run_cli;
using testing::TempDir;
using testing::write_text;

TEST(CliVoronoiOnly, CellsEqualTheWholeDiagrams) {
  DRANGE_REQUIRE_PYTHON("json");
  TempDir dir;
  std::vector<std::string> args;
  int i = 0;
  for (const auto& [distribution, count, dim] : std::vector<std::tuple<std::string, std::string, int>>{
           {"grid", "125", 3}, {"grid", "49", 2}, {"uniform", "500", 2}, {"uniform", "300", 3}, {"uniform", "150", 4}}) {
    const std::string points = dir.file("p" + std::to_string(i) + ".txt");
    const std::string full = dir.file("full" + std::to_string(i) + ".json");
    const std::string part = dir.file("part" + std::to_string(i) + ".json");
    ASSERT_EQ(run_cli(dir, {"generate", distribution, count, std::to_string(dim), "-o", points}).code, 0);
    ASSERT_EQ(run_cli(dir, {"voronoi", points, "-o", full}).code, 0);
    const std::string ids = "0,40,7,24,31," + std::to_string(std::stoi(count) - 1);
    const CliRun run = run_cli(dir, {"voronoi", points, "--only", ids, "-o", part});
    ASSERT_EQ(run.code, 0) << run.err;
    args.insert(args.end(), {full, part, ids});
    ++i;
  }
  const std::string script = R"(
import json, math, sys
def close(a, b):
    return len(a) == len(b) and all(abs(x - y) <= 1e-9 * (1 + abs(x)) for u, w in zip(a, b) for x, y in zip(u, w))
def cell(v, p):
    r = v['point_region'][p]
    ids = v['regions'][r]
    ridges = {}
    for (a, b), rv in zip(v['ridge_points'], v['ridge_vertices']):
        if p in (a, b):
            ridges[b if a == p else a] = (-1 in rv, sorted(v['vertices'][x] for x in rv if x >= 0))
    return (-1 in ids, sorted(v['vertices'][x] for x in ids if x >= 0), v['volumes'][r], ridges)
for full, part, ids in zip(sys.argv[1::3], sys.argv[2::3], sys.argv[3::3]):
    f, g = json.load(open(full)), json.load(open(part))
    asked = [int(x) for x in ids.split(',')]
    assert len(g['regions']) == len(asked), (part, len(g['regions']))
    for p in range(f['npoints']):
        if p not in asked:
            assert g['point_region'][p] == -1, (part, p)
            continue
        fo, fv, fvol, fr = cell(f, p)
        go, gv, gvol, gr = cell(g, p)
        assert fo == go and close(fv, gv), (part, p, fv, gv)
        assert (fvol is None and gvol is None) or abs(fvol - gvol) <= 1e-9 * fvol, (part, p, fvol, gvol)
        assert fr.keys() == gr.keys(), (part, p, sorted(fr), sorted(gr))
        for q in fr:
            assert fr[q][0] == gr[q][0] and close(fr[q][1], gr[q][1]), (part, p, q)
print('ok')
)";
  EXPECT_EQ(testing::run_python(dir, script, args), "ok\n");
}

TEST(CliVoronoiOnly, RefusalsAreNamedAndWriteNothing) {
  TempDir dir;
  write_text(dir.file("p.txt"), testing::kSquareWithCentre);
  write_text(dir.file("out.json"), "untouched");
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--only", "1,5", "-o", dir.file("out.json")}, "point id 5 is out of range"},
      {{"--only", "2,3,2", "-o", dir.file("out.json")}, "point id 2 is given twice"},
      {{"--only", "1,x", "-o", dir.file("out.json")}, "'x' in '1,x' is not a point id"},
      {{"--only", "1", "-o", dir.file("out.json"), "--format", "qhull"}, "--only writes json or npz"},
      {{"--only", "1", "-o", dir.file("out.json"), "--cells", dir.file("c.vtu")}, "--cells cannot be used with --only"},
  };
  for (const auto& [options, message] : cases) {
    std::vector<std::string> args{"voronoi", dir.file("p.txt")};
    args.insert(args.end(), options.begin(), options.end());
    const CliRun run = run_cli(dir, args);
    EXPECT_EQ(run.code, 2) << message;
    EXPECT_TRUE(contains(run.err, message)) << message << ": " << run.err;
    EXPECT_EQ(read_text(dir.file("out.json")), "untouched") << message;
  }
}

// The centre of the unit square with its corners: its cell is the diamond through the edges'
// midpoints, counter-clockwise, the only region written.
TEST(CliVoronoiOnly, TheCentreOfASquare) {
  TempDir dir;
  write_text(dir.file("p.txt"), testing::kSquareWithCentre);
  const CliRun run = run_cli(dir, {"voronoi", dir.file("p.txt"), "--only", "4", "--format", "json"});
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_TRUE(contains(run.out, "\"point_region\": [-1, -1, -1, -1, 0]")) << run.out;
  EXPECT_TRUE(contains(run.out, "\"vertices\": [\n  [0, 0.5],\n  [0.5, 0],\n  [0.5, 1],\n  [1, 0.5]],")) << run.out;
  EXPECT_TRUE(contains(run.out, "\"regions\": [\n  [1, 3, 2, 0]],")) << run.out;
  EXPECT_TRUE(contains(run.out, "\"ridge_points\": [\n  [3, 4],\n  [0, 4],\n  [1, 4],\n  [2, 4]],")) << run.out;
}

}  // namespace
}  // namespace drange
