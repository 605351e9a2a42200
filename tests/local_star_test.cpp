// Tests of drange::delaunay_stars (src/delaunay/local_star.*, stars.cpp): the stars of given
// points equal the corresponding part of the full triangulation, vertex set for vertex set, on
// random and degenerate inputs, hull points included; the neighbours among them; the errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "drange/delaunay.hpp"
#include "drange/errors.hpp"
#include "drange/generate.hpp"
#include "geometry/predicates.hpp"
#include "triangulation_checks.hpp"

namespace {

using drange::Distribution;
using drange::PointCloud;
using drange::Triangulation;
using Ids = std::vector<std::int64_t>;
using VertexSet = std::vector<std::int32_t>;

VertexSet sorted_row(const Triangulation& t, std::size_t s) {
  VertexSet v(t.simplex(s), t.simplex(s) + t.dim + 1);
  std::sort(v.begin(), v.end());
  return v;
}

// The point each id stands for in the triangulation: itself, or the point a duplicate copies.
std::int32_t kept_point(const Triangulation& full, std::int64_t id) {
  for (const drange::Duplicate& dup : full.duplicates)
    if (dup.index == id) return static_cast<std::int32_t>(dup.original);
  return static_cast<std::int32_t>(id);
}

// Compares delaunay_stars(points, ids) with the simplices of `full` incident to the ids: the
// same vertex sets, none twice, each positive, and neighbour k the returned simplex across the
// facet opposite vertex k when the full triangulation has it there and it is returned, else -1.
void expect_stars(const PointCloud& points, const Triangulation& full, const Ids& ids, const std::string& what) {
  const Triangulation stars = drange::delaunay_stars(points, ids);
  const int d = full.dim;
  std::set<std::int32_t> wanted;
  for (const std::int64_t id : ids) wanted.insert(kept_point(full, id));
  std::set<VertexSet> expected;
  std::map<VertexSet, std::size_t> full_index;
  for (std::size_t s = 0; s < full.size(); ++s) {
    const VertexSet v = sorted_row(full, s);
    full_index[v] = s;
    if (std::any_of(v.begin(), v.end(), [&](std::int32_t x) { return wanted.count(x) != 0; })) expected.insert(v);
  }
  std::set<VertexSet> got;
  std::map<VertexSet, std::size_t> star_index;
  for (std::size_t s = 0; s < stars.size(); ++s) {
    const VertexSet v = sorted_row(stars, s);
    EXPECT_TRUE(got.insert(v).second) << what << ": simplex " << s << " returned twice";
    star_index[v] = s;
    std::vector<const double*> p;
    for (int k = 0; k <= d; ++k) p.push_back(points.point(static_cast<std::size_t>(stars.simplex(s)[k])));
    EXPECT_GT(drange::geometry::simplex_orientation(d, p.data()), 0) << what << ": simplex " << s << " not positive";
  }
  ASSERT_EQ(got, expected) << what << ": " << got.size() << " simplices, expected " << expected.size();
  EXPECT_EQ(stars.stats.simplices, stars.size());
  EXPECT_EQ(stars.duplicates.size(), full.duplicates.size()) << what;
  ASSERT_EQ(stars.neighbors.size(), stars.simplices.size()) << what;
  for (std::size_t s = 0; s < stars.size(); ++s) {
    const std::size_t f = full_index.at(sorted_row(stars, s));
    for (int k = 0; k <= d; ++k) {
      const std::int32_t vertex = stars.simplex(s)[k];
      const std::int32_t* full_row = full.simplex(f);
      const auto at = static_cast<std::size_t>(std::find(full_row, full_row + d + 1, vertex) - full_row);
      const std::int32_t full_nb = full.neighbors[f * static_cast<std::size_t>(d + 1) + at];
      std::int32_t expected_nb = -1;
      if (full_nb >= 0) {
        const auto it = star_index.find(sorted_row(full, static_cast<std::size_t>(full_nb)));
        if (it != star_index.end()) expected_nb = static_cast<std::int32_t>(it->second);
      }
      EXPECT_EQ(stars.neighbors[s * static_cast<std::size_t>(d + 1) + static_cast<std::size_t>(k)], expected_nb)
          << what << ": simplex " << s << " neighbour " << k;
    }
  }
}

// `count` distinct ids of 0..n-1 in a random order, the first and last points always among them.
Ids some_ids(std::size_t n, std::size_t count, std::uint64_t seed) {
  Ids all(n);
  std::iota(all.begin(), all.end(), 0);
  std::mt19937_64 rng(seed);
  std::shuffle(all.begin() + 1, all.end() - 1, rng);
  Ids ids(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(std::min(count, n) - 1));
  ids.push_back(static_cast<std::int64_t>(n - 1));
  std::shuffle(ids.begin(), ids.end(), rng);
  return ids;
}

void expect_stars_family(const PointCloud& points, const std::string& what, std::uint64_t seed = 1) {
  const Triangulation full = drange::delaunay(points, drange::Options{});
  const std::size_t n = points.size();
  for (std::size_t id = 0; id < std::min<std::size_t>(n, 3); ++id) expect_stars(points, full, {static_cast<std::int64_t>(id)}, what + " single " + std::to_string(id));
  expect_stars(points, full, {static_cast<std::int64_t>(n / 2)}, what + " single middle");
  expect_stars(points, full, some_ids(n, 12, seed), what + " 12 ids");
  expect_stars(points, full, some_ids(n, n, seed + 1), what + " every id");
  // A region: the points left of the middle of the first axis (one wrapping, many stars).
  std::vector<double> first;
  for (std::size_t i = 0; i < n; ++i) first.push_back(points.point(i)[0]);
  std::nth_element(first.begin(), first.begin() + static_cast<std::ptrdiff_t>(n / 2), first.end());
  Ids left;
  for (std::size_t i = 0; i < n; ++i)
    if (points.point(i)[0] < first[n / 2]) left.push_back(static_cast<std::int64_t>(i));
  expect_stars(points, full, left, what + " left half");
}

// Integer points exactly on the sphere |x|^2 = r2 (many cospherical subsets, every one a tie).
PointCloud integer_sphere(int d, int r2) {
  PointCloud points{d, {}};
  const int r = static_cast<int>(std::sqrt(static_cast<double>(r2)));
  std::vector<int> x(static_cast<std::size_t>(d), -r);
  while (true) {
    int sum = 0;
    for (int c : x) sum += c * c;
    if (sum == r2)
      for (int c : x) points.coords.push_back(c);
    int i = 0;
    while (i < d && ++x[static_cast<std::size_t>(i)] > r) x[static_cast<std::size_t>(i++)] = -r;
    if (i == d) break;
  }
  return points;
}

// The integer points on the faces of the cube [0, k]^3.
PointCloud cube_faces(int k) {
  PointCloud points{3, {}};
  for (int x = 0; x <= k; ++x)
    for (int y = 0; y <= k; ++y)
      for (int z = 0; z <= k; ++z)
        if (x == 0 || x == k || y == 0 || y == k || z == 0 || z == k) points.coords.insert(points.coords.end(), {double(x), double(y), double(z)});
  return points;
}

TEST(LocalStars, UniformPointsTwoToFiveDimensions) {
  const std::size_t sizes[] = {0, 0, 3000, 2000, 600, 250};
  for (int d = 2; d <= 5; ++d)
    expect_stars_family(drange::generate_points(Distribution::Uniform, sizes[d], d, 7), "uniform " + std::to_string(d) + "D",
                        static_cast<std::uint64_t>(d));
}

TEST(LocalStars, IntegerGridsTwoToFourDimensions) {
  expect_stars_family(drange::test::checks::grid(2, 20), "grid 20^2");
  expect_stars_family(drange::test::checks::grid(3, 8), "grid 8^3");
  expect_stars_family(drange::test::checks::grid(4, 4), "grid 4^4");
}

TEST(LocalStars, CosphericalAndCubeFaces) {
  expect_stars_family(integer_sphere(2, 325), "integer circle r2=325");
  expect_stars_family(integer_sphere(3, 50), "integer sphere r2=50");
  expect_stars_family(integer_sphere(4, 12), "integer 3-sphere r2=12");
  expect_stars_family(cube_faces(5), "cube faces 5");
  expect_stars_family(drange::generate_points(Distribution::Sphere, 800, 3, 3), "sphere 3D");
}

TEST(LocalStars, ClusteredAndHighDimension) {
  expect_stars_family(drange::generate_points(Distribution::Clustered, 2000, 3, 5), "clustered 3D");
  expect_stars_family(drange::generate_points(Distribution::Uniform, 40, 7, 5), "uniform 7D");
  expect_stars_family(drange::generate_points(Distribution::Uniform, 20, 9, 5), "uniform 9D (any-d kernel)");
}

TEST(LocalStars, DuplicatesAnswerForThePointTheyCopy) {
  PointCloud points = drange::generate_points(Distribution::Uniform, 200, 3, 11);
  for (int copy = 0; copy < 3; ++copy) points.coords.insert(points.coords.end(), points.coords.begin() + 30, points.coords.begin() + 33);
  const Triangulation full = drange::delaunay(points);
  ASSERT_EQ(full.duplicates.size(), 3u);
  expect_stars(points, full, {201}, "a duplicate alone");
  expect_stars(points, full, Ids{10, 202, 199}, "a duplicate among others");
  // The duplicate and the point it copies: one star, listed once.
  const Triangulation both = drange::delaunay_stars(points, {10, 200});
  const Triangulation one = drange::delaunay_stars(points, {10});
  EXPECT_EQ(both.simplices, one.simplices);
}

TEST(LocalStars, NoIdsGiveNoSimplices) {
  const PointCloud points = drange::generate_points(Distribution::Uniform, 50, 2, 1);
  const Triangulation t = drange::delaunay_stars(points, {});
  EXPECT_EQ(t.size(), 0u);
  EXPECT_TRUE(t.neighbors.empty());
}

TEST(LocalStars, BadIdsAreNamed) {
  const PointCloud points = drange::generate_points(Distribution::Uniform, 50, 2, 1);
  const auto message = [&](const Ids& ids) {
    try {
      drange::delaunay_stars(points, ids);
    } catch (const drange::UsageError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message({3, 50}).find("point id 50 is out of range"), std::string::npos) << message({3, 50});
  EXPECT_NE(message({-1}).find("point id -1 is out of range"), std::string::npos);
  EXPECT_NE(message({4, 7, 4}).find("point id 4 is given twice"), std::string::npos);
  const PointCloud flat{2, {0, 0, 1, 1, 2, 2, 3, 3}};
  EXPECT_THROW(drange::delaunay_stars(flat, {0}), drange::DegenerateInputError);
}

}  // namespace

namespace {

TEST(DelaunayBlocks, EverySimplexInExactlyOneBlock) {
  const std::vector<std::pair<std::string, PointCloud>> cases = {
      {"uniform 2D", drange::generate_points(Distribution::Uniform, 3000, 2, 3)},
      {"clustered 3D", drange::generate_points(Distribution::Clustered, 2000, 3, 4)},
      {"grid 3D", drange::test::checks::grid(3, 7)},
      {"sphere 3D", drange::generate_points(Distribution::Sphere, 800, 3, 5)},
      {"uniform 4D", drange::generate_points(Distribution::Uniform, 400, 4, 6)},
  };
  for (const auto& [name, points] : cases) {
    const Triangulation full = drange::delaunay(points);
    const std::vector<VertexSet> whole = drange::test::checks::canonical(full);
    for (const int blocks : {1, 2, 3, 7}) {
      Triangulation joined;
      joined.dim = points.dim;
      joined.num_points = points.size();
      for (int b = 0; b < blocks; ++b) {
        const Triangulation part = drange::delaunay_block(points, b, blocks);
        EXPECT_TRUE(part.neighbors.empty());
        joined.simplices.insert(joined.simplices.end(), part.simplices.begin(), part.simplices.end());
      }
      // Sorted with repeats kept: a simplex in two blocks would show twice.
      EXPECT_EQ(drange::test::checks::canonical(joined), whole) << name << " blocks=" << blocks;
      drange::link_neighbours(joined);
      joined.stats.hull_facets = full.stats.hull_facets;  // the -1 neighbours must be as many
      drange::test::checks::expect_consistent_adjacency(points, joined);
    }
  }
  const PointCloud points = drange::generate_points(Distribution::Uniform, 50, 2, 1);
  EXPECT_THROW(drange::delaunay_block(points, 2, 2), drange::UsageError);
  EXPECT_THROW(drange::delaunay_block(points, 0, 0), drange::UsageError);
}

}  // namespace
