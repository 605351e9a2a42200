// tests/formats_test.cpp: the result formats of drange/formats.hpp (.npz, JSON, .vtu, OFF,
// qvoronoi o and Fv) and the dispatchers, on small hand-built results so that they do not
// depend on the engines: exact layouts where a format is fixed text, structure and counts
// otherwise, and the files read back by their users' readers (numpy, json, xml.etree,
// zipfile) when Python has them.
#include "drange/formats.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "drange/errors.hpp"
#include "drange/io.hpp"
#include "python_check.hpp"
#include "temp_dir.hpp"

namespace drange {
namespace {

using testing::count_entries;
using testing::read_text;
using testing::run_python;
using testing::TempDir;

constexpr double kInf = std::numeric_limits<double>::infinity();

// ---------------------------------------------------------------- fixtures

// The unit square's corners 0..3, its centre 4, and 5 an exact copy of the centre.
PointCloud square_points() { return {2, {0, 0, 1, 0, 0, 1, 1, 1, 0.5, 0.5, 0.5, 0.5}}; }

// Its triangulation: four counter-clockwise triangles around the centre.
Triangulation square_triangulation() {
  Triangulation t;
  t.dim = 2;
  t.num_points = 6;
  t.simplices = {0, 1, 4, 1, 3, 4, 3, 2, 4, 2, 0, 4};
  t.neighbors = {1, 3, -1, 2, 0, -1, 3, 1, -1, 0, 2, -1};
  t.duplicates = {{5, 4}};
  return t;
}

IndexLists lists(const std::vector<std::vector<std::int32_t>>& rows) {
  IndexLists out;
  for (const auto& row : rows) {
    out.values.insert(out.values.end(), row.begin(), row.end());
    out.end_row();
  }
  return out;
}

// Its Voronoi diagram, worked by hand. Vertices, the triangles' circumcentres:
// 0 (0.5, 0), 1 (1, 0.5), 2 (0.5, 1), 3 (0, 0.5). The centre's cell is the diamond of area
// 0.5; the corners' cells are unbounded.
Voronoi square_voronoi() {
  Voronoi v;
  v.dim = 2;
  v.num_points = 6;
  v.vertices = {0.5, 0, 1, 0.5, 0.5, 1, 0, 0.5};
  v.simplex_vertex = {0, 1, 2, 3};
  v.ridge_points = {0, 1, 0, 2, 0, 4, 1, 3, 1, 4, 2, 3, 2, 4, 3, 4};
  v.ridge_vertices = lists({{-1, 0}, {-1, 3}, {0, 3}, {-1, 1}, {0, 1}, {-1, 2}, {2, 3}, {1, 2}});
  v.regions = lists({{0, 3, -1}, {1, 0, -1}, {3, 2, -1}, {2, 1, -1}, {0, 1, 2, 3}});
  v.point_region = {0, 1, 2, 3, 4, 4};
  v.region_point = {0, 1, 2, 3, 4};
  v.volumes = {kInf, kInf, kInf, kInf, 0.5};
  return v;
}

// The cells clipped to the unit square: four corner triangles and the diamond, each with
// its own corners, counter-clockwise.
ClippedCells square_cells() {
  ClippedCells c;
  c.dim = 2;
  c.box = {{0, 0}, {1, 1}};
  const std::vector<std::vector<double>> polygons = {{0, 0, 0.5, 0, 0, 0.5},
                                                     {1, 0, 1, 0.5, 0.5, 0},
                                                     {0, 1, 0, 0.5, 0.5, 1},
                                                     {1, 1, 0.5, 1, 1, 0.5},
                                                     {0.5, 0, 1, 0.5, 0.5, 1, 0, 0.5}};
  for (const auto& polygon : polygons) {
    std::vector<std::int32_t> loop;
    for (std::size_t k = 0; k < polygon.size(); k += 2)
      loop.push_back(static_cast<std::int32_t>(c.points.size() / 2 + k / 2));
    c.points.insert(c.points.end(), polygon.begin(), polygon.end());
    c.faces.values.insert(c.faces.values.end(), loop.begin(), loop.end());
    c.faces.end_row();
    c.cell_faces.push_back(static_cast<std::int64_t>(c.faces.size()));
  }
  c.volumes = {0.125, 0.125, 0.125, 0.125, 0.5};
  return c;
}

// Appends the box [lower, upper] as one 3D cell: 8 corners, 6 quadrilaterals counter-
// clockwise seen from outside. Corner (x, y, z) of the unit cube is number x + 2y + 4z.
void add_box_cell(ClippedCells& cells, const double lower[3], const double upper[3]) {
  const auto base = static_cast<std::int32_t>(cells.points.size() / 3);
  for (int corner = 0; corner < 8; ++corner) {
    for (int k = 0; k < 3; ++k) cells.points.push_back((corner >> k) & 1 ? upper[k] : lower[k]);
  }
  const std::int32_t quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto& quad : quads) {
    for (std::int32_t corner : quad) cells.faces.values.push_back(base + corner);
    cells.faces.end_row();
  }
  cells.cell_faces.push_back(static_cast<std::int64_t>(cells.faces.size()));
  cells.volumes.push_back((upper[0] - lower[0]) * (upper[1] - lower[1]) * (upper[2] - lower[2]));
}

// Two points (0.5, 0.5, 0.5) and (1.5, 0.5, 0.5): their cells in the box [0,2]x[0,1]x[0,1]
// are two unit cubes. The diagram has no vertex (two points have no Delaunay simplex), so
// only the parts the cell writers read are filled.
Voronoi two_cubes_voronoi() {
  Voronoi v;
  v.dim = 3;
  v.num_points = 2;
  v.ridge_points = {0, 1};
  v.ridge_vertices = lists({{-1}});
  v.regions = lists({{-1}, {-1}});
  v.point_region = {0, 1};
  v.region_point = {0, 1};
  v.volumes = {kInf, kInf};
  return v;
}

ClippedCells two_cubes() {
  ClippedCells c;
  c.dim = 3;
  c.box = {{0, 0, 0}, {2, 1, 1}};
  const double origin[3] = {0, 0, 0}, middle_top[3] = {1, 1, 1}, middle_bottom[3] = {1, 0, 0}, far[3] = {2, 1, 1};
  add_box_cell(c, origin, middle_top);
  add_box_cell(c, middle_bottom, far);
  return c;
}

// Two positively oriented tetrahedra sharing the triangle (1, 2, 3): a bipyramid.
PointCloud bipyramid_points() { return {3, {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1}}; }

Triangulation bipyramid() {
  Triangulation t;
  t.dim = 3;
  t.num_points = 5;
  t.simplices = {0, 1, 2, 3, 1, 2, 3, 4};
  t.neighbors = {1, -1, -1, -1, -1, -1, -1, 0};
  return t;
}

template <typename Write>
std::string written(Write write) {
  std::ostringstream out;
  write(out);
  return out.str();
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::size_t count_of(const std::string& text, const std::string& part) {
  std::size_t n = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
  return n;
}

// ---------------------------------------------------------------- Qhull's layouts

TEST(FormatsQhull, VoronoiO) {
  const std::string expected =
      "2\n"
      "5 6 1\n"
      "-10.101 -10.101\n"
      "0.5 0\n1 0.5\n0.5 1\n0 0.5\n"
      "3 1 4 0\n"  // point 0: vertices 0 and 3, then infinity
      "3 2 1 0\n"
      "3 4 3 0\n"
      "3 3 2 0\n"
      "4 1 2 3 4\n"   // the centre's bounded cell
      "4 1 2 3 4\n";  // its copy has the same region
  EXPECT_EQ(written([](std::ostream& out) { write_qvoronoi_o(out, square_voronoi()); }), expected);
}

TEST(FormatsQhull, VoronoiFv) {
  const std::string expected =
      "8\n"
      "4 0 1 0 1\n"
      "4 0 2 0 4\n"
      "4 0 4 1 4\n"
      "4 1 3 0 2\n"
      "4 1 4 1 2\n"
      "4 2 3 0 3\n"
      "4 2 4 3 4\n"
      "4 3 4 2 3\n";
  EXPECT_EQ(written([](std::ostream& out) { write_qvoronoi_fv(out, square_voronoi()); }), expected);
}

// In 3D qvoronoi leaves out a ridge with fewer than 3 vertex entries: the unbounded face of
// a hull edge that lies in a single tetrahedron (one vertex and infinity).
TEST(FormatsQhull, VoronoiFvKeepsQhullsRidgesIn3D) {
  Voronoi v;
  v.dim = 3;
  v.num_points = 4;
  v.vertices = {0, 0, 0, 1, 1, 1, 2, 2, 2};
  v.ridge_points = {0, 1, 0, 2, 1, 2};
  v.ridge_vertices = lists({{-1, 0}, {-1, 0, 1}, {0, 1, 2}});
  v.regions = lists({{-1, 0, 1}, {-1, 0, 1, 2}, {-1, 0, 1, 2}, {-1, 2}});
  v.point_region = {0, 1, 2, 3};
  EXPECT_EQ(written([&](std::ostream& out) { write_qvoronoi_fv(out, v); }), "2\n5 0 2 0 1 2\n5 1 2 1 2 3\n");
}

// The header lines and the point at infinity as qvoronoi itself prints them, when it is
// installed: same counts, same tokens.
TEST(FormatsQhull, HeaderMatchesQvoronoi) {
  if (std::system("command -v qvoronoi > /dev/null 2>&1") != 0) GTEST_SKIP() << "SKIPPED: qvoronoi is not installed";
  TempDir dir;
  testing::write_text(dir.file("in.txt"), "2\n5\n0 0\n1 0\n0 1\n1 1\n0.5 0.5\n");
  const std::string command =
      "qvoronoi o < " + testing::shell_word(dir.file("in.txt")) + " > " + testing::shell_word(dir.file("o.txt"));
  ASSERT_EQ(std::system(command.c_str()), 0);
  const std::vector<std::string> theirs = lines_of(read_text(dir.file("o.txt")));
  Voronoi five = square_voronoi();
  five.num_points = 5;
  five.point_region.pop_back();
  const std::vector<std::string> ours = lines_of(written([&](std::ostream& out) { write_qvoronoi_o(out, five); }));
  ASSERT_EQ(theirs.size(), ours.size());
  for (std::size_t i = 0; i < 3; ++i) {
    std::istringstream a(theirs[i]), b(ours[i]);
    std::vector<std::string> ta{std::istream_iterator<std::string>(a), {}},
        tb{std::istream_iterator<std::string>(b), {}};
    EXPECT_EQ(ta, tb) << "line " << i + 1;
  }
}

// ---------------------------------------------------------------- JSON

TEST(FormatsJson, DelaunayLayout) {
  const std::string text = written([](std::ostream& out) { write_delaunay_json(out, square_triangulation()); });
  EXPECT_EQ(text,
            "{\"ndim\": 2,\n\"npoints\": 6,\n"
            "\"simplices\": [\n  [0, 1, 4],\n  [1, 3, 4],\n  [3, 2, 4],\n  [2, 0, 4]],\n"
            "\"neighbors\": [\n  [1, 3, -1],\n  [2, 0, -1],\n  [3, 1, -1],\n  [0, 2, -1]],\n"
            "\"coplanar\": [\n  [5, -1, 4]]}\n");
  Triangulation bare = square_triangulation();
  bare.neighbors.clear();
  bare.duplicates.clear();
  const std::string without = written([&](std::ostream& out) { write_delaunay_json(out, bare); });
  EXPECT_EQ(without.find("neighbors"), std::string::npos);
  EXPECT_NE(without.find("\"coplanar\": []}"), std::string::npos) << without;
}

TEST(FormatsJson, VoronoiWritesInfinityAsNull) {
  const Voronoi v = square_voronoi();
  const std::string text = written([&](std::ostream& out) { write_voronoi_json(out, v, nullptr); });
  EXPECT_NE(text.find("\"volumes\": [null, null, null, null, 0.5]"), std::string::npos) << text;
  EXPECT_NE(text.find("\"point_region\": [0, 1, 2, 3, 4, 4]"), std::string::npos) << text;
  EXPECT_EQ(text.find("clipped_cells"), std::string::npos);
}

TEST(FormatsJson, ReadByPython) {
  DRANGE_REQUIRE_PYTHON("json");
  TempDir dir;
  const Voronoi v = square_voronoi();
  const ClippedCells cells = square_cells();
  write_delaunay(dir.file("d.json"), OutputFormat::Json, square_points(), square_triangulation());
  write_voronoi(dir.file("v.json"), OutputFormat::Json, square_points(), v, &cells);
  const std::string script = R"(
import json, sys
d = json.load(open(sys.argv[1] + '/d.json'))
assert sorted(d) == ['coplanar', 'ndim', 'neighbors', 'npoints', 'simplices'], sorted(d)
assert d['ndim'] == 2 and d['npoints'] == 6 and d['simplices'][1] == [1, 3, 4] and d['coplanar'] == [[5, -1, 4]]
v = json.load(open(sys.argv[1] + '/v.json'))
assert sorted(v) == ['clipped_cells', 'ndim', 'npoints', 'point_region', 'regions', 'ridge_points',
                     'ridge_vertices', 'vertices', 'volumes'], sorted(v)
assert v['vertices'] == [[0.5, 0], [1, 0.5], [0.5, 1], [0, 0.5]], v['vertices']
assert v['ridge_points'][2] == [0, 4] and v['ridge_vertices'][0] == [-1, 0]
assert v['regions'][4] == [0, 1, 2, 3] and v['point_region'] == [0, 1, 2, 3, 4, 4]
assert v['volumes'] == [None, None, None, None, 0.5]
c = v['clipped_cells']
assert c['box'] == {'lower': [0, 0], 'upper': [1, 1]}, c['box']
assert len(c['cells']) == 5
centre = c['cells'][4]
assert centre['point'] == 4 and centre['volume'] == 0.5
assert len(centre['points']) == 4 and len(centre['faces']) == 1
assert [centre['points'][i] for i in centre['faces'][0]] == [[0.5, 0], [1, 0.5], [0.5, 1], [0, 0.5]]
assert sum(cell['volume'] for cell in c['cells']) == 1
print('ok')
)";
  EXPECT_EQ(run_python(dir, script, {dir.path()}), "ok\n");
}

TEST(FormatsJson, ClippedCornersAreRenumberedPerCell) {
  const Voronoi v = two_cubes_voronoi();
  const ClippedCells cells = two_cubes();
  const std::string text = written([&](std::ostream& out) { write_voronoi_json(out, v, &cells); });
  // The second cube's faces index its own eight corners, 0..7, not 8..15.
  const std::size_t second = text.find("{\"point\": 1");
  ASSERT_NE(second, std::string::npos) << text;
  EXPECT_NE(text.find("\"faces\": [[0, 4, 6, 2], [1, 3, 7, 5]", second), std::string::npos) << text.substr(second);
}

// ---------------------------------------------------------------- .npz

TEST(FormatsNpz, ZipStructure) {
  const std::int32_t values[3] = {1, 2, 3};
  const std::string zip = written([&](std::ostream& out) {
    write_npz(out, {{"a", NpyArray(values, {3})}, {"bb", NpyArray(values, {1, 3})}});
  });
  EXPECT_EQ(zip.substr(0, 4), "PK\x03\x04");
  EXPECT_EQ(zip.substr(30, 5), "a.npy");
  EXPECT_EQ(count_of(zip, "PK\x01\x02"), 2u);  // central directory entries
  ASSERT_GE(zip.size(), 22u);
  const std::string end = zip.substr(zip.size() - 22);
  EXPECT_EQ(end.substr(0, 4), "PK\x05\x06");
  EXPECT_EQ(static_cast<unsigned char>(end[10]), 2u);  // total entries
  // Deterministic: the same arrays give the same bytes.
  EXPECT_EQ(zip, written([&](std::ostream& out) {
              write_npz(out, {{"a", NpyArray(values, {3})}, {"bb", NpyArray(values, {1, 3})}});
            }));
}

TEST(FormatsNpz, RefusesWhatNeedsZip64BeforeWriting) {
  const double one = 1;
  std::ostringstream out;
  // 600 million doubles: 4.8 GB. The data is never read: the size check comes first.
  EXPECT_THROW(write_npz(out, {{"huge", NpyArray(&one, {600000000})}}), UsageError);
  EXPECT_TRUE(out.str().empty());
  EXPECT_THROW(write_npz(out, {{"x", NpyArray(&one, {1})}, {"x", NpyArray(&one, {1})}}), UsageError);
  try {
    write_npz(out, {{"huge", NpyArray(&one, {600000000})}});
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("ZIP64"), std::string::npos) << e.what();
  }
}

