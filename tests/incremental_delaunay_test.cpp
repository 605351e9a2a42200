// Tests of drange::IncrementalDelaunay: after any sequence of add_points, the same simplices as
// delaunay() on all the points, valid and linked; duplicates as delaunay() reports them; bad
// batches refused without changing the triangulation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include "drange/delaunay.hpp"
#include "drange/errors.hpp"
#include "drange/generate.hpp"
#include "drange/hull.hpp"
#include "drange/incremental.hpp"
#include "oracle.hpp"
#include "triangulation_checks.hpp"

namespace {

using namespace drange::test::checks;
using drange::IncrementalDelaunay;
using drange::PointsView;

PointsView rows(const PointCloud& points, std::size_t begin, std::size_t end) {
  return PointsView(points.point(begin), end - begin, points.dim);
}

// Builds from the first `initial` points, then adds the rest `chunk` at a time.
IncrementalDelaunay grown(const PointCloud& points, std::size_t initial, std::size_t chunk) {
  IncrementalDelaunay t(rows(points, 0, initial));
  for (std::size_t i = initial; i < points.size(); i += chunk) t.add_points(rows(points, i, std::min(points.size(), i + chunk)));
  return t;
}

void expect_same_as_delaunay(const PointCloud& points, const Triangulation& grown_result, const std::string& what) {
  const Triangulation reference = drange::delaunay(points);
  EXPECT_EQ(canonical(grown_result), canonical(reference)) << what;
  ASSERT_EQ(grown_result.duplicates.size(), reference.duplicates.size()) << what;
  for (std::size_t i = 0; i < reference.duplicates.size(); ++i) {
    EXPECT_EQ(grown_result.duplicates[i].index, reference.duplicates[i].index) << what;
    EXPECT_EQ(grown_result.duplicates[i].original, reference.duplicates[i].original) << what;
  }
  EXPECT_EQ(grown_result.stats.hull_facets, reference.stats.hull_facets) << what;
  EXPECT_EQ(grown_result.stats.distinct_points, reference.stats.distinct_points) << what;
  expect_consistent_adjacency(points, grown_result);
}

TEST(IncrementalDelaunay, AnyChunkingGivesTheOneShotSimplices) {
  for (int d = 2; d <= 5; ++d) {
    const PointCloud points = drange::generate_points(Distribution::Uniform, d <= 3 ? 1500 : 300, d, 70 + d);
    for (const std::size_t chunk : {std::size_t{1}, std::size_t{7}, std::size_t{100000}}) {
      const IncrementalDelaunay t = grown(points, static_cast<std::size_t>(d + 2), chunk);
      EXPECT_EQ(t.size(), points.size());
      expect_same_as_delaunay(points, t.triangulation(), "d=" + std::to_string(d) + " chunk=" + std::to_string(chunk));
    }
  }
}

TEST(IncrementalDelaunay, DegenerateInputsGiveTheOneShotSimplices) {
  // Cospherical grids (every tie broken by the perturbation, whose order the later points
  // change), points on hull hyperplanes, spheres, and points added outside the hull so far.
  PointCloud growing_square{2, {}};
  for (int ring = 1; ring <= 6; ++ring)
    for (int i = -ring; i <= ring; ++i)
      growing_square.coords.insert(growing_square.coords.end(), {double(i), double(-ring), double(i), double(ring),
                                                                 double(-ring), double(i), double(ring), double(i)});
  const std::vector<std::pair<std::string, PointCloud>> cases = {
      {"grid 2D 12x12", grid(2, 12)},
      {"grid 3D 5^3", grid(3, 5)},
      {"grid 4D 3^4", grid(4, 3)},
      {"sphere 3D", drange::generate_points(Distribution::Sphere, 300, 3, 5)},
      {"squares growing outwards", growing_square},
  };
  for (const auto& [name, points] : cases)
    for (const std::size_t chunk : {std::size_t{1}, std::size_t{16}}) {
      // The grids' first third is flat: one point more spans them.
      const Triangulation t = grown(points, points.size() / 3 + 1, chunk).triangulation();
      expect_same_as_delaunay(points, t, name + " chunk=" + std::to_string(chunk));
      expect_valid(points, t, name);
    }
}

TEST(IncrementalDelaunay, DuplicatesAreReportedAsDelaunayReportsThem) {
  // Copies within the first points, within a batch, and of earlier points; -0.0 copies 0.0.
  const PointCloud points{2, {0, 0, 1, 0, 0, 1, 1, 0,        // 3 copies 1
                              2, 2, -0.0, 0.0, 3, 1, 2, 2,   // 5 copies 0, 7 copies 4
                              3, 1, 0.5, 0.25, 0.5, 0.25}};  // 8 copies 6, 10 copies 9
  IncrementalDelaunay t(rows(points, 0, 4));
  t.add_points(rows(points, 4, 8));
  t.add_points(rows(points, 8, 11));
  expect_same_as_delaunay(points, t.triangulation(), "duplicates");
}

TEST(IncrementalDelaunay, ScaleChangesKeepTheTriangulation) {
  // Later points far larger than the first (the kernel's scaled copy is redone), then points
  // so small that no power of two keeps every value normal (the unscaled predicates).
  PointCloud points = drange::generate_points(Distribution::Uniform, 200, 3, 9);
  for (std::size_t i = 100; i < 150; ++i)
    for (int k = 0; k < 3; ++k) points.coords[i * 3 + static_cast<std::size_t>(k)] *= 1e200;
  for (std::size_t i = 150; i < 155; ++i)
    for (int k = 0; k < 3; ++k) points.coords[i * 3 + static_cast<std::size_t>(k)] *= 1e-300;
  IncrementalDelaunay t(rows(points, 0, 100));
  t.add_points(rows(points, 100, 150));
  expect_same_as_delaunay(PointCloud{3, std::vector<double>(points.coords.begin(), points.coords.begin() + 450)},
                          t.triangulation(), "large points added");
  t.add_points(rows(points, 150, 200));
  expect_same_as_delaunay(points, t.triangulation(), "tiny points added");
}

TEST(IncrementalDelaunay, BadInputIsRefusedAndLeavesTheTriangulation) {
  EXPECT_THROW(IncrementalDelaunay(PointsView(std::vector<double>{0, 0, 1, 1, 2, 2}.data(), 3, 2)),
               drange::DegenerateInputError);
  EXPECT_THROW(IncrementalDelaunay(PointsView(std::vector<double>{0, 0, 1, 0, 0, 0}.data(), 3, 2)),
               drange::DegenerateInputError);
  const PointCloud points = drange::generate_points(Distribution::Uniform, 50, 2, 4);
  IncrementalDelaunay t(points);
  const std::vector<std::int32_t> before = t.triangulation().simplices;
  const std::vector<double> bad{0.5, 0.5, 0.25, std::numeric_limits<double>::quiet_NaN()};
  try {
    t.add_points(PointsView(bad.data(), 2, 2));
    ADD_FAILURE() << "no exception for a NaN";
  } catch (const drange::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("point 51, coordinate 1 is NaN"), std::string::npos) << e.what();
  }
  EXPECT_THROW(t.add_points(PointsView(bad.data(), 1, 3)), drange::InputError);
  EXPECT_EQ(t.size(), 50u);
  EXPECT_EQ(t.triangulation().simplices, before);
  t.add_points(PointsView(bad.data(), 0, 2));  // nothing to add
  EXPECT_EQ(t.size(), 50u);
}

}  // namespace

