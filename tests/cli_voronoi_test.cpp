// tests/cli_voronoi_test.cpp: `drange voronoi`, and the output formats and pictures that
// `drange delaunay` shares with it, run end to end through the built executable: the Qhull
// layouts (compared with qvoronoi itself when it is installed), the formats by extension and
// by name (read back by Python), the clipped cells, .npy and standard input, the SVG
// pictures, and every usage error with its exact message and exit code.
#include <sys/wait.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <map>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "cli_runner.hpp"
#include "drange/formats.hpp"
#include "drange/generate.hpp"
#include "drange/io.hpp"
#include "python_check.hpp"
#include "temp_dir.hpp"

namespace drange {
namespace {

using testing::CliRun;
using testing::contains;
using testing::count_entries;
using testing::kSquareWithCentre;
using testing::read_text;
using testing::run_cli;
using testing::run_python;
using testing::shell_word;
using testing::TempDir;
using testing::write_text;

// What main.cpp prints for a usage error of `command`.
std::string usage_error(const std::string& command, const std::string& message) {
  return "drange: " + message + "\nTry 'drange " + command + " --help'.\n";
}

void write_cloud(const std::string& path, const PointCloud& points) {
  write_file_atomically(path, [&](std::ostream& out) { write_points(out, points); });
}

bool have_qvoronoi() { return std::system("command -v qvoronoi > /dev/null 2>&1") == 0; }

bool starts_with(const std::string& text, const std::string& prefix) { return text.compare(0, prefix.size(), prefix) == 0; }

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<std::string> tokens_of(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> tokens;
  for (std::string token; in >> token;) tokens.push_back(token);
  return tokens;
}

// ---------------------------------------------------------------- the Qhull layouts, read back

// `qvoronoi o`: the dimension; "nv+1 n 1"; the point at infinity; nv vertices; n regions,
// each "k v1 ... vk" with 0 standing for infinity (Qhull's numbering is kept).
struct QvoronoiO {
  std::vector<std::vector<std::string>> header;  // the first three lines, as tokens
  std::vector<std::vector<double>> vertices;     // without the point at infinity
  std::vector<std::vector<int>> regions;
};

QvoronoiO parse_qvoronoi_o(const std::string& text) {
  const std::vector<std::string> lines = lines_of(text);
  if (lines.size() < 3) throw std::runtime_error("qvoronoi o: fewer than 3 lines:\n" + text);
  QvoronoiO o;
  for (std::size_t i = 0; i < 3; ++i) o.header.push_back(tokens_of(lines[i]));
  const int dim = std::stoi(lines[0]);
  const std::vector<std::string>& counts = o.header[1];
  if (counts.size() != 3) throw std::runtime_error("qvoronoi o: line 2 is not 'nv+1 n 1': " + lines[1]);
  const std::size_t nv = std::stoul(counts[0]) - 1, n = std::stoul(counts[1]);
  if (lines.size() != 3 + nv + n) throw std::runtime_error("qvoronoi o: wrong number of lines:\n" + text);
  for (std::size_t v = 0; v < nv; ++v) {
    std::istringstream in(lines[3 + v]);
    std::vector<double> vertex(static_cast<std::size_t>(dim));
    for (double& x : vertex) in >> x;
    if (!in) throw std::runtime_error("qvoronoi o: bad vertex line " + lines[3 + v]);
    o.vertices.push_back(vertex);
  }
  for (std::size_t i = 0; i < n; ++i) {
    std::istringstream in(lines[3 + nv + i]);
    std::size_t k = 0;
    in >> k;
    std::vector<int> region(k);
    for (int& v : region) in >> v;
    if (!in) throw std::runtime_error("qvoronoi o: bad region line " + lines[3 + nv + i]);
    o.regions.push_back(region);
  }
  return o;
}

// `qvoronoi Fv`: the ridge count, then "k p q v1 ... v(k-2)" per ridge (0 is infinity).
struct FvRidge {
  int p, q;
  std::vector<int> vertices;
};

std::vector<FvRidge> parse_qvoronoi_fv(const std::string& text) {
  const std::vector<std::string> lines = lines_of(text);
  if (lines.empty() || std::stoul(lines[0]) + 1 != lines.size())
    throw std::runtime_error("qvoronoi Fv: the count does not match the lines:\n" + text);
  std::vector<FvRidge> ridges;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    std::istringstream in(lines[i]);
    std::size_t k = 0;
    FvRidge ridge{};
    in >> k >> ridge.p >> ridge.q;
    ridge.vertices.resize(k - 2);
    for (int& v : ridge.vertices) in >> v;
    if (!in || k < 2) throw std::runtime_error("qvoronoi Fv: bad line " + lines[i]);
    ridges.push_back(ridge);
  }
  return ridges;
}

// A region or ridge compared between programs that number their vertices differently: whether
// it is unbounded, and its finite vertices' coordinates rounded to 1e-6, sorted.
using Shape = std::pair<bool, std::vector<std::vector<double>>>;

Shape shape_of(const std::vector<int>& qhull_ids, const std::vector<std::vector<double>>& vertices) {
  Shape shape{false, {}};
  for (const int id : qhull_ids) {
    if (id == 0) {
      shape.first = true;
      continue;
    }
    std::vector<double> corner = vertices.at(static_cast<std::size_t>(id - 1));
    for (double& x : corner) x = std::round(x * 1e6) / 1e6;
    shape.second.push_back(corner);
  }
  std::sort(shape.second.begin(), shape.second.end());
  return shape;
}

std::vector<Shape> region_shapes(const QvoronoiO& o) {
  std::vector<Shape> shapes;
  for (const std::vector<int>& region : o.regions) shapes.push_back(shape_of(region, o.vertices));
  return shapes;
}

std::map<std::pair<int, int>, Shape> ridge_shapes(const std::vector<FvRidge>& ridges,
                                                  const std::vector<std::vector<double>>& vertices) {
  std::map<std::pair<int, int>, Shape> shapes;
  for (const FvRidge& r : ridges) shapes[{std::min(r.p, r.q), std::max(r.p, r.q)}] = shape_of(r.vertices, vertices);
  return shapes;
}

// ---------------------------------------------------------------- help

TEST(CliVoronoi, GeneralHelpListsVoronoi) {
  TempDir dir;
  const CliRun run = run_cli(dir, {"help"});
  EXPECT_EQ(run.code, 0);
  EXPECT_TRUE(contains(run.out, "\n  voronoi [INPUT] [-o OUTPUT] ")) << run.out;
  const CliRun command_help = run_cli(dir, {"help", "voronoi"});
  EXPECT_EQ(command_help.code, 0);
  EXPECT_TRUE(starts_with(command_help.out, "Usage: drange voronoi [INPUT] [OPTIONS]\n")) << command_help.out;
  EXPECT_EQ(run_cli(dir, {"voronoi", "--help"}).out, command_help.out);
  EXPECT_EQ(run_cli(dir, {"voronoi", "-h"}).out, command_help.out);
}

// An option as a help text or a command's kOptions table declares it.
struct OptionDecl {
  char short_name;
  bool takes_value;
};

// The "Options:" section of a help text: "  -o, --output FILE  ..." or "      --stats  ...".
std::map<std::string, OptionDecl> options_in_help(const std::string& help) {
  const std::size_t start = help.find("\nOptions:\n");
  if (start == std::string::npos) throw std::runtime_error("no Options: section in\n" + help);
  const std::size_t end = help.find("\n\n", start + 1);
  const std::regex option_line("^  (?:-([a-z]), |    )--([a-z-]+)( [A-Z]+)?(?:  |$)");
  std::map<std::string, OptionDecl> options;
  for (const std::string& line : lines_of(help.substr(start + 10, end - start - 10))) {
    std::smatch m;
    if (std::regex_search(line, m, option_line))
      options[m[2]] = {m[1].matched ? m[1].str()[0] : '\0', m[3].matched};
  }
  return options;
}

// The kOptions table of cli/command_<name>.cpp, found next to this file in the source tree
// (empty when the source tree is not there).
std::map<std::string, OptionDecl> options_in_source(const std::string& command) {
  const std::string here = __FILE__;
  const std::string path = here.substr(0, here.rfind("/tests/")) + "/cli/command_" + command + ".cpp";
  std::ifstream in(path);
  if (!in) return {};
  const std::string source((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t start = source.find("kOptions = {");
  if (start == std::string::npos) throw std::runtime_error("no kOptions table in " + path);
  const std::string table = source.substr(start, source.find("};", start) - start);
  const std::regex entry(R"re(\{"([a-z-]+)", (?:'(.)'|0), (true|false)\})re");
  std::map<std::string, OptionDecl> options;
  for (std::sregex_iterator it(table.begin(), table.end(), entry), end; it != end; ++it)
    options[(*it)[1]] = {(*it)[2].matched ? (*it)[2].str()[0] : '\0', (*it)[3] == "true"};
  return options;
}

// Each command's help lists exactly the options its parser accepts (plus --help), with the
// same short forms and, for options with a value, a placeholder.
TEST(CliVoronoi, HelpListsEveryOptionOfTheParser) {
  TempDir dir;
  for (const std::string command : {"voronoi", "delaunay"}) {
    std::map<std::string, OptionDecl> declared = options_in_source(command);
    if (declared.empty()) GTEST_SKIP() << "SKIPPED: cli/command_" << command << ".cpp not found next to " << __FILE__;
    declared["help"] = {'h', false};
    const CliRun run = run_cli(dir, {command, "--help"});
    ASSERT_EQ(run.code, 0) << command;
    const std::map<std::string, OptionDecl> listed = options_in_help(run.out);
    for (const auto& [name, decl] : declared) {
      const auto found = listed.find(name);
      ASSERT_NE(found, listed.end()) << command << " --help does not list --" << name;
      EXPECT_EQ(found->second.short_name, decl.short_name) << command << " --" << name;
      EXPECT_EQ(found->second.takes_value, decl.takes_value) << command << " --" << name;
    }
    for (const auto& entry : listed) EXPECT_EQ(declared.count(entry.first), 1u) << command << ": --" << entry.first;
  }
}

// ---------------------------------------------------------------- the Qhull layouts

// The square's corners and centre: the four Voronoi vertices are the midpoints of the sides,
// the centre's region is the diamond through them, and each corner's region is unbounded
// between the midpoints of its two sides.
TEST(CliVoronoi, SquareWithCentreInTheQvoronoiLayouts) {
  TempDir dir;
  write_text(dir.file("p.txt"), kSquareWithCentre);
  const CliRun run = run_cli(dir, {"voronoi", dir.file("p.txt"), "--ridges", dir.file("fv.txt")});
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_EQ(run.err, "");
  const QvoronoiO o = parse_qvoronoi_o(run.out);
  EXPECT_EQ(o.header, (std::vector<std::vector<std::string>>{{"2"}, {"5", "5", "1"}, {"-10.101", "-10.101"}}));
  const std::vector<std::vector<double>> corners = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  std::vector<std::vector<double>> midpoints;  // midpoints[i]: of the side from corner i to i+1
  for (std::size_t i = 0; i < 4; ++i)
    midpoints.push_back({(corners[i][0] + corners[(i + 1) % 4][0]) / 2, (corners[i][1] + corners[(i + 1) % 4][1]) / 2});
  std::vector<std::vector<double>> sorted_midpoints = midpoints;
  std::sort(sorted_midpoints.begin(), sorted_midpoints.end());
  std::vector<std::vector<double>> vertices = o.vertices;
  std::sort(vertices.begin(), vertices.end());
  EXPECT_EQ(vertices, sorted_midpoints);

  const std::vector<Shape> regions = region_shapes(o);
  ASSERT_EQ(regions.size(), 5u);
  EXPECT_EQ(regions[4], Shape(false, sorted_midpoints));
  ASSERT_EQ(o.regions[4].size(), 4u);
  double twice_area = 0;  // the centre's region is listed counter-clockwise
  for (std::size_t k = 0; k < 4; ++k) {
    const std::vector<double>& a = o.vertices[o.regions[4][k] - 1];
    const std::vector<double>& b = o.vertices[o.regions[4][(k + 1) % 4] - 1];
    twice_area += a[0] * b[1] - a[1] * b[0];
  }
  EXPECT_EQ(twice_area, 1.0);
  for (std::size_t i = 0; i < 4; ++i) {
    std::vector<std::vector<double>> sides = {midpoints[i], midpoints[(i + 3) % 4]};
    std::sort(sides.begin(), sides.end());
    EXPECT_EQ(o.regions[i].size(), 3u) << "corner " << i;
    EXPECT_EQ(regions[i], Shape(true, sides)) << "corner " << i;
  }

  // Fv: the four sides (a ray from the side's midpoint) and the four spokes to the centre
  // (the segment between the midpoints of the corner's two sides).
  const std::string fv = read_text(dir.file("fv.txt"));
  const std::map<std::pair<int, int>, Shape> ridges = ridge_shapes(parse_qvoronoi_fv(fv), o.vertices);
  std::map<std::pair<int, int>, Shape> expected;
  for (int i = 0; i < 4; ++i) {
    const int next = (i + 1) % 4;
    expected[{std::min(i, next), std::max(i, next)}] = Shape(true, {midpoints[i]});
    std::vector<std::vector<double>> spoke = {midpoints[i], midpoints[(i + 3) % 4]};
    std::sort(spoke.begin(), spoke.end());
    expected[{i, 4}] = Shape(false, spoke);
  }
  EXPECT_EQ(ridges, expected);
  EXPECT_EQ(lines_of(fv)[0], "8");
}

// With a file for -o, nothing goes to standard output; --stats adds the diagram's counts; an
// exact duplicate is reported and repeats the region of the point it copies.
TEST(CliVoronoi, OutputFileStatsAndDuplicates) {
  TempDir dir;
  write_text(dir.file("p.txt"), std::string(kSquareWithCentre).replace(2, 1, "6") + "0 0\n");
  CliRun run = run_cli(dir, {"voronoi", dir.file("p.txt"), "-o", dir.file("o.txt"), "--stats"});
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_EQ(run.out, "");
  EXPECT_TRUE(starts_with(run.err, "drange: 1 duplicate point left out (point 5 = point 0)\n")) << run.err;
  EXPECT_TRUE(contains(run.err, " voronoi_vertices=4 ridges=8\n")) << run.err;
  const QvoronoiO o = parse_qvoronoi_o(read_text(dir.file("o.txt")));
  EXPECT_EQ(o.header[1], (std::vector<std::string>{"5", "6", "1"}));
  ASSERT_EQ(o.regions.size(), 6u);
  EXPECT_EQ(o.regions[5], o.regions[0]);
  run = run_cli(dir, {"voronoi", dir.file("p.txt"), "-o", dir.file("o.txt"), "-q"});
  EXPECT_EQ(run.code, 0);
  EXPECT_EQ(run.err, "");
}

// --no-volumes leaves the volumes out (not the clipped cells' areas); --variant changes how
// the triangulation is searched, not the result.
TEST(CliVoronoi, NoVolumesAndVariant) {
  TempDir dir;
  write_text(dir.file("p.txt"), kSquareWithCentre);
  const CliRun full = run_cli(dir, {"voronoi", dir.file("p.txt"), "--format", "json", "--box", "0,0,1,1"});
  ASSERT_EQ(full.code, 0) << full.err;
  EXPECT_TRUE(contains(full.out, "\n\"volumes\": [")) << full.out;
  const CliRun bare = run_cli(dir, {"voronoi", dir.file("p.txt"), "--format", "json", "--box", "0,0,1,1", "--no-volumes"});
  ASSERT_EQ(bare.code, 0) << bare.err;
  EXPECT_FALSE(contains(bare.out, "\n\"volumes\": [")) << bare.out;
  EXPECT_TRUE(contains(bare.out, "\"clipped_cells\": {")) << bare.out;
  EXPECT_EQ(run_cli(dir, {"voronoi", dir.file("p.txt"), "--format", "json", "--box", "0,0,1,1", "--variant", "scan"}).out,
            full.out);
  const CliRun bad = run_cli(dir, {"voronoi", dir.file("p.txt"), "--variant", "fastest"});
  EXPECT_EQ(bad.code, 2);
  EXPECT_TRUE(starts_with(bad.err, "drange: ") && contains(bad.err, "fastest")) << bad.err;
}

// On random points in general position (a unique diagram), the same regions and ridges as
// qvoronoi's own `o` and `Fv`, up to the numbering of the vertices.
TEST(CliVoronoi, AgreesWithQvoronoi) {
  if (!have_qvoronoi())
    GTEST_SKIP() << "SKIPPED: qvoronoi (Debian qhull-bin) is not installed: agreement with Qhull NOT tested";
  TempDir dir;
  write_cloud(dir.file("p.txt"), generate_points(Distribution::Uniform, 500, 2, 42));
  const CliRun ours = run_cli(dir, {"voronoi", dir.file("p.txt"), "--ridges", dir.file("fv.txt")});
  ASSERT_EQ(ours.code, 0) << ours.err;
  const std::string input = shell_word(dir.file("p.txt"));
  ASSERT_EQ(std::system(("qvoronoi o < " + input + " > " + shell_word(dir.file("qo.txt"))).c_str()), 0);
  ASSERT_EQ(std::system(("qvoronoi Fv < " + input + " > " + shell_word(dir.file("qfv.txt"))).c_str()), 0);

  const QvoronoiO o_ours = parse_qvoronoi_o(ours.out);
  const QvoronoiO o_theirs = parse_qvoronoi_o(read_text(dir.file("qo.txt")));
  EXPECT_EQ(o_ours.header, o_theirs.header);
  const std::vector<Shape> regions_ours = region_shapes(o_ours), regions_theirs = region_shapes(o_theirs);
  ASSERT_EQ(regions_ours.size(), 500u);
  ASSERT_EQ(regions_theirs.size(), 500u);
  std::size_t bounded = 0;
  for (std::size_t i = 0; i < 500; ++i) {
    EXPECT_EQ(regions_ours[i], regions_theirs[i]) << "point " << i;
    bounded += regions_ours[i].first ? 0 : 1;
  }
  EXPECT_GT(bounded, 400u);  // the comparison is not vacuous

  const auto ridges_ours = ridge_shapes(parse_qvoronoi_fv(read_text(dir.file("fv.txt"))), o_ours.vertices);
  const auto ridges_theirs = ridge_shapes(parse_qvoronoi_fv(read_text(dir.file("qfv.txt"))), o_theirs.vertices);
  EXPECT_EQ(ridges_ours.size(), ridges_theirs.size());
  EXPECT_TRUE(ridges_ours == ridges_theirs);
}

// ---------------------------------------------------------------- formats

struct FormatCase {
  const char* name;
  const char* extension;
  std::string signature;  // how the file starts
};

const std::vector<FormatCase> kFormats = {
    {"json", ".json", "{\"ndim\": 2,\n"},
    {"npz", ".npz", std::string("PK\x03\x04", 4)},
    {"vtu", ".vtu", "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\""},
    {"off", ".off", "OFF\n"},
};

// Each format, chosen by the output's extension (in any letter case), by --format with
// another file name, and by --format on standard output, gives the same bytes; --format
// wins over the extension.
TEST(CliVoronoiFormats, ByExtensionAndByName) {
  TempDir dir;
  write_text(dir.file("p.txt"), kSquareWithCentre);
  for (const std::string command : {"delaunay", "voronoi"}) {
    for (const FormatCase& format : kFormats) {
      const std::string what = command + " " + format.name;
      const std::string by_extension = dir.file(std::string("out") + format.extension);
      CliRun run = run_cli(dir, {command, dir.file("p.txt"), "-o", by_extension});
      ASSERT_EQ(run.code, 0) << what << ": " << run.err;
      EXPECT_EQ(run.out, "") << what;
      const std::string written = read_text(by_extension);
      EXPECT_TRUE(starts_with(written, format.signature)) << what << ":\n" << written.substr(0, 80);
      run = run_cli(dir, {command, dir.file("p.txt"), "--format", format.name, "-o", dir.file("out.dat")});
      ASSERT_EQ(run.code, 0) << what << ": " << run.err;
      EXPECT_EQ(read_text(dir.file("out.dat")), written) << what;
      run = run_cli(dir, {command, dir.file("p.txt"), "--format=" + std::string(format.name)});
      ASSERT_EQ(run.code, 0) << what << ": " << run.err;
      EXPECT_EQ(run.out, written) << what;
      std::string upper = std::string("OUT") + format.extension;
      std::transform(upper.begin(), upper.end(), upper.begin(), [](unsigned char c) { return std::toupper(c); });
      ASSERT_EQ(run_cli(dir, {command, dir.file("p.txt"), "-o", dir.file(upper)}).code, 0) << what;
      EXPECT_EQ(read_text(dir.file(upper)), written) << what;
    }
    const CliRun plain = run_cli(dir, {command, dir.file("p.txt")});
    ASSERT_EQ(plain.code, 0) << plain.err;
    ASSERT_EQ(run_cli(dir, {command, dir.file("p.txt"), "-o", dir.file("q.json"), "--format", "qhull"}).code, 0);
    EXPECT_EQ(read_text(dir.file("q.json")), plain.out) << command;
  }
}

TEST(CliVoronoiFormats, JsonHasScipysNames) {
  DRANGE_REQUIRE_PYTHON("json");
  TempDir dir;
  write_text(dir.file("p.txt"), kSquareWithCentre);
  ASSERT_EQ(run_cli(dir, {"delaunay", dir.file("p.txt"), "-o", dir.file("d.json")}).code, 0);
  ASSERT_EQ(run_cli(dir, {"voronoi", dir.file("p.txt"), "-o", dir.file("v.json")}).code, 0);
  const std::string script = R"(
import json, sys
d = json.load(open(sys.argv[1]))
assert sorted(d) == ['coplanar', 'ndim', 'neighbors', 'npoints', 'simplices'], sorted(d)
assert d['ndim'] == 2 and d['npoints'] == 5 and d['coplanar'] == [], d
assert len(d['simplices']) == 4 and all(4 in s for s in d['simplices']), d['simplices']
assert sorted(n.count(-1) for n in d['neighbors']) == [1, 1, 1, 1], d['neighbors']
v = json.load(open(sys.argv[2]))
assert sorted(v) == ['ndim', 'npoints', 'point_region', 'regions', 'ridge_points', 'ridge_vertices',
                     'vertices', 'volumes'], sorted(v)
assert v['ndim'] == 2 and v['npoints'] == 5
assert sorted(v['vertices']) == [[0, 0.5], [0.5, 0], [0.5, 1], [1, 0.5]], v['vertices']
assert sorted(map(sorted, v['ridge_points'])) == [[0, 1], [0, 3], [0, 4], [1, 2], [1, 4], [2, 3], [2, 4], [3, 4]]
assert len(v['ridge_vertices']) == 8
centre = v['point_region'][4]
assert sorted(v['regions'][centre]) == [0, 1, 2, 3] and abs(v['volumes'][centre] - 0.5) < 1e-12, v['volumes']
for corner in range(4):
    region = v['point_region'][corner]
    assert -1 in v['regions'][region] and v['volumes'][region] is None
print('ok')
)";
  EXPECT_EQ(run_python(dir, script, {dir.file("d.json"), dir.file("v.json")}), "ok\n");
}

TEST(CliVoronoiFormats, NpzReadByNumpy) {
  DRANGE_REQUIRE_PYTHON("numpy");
  TempDir dir;
  write_text(dir.file("p.txt"), kSquareWithCentre);
  ASSERT_EQ(run_cli(dir, {"delaunay", dir.file("p.txt"), "-o", dir.file("d.npz")}).code, 0);
  ASSERT_EQ(run_cli(dir, {"voronoi", dir.file("p.txt"), "-o", dir.file("v.npz"), "--box", "0,0,1,1"}).code, 0);
  const std::string script = R"(
import sys
import numpy as np
d = np.load(sys.argv[1])
assert sorted(d.files) == ['coplanar', 'ndim', 'neighbors', 'npoints', 'simplices'], d.files
assert d['simplices'].shape == (4, 3) and d['simplices'].dtype == np.int32 and int(d['ndim']) == 2
v = np.load(sys.argv[2])
assert sorted(v.files) == sorted(['ndim', 'npoints', 'vertices', 'ridge_points', 'ridge_vertices',
    'ridge_vertices_offsets', 'regions', 'regions_offsets', 'point_region', 'volumes', 'clipped_box_lower',
    'clipped_box_upper', 'clipped_points', 'clipped_faces', 'clipped_faces_offsets', 'clipped_cell_faces',
    'clipped_volumes']), v.files
assert v['vertices'].shape == (4, 2) and v['ridge_points'].shape == (8, 2)
assert sorted(v['point_region'].tolist()) == [0, 1, 2, 3, 4], v['point_region']
assert v['clipped_volumes'].shape == (5,) and abs(v['clipped_volumes'].sum() - 1) < 1e-12
assert list(v['clipped_box_lower']) == [0, 0] and list(v['clipped_box_upper']) == [1, 1]
print('ok')
)";
  EXPECT_EQ(run_python(dir, script, {dir.file("d.npz"), dir.file("v.npz")}), "ok\n");
}

// ---------------------------------------------------------------- clipped cells

// The clipped cells tile the box: their volumes in the JSON add up to the box's, for a box
// around the points and one inside them, in 2D and 3D.
TEST(CliVoronoiCells, BoxVolumesAddUpToTheBox) {
  DRANGE_REQUIRE_PYTHON("json");
  TempDir dir;
  write_cloud(dir.file("p2.txt"), generate_points(Distribution::Uniform, 300, 2, 5));
  write_cloud(dir.file("p3.txt"), generate_points(Distribution::Uniform, 200, 3, 6));
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"p2.txt", "-0.2,-0.1,1.3,1.2"}, {"p2.txt", "0.25,0.25,0.75,0.75"}, {"p3.txt", "-0.5,-0.5,-0.5,1.5,1.5,1.5"}};
  std::vector<std::string> args;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const std::string out = dir.file("v" + std::to_string(i) + ".json");
    const CliRun run = run_cli(dir, {"voronoi", dir.file(cases[i].first), "-o", out, "--box", cases[i].second});
    ASSERT_EQ(run.code, 0) << run.err;
    args.push_back(out);
    args.push_back(cases[i].second);
  }
  const std::string script = R"(