TEST(FormatsNpz, DelaunayReadByNumpy) {
  DRANGE_REQUIRE_PYTHON("numpy");
  TempDir dir;
  write_delaunay(dir.file("d.npz"), OutputFormat::Npz, square_points(), square_triangulation());
  const std::string script = R"(
import sys, zipfile, numpy as np
assert zipfile.ZipFile(sys.argv[1]).testzip() is None  # every CRC checks
d = np.load(sys.argv[1])
assert sorted(d.files) == ['coplanar', 'ndim', 'neighbors', 'npoints', 'simplices'], d.files
assert int(d['ndim']) == 2 and int(d['npoints']) == 6
s = d['simplices']
assert s.dtype == np.int32 and s.shape == (4, 3) and s.tolist()[2] == [3, 2, 4], s
assert d['neighbors'].tolist()[0] == [1, 3, -1]
assert d['coplanar'].tolist() == [[5, -1, 4]] and d['coplanar'].dtype == np.int32
print('ok')
)";
  EXPECT_EQ(run_python(dir, script, {dir.file("d.npz")}), "ok\n");
}

TEST(FormatsNpz, VoronoiReadByNumpy) {
  DRANGE_REQUIRE_PYTHON("numpy");
  TempDir dir;
  const ClippedCells cells = square_cells();
  write_voronoi(dir.file("v.npz"), OutputFormat::Npz, square_points(), square_voronoi(), &cells);
  const std::string script = R"(
import sys, zipfile, numpy as np
assert zipfile.ZipFile(sys.argv[1]).testzip() is None
d = np.load(sys.argv[1])
expected = ['clipped_box_lower', 'clipped_box_upper', 'clipped_cell_faces', 'clipped_faces', 'clipped_faces_offsets',
            'clipped_points', 'clipped_volumes', 'ndim', 'npoints', 'point_region', 'regions', 'regions_offsets',
            'ridge_points', 'ridge_vertices', 'ridge_vertices_offsets', 'vertices', 'volumes']
assert sorted(d.files) == expected, d.files
assert d['vertices'].shape == (4, 2) and d['vertices'].dtype == np.float64
assert d['ridge_points'].shape == (8, 2) and d['ridge_points'].dtype == np.int32
regions = np.split(d['regions'], d['regions_offsets'][1:-1])
assert [r.tolist() for r in regions] == [[0, 3, -1], [1, 0, -1], [3, 2, -1], [2, 1, -1], [0, 1, 2, 3]], regions
assert d['regions_offsets'].dtype == np.int64
ridges = np.split(d['ridge_vertices'], d['ridge_vertices_offsets'][1:-1])
assert ridges[2].tolist() == [0, 3]
assert d['point_region'].tolist() == [0, 1, 2, 3, 4, 4]
assert np.isinf(d['volumes'][:4]).all() and d['volumes'][4] == 0.5
assert d['clipped_points'].shape == (16, 2) and d['clipped_cell_faces'].tolist() == [0, 1, 2, 3, 4, 5]
assert d['clipped_volumes'].sum() == 1 and d['clipped_box_upper'].tolist() == [1, 1]
print('ok')
)";
  EXPECT_EQ(run_python(dir, script, {dir.file("v.npz")}), "ok\n");
}

