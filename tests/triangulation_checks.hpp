// tests/triangulation_checks.hpp: checks of a whole triangulation shared by the engine's
// tests: the perturbed brute-force oracle, the exact validator, the adjacency's invariants and
// the perturbed emptiness of every simplex by the rational references of oracle.hpp.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <numeric>
#include <set>
#include <string>
#include <vector>

#include "drange/check.hpp"
#include "drange/delaunay.hpp"
#include "drange/generate.hpp"
#include "geometry/predicates.hpp"
#include "oracle.hpp"

namespace drange::test::checks {

using drange::Distribution;
using drange::PointCloud;
using drange::Triangulation;

inline std::vector<Simplex> canonical(const Triangulation& t) { return drange::test::canonical(t.simplices, t.dim); }

// Simplices as sets of coordinate tuples: comparable across permutations and duplicates.
inline std::set<std::vector<std::vector<double>>> geometric(const Triangulation& t, const PointCloud& points) {
  std::set<std::vector<std::vector<double>>> out;
  for (std::size_t s = 0; s < t.size(); ++s) {
    std::vector<std::vector<double>> v;
    for (int k = 0; k <= t.dim; ++k) {
      const double* p = points.point(static_cast<std::size_t>(t.simplex(s)[k]));
      v.emplace_back(p, p + t.dim);
    }
    std::sort(v.begin(), v.end());
    out.insert(v);
  }
  return out;
}

// The perturbed Delaunay triangulation by definition: every (d+1)-subset of distinct points,
// with nonzero volume, such that no other point is inside its circumsphere under the
// symbolic perturbation (ranks: lexicographic order). O(n^(d+2)); for tiny inputs only.
// It shares nothing with the engine: the predicates are the test's own rational references
// (oracle.hpp), so neither the search, the kd-tree, the first facet, the facet table nor the
// library's filters are involved.
// The perturbation's ranks: the lexicographic order of the coordinates (distinct points).
inline std::vector<std::int64_t> lexicographic_ranks(const PointCloud& points) {
  const int d = points.dim;
  const auto n = static_cast<std::int32_t>(points.size());
  std::vector<std::int32_t> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::int32_t a, std::int32_t b) {
    return std::lexicographical_compare(points.point(a), points.point(a) + d, points.point(b), points.point(b) + d);
  });
  std::vector<std::int64_t> rank(static_cast<std::size_t>(n));
  for (std::int32_t r = 0; r < n; ++r) rank[static_cast<std::size_t>(order[static_cast<std::size_t>(r)])] = r;
  return rank;
}

inline std::vector<Simplex> perturbed_oracle(const PointCloud& points) {
  const int d = points.dim;
  const auto n = static_cast<std::int32_t>(points.size());
  const std::vector<std::int64_t> rank = lexicographic_ranks(points);
  std::vector<Simplex> out;
  Simplex subset(static_cast<std::size_t>(d + 1));
  std::function<void(int, std::int32_t)> choose = [&](int position, std::int32_t from) {
    if (position == d + 1) {
      const std::vector<const double*> p = drange::test::corners(points, subset);
      const int o = drange::test::reference_orientation(d, p);
      if (o == 0) return;
      std::vector<const double*> rows(p.begin() + 1, p.end());
      rows.push_back(nullptr);
      std::vector<std::int64_t> ranks;
      for (std::int32_t i : subset) ranks.push_back(rank[static_cast<std::size_t>(i)]);
      ranks.push_back(0);
      for (std::int32_t q = 0; q < n; ++q) {
        if (std::find(subset.begin(), subset.end(), q) != subset.end()) continue;
        rows.back() = points.point(static_cast<std::size_t>(q));
        ranks.back() = rank[static_cast<std::size_t>(q)];
        if (o * drange::test::reference_lifted_sign_perturbed(d, p[0], rows, ranks) < 0) return;  // inside
      }
      out.push_back(subset);
      return;
    }
    for (std::int32_t i = from; i < n; ++i) {
      subset[static_cast<std::size_t>(position)] = i;
      choose(position + 1, i + 1);
    }
  };
  choose(0, 0);
  return out;
}