import json, math, sys
for path, box in zip(sys.argv[1::2], sys.argv[2::2]):
    numbers = [float(x) for x in box.split(',')]
    d = len(numbers) // 2
    lower, upper = numbers[:d], numbers[d:]
    v = json.load(open(path))
    c = v['clipped_cells']
    assert c['box'] == {'lower': lower, 'upper': upper}, (path, c['box'])
    assert len(c['cells']) == len(v['regions']), path
    total = sum(cell['volume'] for cell in c['cells'])
    want = math.prod(b - a for a, b in zip(lower, upper))
    assert abs(total - want) <= 1e-9 * want, (path, total, want)
    for region, cell in enumerate(c['cells']):
        assert v['point_region'][cell['point']] == region, (path, region, cell['point'])
print('ok')
)";
  EXPECT_EQ(run_python(dir, script, args), "ok\n");
}

// --cells writes the clipped cells besides the diagram (which is unchanged), in the format
// of the cells file's extension; "-" is VTU on standard output.
TEST(CliVoronoiCells, CellsFileBesideTheDiagram) {
  TempDir dir;
  write_text(dir.file("p.txt"), kSquareWithCentre);
  const CliRun plain = run_cli(dir, {"voronoi", dir.file("p.txt")});
  ASSERT_EQ(plain.code, 0) << plain.err;
  CliRun run = run_cli(dir, {"voronoi", dir.file("p.txt"), "--cells", dir.file("cells.vtu")});
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_EQ(run.out, plain.out);
  const std::string vtu = read_text(dir.file("cells.vtu"));
  EXPECT_TRUE(contains(vtu, "<Piece NumberOfPoints=\"24\" NumberOfCells=\"5\">")) << vtu.substr(0, 200);
  run = run_cli(dir, {"voronoi", dir.file("p.txt"), "-o", dir.file("o.txt"), "--cells", "-"});
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_EQ(run.out, vtu);
  EXPECT_EQ(read_text(dir.file("o.txt")), plain.out);
  ASSERT_EQ(run_cli(dir, {"voronoi", dir.file("p.txt"), "--cells", dir.file("cells.off")}).code, 0);
  EXPECT_TRUE(starts_with(read_text(dir.file("cells.off")), "OFF\n"));
  ASSERT_EQ(run_cli(dir, {"voronoi", dir.file("p.txt"), "--cells", dir.file("cells.json")}).code, 0);
  EXPECT_TRUE(contains(read_text(dir.file("cells.json")), "\"clipped_cells\": {")) << read_text(dir.file("cells.json"));

  if (!testing::python_has("xml.etree.ElementTree")) {
    GTEST_SKIP() << "SKIPPED: " << testing::kPython << " with xml.etree is not available: the VTU file was NOT parsed";
  }
  // The default box is the points' bounding box enlarged by 10% on every side: 1.2 x 1.2.
  const std::string script = R"(
import sys
import xml.etree.ElementTree as ET
root = ET.parse(sys.argv[1]).getroot()
assert root.tag == 'VTKFile' and root.get('type') == 'UnstructuredGrid', root.attrib
piece = root.find('UnstructuredGrid/Piece')
assert piece.get('NumberOfCells') == '5'
volume = [a for a in piece.iter('DataArray') if a.get('Name') == 'volume'][0]
values = [float(x) for x in volume.text.split()]
assert len(values) == 5 and abs(sum(values) - 1.44) < 1e-12 and abs(max(values) - 0.5) < 1e-12, values
point = [a for a in piece.iter('DataArray') if a.get('Name') == 'point'][0]
assert sorted(int(x) for x in point.text.split()) == [0, 1, 2, 3, 4]
print('ok')
)";
  EXPECT_EQ(run_python(dir, script, {dir.file("cells.vtu")}), "ok\n");
}