// ---------------------------------------------------------------- VTK

// The number of values between <DataArray ... Name="name" ...> and </DataArray>.
std::size_t array_length(const std::string& xml, const std::string& name) {
  const std::size_t open = xml.find("Name=\"" + name + "\"");
  if (open == std::string::npos) return 0;
  const std::size_t start = xml.find('>', open) + 1;
  std::istringstream values(xml.substr(start, xml.find("</DataArray>", start) - start));
  return static_cast<std::size_t>(
      std::distance(std::istream_iterator<std::string>(values), std::istream_iterator<std::string>()));
}

TEST(FormatsVtu, Delaunay2DAnd3D) {
  const std::string flat =
      written([](std::ostream& out) { write_delaunay_vtu(out, square_points(), square_triangulation()); });
  EXPECT_NE(flat.find("<Piece NumberOfPoints=\"6\" NumberOfCells=\"4\">"), std::string::npos) << flat;
  EXPECT_EQ(array_length(flat, "Points"), 18u);  // z = 0 added
  EXPECT_EQ(array_length(flat, "connectivity"), 12u);
  EXPECT_NE(flat.find("\"offsets\" format=\"ascii\">\n3\n6\n9\n12\n</DataArray>"), std::string::npos) << flat;
  EXPECT_NE(flat.find("\"types\" format=\"ascii\">\n5\n5\n5\n5\n</DataArray>"), std::string::npos) << flat;

  const std::string solid =
      written([](std::ostream& out) { write_delaunay_vtu(out, bipyramid_points(), bipyramid()); });
  EXPECT_NE(solid.find("NumberOfPoints=\"5\" NumberOfCells=\"2\""), std::string::npos);
  EXPECT_NE(solid.find("\"types\" format=\"ascii\">\n10\n10\n</DataArray>"), std::string::npos) << solid;
  EXPECT_NE(solid.find("0 1 2 3\n1 2 3 4\n"), std::string::npos);
}

