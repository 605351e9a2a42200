// tests/svg_test.cpp: the SVG pictures of drange/svg.hpp: every edge drawn once in its layer,
// unbounded Voronoi edges as rays pointing away from the hull, far geometry clipped to the
// view, and the files well-formed (Python's XML parser) and renderable (rsvg-convert).
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "drange/delaunay.hpp"
#include "drange/errors.hpp"
#include "drange/generate.hpp"
#include "drange/svg.hpp"
#include "drange/voronoi.hpp"
#include "temp_dir.hpp"
#include "voronoi/circumcentre.hpp"

namespace drange {
namespace {

using testing::TempDir;
using testing::write_text;

// The Voronoi diagram of points in general position, read off their triangulation by hand
// (one vertex per triangle, one ridge per Delaunay edge), so that the drawing is tested
// apart from drange::voronoi.
Voronoi hand_made_voronoi(PointsView points, const Triangulation& t) {
  Voronoi v;
  v.dim = 2;
  v.num_points = points.n;
  for (std::size_t s = 0; s < t.size(); ++s) {
    const double* corners[3] = {points.point(t.simplex(s)[0]), points.point(t.simplex(s)[1]), points.point(t.simplex(s)[2])};
    double centre[2];
    diagram::simplex_circumcentre(2, corners, centre);
    v.vertices.insert(v.vertices.end(), centre, centre + 2);
    v.simplex_vertex.push_back(static_cast<std::int32_t>(s));
    for (int k = 0; k < 3; ++k) {
      // The edge opposite vertex k is shared with neighbour k; each ridge is made once.
      const std::int32_t other = t.neighbors[3 * s + static_cast<std::size_t>(k)];
      if (other >= 0 && other < static_cast<std::int32_t>(s)) continue;
      const std::int32_t p = t.simplex(s)[(k + 1) % 3], q = t.simplex(s)[(k + 2) % 3];
      v.ridge_points.push_back(std::min(p, q));
      v.ridge_points.push_back(std::max(p, q));
      v.ridge_vertices.values.push_back(static_cast<std::int32_t>(s));
      v.ridge_vertices.values.push_back(other);
      v.ridge_vertices.end_row();
    }
  }
  return v;
}

std::string svg_of(PointsView points, const Triangulation& t, const Voronoi* diagram, const SvgOptions& options = {}) {
  std::ostringstream out;
  write_svg(out, points, t, diagram, options);
  return out.str();
}

// The text of the layer <g id="id" ...>...</g>, empty when absent.
std::string layer(const std::string& svg, const std::string& id) {
  const std::size_t start = svg.find("<g id=\"" + id + "\"");
  if (start == std::string::npos) return "";
  return svg.substr(start, svg.find("</g>", start) + 4 - start);
}

// The path data of a layer, empty when it has none.
std::string path_data(const std::string& svg, const std::string& id) {
  const std::string text = layer(svg, id);
  const std::size_t d = text.find(" d=\"");
  return d == std::string::npos ? "" : text.substr(d + 4, text.find('"', d + 4) - d - 4);
}

struct Segment {
  double x0, y0, x1, y1;
};

// The segments of a line layer, in absolute pixels, read from the writer's "M x y" and
// relative "l dx dy" commands.
std::vector<Segment> segments(const std::string& svg, const std::string& id) {
  const std::string d = path_data(svg, id);
  std::vector<Segment> result;
  double x = 0, y = 0;
  const char* p = d.c_str();
  while (*p != '\0') {
    const char command = *p++;
    char* end = nullptr;
    const double a = std::strtod(p, &end);
    const double b = std::strtod(end, &end);
    p = end;
    if (command == 'M') {
      x = a, y = b;
    } else if (command == 'l') {
      result.push_back({x, y, x + a, y + b});
      x += a, y += b;
    } else {
      ADD_FAILURE() << "unexpected command " << command << " in " << id;
      break;
    }
  }
  return result;
}

// Elements drawn in a layer: line segments, circles (two arcs each) or dots ("h0" each).
std::size_t drawn(const std::string& svg, const std::string& id) {
  std::size_t lines = 0, arcs = 0, dots = 0;
  for (const char c : path_data(svg, id)) lines += c == 'l', arcs += c == 'a', dots += c == 'h';
  return lines + arcs / 2 + dots;
}

bool has_segment(const std::vector<Segment>& list, Segment s) {
  const auto near = [](double a, double b) { return std::abs(a - b) < 0.006; };
  for (const Segment& t : list)
    if (near(t.x0, s.x0) && near(t.y0, s.y0) && near(t.x1, s.x1) && near(t.y1, s.y1)) return true;
  return false;
}

struct Scene {
  PointCloud points;
  Triangulation t;
  Voronoi diagram;
};

Scene scene(PointCloud points) {
  Scene s{std::move(points), {}, {}};
  s.t = delaunay(s.points);
  s.diagram = hand_made_voronoi(s.points, s.t);
  return s;
}

// The unit square's corners and centre: four triangles, four Voronoi vertices at the middles
// of the square's sides, four bounded ridges and four rays.
Scene square_with_centre() { return scene(PointCloud{2, {0, 0, 1, 0, 1, 1, 0, 1, 0.5, 0.5}}); }

TEST(SvgTest, DrawsEveryEdgeOnceInItsLayer) {
  const Scene s = square_with_centre();
  SvgOptions options;
  options.circumcircles = true;
  const std::string svg = svg_of(s.points, s.t, &s.diagram, options);
  EXPECT_EQ(drawn(svg, "delaunay"), 4u);  // centre to corners
  EXPECT_EQ(drawn(svg, "hull"), 4u);
  EXPECT_EQ(drawn(svg, "voronoi"), 8u);
  EXPECT_EQ(drawn(svg, "circles"), 4u);
  EXPECT_EQ(drawn(svg, "points"), 5u);
  EXPECT_EQ(layer(svg, "labels"), "");
  EXPECT_NE(svg.find("<title>Delaunay triangulation and Voronoi diagram of 5 points (drange)</title>"), std::string::npos);
  EXPECT_NE(layer(svg, "legend").find("5 points"), std::string::npos);
  EXPECT_NE(layer(svg, "legend").find("4 triangles"), std::string::npos);
  EXPECT_NE(layer(svg, "legend").find("4 Voronoi vertices"), std::string::npos);
}

// The view is [-0.05, 1.05]^2 at 800/1.1 px per unit, y up. The Voronoi vertex (0.5, 0) of
// the bottom triangle is pixel (400, 763.64); the ray of the bottom hull edge leaves it
// downwards, away from the hull, to the view's lower side (pixel y 800). Likewise left.
TEST(SvgTest, UnboundedVoronoiEdgesPointAwayFromTheHull) {
  const Scene s = square_with_centre();
  const std::string svg = svg_of(s.points, s.t, &s.diagram);
  const std::vector<Segment> voronoi = segments(svg, "voronoi");
  EXPECT_TRUE(has_segment(voronoi, {400, 763.64, 400, 800})) << path_data(svg, "voronoi");
  EXPECT_TRUE(has_segment(voronoi, {400, 36.36, 400, 0})) << path_data(svg, "voronoi");
  EXPECT_TRUE(has_segment(voronoi, {36.36, 400, 0, 400})) << path_data(svg, "voronoi");
  EXPECT_TRUE(has_segment(voronoi, {763.64, 400, 800, 400})) << path_data(svg, "voronoi");
}

TEST(SvgTest, TriangulationAloneWithoutDiagram) {
  const Scene s = square_with_centre();
  SvgOptions options;
  options.point_labels = true;
  const std::string svg = svg_of(s.points, s.t, nullptr, options);
  EXPECT_EQ(layer(svg, "voronoi"), "");
  EXPECT_EQ(drawn(svg, "delaunay") + drawn(svg, "hull"), 8u);
  EXPECT_EQ(layer(svg, "legend").find("Voronoi"), std::string::npos);
  EXPECT_NE(svg.find("<title>Delaunay triangulation of 5 points (drange)</title>"), std::string::npos);
  EXPECT_NE(layer(svg, "labels").find(">4</text>"), std::string::npos);
}

// A sliver on the hull has its circumcentre some 1e8 units away: its Voronoi edges are cut
// at the view, so no coordinate leaves the picture.
TEST(SvgTest, FarVoronoiVerticesAreClippedToTheView) {
  const Scene s = scene(PointCloud{2, {0, 0, 1, 0, 0.5, 1e-9, 0.5, 0.6}});
  const std::string svg = svg_of(s.points, s.t, &s.diagram);
  const std::vector<Segment> voronoi = segments(svg, "voronoi");
  ASSERT_FALSE(voronoi.empty());
  const auto inside = [](double v) { return v >= -0.005 && v <= 800.005; };  // the view is widened to a square
  for (const Segment& v : voronoi) {
    EXPECT_TRUE(inside(v.x0) && inside(v.x1)) << v.x0 << ' ' << v.x1;
    EXPECT_TRUE(inside(v.y0) && inside(v.y1)) << v.y0 << ' ' << v.y1;
  }
}

TEST(SvgTest, RejectsPointsThatAreNot2D) {
  const PointCloud points{3, {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}};
  const Triangulation t = delaunay(points);
  std::ostringstream out;
  try {
    write_svg(out, points, t, nullptr, {});
    FAIL() << "no error for 3D points";
  } catch (const UsageError& e) {
    EXPECT_STREQ(e.what(), "SVG pictures are 2D only, the points have dimension 3");
  }
}

TEST(SvgTest, RejectsADiagramOfOtherPoints) {
  const Scene s = square_with_centre();
  Voronoi wrong = s.diagram;
  wrong.ridge_points[0] = 99;
  std::ostringstream out;
  EXPECT_THROW(write_svg(out, s.points, s.t, &wrong, {}), UsageError);
}

bool have_command(const std::string& name) { return std::system(("command -v " + name + " >/dev/null 2>&1").c_str()) == 0; }

// The width and height in a PNG's IHDR chunk (bytes 16..23, big-endian), {0, 0} if not a PNG.
std::pair<std::uint32_t, std::uint32_t> png_size(const std::string& png) {
  if (png.size() < 24 || png.compare(1, 3, "PNG") != 0) return {0, 0};
  const auto be32 = [&](std::size_t at) {
    std::uint32_t v = 0;
    for (std::size_t i = 0; i < 4; ++i) v = (v << 8) | static_cast<unsigned char>(png[at + i]);
    return v;
  };
  return {be32(16), be32(20)};
}

// 100 uniform points: the edges split between the interior and hull layers add up to Euler's
// count (n + triangles - 1), the file parses as XML, and rsvg-convert renders it.
TEST(SvgTest, RandomPointsParseAndRender) {
  const Scene s = scene(generate_points(Distribution::Uniform, 100, 2, 1));
  SvgOptions options;
  options.circumcircles = true;
  const std::string svg = svg_of(s.points, s.t, &s.diagram, options);
  EXPECT_EQ(drawn(svg, "delaunay") + drawn(svg, "hull"), s.points.size() + s.t.size() - 1);
  EXPECT_EQ(drawn(svg, "hull"), s.t.stats.hull_facets);
  EXPECT_LE(drawn(svg, "voronoi"), s.diagram.num_ridges());
  EXPECT_GT(drawn(svg, "voronoi"), s.diagram.num_ridges() / 2);  // most vertices lie inside the view
  EXPECT_EQ(drawn(svg, "points"), 100u);

  TempDir dir;
  write_text(dir.file("picture.svg"), svg);
  if (have_command("python3")) {
    EXPECT_EQ(std::system(("python3 -c 'import sys, xml.etree.ElementTree as E; E.parse(sys.argv[1])' " +
                           dir.file("picture.svg")).c_str()),
              0);
  } else {
    std::cerr << "python3 not installed: the SVG's XML is NOT parsed\n";
  }

  if (!have_command("rsvg-convert")) GTEST_SKIP() << "rsvg-convert not installed (Debian librsvg2-bin): the SVG is NOT rendered";
  // The same view with nothing drawn but the legend: the full picture must weigh more.
  SvgOptions empty;
  empty.triangulation = empty.voronoi = empty.points = false;
  write_text(dir.file("empty.svg"), svg_of(s.points, s.t, &s.diagram, empty));
  for (const char* name : {"picture", "empty"}) {
    const std::string command = "rsvg-convert -o " + dir.file(std::string(name) + ".png") + " " +
                                dir.file(std::string(name) + ".svg") + " 2>" + dir.file("stderr.txt");
    ASSERT_EQ(std::system(command.c_str()), 0) << testing::read_text(dir.file("stderr.txt"));
    EXPECT_EQ(testing::read_text(dir.file("stderr.txt")), "");
  }
  const std::string png = testing::read_text(dir.file("picture.png"));
  const auto size = png_size(png);
  EXPECT_EQ(size.first, 800u);
  EXPECT_GT(size.second, 700u);  // 800 x (about 800 + legend) for points filling the unit square
  EXPECT_GT(png.size(), 2 * testing::read_text(dir.file("empty.png")).size());
}

}  // namespace
}  // namespace drange