// ---------------------------------------------------------------- inputs

// The same points as text, as .npy, and on standard input give the same outputs.
TEST(CliVoronoiInput, NpyAndStandardInputGiveTheSameResult) {
  TempDir dir;
  const PointCloud points = generate_points(Distribution::Uniform, 200, 3, 11);
  write_cloud(dir.file("p.txt"), points);
  write_file_atomically(dir.file("p.npy"), [&](std::ostream& out) {
    write_npy(out, NpyArray(points.coords.data(), {points.size(), static_cast<std::size_t>(points.dim)}));
  });
  for (const std::string command : {"voronoi", "delaunay"}) {
    const CliRun text = run_cli(dir, {command, dir.file("p.txt")});
    ASSERT_EQ(text.code, 0) << text.err;
    ASSERT_FALSE(text.out.empty());
    const CliRun npy = run_cli(dir, {command, dir.file("p.npy")});
    EXPECT_EQ(npy.code, 0) << npy.err;
    EXPECT_EQ(npy.out, text.out) << command;
    const CliRun redirected = run_cli(dir, {command}, dir.file("p.txt"));
    EXPECT_EQ(redirected.code, 0) << redirected.err;
    EXPECT_EQ(redirected.out, text.out) << command;
    const CliRun dash_npy = run_cli(dir, {command, "-"}, dir.file("p.npy"));
    EXPECT_EQ(dash_npy.code, 0) << dash_npy.err;
    EXPECT_EQ(dash_npy.out, text.out) << command;
  }
  // The ridges too.
  ASSERT_EQ(run_cli(dir, {"voronoi", dir.file("p.txt"), "-o", "/dev/null", "--ridges", dir.file("a.txt")}).code, 0);
  ASSERT_EQ(run_cli(dir, {"voronoi", "-o", "/dev/null", "--ridges", dir.file("b.txt")}, dir.file("p.npy")).code, 0);
  EXPECT_EQ(read_text(dir.file("a.txt")), read_text(dir.file("b.txt")));
}