TEST(FormatsVtu, ThrowsBeyond3D) {
  Triangulation t;
  t.dim = 4;
  t.num_points = 5;
  t.simplices = {0, 1, 2, 3, 4};
  const PointCloud points{4, std::vector<double>(20, 0.0)};
  std::ostringstream out;
  try {
    write_delaunay_vtu(out, points, t);
    FAIL() << "no error";
  } catch (const UsageError& e) {
    EXPECT_EQ(std::string(e.what()), "VTK holds 2D and 3D only; the points have dimension 4");
  }
}

TEST(FormatsVtu, CellsAsPolygonsAndPolyhedra) {
  const std::string polygons =
      written([](std::ostream& out) { write_cells_vtu(out, square_voronoi(), square_cells()); });
  EXPECT_NE(polygons.find("NumberOfPoints=\"16\" NumberOfCells=\"5\""), std::string::npos);
  EXPECT_EQ(array_length(polygons, "connectivity"), 16u);
  EXPECT_NE(polygons.find("\"types\" format=\"ascii\">\n7\n7\n7\n7\n7\n</DataArray>"), std::string::npos) << polygons;
  EXPECT_NE(polygons.find("\"volume\" format=\"ascii\">\n0.125\n0.125\n0.125\n0.125\n0.5\n"), std::string::npos);
  EXPECT_NE(polygons.find("\"point\" format=\"ascii\">\n0\n1\n2\n3\n4\n"), std::string::npos);

  const std::string solids = written([](std::ostream& out) { write_cells_vtu(out, two_cubes_voronoi(), two_cubes()); });
  EXPECT_NE(solids.find("NumberOfPoints=\"16\" NumberOfCells=\"2\""), std::string::npos);
  EXPECT_NE(solids.find("\"types\" format=\"ascii\">\n42\n42\n</DataArray>"), std::string::npos);
  // Per cube: its face count, then 6 faces of (4, four ids): 1 + 6 * 5 = 31 values.
  EXPECT_EQ(array_length(solids, "faces"), 62u);
  EXPECT_NE(solids.find("\"faceoffsets\" format=\"ascii\">\n31\n62\n</DataArray>"), std::string::npos) << solids;
  EXPECT_NE(solids.find("\"offsets\" format=\"ascii\">\n8\n16\n</DataArray>"), std::string::npos);
}

