// tests/hull_test.cpp: drange::convex_hull against brute force on GMP rationals (the facets of
// points in general position), and its properties on degenerate input: corners of cube grids
// as the only vertices, every other boundary point coplanar, ridges in two facets, the volume;
// the perturbation's three stages against the perturbation itself, evaluated at small rationals.
#include <gtest/gtest.h>

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <string>
#include <vector>

#include "drange/errors.hpp"
#include "drange/hull.hpp"
#include "hull/initial_simplex.hpp"
#include "hull/perturbation.hpp"
#include "oracle.hpp"

namespace drange {
namespace {

using test::corners;
using test::reference_orientation;

// Every d-subset of the points with all the others strictly on one side: the hull's facets when
// no d+1 points lie on a hyperplane. Sorted tuples.
std::set<std::vector<std::int32_t>> brute_force_facets(const PointCloud& points) {
  const int d = points.dim;
  const auto n = static_cast<std::int32_t>(points.size());
  std::set<std::vector<std::int32_t>> facets;
  std::vector<std::int32_t> subset(static_cast<std::size_t>(d));
  std::iota(subset.begin(), subset.end(), 0);
  while (true) {
    int positive = 0, negative = 0;
    for (std::int32_t x = 0; x < n; ++x) {
      if (std::find(subset.begin(), subset.end(), x) != subset.end()) continue;
      std::vector<std::int32_t> ids = subset;
      ids.push_back(x);
      const int s = reference_orientation(d, corners(points, ids));
      positive += s > 0;
      negative += s < 0;
    }
    if (positive == 0 || negative == 0) facets.insert(subset);
    int i = d - 1;
    while (i >= 0 && subset[static_cast<std::size_t>(i)] == n - d + i) --i;
    if (i < 0) break;
    ++subset[static_cast<std::size_t>(i)];
    for (int j = i + 1; j < d; ++j) subset[static_cast<std::size_t>(j)] = subset[static_cast<std::size_t>(j - 1)] + 1;
  }
  return facets;
}

std::set<std::vector<std::int32_t>> facet_set(const ConvexHull& hull) {
  std::set<std::vector<std::int32_t>> facets;
  for (std::size_t f = 0; f < hull.size(); ++f) {
    std::vector<std::int32_t> v(hull.facet(f), hull.facet(f) + hull.dim);
    std::sort(v.begin(), v.end());
    facets.insert(v);
  }
  return facets;
}

// The structure every hull must have, exactly: each facet's orientation (-1)^d or 0 at every
// point (all on the closed inner side), neighbour k sharing the ridge opposite vertex k and
// pointing back, every ridge in exactly two facets, vertices those of the facets.
void expect_valid(const PointCloud& points, const ConvexHull& hull) {
  const int d = points.dim;
  const int inside = (d % 2 == 0) ? 1 : -1;
  std::map<std::vector<std::int32_t>, int> ridges;
  std::set<std::int32_t> vertices;
  for (std::size_t f = 0; f < hull.size(); ++f) {
    const std::vector<std::int32_t> facet(hull.facet(f), hull.facet(f) + d);
    vertices.insert(facet.begin(), facet.end());
    for (std::size_t x = 0; x < points.size(); ++x) {
      std::vector<std::int32_t> ids = facet;
      ids.push_back(static_cast<std::int32_t>(x));
      const int s = reference_orientation(d, corners(points, ids));
      ASSERT_TRUE(s == 0 || s == inside) << "point " << x << " is outside facet " << f;
    }
    for (int k = 0; k < d; ++k) {
      std::vector<std::int32_t> ridge = facet;
      ridge.erase(ridge.begin() + k);
      std::sort(ridge.begin(), ridge.end());
      ++ridges[ridge];
      const std::int32_t g = hull.neighbors[f * static_cast<std::size_t>(d) + static_cast<std::size_t>(k)];
      ASSERT_GE(g, 0);
      std::vector<std::int32_t> other(hull.facet(static_cast<std::size_t>(g)), hull.facet(static_cast<std::size_t>(g)) + d);
      for (const std::int32_t v : ridge) EXPECT_NE(std::find(other.begin(), other.end(), v), other.end()) << "facet " << f << " place " << k;
      const std::int32_t* back = hull.neighbors.data() + static_cast<std::size_t>(g) * static_cast<std::size_t>(d);
      EXPECT_NE(std::find(back, back + d, static_cast<std::int32_t>(f)), back + d);
    }
  }
  for (const auto& [ridge, count] : ridges) EXPECT_EQ(count, 2) << "a ridge in " << count << " facets";
  EXPECT_EQ(std::vector<std::int32_t>(vertices.begin(), vertices.end()), hull.vertices);
}

TEST(ConvexHull, FacetsAreThoseOfBruteForceInGeneralPosition) {
  const std::size_t sizes[] = {0, 0, 40, 16, 12, 11, 10};
  for (int d = 2; d <= 6; ++d)
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      SCOPED_TRACE("d=" + std::to_string(d) + " seed=" + std::to_string(seed));
      const PointCloud points = test::random_points(sizes[d], d, seed);
      const ConvexHull hull = convex_hull(points);
      EXPECT_EQ(facet_set(hull), brute_force_facets(points));
      expect_valid(points, hull);
      EXPECT_TRUE(hull.coplanar.empty());
    }
}

TEST(ConvexHull, LargerInputsAreValid) {
  for (int d = 2; d <= 5; ++d) {
    SCOPED_TRACE("d=" + std::to_string(d));
    const PointCloud points = test::random_points(d <= 3 ? 300 : 60, d, 11);
    expect_valid(points, convex_hull(points));
  }
}

PointCloud grid(int d, int side) {
  PointCloud points;
  points.dim = d;
  std::vector<int> index(static_cast<std::size_t>(d), 0);
  while (true) {
    for (const int i : index) points.coords.push_back(i);
    int k = 0;
    while (k < d && ++index[static_cast<std::size_t>(k)] == side) index[static_cast<std::size_t>(k++)] = 0;
    if (k == d) break;
  }
  return points;
}

TEST(ConvexHull, CubeGridHasItsCornersAsVerticesAndTheRestOfItsBoundaryCoplanar) {
  for (const auto& [d, side] : std::vector<std::pair<int, int>>{{2, 5}, {3, 4}, {4, 3}, {5, 3}}) {
    SCOPED_TRACE("d=" + std::to_string(d) + " side=" + std::to_string(side));
    const PointCloud points = grid(d, side);
    const ConvexHull hull = convex_hull(points);
    expect_valid(points, hull);
    std::vector<std::int32_t> corners_expected, boundary;
    for (std::size_t i = 0; i < points.size(); ++i) {
      int extreme = 0;
      for (int k = 0; k < d; ++k) {
        const double x = points.point(i)[k];
        extreme += x == 0 || x == side - 1;
      }
      if (extreme == d) corners_expected.push_back(static_cast<std::int32_t>(i));
      else if (extreme > 0) boundary.push_back(static_cast<std::int32_t>(i));
    }
    EXPECT_EQ(hull.vertices, corners_expected);
    std::vector<std::int32_t> coplanar;
    for (std::size_t c = 0; c < hull.coplanar.size(); c += 3) {
      coplanar.push_back(hull.coplanar[c]);
      // The named facet's hyperplane holds the point; the named vertex is one of the facet's.
      const std::int32_t f = hull.coplanar[c + 1];
      std::vector<std::int32_t> ids(hull.facet(static_cast<std::size_t>(f)), hull.facet(static_cast<std::size_t>(f)) + d);
      EXPECT_NE(std::find(ids.begin(), ids.end(), hull.coplanar[c + 2]), ids.end());
      ids.push_back(hull.coplanar[c]);
      EXPECT_EQ(reference_orientation(d, corners(points, ids)), 0);
    }
    std::sort(coplanar.begin(), coplanar.end());
    EXPECT_EQ(coplanar, boundary);
    const HullGeometry geometry = hull_geometry(points, hull);
    const double edge = side - 1;
    EXPECT_NEAR(geometry.volume, std::pow(edge, d), 1e-12 * std::pow(edge, d));
    EXPECT_NEAR(geometry.area, 2 * d * std::pow(edge, d - 1), 1e-12 * std::pow(edge, d));
  }
}

TEST(ConvexHull, AnyOrderGivesTheSameFacetsOnDegenerateInput) {
  const PointCloud points = grid(3, 4);
  const ConvexHull hull = convex_hull(points);
  PointCloud reversed;
  reversed.dim = 3;
  const std::size_t n = points.size();
  for (std::size_t i = n; i-- > 0;) reversed.coords.insert(reversed.coords.end(), points.point(i), points.point(i) + 3);
  std::set<std::vector<std::int32_t>> mapped;
  for (const std::vector<std::int32_t>& facet : facet_set(convex_hull(reversed))) {
    std::vector<std::int32_t> v;
    for (const std::int32_t id : facet) v.push_back(static_cast<std::int32_t>(n - 1) - id);
    std::sort(v.begin(), v.end());
    mapped.insert(v);
  }
  EXPECT_EQ(mapped, facet_set(hull));
}

TEST(ConvexHull, DuplicatesAndPointsOnEdgesAreCoplanar) {
  // A square's corners, each twice, and the middles of two sides; the centre is inside.
  PointCloud points{2, {0, 0, 2, 0, 2, 2, 0, 2, 0, 0, 2, 0, 2, 2, 0, 2, 1, 0, 2, 1, 1, 1}};
  const ConvexHull hull = convex_hull(points);
  expect_valid(points, hull);
  EXPECT_EQ(hull.size(), 4u);
  std::vector<std::int32_t> coplanar;
  for (std::size_t c = 0; c < hull.coplanar.size(); c += 3) coplanar.push_back(hull.coplanar[c]);
  std::sort(coplanar.begin(), coplanar.end());
  EXPECT_EQ(coplanar.size(), 6u);  // four copies (of whichever kept) and the two middles
  EXPECT_TRUE(std::find(coplanar.begin(), coplanar.end(), 8) != coplanar.end());
  EXPECT_TRUE(std::find(coplanar.begin(), coplanar.end(), 9) != coplanar.end());
  EXPECT_TRUE(std::find(coplanar.begin(), coplanar.end(), 10) == coplanar.end());
}

TEST(ConvexHull, GeometryAgreesWithTheSimplex) {
  // The unit simplex in 4D: volume 1/24, outward normals, offsets.
  PointCloud points{4, {0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}};
  const ConvexHull hull = convex_hull(points);
  const HullGeometry g = hull_geometry(points, hull);
  EXPECT_NEAR(g.volume, 1.0 / 24, 1e-15);
  EXPECT_NEAR(g.area, 4.0 / 6 + std::sqrt(4.0) / 6, 1e-14);
  for (std::size_t f = 0; f < hull.size(); ++f) {
    const double* e = g.equations.data() + f * 5;
    // normal . x + offset: 0 on the facet's vertices, negative at the vertex left out.
    for (std::size_t x = 0; x < points.size(); ++x) {
      double value = e[4];
      for (int k = 0; k < 4; ++k) value += e[k] * points.point(x)[k];
      const bool on = std::find(hull.facet(f), hull.facet(f) + 4, static_cast<std::int32_t>(x)) != hull.facet(f) + 4;
      if (on) EXPECT_NEAR(value, 0.0, 1e-15);
      else EXPECT_LT(value, -0.4);
    }
  }
  const double outside[] = {1, 1, 1, 1};
  const std::vector<std::int8_t> sides = facet_sides(points, hull, outside);
  EXPECT_EQ(std::count(sides.begin(), sides.end(), 1), 1);  // only the slanted facet sees it
  EXPECT_EQ(std::count(sides.begin(), sides.end(), -1), 4);
}

TEST(ConvexHull, BadInputIsRefusedWithItsReason) {
  EXPECT_THROW(convex_hull(PointCloud{2, {0, 0, 1, 0, 2, 0, 3, 0}}), DegenerateInputError);  // collinear
  EXPECT_THROW(convex_hull(PointCloud{3, {0, 0, 0, 1, 0, 0, 0, 1, 0}}), DegenerateInputError);  // too few
  EXPECT_THROW(convex_hull(PointCloud{2, {0, 0, 1, 0, NAN, 1}}), InputError);
  EXPECT_THROW(convex_hull(PointCloud{1, {0, 1, 2}}), InputError);
  try {
    convex_hull(PointCloud{3, {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 2, 3, 0}});
    FAIL();
  } catch (const DegenerateInputError& e) {
    EXPECT_NE(std::string(e.what()).find("dimension 2"), std::string::npos) << e.what();
  }
}

// The perturbed orientation by its definition: the points moved to O + q/t with t = 1 - eps w
// - eta_rank, at eps = 2^-40 and eta = 2^-(110 + 40 r) for the r-th point in lexicographic
// order, exactly on rationals. The coordinates (multiples of 1/16 after the shift, below 3)
// keep every nonzero term of det[q_i, t_i] = det[q, 1] - eps det[q, w] - sum eta_i cof_i
// within factors far smaller than the gaps between these powers: the signs are the
// infinitesimal ones.
int defined_sign(const PointCloud& points, const std::vector<std::int32_t>& ids, const std::vector<mpq_class>& o,
                 const hull::Perturbation& perturbation) {
  const int d = points.dim;
  std::vector<std::int32_t> by_rank = ids;
  std::sort(by_rank.begin(), by_rank.end(), [&](std::int32_t a, std::int32_t b) { return perturbation.before(a, b); });
  std::vector<mpq_class> rows;
  std::vector<std::vector<mpq_class>> moved;
  for (const std::int32_t id : ids) {
    mpq_class w = 0;
    std::vector<mpq_class> q(static_cast<std::size_t>(d));
    for (int k = 0; k < d; ++k) {
      q[static_cast<std::size_t>(k)] = mpq_class(points.point(static_cast<std::size_t>(id))[k]) - o[static_cast<std::size_t>(k)];
      w += q[static_cast<std::size_t>(k)] * q[static_cast<std::size_t>(k)];
    }
    const auto rank = std::find(by_rank.begin(), by_rank.end(), id) - by_rank.begin();
    mpq_class eta = 1;
    mpz_class denominator = 1;
    denominator <<= static_cast<unsigned long>(110 + 40 * rank);
    eta /= denominator;
    mpz_class eps_denominator = 1;
    eps_denominator <<= 40;
    const mpq_class eps = mpq_class(1) / eps_denominator;
    const mpq_class t = 1 - eps * w - eta;
    for (int k = 0; k < d; ++k) q[static_cast<std::size_t>(k)] /= t;
    moved.push_back(q);
  }
  for (int i = 1; i <= d; ++i)
    for (int k = 0; k < d; ++k)
      rows.push_back(moved[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)] - moved[0][static_cast<std::size_t>(k)]);
  return sgn(test::reference_determinant(rows, d));
}