// ---------------------------------------------------------------- SVG

TEST(CliVoronoiSvg, WellFormedPicturesIn2D) {
  TempDir dir;
  write_text(dir.file("p.txt"), kSquareWithCentre);
  for (const std::string command : {"voronoi", "delaunay"}) {
    const std::string svg_path = dir.file(command + ".svg");
    const CliRun run = run_cli(dir, {command, dir.file("p.txt"), "-o", dir.file("out.txt"), "--svg", svg_path, "--circles"});
    ASSERT_EQ(run.code, 0) << run.err;
    const std::string svg = read_text(svg_path);
    EXPECT_TRUE(starts_with(svg, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\""))
        << svg.substr(0, 200);
    EXPECT_TRUE(svg.size() > 7 && svg.compare(svg.size() - 7, 7, "</svg>\n") == 0);
    EXPECT_EQ(contains(svg, "<g id=\"voronoi\""), command == "voronoi") << command;
    EXPECT_TRUE(contains(svg, "<g id=\"circles\"")) << command;
  }
  DRANGE_REQUIRE_PYTHON("xml.etree.ElementTree");
  const std::string script = R"(
import sys
import xml.etree.ElementTree as ET
ns = '{http://www.w3.org/2000/svg}'
for path, layers in zip(sys.argv[1::2], sys.argv[2::2]):
    root = ET.parse(path).getroot()
    assert root.tag == ns + 'svg', root.tag
    ids = sorted(g.get('id') for g in root.iter(ns + 'g'))
    assert ids == sorted(layers.split(',')), (path, ids)
print('ok')
)";
  EXPECT_EQ(run_python(dir, script,
                       {dir.file("voronoi.svg"), "circles,delaunay,voronoi,hull,points,legend", dir.file("delaunay.svg"),
                        "circles,delaunay,hull,points,legend"}),
            "ok\n");
}

