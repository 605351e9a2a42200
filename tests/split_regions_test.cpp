// The boxes of cli/split_regions.hpp hold their regions: every point of the bounds inside the
// closed circumball (or the closed half-space beyond a facet), decided in exact rational
// arithmetic, is inside the box; on well shaped and nearly flat simplices, 2D to 5D.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "../cli/split_regions.hpp"

namespace {

using drange::cli::Box;

// The determinant of a square rational matrix by expansion along the first row: another way
// to the exact centre than the code under test's elimination, and small enough for d <= 4.
mpq_class determinant(const std::vector<std::vector<mpq_class>>& a) {
  const std::size_t n = a.size();
  if (n == 1) return a[0][0];
  mpq_class sum = 0;
  for (std::size_t j = 0; j < n; ++j) {
    std::vector<std::vector<mpq_class>> minor;
    for (std::size_t r = 1; r < n; ++r) {
      std::vector<mpq_class> row;
      for (std::size_t k = 0; k < n; ++k)
        if (k != j) row.push_back(a[r][k]);
      minor.push_back(row);
    }
    const mpq_class term = a[0][j] * determinant(minor);
    sum += j % 2 ? -term : term;
  }
  return sum;
}

// Solves a x = b exactly by Cramer's rule; false when singular.
bool solve_exact(const std::vector<std::vector<mpq_class>>& a, const std::vector<mpq_class>& b, std::vector<mpq_class>& x) {
  const mpq_class det = determinant(a);
  if (det == 0) return false;
  x.assign(b.size(), 0);
  for (std::size_t c = 0; c < b.size(); ++c) {
    std::vector<std::vector<mpq_class>> replaced(a);
    for (std::size_t r = 0; r < b.size(); ++r) replaced[r][c] = b[r];
    x[c] = determinant(replaced) / det;
  }
  return true;
}

Box unit_bounds(std::size_t d) { return Box::filled(d, -1.0, 1.0); }

// Random points of the bounds, many of them near `centre` +- `radius` along each axis.
std::vector<std::vector<double>> probes(std::size_t d, const std::vector<double>& centre, double radius, std::mt19937& rng) {
  std::uniform_real_distribution<double> any(-1.0, 1.0), unit(-1.0, 1.0);
  std::vector<std::vector<double>> result;
  for (int i = 0; i < 400; ++i) {
    std::vector<double> q(d);
    for (std::size_t k = 0; k < d; ++k) {
      q[k] = i % 2 ? any(rng) : centre[k] + radius * unit(rng);
      q[k] = std::fmin(1.0, std::fmax(-1.0, q[k]));
    }
    result.push_back(q);
  }
  return result;
}

void expect_ball_held(const std::vector<std::vector<double>>& v, std::mt19937& rng) {
  const std::size_t d = v.size() - 1;
  std::vector<const double*> corners;
  for (const auto& p : v) corners.push_back(p.data());
  const Box bounds = unit_bounds(d);
  const Box box = drange::cli::ball_region(corners, bounds);
  for (const auto& p : v) EXPECT_TRUE(box.contains_point(p.data()));
  std::vector<std::vector<mpq_class>> a(d, std::vector<mpq_class>(d));
  std::vector<mpq_class> b(d), x;
  for (std::size_t i = 0; i < d; ++i) {
    b[i] = 0;
    for (std::size_t k = 0; k < d; ++k) {
      a[i][k] = mpq_class(v[i + 1][k]) - mpq_class(v[0][k]);
      b[i] += a[i][k] * a[i][k] / 2;
    }
  }
  if (!solve_exact(a, b, x)) return;  // flat: the box must be the bounds, checked by the caller
  std::vector<double> centre(d);
  mpq_class r2 = 0;
  for (std::size_t k = 0; k < d; ++k) {
    centre[k] = mpq_class(x[k] + mpq_class(v[0][k])).get_d();
    r2 += x[k] * x[k];
  }
  for (const auto& q : probes(d, centre, std::sqrt(r2.get_d()) * 1.0000001, rng)) {
    mpq_class s = 0;
    for (std::size_t k = 0; k < d; ++k) {
      const mpq_class e = mpq_class(q[k]) - (x[k] + mpq_class(v[0][k]));
      s += e * e;
    }
    if (s <= r2) EXPECT_TRUE(box.contains_point(q.data())) << "a point of the ball outside its box";
  }
}

TEST(SplitRegions, BallBoxesHoldTheirBalls) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> coordinate(-0.9, 0.9), tiny(-1e-9, 1e-9);
  for (std::size_t d = 2; d <= 5; ++d) {
    for (int trial = 0; trial < 60; ++trial) {
      std::vector<std::vector<double>> v(d + 1, std::vector<double>(d));
      for (auto& p : v)
        for (double& c : p) c = coordinate(rng);
      if (trial % 3 == 1)  // nearly flat along the last axis, near a side: a large cap
        for (auto& p : v) p[d - 1] = -0.9 + (trial % 2 ? 1e-4 : 1e-7) * coordinate(rng);
      if (trial % 3 == 2)  // nearly flat in a tilted hyperplane
        for (auto& p : v) p[d - 1] = 0.3 * p[0] + tiny(rng);
      expect_ball_held(v, rng);
    }
  }
}