// Random (d+1)-tuples of `points`, many of them degenerate, against the definition, with O at
// `o` (exactly; `perturbation` must use the same point).
void expect_stages_match(const PointCloud& points, const std::vector<mpq_class>& o, const hull::Perturbation& perturbation) {
  const int d = points.dim;
  const auto n = static_cast<std::int64_t>(points.size());
  test::TestRandom random(17);
  int ties = 0;
  for (int trial = 0; trial < 400; ++trial) {
    std::vector<std::int32_t> ids;
    while (static_cast<int>(ids.size()) <= d) {
      const auto id = static_cast<std::int32_t>(random.integer(0, n - 1));
      if (std::find(ids.begin(), ids.end(), id) == ids.end()) ids.push_back(id);
    }
    // Skip d+1 points in one hyperplane through O: there the perturbation is undefined.
    bool through_o = true;
    for (int i = 0; i <= d && through_o; ++i) {
      std::vector<mpq_class> rows;
      for (int k = 0; k <= d; ++k)
        if (k != i)
          for (int j = 0; j < d; ++j)
            rows.push_back(mpq_class(points.point(static_cast<std::size_t>(ids[static_cast<std::size_t>(k)]))[j]) -
                           o[static_cast<std::size_t>(j)]);
      through_o = test::reference_determinant(rows, d) == 0;
    }
    if (through_o) continue;
    const int unperturbed = perturbation.unperturbed(ids.data());
    ties += unperturbed == 0;
    EXPECT_EQ(perturbation.sign(ids.data(), unperturbed), defined_sign(points, ids, o, perturbation)) << "trial " << trial;
  }
  EXPECT_GT(ties, 40);  // the stages after the first were exercised
}

