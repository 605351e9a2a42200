// Tests of drange::clip_cells and drange::default_clip_box (src/voronoi/clip_cells.cpp and the
// convex polygon / polyhedron it clips): the cells tile the box, hold their points, have
// only real corners (on a bisector of a ridge partner or on the box), run counter-clockwise
// (3D faces seen from outside) and close up; grids give exact squares and cubes; the cells
// from drange::voronoi's ridges equal the brute-force cells cut by every other point's
// bisector; and every invalid argument is refused with a message.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "drange/errors.hpp"
#include "drange/generate.hpp"
#include "drange/voronoi.hpp"

namespace {

using drange::Box;
using drange::ClippedCells;
using drange::Distribution;
using drange::PointCloud;
using drange::Voronoi;
using Vec = std::array<double, 3>;  // 2D corners have z = 0

// A diagram with one region per point and every pair of points as a ridge: a superset of
// the true ridges. Extra bisectors only touch a cell or miss it, so the clipped cells are the
// true ones, found by brute force; many extra bisectors pass exactly through the corners of
// degenerate inputs, which exercises the tolerance.
Voronoi all_pairs_diagram(const PointCloud& points) {
  Voronoi v;
  v.dim = points.dim;
  v.num_points = points.size();
  for (std::size_t i = 0; i < points.size(); ++i) {
    v.regions.end_row();
    v.region_point.push_back(static_cast<std::int32_t>(i));
    v.point_region.push_back(static_cast<std::int32_t>(i));
    for (std::size_t j = i + 1; j < points.size(); ++j) {
      v.ridge_points.push_back(static_cast<std::int32_t>(i));
      v.ridge_points.push_back(static_cast<std::int32_t>(j));
    }
  }
  return v;
}

// The grid {0, ..., k-1}^d times `spacing`. Spacings like 0.1 make the arithmetic of the
// bisectors inexact, so that only the tolerance finds the corners they pass through.
PointCloud grid(int d, int k, double spacing = 1) {
  PointCloud points{d, {}};
  const int count = d == 2 ? k * k : k * k * k;
  for (int i = 0; i < count; ++i)
    for (int c = 0, rest = i; c < d; ++c, rest /= k) points.coords.push_back(spacing * (rest % k));
  return points;
}

Box cube(int d, double lower, double upper) {
  return Box{std::vector<double>(static_cast<std::size_t>(d), lower), std::vector<double>(static_cast<std::size_t>(d), upper)};
}

double box_volume(const Box& box) {
  double v = 1;
  for (std::size_t k = 0; k < box.lower.size(); ++k) v *= box.upper[k] - box.lower[k];
  return v;
}

Vec corner(const ClippedCells& cells, std::int32_t v) {
  Vec x{0, 0, 0};
  for (int k = 0; k < cells.dim; ++k) x[static_cast<std::size_t>(k)] = cells.points[static_cast<std::size_t>(v) * static_cast<std::size_t>(cells.dim) + static_cast<std::size_t>(k)];
  return x;
}

Vec sub(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec cross(const Vec& a, const Vec& b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
double norm(const Vec& a) { return std::sqrt(dot(a, a)); }

Vec point_of(const PointCloud& points, std::size_t i) {
  Vec x{0, 0, 0};
  for (int k = 0; k < points.dim; ++k) x[static_cast<std::size_t>(k)] = points.point(i)[k];
  return x;
}

// Twice the area vector of a face by Newell's method (in 2D: (0, 0, twice the signed area)).
Vec newell(const ClippedCells& cells, std::size_t f) {
  const std::int32_t* loop = cells.faces.row(f);
  const std::size_t k = cells.faces.row_size(f);
  const Vec origin = corner(cells, loop[0]);
  Vec sum{0, 0, 0};
  for (std::size_t i = 0; i < k; ++i) {
    const Vec c = cross(sub(corner(cells, loop[i]), origin), sub(corner(cells, loop[(i + 1) % k]), origin));
    for (int j = 0; j < 3; ++j) sum[static_cast<std::size_t>(j)] += c[static_cast<std::size_t>(j)];
  }
  return sum;
}

// The distinct corners used by cell c's faces.
std::set<std::int32_t> cell_corners(const ClippedCells& cells, std::size_t c) {
  std::set<std::int32_t> out;
  for (auto f = static_cast<std::size_t>(cells.cell_faces[c]); f < static_cast<std::size_t>(cells.cell_faces[c + 1]); ++f)
    out.insert(cells.faces.row(f), cells.faces.row(f) + cells.faces.row_size(f));
  return out;
}

Vec centroid(const ClippedCells& cells, const std::set<std::int32_t>& corners) {
  Vec sum{0, 0, 0};
  for (const std::int32_t v : corners)
    for (int j = 0; j < 3; ++j) sum[static_cast<std::size_t>(j)] += corner(cells, v)[static_cast<std::size_t>(j)] / static_cast<double>(corners.size());
  return sum;
}

bool inside_box(const PointCloud& points, std::size_t i, const Box& box) {
  for (int k = 0; k < points.dim; ++k)
    if (points.point(i)[k] <= box.lower[static_cast<std::size_t>(k)] || points.point(i)[k] >= box.upper[static_cast<std::size_t>(k)]) return false;
  return true;
}

// Every point's ridge partners.
std::vector<std::vector<std::int32_t>> partners_of(const Voronoi& diagram) {
  std::vector<std::vector<std::int32_t>> out(diagram.num_points);
  for (std::size_t r = 0; r < diagram.num_ridges(); ++r) {
    out[static_cast<std::size_t>(diagram.ridge_points[2 * r])].push_back(diagram.ridge_points[2 * r + 1]);
    out[static_cast<std::size_t>(diagram.ridge_points[2 * r + 1])].push_back(diagram.ridge_points[2 * r]);
  }
  return out;
}

// The invariants every clipped diagram satisfies (the context names the input on failure):
//   - the volumes are >= 0 and sum to the box's, within 1e-9 relative;
//   - the stored volume is the one of the faces (2D: the loop's shoelace area, which is
//     positive, so the loop runs counter-clockwise);
//   - 3D: every face's Newell normal points away from the cell's centroid (counter-clockwise
//     seen from outside), and the faces close up: each edge is walked once each way;
//   - a point inside the box is inside its own cell;
//   - every corner is a real vertex: on the box, or as near p as some ridge partner q.
void expect_valid(const PointCloud& points, const Voronoi& diagram, const ClippedCells& cells, const std::string& context) {
  SCOPED_TRACE(context);
  const int d = points.dim;
  ASSERT_EQ(cells.dim, d);
  ASSERT_EQ(cells.size(), diagram.regions.size());
  ASSERT_EQ(cells.volumes.size(), cells.size());
  double size = 0;  // the box's largest extent
  for (int k = 0; k < d; ++k) size = std::max(size, cells.box.upper[static_cast<std::size_t>(k)] - cells.box.lower[static_cast<std::size_t>(k)]);
  const double tol = 1e-10 * size;
  const auto partners = partners_of(diagram);
  double total = 0;
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const auto i = static_cast<std::size_t>(diagram.region_point[c]);
    const Vec p = point_of(points, i);
    const auto first = static_cast<std::size_t>(cells.cell_faces[c]), last = static_cast<std::size_t>(cells.cell_faces[c + 1]);
    ASSERT_GE(cells.volumes[c], 0.0) << "cell " << c;
    total += cells.volumes[c];
    if (first == last) {
      EXPECT_EQ(cells.volumes[c], 0.0) << "empty cell " << c;
      EXPECT_FALSE(inside_box(points, i, cells.box)) << "empty cell " << c << " of a point inside the box";
      continue;
    }
    const std::set<std::int32_t> corners = cell_corners(cells, c);
    const Vec centre = centroid(cells, corners);
    if (d == 2) {
      ASSERT_EQ(last - first, 1u) << "cell " << c;
      EXPECT_NEAR(newell(cells, first)[2] / 2, cells.volumes[c], 1e-12 * size * size) << "cell " << c;
      EXPECT_GT(cells.volumes[c], 0.0) << "cell " << c << ": the loop is clockwise";
    } else {
      double six = 0;  // six times the volume, from the faces
      std::multiset<std::pair<std::int32_t, std::int32_t>> edges;
      for (std::size_t f = first; f < last; ++f) {
        const std::int32_t* loop = cells.faces.row(f);
        const std::size_t k = cells.faces.row_size(f);
        ASSERT_GE(k, 3u) << "cell " << c;
        const Vec n = newell(cells, f);
        EXPECT_GT(dot(n, sub(corner(cells, loop[0]), centre)), 0.0) << "cell " << c << " face " << f << " runs clockwise";
        six += dot(n, sub(corner(cells, loop[0]), centre));
        for (std::size_t j = 0; j < k; ++j) edges.insert({loop[j], loop[(j + 1) % k]});
      }
      EXPECT_NEAR(six / 6, cells.volumes[c], 1e-12 * size * size * size) << "cell " << c;
      for (const auto& e : edges)
        EXPECT_EQ(edges.count({e.second, e.first}), 1u) << "cell " << c << ": edge " << e.first << "-" << e.second << " is not closed";
    }
    if (inside_box(points, i, cells.box))
      for (std::size_t f = first; f < last; ++f) {
        const Vec n = d == 2 ? Vec{0, 0, 1} : newell(cells, f);
        const std::int32_t* loop = cells.faces.row(f);
        for (std::size_t j = 0; d == 2 && j < cells.faces.row_size(f); ++j) {  // 2D: p left of every edge
          const Vec a = corner(cells, loop[j]), b = corner(cells, loop[(j + 1) % cells.faces.row_size(f)]);
          EXPECT_GE(cross(sub(b, a), sub(p, a))[2], -tol * norm(sub(b, a))) << "cell " << c << " misses its point";
        }
        if (d == 3) {
          EXPECT_LE(dot(n, sub(p, corner(cells, loop[0]))), tol * norm(n)) << "cell " << c << " misses its point";
        }
      }
    for (const std::int32_t v : corners) {
      const Vec x = corner(cells, v);
      bool real = false;
      for (int k = 0; k < d && !real; ++k)
        real = std::fabs(x[static_cast<std::size_t>(k)] - cells.box.lower[static_cast<std::size_t>(k)]) <= tol ||
               std::fabs(x[static_cast<std::size_t>(k)] - cells.box.upper[static_cast<std::size_t>(k)]) <= tol;
      for (std::size_t j = 0; j < partners[i].size() && !real; ++j)
        real = std::fabs(norm(sub(x, p)) - norm(sub(x, point_of(points, static_cast<std::size_t>(partners[i][j]))))) <= tol;
      EXPECT_TRUE(real) << "cell " << c << ": corner " << v << " is neither on the box nor on a bisector";
    }
  }
  EXPECT_NEAR(total, box_volume(cells.box), 1e-9 * box_volume(cells.box));
}

// Random points of every kind, in the box with a margin and in their bounding box (whose
// sides pass through the extreme points).
void expect_tiling(int d, std::initializer_list<std::size_t> sizes) {
  const std::pair<Distribution, const char*> kinds[] = {
      {Distribution::Uniform, "uniform"}, {Distribution::Gaussian, "gaussian"}, {Distribution::Clustered, "clustered"}};
  for (const auto& [distribution, name] : kinds)
    for (const std::size_t n : sizes) {
      const PointCloud points = drange::generate_points(distribution, n, d, 7);
      const Voronoi diagram = drange::voronoi(points);
      const std::string context = std::string(name) + " n=" + std::to_string(n) + " d=" + std::to_string(d) + " seed 7";
      for (const double margin : {0.1, 0.0})
        expect_valid(points, diagram, drange::clip_cells(points, diagram, drange::default_clip_box(points, margin)),
                     context + " margin " + std::to_string(margin));
    }
}

TEST(ClipCells, TilesTheBox2D) { expect_tiling(2, {10, 200, 2000}); }
TEST(ClipCells, TilesTheBox3D) { expect_tiling(3, {10, 200, 1000}); }

// A box well inside the cloud: most points lie outside it, their cells cut or missing it.
TEST(ClipCells, BoxInsideTheCloud) {
  for (const int d : {2, 3}) {
    const PointCloud points = drange::generate_points(Distribution::Gaussian, 500, d, 3);
    const Voronoi diagram = drange::voronoi(points);
    const ClippedCells cells = drange::clip_cells(points, diagram, cube(d, -0.5, 0.5));
    expect_valid(points, diagram, cells, "gaussian 500 in [-0.5, 0.5]^d, d=" + std::to_string(d));
    std::size_t empty = 0;
    for (std::size_t c = 0; c < cells.size(); ++c) empty += cells.cell_faces[c] == cells.cell_faces[c + 1];
    EXPECT_GT(empty, 100u);
  }
}

// The cells from the diagram's ridges equal the brute-force cells (all pairs): the same
// volumes and the same corners. Also the degeneracy test: most bisectors of the brute force
// do not bound the cell, and on the grid many pass exactly through its corners.
TEST(ClipCells, RidgesAgreeWithAllPairs) {
  struct Input {
    PointCloud points;
    std::string name;
  };
  const Input inputs[] = {{drange::generate_points(Distribution::Uniform, 300, 2, 11), "uniform 2D"},
                          {drange::generate_points(Distribution::Clustered, 300, 2, 11), "clustered 2D"},
                          {grid(2, 9), "grid 9x9"},
                          {drange::generate_points(Distribution::Uniform, 200, 3, 11), "uniform 3D"},
                          {grid(3, 5), "grid 5^3"}};
  for (const Input& input : inputs) {
    SCOPED_TRACE(input.name);
    const Box box = drange::default_clip_box(input.points, 0.1);
    const Voronoi diagram = drange::voronoi(input.points);
    const Voronoi brute = all_pairs_diagram(input.points);
    const ClippedCells cells = drange::clip_cells(input.points, diagram, box);
    const ClippedCells reference = drange::clip_cells(input.points, brute, box);
    expect_valid(input.points, brute, reference, input.name + " all pairs");
    ASSERT_EQ(cells.size(), reference.size());
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const auto i = static_cast<std::size_t>(diagram.region_point[c]);  // brute force: region i is point i
      EXPECT_NEAR(cells.volumes[c], reference.volumes[i], 1e-12 * box_volume(box)) << "cell of point " << i;
      std::vector<Vec> mine, theirs;
      for (const std::int32_t v : cell_corners(cells, c)) mine.push_back(corner(cells, v));
      for (const std::int32_t v : cell_corners(reference, i)) theirs.push_back(corner(reference, v));
      ASSERT_EQ(mine.size(), theirs.size()) << "cell of point " << i;
      for (const Vec& x : mine) {
        double nearest = std::numeric_limits<double>::infinity();
        for (const Vec& y : theirs) nearest = std::min(nearest, norm(sub(x, y)));
        EXPECT_LT(nearest, 1e-12) << "cell of point " << i;
      }
    }
  }
}

// The integer grid in the half-integer box: every cell is a unit square or cube, with exactly
// its 4 or 8 corners, whichever diagram (the true one, or all pairs with the diagonal
// neighbours' bisectors through the corners).
TEST(ClipCells, GridCellsAreUnitSquaresAndCubes) {
  for (const int d : {2, 3})
    for (const double h : {1.0, 0.1, 1.0 / 3})
    for (const bool brute : {false, true}) {
      const int k = d == 2 ? 5 : 4;
      const PointCloud points = grid(d, k, h);
      const Box box = cube(d, -0.5 * h, (k - 0.5) * h);
      SCOPED_TRACE("d=" + std::to_string(d) + " spacing " + std::to_string(h) + (brute ? " all pairs" : " voronoi"));
      const Voronoi diagram = brute ? all_pairs_diagram(points) : drange::voronoi(points);
      const ClippedCells cells = drange::clip_cells(points, diagram, box);
      expect_valid(points, diagram, cells, "grid");
      ASSERT_EQ(cells.size(), points.size());
      EXPECT_EQ(cells.points.size(), points.size() * (d == 2 ? 4u : 8u) * static_cast<std::size_t>(d));
      for (std::size_t c = 0; c < cells.size(); ++c) {
        const Vec p = point_of(points, static_cast<std::size_t>(diagram.region_point[c]));
        EXPECT_NEAR(cells.volumes[c], std::pow(h, d), 1e-12) << "cell " << c;
        ASSERT_EQ(cells.cell_faces[c + 1] - cells.cell_faces[c], d == 2 ? 1 : 6) << "cell " << c;
        for (auto f = static_cast<std::size_t>(cells.cell_faces[c]); f < static_cast<std::size_t>(cells.cell_faces[c + 1]); ++f)
          EXPECT_EQ(cells.faces.row_size(f), 4u) << "cell " << c;
        const std::set<std::int32_t> corners = cell_corners(cells, c);
        ASSERT_EQ(corners.size(), d == 2 ? 4u : 8u) << "cell " << c;
        for (const std::int32_t v : corners)
          for (int j = 0; j < d; ++j)
            EXPECT_NEAR(std::fabs(corner(cells, v)[static_cast<std::size_t>(j)] - p[static_cast<std::size_t>(j)]), 0.5 * h, 1e-12) << "cell " << c;
      }
    }
}

// A box through the grid points cuts the border cells in half and the corner cells in
// quarters (eighths in 3D): volume 2^-(number of axes on which the point is on the box).
TEST(ClipCells, BoxThroughTheGridPointsHalvesTheBorderCells) {
  for (const int d : {2, 3}) {
    const int k = d == 2 ? 5 : 4;
    const PointCloud points = grid(d, k);
    const Box box = cube(d, 0, k - 1);
    for (const bool brute : {false, true}) {
      SCOPED_TRACE("d=" + std::to_string(d) + (brute ? " all pairs" : " voronoi"));
      const Voronoi diagram = brute ? all_pairs_diagram(points) : drange::voronoi(points);
      const ClippedCells cells = drange::clip_cells(points, diagram, box);
      expect_valid(points, diagram, cells, "grid, box through the points");
      for (std::size_t c = 0; c < cells.size(); ++c) {
        const Vec p = point_of(points, static_cast<std::size_t>(diagram.region_point[c]));
        int on_box = 0;
        for (int j = 0; j < d; ++j) on_box += p[static_cast<std::size_t>(j)] == 0 || p[static_cast<std::size_t>(j)] == k - 1;
        EXPECT_NEAR(cells.volumes[c], std::ldexp(1.0, -on_box), 1e-12) << "cell " << c;
        EXPECT_EQ(cell_corners(cells, c).size(), d == 2 ? 4u : 8u) << "cell " << c;
      }
    }
  }
}

// Nearly degenerate: a grid moved by amounts near the tolerance and far above it. Every cell
// must stay valid (closed, counter-clockwise, tiling) whatever the tolerance decides.
TEST(ClipCells, PerturbedGrids) {
  for (const int d : {2, 3})
    for (const double amount : {1e-14, 1e-12, 1e-10, 1e-6}) {
      PointCloud points = grid(d, d == 2 ? 6 : 4);
      const PointCloud noise = drange::generate_points(Distribution::Uniform, points.size(), d, 5);
      for (std::size_t j = 0; j < points.coords.size(); ++j) points.coords[j] += amount * (noise.coords[j] - 0.5);
      const Box box = cube(d, -0.5, (d == 2 ? 6 : 4) - 0.5);
      const std::string context = "d=" + std::to_string(d) + " moved by " + std::to_string(amount);
      expect_valid(points, all_pairs_diagram(points), drange::clip_cells(points, all_pairs_diagram(points), box), context + " all pairs");
      const Voronoi diagram = drange::voronoi(points);
      expect_valid(points, diagram, drange::clip_cells(points, diagram, box), context);
    }
}

// Far from the origin: the cells are computed relative to their points, so an offset of 1e6
// loses nothing at the scale of the cells.
TEST(ClipCells, FarFromTheOrigin) {
  for (const int d : {2, 3}) {
    PointCloud points = grid(d, 4);
    for (double& x : points.coords) x += 1e6;
    const Voronoi diagram = all_pairs_diagram(points);
    const ClippedCells cells = drange::clip_cells(points, diagram, cube(d, 1e6 - 0.5, 1e6 + 3.5));
    for (std::size_t c = 0; c < cells.size(); ++c) {
      EXPECT_NEAR(cells.volumes[c], 1.0, 1e-9) << "d=" << d << " cell " << c;
      EXPECT_EQ(cell_corners(cells, c).size(), d == 2 ? 4u : 8u) << "d=" << d << " cell " << c;
    }
  }
}

// The tolerance is relative: the same points scaled by 1e-9 or 1e9 give the same cells, scaled.
TEST(ClipCells, ScaleInvariant) {
  for (const int d : {2, 3}) {
    const PointCloud points = drange::generate_points(Distribution::Clustered, 300, d, 4);
    const Voronoi diagram = drange::voronoi(points);
    const Box box = drange::default_clip_box(points, 0.1);
    const ClippedCells reference = drange::clip_cells(points, diagram, box);
    for (const double scale : {1e-9, 1e9}) {
      PointCloud scaled = points;
      for (double& x : scaled.coords) x *= scale;
      Box scaled_box = box;
      for (int k = 0; k < d; ++k) {
        scaled_box.lower[static_cast<std::size_t>(k)] *= scale;
        scaled_box.upper[static_cast<std::size_t>(k)] *= scale;
      }
      const ClippedCells cells = drange::clip_cells(scaled, diagram, scaled_box);
      expect_valid(scaled, diagram, cells, "d=" + std::to_string(d) + " scaled by " + std::to_string(scale));
      ASSERT_EQ(cells.points.size(), reference.points.size()) << "d=" << d << " scale " << scale;
      for (std::size_t c = 0; c < cells.size(); ++c)
        EXPECT_NEAR(cells.volumes[c] / std::pow(scale, d), reference.volumes[c], 1e-12 * box_volume(box)) << "d=" << d << " cell " << c;
    }
  }
}

TEST(ClipCells, OnePointFillsTheBoxAndAnOutsidePointsCellCanMissIt) {
  // Two points: the bisector x = 5 splits the box [0, 4] x [0, 1] nowhere, so the outer
  // point's cell misses it.
  const PointCloud points{2, {1, 0.5, 9, 0.5}};
  const Voronoi diagram = all_pairs_diagram(points);
  const ClippedCells cells = drange::clip_cells(points, diagram, Box{{0, 0}, {4, 1}});
  ASSERT_EQ(cells.size(), 2u);
  EXPECT_DOUBLE_EQ(cells.volumes[0], 4.0);
  EXPECT_EQ(cells.volumes[1], 0.0);
  EXPECT_EQ(cells.cell_faces[2], cells.cell_faces[1]);
  // The bisector exactly on the box's side: the outer cell is flat, hence empty.
  const ClippedCells touching = drange::clip_cells(points, diagram, Box{{0, 0}, {5, 1}});
  EXPECT_DOUBLE_EQ(touching.volumes[0], 5.0);
  EXPECT_EQ(touching.cell_faces[2], touching.cell_faces[1]);
}

TEST(ClipCells, DuplicatesShareTheirOriginalsCell) {
  // Point 2 copies point 0; the diagram has regions for the distinct points only.
  const PointCloud points{2, {0, 0, 1, 0, 0, 0, 0, 1}};
  const Voronoi diagram = drange::voronoi(points);
  ASSERT_EQ(diagram.regions.size(), 3u);
  const ClippedCells cells = drange::clip_cells(points, diagram, Box{{-1, -1}, {2, 2}});
  expect_valid(points, diagram, cells, "duplicates");
}

// Corners a rounding apart in the cell's own frame can become one double far from the origin,
// and must then be listed once: every corner of a cell is distinct, and every face loop has at
// least 3 corners and no zero-length edge.
void expect_distinct_corners(const PointCloud& points) {
  const Voronoi diagram = voronoi(points);
  const ClippedCells cells = clip_cells(points, diagram, default_clip_box(points));
  const auto d = static_cast<std::size_t>(points.dim);
  for (std::size_t c = 0; c < cells.size(); ++c) {
    std::set<std::vector<double>> corners;
    std::set<std::int32_t> used;
    for (auto f = static_cast<std::size_t>(cells.cell_faces[c]); f < static_cast<std::size_t>(cells.cell_faces[c + 1]); ++f) {
      const std::size_t n = cells.faces.row_size(f);
      EXPECT_GE(n, 3u) << "cell " << c << " face " << f;
      for (std::size_t i = 0; i < n; ++i) {
        EXPECT_NE(cells.faces.row(f)[i], cells.faces.row(f)[(i + 1) % n]) << "cell " << c << " face " << f;
        used.insert(cells.faces.row(f)[i]);
      }
    }
    for (const std::int32_t v : used)
      corners.insert(std::vector<double>(cells.points.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(v) * d),
                                         cells.points.begin() + static_cast<std::ptrdiff_t>((static_cast<std::size_t>(v) + 1) * d)));
    EXPECT_EQ(corners.size(), used.size()) << "cell " << c << " lists a corner twice";
  }
}

