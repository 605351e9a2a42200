// Tests of drange::voronoi_cells: each asked-for point's cell equals the whole diagram's cell
// for that point (its vertices as coordinates, boundedness, volume, and each ridge's other
// point and vertices), on random input in 2D to 4D and on integer grids (cospherical simplices
// merged into one vertex, hull points); the other points have no region; bad ids are named.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <sstream>

#include "drange/errors.hpp"
#include "drange/formats.hpp"
#include "drange/generate.hpp"
#include "drange/voronoi.hpp"

namespace drange {
namespace {

using Coords = std::vector<std::vector<double>>;

// The coordinates of the vertex ids (-1 skipped), sorted.
Coords coordinates(const Voronoi& v, const std::int32_t* ids, std::size_t count) {
  Coords out;
  for (std::size_t i = 0; i < count; ++i)
    if (ids[i] >= 0) out.emplace_back(v.vertex(static_cast<std::size_t>(ids[i])), v.vertex(static_cast<std::size_t>(ids[i])) + v.dim);
  std::sort(out.begin(), out.end());
  return out;
}

bool has_infinity(const std::int32_t* ids, std::size_t count) { return std::find(ids, ids + count, -1) != ids + count; }

void expect_same_coordinates(const Coords& a, const Coords& b, const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t k = 0; k < a[i].size(); ++k) EXPECT_NEAR(a[i][k], b[i][k], 1e-9 * (1 + std::fabs(a[i][k]))) << what;
}

// The ridges of point p: the other point -> (bounded?, vertex coordinates).
std::map<std::int32_t, std::pair<bool, Coords>> ridges_of(const Voronoi& v, std::int32_t p) {
  std::map<std::int32_t, std::pair<bool, Coords>> out;
  for (std::size_t r = 0; r < v.num_ridges(); ++r) {
    const std::int32_t a = v.ridge_points[2 * r], b = v.ridge_points[2 * r + 1];
    if (a != p && b != p) continue;
    const std::int32_t* ids = v.ridge_vertices.row(r);
    const std::size_t n = v.ridge_vertices.row_size(r);
    out[a == p ? b : a] = {!has_infinity(ids, n), coordinates(v, ids, n)};
  }
  return out;
}

void expect_cells_match(const PointCloud& points, const std::vector<std::int64_t>& ids, const std::string& name) {
  const Voronoi full = voronoi(points);
  const Voronoi part = voronoi_cells(points, ids);
  std::vector<char> asked(points.size(), 0);
  for (const std::int64_t id : ids) asked[static_cast<std::size_t>(id)] = 1;
  std::size_t kept = 0;
  for (std::size_t p = 0; p < points.size(); ++p) {
    const std::string what = name + " point " + std::to_string(p);
    if (!asked[p]) {
      // Only an asked-for point's copies or original may share its region.
      if (part.point_region[p] >= 0) {
        bool shares = false;
        for (const std::int64_t id : ids) shares |= full.point_region[static_cast<std::size_t>(id)] == full.point_region[p];
        EXPECT_TRUE(shares) << what;
      }
      continue;
    }
    ASSERT_GE(part.point_region[p], 0) << what;
    ++kept;
    const auto fr = static_cast<std::size_t>(full.point_region[p]);
    const auto pr = static_cast<std::size_t>(part.point_region[p]);
    EXPECT_EQ(part.region_point[pr], full.region_point[fr]) << what;
    const bool full_open = has_infinity(full.regions.row(fr), full.regions.row_size(fr));
    EXPECT_EQ(has_infinity(part.regions.row(pr), part.regions.row_size(pr)), full_open) << what;
    expect_same_coordinates(coordinates(full, full.regions.row(fr), full.regions.row_size(fr)),
                            coordinates(part, part.regions.row(pr), part.regions.row_size(pr)), what + " vertices");
    if (full_open) {
      EXPECT_TRUE(std::isinf(part.volumes[pr])) << what;
    } else {
      EXPECT_NEAR(part.volumes[pr], full.volumes[fr], 1e-9 * full.volumes[fr]) << what;
    }
    const auto owner = static_cast<std::int32_t>(full.region_point[fr]);
    const auto expected = ridges_of(full, owner);
    const auto got = ridges_of(part, owner);
    ASSERT_EQ(got.size(), expected.size()) << what;
    for (const auto& [q, ridge] : expected) {
      ASSERT_EQ(got.count(q), 1u) << what << " ridge to " << q;
      EXPECT_EQ(got.at(q).first, ridge.first) << what << " ridge to " << q;
      expect_same_coordinates(ridge.second, got.at(q).second, what + " ridge to " + std::to_string(q));
    }
  }
  EXPECT_GT(kept, 0u);
  // Every ridge kept has an asked-for cell at one end.
  for (std::size_t r = 0; r < part.num_ridges(); ++r)
    EXPECT_TRUE(part.point_region[static_cast<std::size_t>(part.ridge_points[2 * r])] >= 0 ||
                part.point_region[static_cast<std::size_t>(part.ridge_points[2 * r + 1])] >= 0);
}

std::vector<std::int64_t> spread_ids(std::size_t n, std::size_t count) {
  std::vector<std::int64_t> ids;
  for (std::size_t i = 0; i < count; ++i) ids.push_back(static_cast<std::int64_t>((i * 7919 + 3) % n));
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  ids.push_back(static_cast<std::int64_t>(n - 1) == ids.back() ? 0 : static_cast<std::int64_t>(n - 1));
  if (std::count(ids.begin(), ids.end(), ids.back()) > 1) ids.pop_back();
  return ids;
}

TEST(VoronoiCells, RandomCellsEqualTheWholeDiagrams) {
  for (const auto& [n, d] : std::vector<std::pair<std::size_t, int>>{{400, 2}, {300, 3}, {150, 4}}) {
    for (const Distribution distribution : {Distribution::Uniform, Distribution::Gaussian}) {
      const PointCloud points = generate_points(distribution, n, d, 11);
      expect_cells_match(points, spread_ids(n, 25), std::to_string(d) + "D random");
    }
  }
}

// Every interior grid cell merges many simplices into each vertex; the corners and faces of
// the grid are hull points with unbounded cells.
TEST(VoronoiCells, GridCellsEqualTheWholeDiagrams) {
  for (const auto& [k, d] : std::vector<std::pair<int, int>>{{7, 2}, {5, 3}, {4, 4}}) {
    const std::size_t n = static_cast<std::size_t>(std::pow(k, d));
    const PointCloud points = generate_points(Distribution::Grid, n, d, 1);
    std::vector<std::int64_t> ids;
    for (std::size_t p = 0; p < n; p += 3) ids.push_back(static_cast<std::int64_t>(p));
    expect_cells_match(points, ids, std::to_string(d) + "D grid");
    expect_cells_match(points, {static_cast<std::int64_t>(n / 2)}, std::to_string(d) + "D grid centre");
  }
}

TEST(VoronoiCells, DuplicateIdGivesTheOriginalsCell) {
  PointCloud points = generate_points(Distribution::Uniform, 100, 2, 5);
  points.coords.insert(points.coords.end(), points.coords.begin() + 2 * 10, points.coords.begin() + 2 * 11);  // 100 copies 10
  expect_cells_match(points, {100, 40}, "duplicate");
  const Voronoi part = voronoi_cells(points, {100});
  EXPECT_EQ(part.regions.size(), 1u);
  EXPECT_EQ(part.point_region[10], part.point_region[100]);
}

// The `qvoronoi o` layout has a line per input point; it refuses a diagram of some cells.
TEST(VoronoiCells, QhullLayoutIsRefused) {
  const PointCloud points = generate_points(Distribution::Uniform, 50, 2, 3);
  std::ostringstream out;
  EXPECT_THROW(write_qvoronoi_o(out, voronoi_cells(points, {4})), UsageError);
  write_qvoronoi_fv(out, voronoi_cells(points, {4}));  // the ridges alone are fine
  EXPECT_NE(out.str(), "");
}

TEST(VoronoiCells, BadIdsAreNamed) {
  const PointCloud points = generate_points(Distribution::Uniform, 50, 3, 2);
  try {
    voronoi_cells(points, {3, 50});
    FAIL() << "no error for an id out of range";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("50"), std::string::npos) << e.what();
  }
  try {
    voronoi_cells(points, {7, 7});
    FAIL() << "no error for an id given twice";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("7"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace drange