TEST(ConvexHull, PerturbationStagesMatchTheirDefinition) {
  // Integer points in a small box: many d+1 on one hyperplane, on one sphere, or repeated.
  for (int d = 2; d <= 4; ++d) {
    SCOPED_TRACE("d=" + std::to_string(d));
    const PointCloud points = test::random_integer_points(30, d, 0, 2, 5 + static_cast<std::uint64_t>(d));
    // About a double (off every hyperplane the points span), as when the centroid rounds inside.
    const std::vector<double> o(static_cast<std::size_t>(d), 0.8125);
    expect_stages_match(points, std::vector<mpq_class>(o.begin(), o.end()), hull::Perturbation(points.coords.data(), d, {}, o));
    // About the exact centroid of a simplex, in integers, as when it does not round inside.
    std::vector<std::int32_t> simplex;
    test::TestRandom pick(3);
    while (static_cast<int>(simplex.size()) <= d || reference_orientation(d, corners(points, simplex)) == 0) {
      if (static_cast<int>(simplex.size()) > d) simplex.clear();
      const auto id = static_cast<std::int32_t>(pick.integer(0, 29));
      if (std::find(simplex.begin(), simplex.end(), id) == simplex.end()) simplex.push_back(id);
    }
    std::vector<mpq_class> centroid(static_cast<std::size_t>(d), 0);
    for (const std::int32_t id : simplex)
      for (int k = 0; k < d; ++k) centroid[static_cast<std::size_t>(k)] += mpq_class(points.point(static_cast<std::size_t>(id))[k]);
    for (mpq_class& c : centroid) c /= d + 1;
    expect_stages_match(points, centroid, hull::Perturbation(points.coords.data(), d, simplex, {}));
  }
}