namespace {

// The volume of a simplex in doubles: |det[p_1 - p_0; ...]| / d!, by elimination.
double simplex_volume(const PointCloud& points, const std::vector<std::int32_t>& ids) {
  const int d = points.dim;
  std::vector<std::vector<double>> a(static_cast<std::size_t>(d), std::vector<double>(static_cast<std::size_t>(d)));
  for (int r = 0; r < d; ++r)
    for (int c = 0; c < d; ++c)
      a[r][c] = points.point(static_cast<std::size_t>(ids[r + 1]))[c] - points.point(static_cast<std::size_t>(ids[0]))[c];
  double det = 1.0;
  for (int c = 0; c < d; ++c) {
    int pivot = c;
    for (int r = c + 1; r < d; ++r)
      if (std::fabs(a[r][c]) > std::fabs(a[pivot][c])) pivot = r;
    std::swap(a[c], a[pivot]);
    if (a[c][c] == 0.0) return 0.0;
    det *= a[c][c];
    for (int r = c + 1; r < d; ++r) {
      const double f = a[r][c] / a[c][c];
      for (int k = c; k < d; ++k) a[r][k] -= f * a[c][k];
    }
  }
  for (int k = 2; k <= d; ++k) det /= k;
  return std::fabs(det);
}

// The furthest-site triangulation's defining properties, exactly: every simplex is positively
// oriented and its closed circumsphere holds every point; the simplices tile the convex hull
// (their volumes sum to the hull's, each hull facet is a facet of one simplex with no
// neighbour); the vertices are the hull's vertices.
void expect_furthest_site(const PointCloud& points, const Triangulation& t, const std::string& what) {
  const int d = points.dim;
  const drange::ConvexHull hull = drange::convex_hull(points);
  double volume = 0.0;
  std::set<std::int32_t> used;
  for (std::size_t s = 0; s < t.size(); ++s) {
    const std::vector<std::int32_t> ids(t.simplex(s), t.simplex(s) + d + 1);
    const std::vector<const double*> corner = drange::test::corners(points, ids);
    ASSERT_EQ(drange::test::reference_orientation(d, corner), 1) << what << " simplex " << s;
    for (std::size_t i = 0; i < points.size(); ++i)
      ASSERT_GE(drange::test::reference_in_sphere(d, corner, points.point(i)), 0) << what << " simplex " << s << " point " << i;
    used.insert(ids.begin(), ids.end());
    volume += simplex_volume(points, ids);
  }
  EXPECT_EQ(used, std::set<std::int32_t>(hull.vertices.begin(), hull.vertices.end())) << what;
  EXPECT_NEAR(volume, drange::hull_geometry(points, hull).volume, 1e-9 * volume) << what;
  expect_consistent_adjacency(points, t);
}

TEST(FurthestSite, RandomAndDegenerateInputs) {
  PointCloud square_and_centre{2, {0, 0, 1, 0, 0, 1, 1, 1, 0.5, 0.5}};
  const std::vector<std::pair<std::string, PointCloud>> cases = {
      {"uniform 2D", drange::generate_points(Distribution::Uniform, 200, 2, 1)},
      {"uniform 3D", drange::generate_points(Distribution::Uniform, 200, 3, 2)},
      {"uniform 4D", drange::generate_points(Distribution::Uniform, 80, 4, 3)},
      {"circle", drange::generate_points(Distribution::Sphere, 60, 2, 4)},
      {"sphere 3D", drange::generate_points(Distribution::Sphere, 60, 3, 5)},
      {"square and centre", square_and_centre},
      {"grid 2D 6x6", grid(2, 6)},
      {"grid 3D 4^3", grid(3, 4)},
  };
  for (const auto& [name, points] : cases) {
    const Triangulation whole = IncrementalDelaunay(points, true).triangulation();
    expect_furthest_site(points, whole, name);
    // Grown a point at a time (from a third of them, which spans E^d): the same simplices.
    const std::size_t initial = std::max(points.size() / 3 + 1, static_cast<std::size_t>(points.dim + 1));
    IncrementalDelaunay grown_one(rows(points, 0, initial), true);
    for (std::size_t i = initial; i < points.size(); ++i) grown_one.add_points(rows(points, i, i + 1));
    EXPECT_EQ(canonical(grown_one.triangulation()), canonical(whole)) << name;
  }
}

}  // namespace