// SVG is 2D only: 3D points are a usage error found before any work, and nothing is written,
// neither the picture nor the main output (an existing one is kept).
TEST(CliVoronoiSvg, ThreeDimensionalPointsAreAUsageErrorAndWriteNothing) {
  TempDir dir;
  write_text(dir.file("p.txt"), "3\n5\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1\n");
  for (const std::string command : {"voronoi", "delaunay"}) {
    CliRun run = run_cli(dir, {command, dir.file("p.txt"), "-o", dir.file("out.json"), "--svg", dir.file("p.svg")});
    EXPECT_EQ(run.code, 2) << command;
    EXPECT_EQ(run.err, usage_error(command, "SVG pictures are 2D only, the points have dimension 3"));
    EXPECT_EQ(count_entries(dir.path()), 1u) << command;  // only p.txt
    write_text(dir.file("out.txt"), "previous\n");
    run = run_cli(dir, {command, dir.file("p.txt"), "-o", dir.file("out.txt"), "--svg", dir.file("p.svg")});
    EXPECT_EQ(run.code, 2) << command;
    EXPECT_EQ(read_text(dir.file("out.txt")), "previous\n") << command;
    EXPECT_EQ(count_entries(dir.path()), 2u) << command;
    std::remove(dir.file("out.txt").c_str());
  }
}

