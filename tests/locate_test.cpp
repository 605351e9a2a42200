// Tests of drange::SimplexLocator: every answer checked with exact rational arithmetic that
// shares no code with the engine. A returned simplex must contain the query (closed); -1 must
// mean that no simplex does. Queries on vertices, shared faces and the hull (exact on grids)
// are the cases a tolerance gets wrong.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "drange/delaunay.hpp"
#include "drange/errors.hpp"
#include "drange/generate.hpp"
#include "drange/locate.hpp"

namespace drange {
namespace {

// Sign of det[rows[1]-rows[0], ..., rows[d]-rows[0]] in rationals (Gaussian elimination).
int exact_orientation(int d, const std::vector<const double*>& rows) {
  std::vector<std::vector<mpq_class>> m(static_cast<std::size_t>(d), std::vector<mpq_class>(static_cast<std::size_t>(d)));
  for (int i = 0; i < d; ++i)
    for (int k = 0; k < d; ++k) m[i][k] = mpq_class(rows[i + 1][k]) - mpq_class(rows[0][k]);
  int sign = 1;
  for (int c = 0; c < d; ++c) {
    int pivot = c;
    while (pivot < d && m[pivot][c] == 0) ++pivot;
    if (pivot == d) return 0;
    if (pivot != c) {
      std::swap(m[pivot], m[c]);
      sign = -sign;
    }
    if (m[c][c] < 0) sign = -sign;
    for (int r = c + 1; r < d; ++r) {
      const mpq_class f = m[r][c] / m[c][c];
      for (int k = c; k < d; ++k) m[r][k] -= f * m[c][k];
    }
  }
  return sign;
}

// Whether the closed simplex s contains q, exactly.
bool contains(const PointCloud& points, const Triangulation& t, std::size_t s, const double* q) {
  const int d = points.dim;
  for (int k = 0; k <= d; ++k) {
    std::vector<const double*> rows;
    for (int i = 0; i <= d; ++i) rows.push_back(i == k ? q : points.point(static_cast<std::size_t>(t.simplex(s)[i])));
    if (exact_orientation(d, rows) < 0) return false;
  }
  return true;
}

void expect_correct(const PointCloud& points, const Triangulation& t, const SimplexLocator& locator, const double* q) {
  const std::int32_t s = locator.find(q);
  if (s >= 0) {
    EXPECT_TRUE(contains(points, t, static_cast<std::size_t>(s), q)) << "simplex " << s << " does not hold the query";
    return;
  }
  // The points lie in the unit cube, so does their hull: only queries in it need the scan.
  for (int k = 0; k < points.dim; ++k)
    if (q[k] < 0 || q[k] > 1) return;
  for (std::size_t other = 0; other < t.size(); ++other)
    ASSERT_FALSE(contains(points, t, other, q)) << "-1, but simplex " << other << " holds the query";
}

TEST(Locate, RandomQueriesInAndOutOfTheHull) {
  for (int d = 2; d <= 4; ++d) {
    const PointCloud points = generate_points(Distribution::Uniform, d == 4 ? 150 : 400, d, 3);
    const Triangulation t = delaunay(points);
    const SimplexLocator locator(points, t);
    std::mt19937_64 random(d);
    std::uniform_real_distribution<double> coordinate(-0.2, 1.2);
    std::vector<double> q(static_cast<std::size_t>(d));
    for (int i = 0; i < 200; ++i) {
      for (double& x : q) x = coordinate(random);
      expect_correct(points, t, locator, q.data());
    }
  }
}

// On the integer grid, lattice points, edge midpoints and cell centres lie on vertices, shared
// faces and the hull: all are inside (the closed hull), and a point one ulp outside is not.
TEST(Locate, GridPointsOnFacesAndTheHullAreInside) {
  for (int d = 2; d <= 3; ++d) {
    const int k = d == 2 ? 6 : 4;
    const PointCloud points = generate_points(Distribution::Grid, static_cast<std::size_t>(std::pow(k, d)), d, 1);
    const Triangulation t = delaunay(points);
    const SimplexLocator locator(points, t);
    const int steps = 2 * (k - 1);
    std::vector<int> index(static_cast<std::size_t>(d), 0);
    std::vector<double> q(static_cast<std::size_t>(d));
    while (true) {
      for (int a = 0; a < d; ++a) q[static_cast<std::size_t>(a)] = 0.5 * index[static_cast<std::size_t>(a)];
      const std::int32_t s = locator.find(q.data());
      ASSERT_GE(s, 0) << "a point of the closed hull was reported outside";
      EXPECT_TRUE(contains(points, t, static_cast<std::size_t>(s), q.data()));
      int a = 0;
      while (a < d && ++index[static_cast<std::size_t>(a)] > steps) index[static_cast<std::size_t>(a++)] = 0;
      if (a == d) break;
    }
    q.assign(static_cast<std::size_t>(d), 1.0);
    q[0] = std::nextafter(0.0, -1.0);
    EXPECT_EQ(locator.find(q.data()), -1);
    q[0] = std::nextafter(double(k - 1), double(k));
    EXPECT_EQ(locator.find(q.data()), -1);
  }
}

TEST(Locate, NonFiniteQueriesAreOutside) {
  const PointCloud points = generate_points(Distribution::Uniform, 50, 2, 1);
  const Triangulation t = delaunay(points);
  const SimplexLocator locator(points, t);
  const double nan[2] = {std::numeric_limits<double>::quiet_NaN(), 0.5};
  const double inf[2] = {0.5, std::numeric_limits<double>::infinity()};
  EXPECT_EQ(locator.find(nan), -1);
  EXPECT_EQ(locator.find(inf), -1);
}

TEST(Locate, VectorFormAndErrors) {
  const PointCloud points = generate_points(Distribution::Uniform, 100, 3, 2);
  const Triangulation t = delaunay(points);
  const SimplexLocator locator(points, t);
  std::vector<std::int32_t> out(points.size());
  locator.find(points, out.data());
  for (std::size_t i = 0; i < points.size(); ++i) {
    ASSERT_GE(out[i], 0);
    EXPECT_TRUE(contains(points, t, static_cast<std::size_t>(out[i]), points.point(i)));
  }
  const std::vector<double> flat(4, 0.5);
  EXPECT_THROW(locator.find(PointsView(flat.data(), 2, 2), out.data()), UsageError);
  Triangulation no_neighbors = t;
  no_neighbors.neighbors.clear();
  EXPECT_THROW(SimplexLocator(points, no_neighbors), UsageError);
}

TEST(Locate, ThreadsGiveTheSameAnswers) {
  // Enough queries for several chunks per thread, a quarter of them outside the hull, and grid
  // queries on shared faces, where more than one simplex is a correct answer: every thread count
  // must pick the same one.
  for (const Distribution kind : {Distribution::Uniform, Distribution::Grid}) {
    const PointCloud points = generate_points(kind, 4096, 2, 3);
    const Triangulation t = delaunay(points);
    const SimplexLocator locator(points, t);
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> coordinate(-0.1, 1.1);
    const double scale = kind == Distribution::Grid ? 63.0 : 1.0;
    std::vector<double> queries;
    for (int i = 0; i < 30000; ++i)
      for (int a = 0; a < 2; ++a)
        queries.push_back(kind == Distribution::Grid ? std::round(coordinate(random) * 2 * scale) / 2 : coordinate(random));
    const PointsView view(queries.data(), queries.size() / 2, 2);
    std::vector<std::int32_t> serial(view.n), threaded(view.n);
    locator.find(view, serial.data(), 1);
    for (const int threads : {0, 2, 3, 8}) {
      std::fill(threaded.begin(), threaded.end(), -7);
      locator.find(view, threaded.data(), threads);
      EXPECT_EQ(serial, threaded) << "threads " << threads;
    }
    // Many queries are walked in Z order: each answer must still be the one query's own.
    for (std::size_t i = 0; i < view.n; i += 97) {
      EXPECT_EQ(serial[i], locator.find(view.point(i)));
      if (serial[i] >= 0) EXPECT_TRUE(contains(points, t, static_cast<std::size_t>(serial[i]), view.point(i)));
    }
    EXPECT_THROW(locator.find(view, threaded.data(), -1), UsageError);
  }
}

}  // namespace
}  // namespace drange