TEST(FormatsVtu, EmptyCellsAreLeftOut) {
  Voronoi v = two_cubes_voronoi();
  ClippedCells cells = two_cubes();
  // A third region whose cell misses the box.
  v.num_points = 3;
  v.point_region.push_back(2);
  v.regions = lists({{-1}, {-1}, {-1}});
  v.volumes.push_back(kInf);
  cells.cell_faces.push_back(cells.cell_faces.back());
  cells.volumes.push_back(0);
  const std::string text = written([&](std::ostream& out) { write_cells_vtu(out, v, cells); });
  EXPECT_NE(text.find("NumberOfCells=\"2\""), std::string::npos);
  EXPECT_NE(text.find("\"point\" format=\"ascii\">\n0\n1\n</DataArray>"), std::string::npos) << text;
}

TEST(FormatsVtu, ParsedByXmlReader) {
  DRANGE_REQUIRE_PYTHON("xml.etree.ElementTree");
  TempDir dir;
  const ClippedCells cubes = two_cubes();
  const PointCloud cube_points{3, {0.5, 0.5, 0.5, 1.5, 0.5, 0.5}};
  write_delaunay(dir.file("d.vtu"), OutputFormat::Vtu, bipyramid_points(), bipyramid());
  write_voronoi(dir.file("v.vtu"), OutputFormat::Vtu, cube_points, two_cubes_voronoi(), &cubes);
  const std::string script = R"(
import sys, xml.etree.ElementTree as ET
for name, cells, types in (('d.vtu', 2, ['10', '10']), ('v.vtu', 2, ['42', '42'])):
    root = ET.parse(sys.argv[1] + '/' + name).getroot()
    assert root.tag == 'VTKFile' and root.get('type') == 'UnstructuredGrid'
    piece = root.find('UnstructuredGrid/Piece')
    assert int(piece.get('NumberOfCells')) == cells
    arrays = {a.get('Name'): a.text.split() for a in piece.iter('DataArray')}
    assert arrays['types'] == types, arrays['types']
    assert len(arrays['Points']) == 3 * int(piece.get('NumberOfPoints'))
    assert int(arrays['offsets'][-1]) == len(arrays['connectivity'])
print('ok')
)";
  EXPECT_EQ(run_python(dir, script, {dir.path()}), "ok\n");
}