// The integer grid {0..k-1}^d.
inline PointCloud grid(int d, int k) {
  std::size_t total = 1;
  for (int i = 0; i < d; ++i) total *= static_cast<std::size_t>(k);
  return drange::generate_points(Distribution::Grid, total, d, 1);
}

inline void expect_valid(const PointCloud& points, const Triangulation& t, const std::string& what) {
  const drange::CheckReport report = drange::check_triangulation(points, t.simplices);
  EXPECT_TRUE(report.valid) << what << ": " << (report.problems.empty() ? "" : report.problems.front());
  EXPECT_EQ(t.stats.simplices, t.size());
}

// Every simplex positive; neighbour k is opposite vertex k, shares the other d vertices, and
// points back; -1 exactly on hull facets.
inline void expect_consistent_adjacency(const PointCloud& points, const Triangulation& t) {
  const int d = t.dim;
  ASSERT_EQ(t.neighbors.size(), t.simplices.size());
  std::size_t hull = 0;
  for (std::size_t s = 0; s < t.size(); ++s) {
    std::vector<const double*> p;
    for (int k = 0; k <= d; ++k) p.push_back(points.point(static_cast<std::size_t>(t.simplex(s)[k])));
    ASSERT_GT(drange::geometry::simplex_orientation(d, p.data()), 0) << "simplex " << s << " not positive";
    for (int k = 0; k <= d; ++k) {
      const std::int32_t nb = t.neighbors[s * static_cast<std::size_t>(d + 1) + static_cast<std::size_t>(k)];
      if (nb < 0) {
        ++hull;
        continue;
      }
      const std::int32_t* mine = t.simplex(s);
      const std::int32_t* theirs = t.simplex(static_cast<std::size_t>(nb));
      int shared = 0;
      for (int i = 0; i <= d; ++i)
        if (i != k && std::find(theirs, theirs + d + 1, mine[i]) != theirs + d + 1) ++shared;
      EXPECT_EQ(shared, d) << "simplex " << s << " neighbour " << k;
      EXPECT_EQ(std::find(theirs, theirs + d + 1, mine[k]), theirs + d + 1) << "neighbour holds the opposite vertex";
      const std::int32_t* back = &t.neighbors[static_cast<std::size_t>(nb) * static_cast<std::size_t>(d + 1)];
      EXPECT_NE(std::find(back, back + d + 1, static_cast<std::int32_t>(s)), back + d + 1) << "not symmetric";
    }
  }
  EXPECT_EQ(hull, t.stats.hull_facets);
}

// Every simplex of t is empty of every input point under the symbolic perturbation, by the
// rational reference: O(simplices * n). With the validator's covering, this identifies the
// perturbed Delaunay triangulation on inputs too large for perturbed_oracle.
inline void expect_perturbed_empty(const PointCloud& points, const Triangulation& t, const std::string& what) {
  const int d = points.dim;
  const std::vector<std::int64_t> rank = lexicographic_ranks(points);
  int violations = 0;
  for (std::size_t s = 0; s < t.size() && violations < 3; ++s) {
    const Simplex simplex(t.simplex(s), t.simplex(s) + d + 1);
    const std::vector<const double*> p = drange::test::corners(points, simplex);
    const int o = drange::test::reference_orientation(d, p);
    std::vector<const double*> rows(p.begin() + 1, p.end());
    rows.push_back(nullptr);
    std::vector<std::int64_t> ranks;
    for (std::int32_t i : simplex) ranks.push_back(rank[static_cast<std::size_t>(i)]);
    ranks.push_back(0);
    for (std::size_t q = 0; q < points.size(); ++q) {
      if (std::find(simplex.begin(), simplex.end(), static_cast<std::int32_t>(q)) != simplex.end()) continue;
      rows.back() = points.point(q);
      ranks.back() = rank[q];
      if (o * drange::test::reference_lifted_sign_perturbed(d, p[0], rows, ranks) < 0) {
        ADD_FAILURE() << what << ": point " << q << " is inside simplex " << s << " under the perturbation";
        ++violations;
        break;
      }
    }
  }
}

}  // namespace drange::test::checks