// ---------------------------------------------------------------- usage errors

// Runs `args` expecting a usage error of `command` with exactly `message`.
void expect_usage_error(const TempDir& dir, const std::vector<std::string>& args, const std::string& message,
                        const std::string& stdin_path = "/dev/null") {
  const CliRun run = run_cli(dir, args, stdin_path);
  EXPECT_EQ(run.code, 2) << args[0] << " " << (args.size() > 1 ? args.back() : "");
  EXPECT_EQ(run.err, usage_error(args[0], message));
  EXPECT_EQ(run.out, "");
}

TEST(CliVoronoiErrors, BadBox) {
  TempDir dir;
  write_text(dir.file("p.txt"), kSquareWithCentre);
  write_text(dir.file("out.txt"), "previous\n");
  const std::string p = dir.file("p.txt"), out = dir.file("out.txt");
  const std::string not_finite = " is not a finite number (in '";
  const std::string not_below = "--box: the lower corner must be below the upper one on every axis ";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"0,0,1", "--box needs 4 numbers for dimension 2 (lower corner, then upper corner), got 3"},
      {"0,0,1,1,2", "--box needs 4 numbers for dimension 2 (lower corner, then upper corner), got 5"},
      {"0,0,1,x", "--box: 'x'" + not_finite + "0,0,1,x')"},
      {"0,,1,1", "--box: ''" + not_finite + "0,,1,1')"},
      {"0,0,1e999,1", "--box: '1e999'" + not_finite + "0,0,1e999,1')"},
      {"0,0,nan,1", "--box: 'nan'" + not_finite + "0,0,nan,1')"},
      {"0,0.5,1,0.5", not_below + "(axis 1: 0.5 >= 0.5)"},
      {"2,0,1,1", not_below + "(axis 0: 2 >= 1)"},
  };
  for (const auto& [box, message] : cases)
    expect_usage_error(dir, {"voronoi", p, "-o", out, "--format", "json", "--box", box}, message);
  EXPECT_EQ(read_text(out), "previous\n");
  EXPECT_EQ(count_entries(dir.path()), 2u);
}