namespace {

TEST(NaturalNeighbours, LinearPrecisionDataPointsOutsideAndErrors) {
  for (int d = 2; d <= 5; ++d) {
    const PointCloud points = drange::generate_points(Distribution::Uniform, d <= 3 ? 400 : 250, d, 90 + d);
    IncrementalDelaunay t(points);
    std::vector<double> queries;
    for (int i = 0; i < 8; ++i)
      for (int k = 0; k < d; ++k) queries.push_back(0.3 + 0.05 * i + 0.01 * k);  // inside: the cube's middle
    queries.insert(queries.end(), points.point(7), points.point(7) + d);  // a data point
    queries.insert(queries.end(), static_cast<std::size_t>(d), 2.0);      // outside the hull
    const auto found = t.natural_neighbours(PointsView(queries.data(), 10, d));
    ASSERT_EQ(found.offsets.size(), 11u);
    for (std::size_t q = 0; q < 8; ++q) {
      std::vector<double> centre(static_cast<std::size_t>(d), 0.0);
      double total = 0.0;
      for (std::size_t i = found.offsets[q]; i < found.offsets[q + 1]; ++i) {
        EXPECT_GT(found.weights[i], 0.0);
        total += found.weights[i];
        for (int k = 0; k < d; ++k) centre[static_cast<std::size_t>(k)] += found.weights[i] * points.point(static_cast<std::size_t>(found.ids[i]))[k];
      }
      EXPECT_NEAR(total, 1.0, 1e-12) << "d=" << d;
      for (int k = 0; k < d; ++k) EXPECT_NEAR(centre[static_cast<std::size_t>(k)], queries[q * static_cast<std::size_t>(d) + static_cast<std::size_t>(k)], 1e-12) << "d=" << d;
    }
    ASSERT_EQ(found.offsets[9] - found.offsets[8], 1u);
    EXPECT_EQ(found.ids[found.offsets[8]], 7);
    EXPECT_EQ(found.weights[found.offsets[8]], 1.0);
    EXPECT_EQ(found.offsets[10], found.offsets[9]) << "a query outside the hull has no neighbours";
    EXPECT_EQ(t.triangulation().simplices, IncrementalDelaunay(points).triangulation().simplices) << "probes change nothing";
  }
  {
    // Inside the points' box but outside their hull (a circle's): the conflicts reach the
    // infinite cells, and there are no neighbours.
    const PointCloud circle = drange::generate_points(Distribution::Sphere, 200, 2, 3);
    IncrementalDelaunay t(circle);
    const std::vector<double> corner{0.9, 0.9};
    const auto found = t.natural_neighbours(PointsView(corner.data(), 1, 2));
    EXPECT_EQ(found.offsets, (std::vector<std::size_t>{0, 0}));
  }
  const PointCloud points = drange::generate_points(Distribution::Uniform, 30, 2, 1);
  IncrementalDelaunay furthest(points, true);
  const std::vector<double> x{0.5, 0.5};
  EXPECT_THROW(furthest.natural_neighbours(PointsView(x.data(), 1, 2)), drange::UsageError);
  IncrementalDelaunay t(points);
  EXPECT_THROW(t.natural_neighbours(PointsView(x.data(), 1, 3)), drange::InputError);
  const std::vector<double> nan{0.5, std::numeric_limits<double>::quiet_NaN()};
  EXPECT_THROW(t.natural_neighbours(PointsView(nan.data(), 1, 2)), drange::InputError);
}

}  // namespace