TEST(ConvexHull, ThinFirstSimplexUsesTheExactCentroid) {
  // A point 2^60 away from the others: the first simplex is 2^60 long and about 1 wide, and its
  // centroid rounds to a double outside it. Points on the hull's edges make ties that the exact
  // centroid decides.
  const double far = std::ldexp(1.0, 60);
  const PointCloud points{2, {-0.5, 0, 1, 0, 0, -1, 0, 0.5, far, -0.75 * far, 0.25, 0, 0.5, 0, -0.25, 0.25, -0.25, -0.5}};
  const hull::InitialSimplex simplex = hull::initial_simplex(points);
  EXPECT_TRUE(simplex.interior.empty());
  const ConvexHull hull = convex_hull(points);
  expect_valid(points, hull);
  EXPECT_EQ(hull.vertices, (std::vector<std::int32_t>{0, 1, 2, 3, 4}));
  std::vector<std::int32_t> coplanar;
  for (std::size_t c = 0; c < hull.coplanar.size(); c += 3) coplanar.push_back(hull.coplanar[c]);
  std::sort(coplanar.begin(), coplanar.end());
  EXPECT_EQ(coplanar, (std::vector<std::int32_t>{7, 8}));  // the middles of two edges
}

}  // namespace
}  // namespace drange

TEST(HullGeometry, ThinFacetsGetTheirNormalsExactly) {
  // A facet whose minors underflow in doubles (edges of 1e-170): its normal is exact, not NaN.
  const drange::PointCloud points{3, {0, 0, 0, 1e-170, 0, 0, 0, 1e-170, 0, 0, 0, 1e-170}};
  const drange::ConvexHull hull = drange::convex_hull(points);
  const drange::HullGeometry geometry = drange::hull_geometry(points, hull);
  bool slanted = false;
  for (std::size_t f = 0; f < hull.size(); ++f) {
    const double* e = geometry.equations.data() + f * 4;
    EXPECT_NEAR(e[0] * e[0] + e[1] * e[1] + e[2] * e[2], 1.0, 1e-15);
    if (e[0] > 0 && e[1] > 0 && e[2] > 0) {
      slanted = true;
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(e[k], 1.0 / std::sqrt(3.0), 1e-15);
    }
  }
  EXPECT_TRUE(slanted);
}