// The Qhull layout holds no cells: a box alone would be computed and thrown away.
TEST(CliVoronoiErrors, BoxNeedsSomewhereToPutTheCells) {
  TempDir dir;
  write_text(dir.file("p.txt"), kSquareWithCentre);
  expect_usage_error(dir, {"voronoi", dir.file("p.txt"), "--box", "0,0,1,1"},
                     "--box clips the cells, which Qhull's layout does not hold: add --cells FILE, or choose "
                     "--format json, npz, vtu or off");
}

TEST(CliVoronoiErrors, CellsNeedACellFormat) {
  TempDir dir;
  write_text(dir.file("p.txt"), kSquareWithCentre);
  for (const std::string name : {"x.dat", "cells"}) {
    expect_usage_error(dir, {"voronoi", dir.file("p.txt"), "--cells", dir.file(name)},
                       "--cells: Qhull's layouts hold no clipped cells; name a .vtu, .off, .json, .npz or .txt file");
  }
  EXPECT_EQ(count_entries(dir.path()), 1u);
}

TEST(CliVoronoiErrors, UnknownFormatListsTheNames) {
  TempDir dir;
  write_text(dir.file("p.txt"), kSquareWithCentre);
  for (const std::string command : {"voronoi", "delaunay"}) {
    expect_usage_error(dir, {command, dir.file("p.txt"), "--format", "bogus"},
                       "unknown output format 'bogus' (expected one of: qhull, json, npz, vtu, off)");
    expect_usage_error(dir, {command, dir.file("p.txt"), "--format", "JSON"},
                       "unknown output format 'JSON' (expected one of: qhull, json, npz, vtu, off)");
  }
}