// ---------------------------------------------------------------- OFF

TEST(FormatsOff, Delaunay2DIsAFlatSurface) {
  const std::string text =
      written([](std::ostream& out) { write_delaunay_off(out, square_points(), square_triangulation()); });
  EXPECT_EQ(text,
            "OFF\n6 4 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0.5 0.5 0\n0.5 0.5 0\n"
            "3 0 1 4\n3 1 3 4\n3 3 2 4\n3 2 0 4\n");
}

TEST(FormatsOff, Delaunay3DHullFacesOutward) {
  const std::string text = written([](std::ostream& out) { write_delaunay_off(out, bipyramid_points(), bipyramid()); });
  const std::vector<std::string> lines = lines_of(text);
  ASSERT_EQ(lines.size(), 2u + 5u + 6u) << text;
  EXPECT_EQ(lines[0], "OFF");
  EXPECT_EQ(lines[1], "5 6 0");
  std::vector<double> xyz;
  for (std::size_t i = 2; i < 7; ++i) {
    std::istringstream in(lines[i]);
    for (double c; in >> c;) xyz.push_back(c);
  }
  const double inside[3] = {0.4, 0.4, 0.4};
  for (std::size_t i = 7; i < lines.size(); ++i) {
    std::istringstream in(lines[i]);
    int k, a, b, c;
    in >> k >> a >> b >> c;
    ASSERT_EQ(k, 3);
    const double* p = &xyz[3 * a];
    const double* q = &xyz[3 * b];
    const double* r = &xyz[3 * c];
    const double u[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]}, w[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
    const double normal[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
    const double out = normal[0] * (p[0] - inside[0]) + normal[1] * (p[1] - inside[1]) + normal[2] * (p[2] - inside[2]);
    EXPECT_GT(out, 0) << "face " << lines[i] << " points inward";
  }
}

TEST(FormatsOff, Delaunay3DOnlyHullVerticesAndNeedsNeighbours) {
  // A point inside the bipyramid that no hull facet uses is left out.
  PointCloud points = bipyramid_points();
  points.coords.insert(points.coords.end(), {0.3, 0.3, 0.3});
  Triangulation t = bipyramid();
  t.num_points = 6;
  const std::string text = written([&](std::ostream& out) { write_delaunay_off(out, points, t); });
  EXPECT_EQ(lines_of(text)[1], "5 6 0");
  t.neighbors.clear();
  std::ostringstream out;
  EXPECT_THROW(write_delaunay_off(out, points, t), UsageError);
}

TEST(FormatsOff, Cells) {
  const std::string flat = written([](std::ostream& out) { write_cells_off(out, square_cells()); });
  const std::vector<std::string> lines = lines_of(flat);
  EXPECT_EQ(lines[1], "16 5 0");
  EXPECT_EQ(lines[2], "0 0 0");
  EXPECT_EQ(lines.back(), "4 12 13 14 15");
  const std::string solid = written([](std::ostream& out) { write_cells_off(out, two_cubes()); });
  EXPECT_EQ(lines_of(solid)[1], "16 12 0");
  EXPECT_EQ(lines_of(solid).size(), 2u + 16u + 12u);
}

TEST(FormatsOff, ThrowsBeyond3D) {
  ClippedCells cells;
  cells.dim = 4;
  cells.box = {{0, 0, 0, 0}, {1, 1, 1, 1}};
  std::ostringstream out;
  EXPECT_THROW(write_cells_off(out, cells), UsageError);
}

// ---------------------------------------------------------------- choosing and writing files

TEST(FormatsChoose, ByNameAndByExtension) {
  EXPECT_EQ(output_format_from_name("qhull"), OutputFormat::Qhull);
  EXPECT_EQ(output_format_from_name("json"), OutputFormat::Json);
  EXPECT_EQ(output_format_from_name("npz"), OutputFormat::Npz);
  EXPECT_EQ(output_format_from_name("vtu"), OutputFormat::Vtu);
  EXPECT_EQ(output_format_from_name("off"), OutputFormat::Off);
  try {
    output_format_from_name("xml");
    FAIL() << "no error";
  } catch (const UsageError& e) {
    EXPECT_EQ(std::string(e.what()), "unknown output format 'xml' (expected one of: qhull, json, npz, vtu, off)");
  }
  EXPECT_EQ(output_format_from_path("out/a.json", OutputFormat::Qhull), OutputFormat::Json);
  EXPECT_EQ(output_format_from_path("A.NPZ", OutputFormat::Qhull), OutputFormat::Npz);
  EXPECT_EQ(output_format_from_path("mesh.vtu", OutputFormat::Qhull), OutputFormat::Vtu);
  EXPECT_EQ(output_format_from_path("hull.off", OutputFormat::Qhull), OutputFormat::Off);
  EXPECT_EQ(output_format_from_path("simplices.txt", OutputFormat::Qhull), OutputFormat::Qhull);
  EXPECT_EQ(output_format_from_path("-", OutputFormat::Json), OutputFormat::Json);
  EXPECT_EQ(output_format_from_path("json", OutputFormat::Qhull), OutputFormat::Qhull);
}

TEST(FormatsWrite, QhullLayoutsThroughTheDispatchers) {
  TempDir dir;
  write_delaunay(dir.file("s.txt"), OutputFormat::Qhull, square_points(), square_triangulation());
  EXPECT_EQ(read_text(dir.file("s.txt")), "4\n0 1 4\n1 3 4\n3 2 4\n2 0 4\n");
  write_voronoi(dir.file("o.txt"), OutputFormat::Qhull, square_points(), square_voronoi(), nullptr);
  EXPECT_EQ(read_text(dir.file("o.txt")), written([](std::ostream& out) { write_qvoronoi_o(out, square_voronoi()); }));
}

TEST(FormatsWrite, BinaryToStandardOutput) {
  std::ostringstream captured;
  std::streambuf* saved = std::cout.rdbuf(captured.rdbuf());
  try {
    write_delaunay("-", OutputFormat::Npz, square_points(), square_triangulation());
  } catch (...) {
    std::cout.rdbuf(saved);
    throw;
  }
  std::cout.rdbuf(saved);
  EXPECT_EQ(captured.str(), written([](std::ostream& out) { write_delaunay_npz(out, square_triangulation()); }));
  EXPECT_EQ(captured.str().substr(0, 4), "PK\x03\x04");
}

TEST(FormatsWrite, FailedWritesLeaveNoFile) {
  TempDir dir;
  // A directory that does not exist.
  EXPECT_THROW(write_delaunay(dir.file("missing/d.json"), OutputFormat::Json, square_points(), square_triangulation()),
               InputError);
  // A writer that refuses its input (VTK beyond 3D, OFF without cells, points of another result).
  Triangulation t4;
  t4.dim = 4;
  t4.num_points = 5;
  t4.simplices = {0, 1, 2, 3, 4};
  const PointCloud points4{4, std::vector<double>(20, 0.0)};
  EXPECT_THROW(write_delaunay(dir.file("d.vtu"), OutputFormat::Vtu, points4, t4), UsageError);
  EXPECT_THROW(write_voronoi(dir.file("v.off"), OutputFormat::Off, square_points(), square_voronoi(), nullptr),
               UsageError);
  EXPECT_THROW(write_voronoi(dir.file("v.json"), OutputFormat::Json, bipyramid_points(), square_voronoi(), nullptr),
               UsageError);
  EXPECT_EQ(count_entries(dir.path()), 0u);
}

TEST(FormatsWrite, InconsistentResultsAreUsageErrors) {
  std::ostringstream out;
  Voronoi v = square_voronoi();
  v.point_region[5] = 9;
  EXPECT_THROW(write_qvoronoi_o(out, v), UsageError);
  Triangulation t = square_triangulation();
  t.simplices[0] = 6;
  EXPECT_THROW(write_delaunay_json(out, t), UsageError);
  ClippedCells cells = square_cells();
  cells.faces.values[0] = 16;
  EXPECT_THROW(write_cells_off(out, cells), UsageError);
  const ClippedCells other = two_cubes();
  EXPECT_THROW(write_voronoi_json(out, square_voronoi(), &other), UsageError);
}

}  // namespace
}  // namespace drange