TEST(ClipCells, FarCellsListEveryCornerOnce) {
  // A floating-point regular pentagon around (1e6, 1e6): its five vertices are cocircular up
  // to rounding, so the Voronoi vertices lie 1e-10 apart.
  expect_distinct_corners(PointCloud{2, {1000003.0, 1000000.0, 1000000.9270509831, 1000002.8531695489,
                                         999997.5729490169, 1000001.7633557569, 999997.5729490169,
                                         999998.2366442431, 1000000.9270509831, 999997.1468304511}});
  // The same in 3D: points of a sphere of radius 4.5 around (1e6 + 1.5, ...), rounded.
  PointCloud sphere{3, {}};
  for (int i = 0; i < 40; ++i) {
    const double z = -1 + (2.0 * i + 1) / 40, r = std::sqrt(1 - z * z), a = 2.399963229728653 * i;
    sphere.coords.insert(sphere.coords.end(), {1e6 + 4.5 * r * std::cos(a), 1e6 + 4.5 * r * std::sin(a), 1e6 + 4.5 * z});
  }
  expect_distinct_corners(sphere);
}

TEST(ClipCells, RefusesBadArguments) {
  const PointCloud points = drange::generate_points(Distribution::Uniform, 20, 2, 1);
  const Voronoi diagram = all_pairs_diagram(points);
  auto message = [&](const Box& box) {
    try {
      drange::clip_cells(points, diagram, box);
    } catch (const drange::UsageError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  EXPECT_NE(message(Box{{0, 0, 0}, {1, 1, 1}}).find("box has dimension 3"), std::string::npos) << message(Box{{0, 0, 0}, {1, 1, 1}});
  EXPECT_NE(message(Box{{0, 0}, {1}}).find("dimension"), std::string::npos);
  EXPECT_NE(message(Box{{0, 1}, {1, 1}}).find("empty on axis 1"), std::string::npos) << message(Box{{0, 1}, {1, 1}});
  EXPECT_NE(message(Box{{0, 2}, {1, 1}}).find("empty on axis 1"), std::string::npos);
  EXPECT_NE(message(Box{{nan, 0}, {1, 1}}).find("not finite on axis 0"), std::string::npos) << message(Box{{nan, 0}, {1, 1}});
  EXPECT_NE(message(Box{{0, 0}, {1, inf}}).find("not finite on axis 1"), std::string::npos);

  const PointCloud four = drange::generate_points(Distribution::Uniform, 10, 4, 1);
  try {
    drange::clip_cells(four, all_pairs_diagram(four), cube(4, 0, 1));
    ADD_FAILURE() << "d=4 accepted";
  } catch (const drange::UsageError& e) {
    EXPECT_EQ(std::string(e.what()), "clipped cells are computed in 2D and 3D; the points have dimension 4");
  }
  const PointCloud other = drange::generate_points(Distribution::Uniform, 21, 2, 1);
  EXPECT_THROW(drange::clip_cells(other, diagram, cube(2, 0, 1)), drange::UsageError);
}

TEST(DefaultClipBox, EnlargesTheBoundingBox) {
  const PointCloud points{2, {0, 1, 4, 3, 2, 2}};
  const Box box = drange::default_clip_box(points, 0.25);
  EXPECT_EQ(box.lower, (std::vector<double>{-1, 0.5}));
  EXPECT_EQ(box.upper, (std::vector<double>{5, 3.5}));
  const Box tight = drange::default_clip_box(points, 0);
  EXPECT_EQ(tight.lower, (std::vector<double>{0, 1}));
  EXPECT_EQ(tight.upper, (std::vector<double>{4, 3}));
  // A flat axis borrows the largest extent; a single point gets 1.
  const Box flat = drange::default_clip_box(PointCloud{2, {0, 7, 2, 7}}, 0.5);
  EXPECT_EQ(flat.lower, (std::vector<double>{-1, 6}));
  EXPECT_EQ(flat.upper, (std::vector<double>{3, 8}));
  const Box single = drange::default_clip_box(PointCloud{3, {1, 2, 3}}, 0.5);
  EXPECT_EQ(single.lower, (std::vector<double>{0.5, 1.5, 2.5}));
  const Box single_tight = drange::default_clip_box(PointCloud{2, {1, 2}}, 0);
  EXPECT_LT(single_tight.lower[0], single_tight.upper[0]);
  EXPECT_THROW(drange::default_clip_box(points, -0.1), drange::UsageError);
  EXPECT_THROW(drange::default_clip_box(PointCloud{2, {}}, 0.1), drange::UsageError);
}

}  // namespace