TEST(CliVoronoiErrors, TwoOutputsToOneFile) {
  TempDir dir;
  write_text(dir.file("p.txt"), kSquareWithCentre);
  const std::string p = dir.file("p.txt"), a = dir.file("a");
  expect_usage_error(dir, {"voronoi", p, "-o", a, "--ridges", a}, "--output and --ridges name the same file '" + a + "'");
  expect_usage_error(dir, {"voronoi", p, "--ridges", "-"}, "--output and --ridges cannot both go to standard output");
  expect_usage_error(dir, {"voronoi", p, "--cells", a + ".vtu", "--svg", a + ".vtu"},
                     "--cells and --svg name the same file '" + a + ".vtu'");
  expect_usage_error(dir, {"delaunay", p, "-o", a, "--svg", a}, "--output and --svg name the same file '" + a + "'");
  EXPECT_EQ(count_entries(dir.path()), 1u);
}

TEST(CliVoronoiErrors, MissingInput) {
  TempDir dir;
  write_text(dir.file("empty.txt"), "");
  const std::string message = "missing argument INPUT (a point file, or points on standard input)";
  expect_usage_error(dir, {"voronoi"}, message);
  expect_usage_error(dir, {"voronoi", "-o", dir.file("out.txt")}, message, dir.file("empty.txt"));
  EXPECT_EQ(count_entries(dir.path()), 1u);
}

// Standard input that is a terminal is not read: util-linux `script` gives the command a
// pseudo-terminal (and `timeout` ends a run that waits for typed points).
TEST(CliVoronoiErrors, MissingInputOnATerminal) {
  if (std::system("command -v script > /dev/null 2>&1 && command -v timeout > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "SKIPPED: util-linux script or timeout is not installed: a terminal stdin was NOT tested";
  TempDir dir;
  const std::string inner = shell_word(DRANGE_CLI_PATH) + " voronoi";
  const std::string command = "timeout 10 script -qec " + shell_word(inner) + " /dev/null < /dev/null > " +
                              shell_word(dir.file("tty.txt")) + " 2>&1";
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  EXPECT_TRUE(contains(read_text(dir.file("tty.txt")),
                       "drange: missing argument INPUT (a point file, or points on standard input)\r\n"))
      << read_text(dir.file("tty.txt"));
}

// VTK and OFF hold 2D and 3D: for 4D points, a usage error and no file.
TEST(CliVoronoiErrors, VtuAndOffBeyond3D) {
  TempDir dir;
  write_text(dir.file("p.txt"), "4\n6\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n1 1 1 1\n");
  const std::string p = dir.file("p.txt");
  const std::string cells_message = "clipped cells are computed in 2D and 3D; the points have dimension 4";
  expect_usage_error(dir, {"voronoi", p, "-o", dir.file("v.vtu")}, cells_message);
  expect_usage_error(dir, {"voronoi", p, "-o", dir.file("v.off")}, cells_message);
  expect_usage_error(dir, {"voronoi", p, "--format", "vtu"}, cells_message);
  expect_usage_error(dir, {"voronoi", p, "-o", dir.file("v.json"), "--cells", dir.file("c.vtu")}, cells_message);
  expect_usage_error(dir, {"voronoi", p, "-o", dir.file("v.json"), "--box", "0,0,0,0,1,1,1,1"}, cells_message);
  expect_usage_error(dir, {"delaunay", p, "-o", dir.file("d.vtu")}, "VTK holds 2D and 3D only; the points have dimension 4");
  expect_usage_error(dir, {"delaunay", p, "--format", "off"}, "OFF holds 2D and 3D only; the points have dimension 4");
  EXPECT_EQ(count_entries(dir.path()), 1u);
  // JSON, npz and the Qhull layouts hold any dimension.
  EXPECT_EQ(run_cli(dir, {"voronoi", p, "-o", dir.file("v.json")}).code, 0);
  EXPECT_EQ(run_cli(dir, {"delaunay", p, "-o", dir.file("d.npz")}).code, 0);
}

// A run that fails on its input replaces none of its outputs, and leaves no temporary file.
TEST(CliVoronoiErrors, FailedRunKeepsEveryExistingOutput) {
  TempDir dir;
  write_text(dir.file("p.txt"), "0 0\n1 0\n1 x\n");
  const std::vector<std::string> outputs = {"o.txt", "fv.txt", "c.vtu", "p.svg"};
  for (const std::string& name : outputs) write_text(dir.file(name), "previous " + name + "\n");
  const CliRun run = run_cli(dir, {"voronoi", dir.file("p.txt"), "-o", dir.file("o.txt"), "--ridges", dir.file("fv.txt"),
                                   "--cells", dir.file("c.vtu"), "--svg", dir.file("p.svg")});
  EXPECT_EQ(run.code, 3);
  EXPECT_EQ(run.err, "drange: " + dir.file("p.txt") + ":3: not a number: \"x\"\n");
  for (const std::string& name : outputs) EXPECT_EQ(read_text(dir.file(name)), "previous " + name + "\n");
  EXPECT_EQ(count_entries(dir.path()), 5u);
}

// ---------------------------------------------------------------- standard error

// With standard error not a terminal there is no progress line, and --quiet also silences the
// report of duplicates: stderr stays empty, on a run of 70 000 points.
TEST(CliVoronoiQuiet, NothingOnStandardError) {
  TempDir dir;
  PointCloud points = generate_points(Distribution::Uniform, 70000, 2, 3);
  points.coords.push_back(points.coords[0]);
  points.coords.push_back(points.coords[1]);
  write_cloud(dir.file("p.txt"), points);
  CliRun run = run_cli(dir, {"voronoi", dir.file("p.txt"), "-o", dir.file("v.txt"), "--quiet"});
  EXPECT_EQ(run.code, 0);
  EXPECT_EQ(run.err, "");
  run = run_cli(dir, {"voronoi", dir.file("p.txt"), "-o", dir.file("v.txt")});
  EXPECT_EQ(run.code, 0);
  EXPECT_EQ(run.err, "drange: 1 duplicate point left out (point 70000 = point 0)\n");
}

}  // namespace
}  // namespace drange