TEST(SplitRegions, FlatSimplexReachesEverywhere) {
  std::vector<std::vector<double>> v{{0, 0, 0}, {0.5, 0, 0}, {0, 0.5, 0}, {0.5, 0.5, 0}};
  std::vector<const double*> corners;
  for (const auto& p : v) corners.push_back(p.data());
  const Box bounds = unit_bounds(3);
  const Box box = drange::cli::ball_region(corners, bounds);
  EXPECT_TRUE(box.contains(bounds));
}

TEST(SplitRegions, BeyondBoxesHoldTheirHalfSpaces) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coordinate(-0.9, 0.9);
  for (std::size_t d = 2; d <= 5; ++d) {
    for (int trial = 0; trial < 60; ++trial) {
      std::vector<std::vector<double>> v(d + 1, std::vector<double>(d));
      for (auto& p : v)
        for (double& c : p) c = coordinate(rng);
      if (trial % 2)  // a facet nearly along a side of the bounds
        for (std::size_t i = 0; i < d; ++i) v[i][0] = -0.9 + 1e-6 * coordinate(rng);
      std::vector<const double*> facet;
      for (std::size_t i = 0; i < d; ++i) facet.push_back(v[i].data());
      const Box bounds = unit_bounds(d);
      const Box box = drange::cli::beyond_region(facet, v[d].data(), bounds);
      // The exact side: the sign of det[v1 - v0, ..., v(d-1) - v0, q - v0] against the inside's.
      const auto side = [&](const std::vector<double>& q) {
        std::vector<std::vector<mpq_class>> m(d, std::vector<mpq_class>(d));
        for (std::size_t i = 0; i < d; ++i)
          for (std::size_t k = 0; k < d; ++k)
            m[i][k] = mpq_class(i + 1 < d ? v[i + 1][k] : q[k]) - mpq_class(v[0][k]);
        mpq_class det = 1;  // by elimination
        for (std::size_t c = 0; c < d; ++c) {
          std::size_t p = c;
          while (p < d && m[p][c] == 0) ++p;
          if (p == d) return 0;
          if (p != c) {
            std::swap(m[p], m[c]);
            det = -det;
          }
          det *= m[c][c];
          for (std::size_t r = c + 1; r < d; ++r) {
            const mpq_class f = m[r][c] / m[c][c];
            for (std::size_t k = c; k < d; ++k) m[r][k] -= f * m[c][k];
          }
        }
        return sgn(det);
      };
      const int inside = side(v[d]);
      ASSERT_NE(inside, 0);
      for (const auto& q : probes(d, v[0], 0.5, rng))
        if (side(q) != inside) EXPECT_TRUE(box.contains_point(q.data())) << "a point beyond the facet outside the box";
    }
  }
}

}  // namespace
