// tests/predicates_test.cpp: the exact predicates of geometry/predicates.hpp and exact.hpp
// against an independent rational reference (oracle.hpp: Gaussian elimination on mpq), on
// random points, on integer points with exact ties, on near-degenerate inputs at large offsets,
// and the symbolic perturbation's two defining properties (never zero, antisymmetric).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "geometry/error_bound.hpp"
#include "geometry/exact.hpp"
#include "geometry/minors.hpp"
#include "geometry/predicate_stages.hpp"
#include "geometry/predicates.hpp"
#include "oracle.hpp"

namespace drange::test {
namespace {

using geometry::Frame;

// d+2 points of dimension d, as a base and d+1 others.
struct LiftedCase {
  const double* base;
  std::vector<const double*> points;
};

LiftedCase lifted_case(const PointCloud& cloud, const std::vector<std::int32_t>& ids) {
  LiftedCase c{cloud.point(static_cast<std::size_t>(ids[0])), {}};
  for (std::size_t i = 1; i < ids.size(); ++i) c.points.push_back(cloud.point(static_cast<std::size_t>(ids[i])));
  return c;
}

std::vector<std::int32_t> first_ids(int count) {
  std::vector<std::int32_t> ids;
  for (int i = 0; i < count; ++i) ids.push_back(i);
  return ids;
}

// Compares orientation, in_sphere and lifted_sign with the reference on the first d+2 points.
void expect_predicates_agree(const PointCloud& cloud) {
  const int d = cloud.dim;
  const std::vector<const double*> simplex = corners(cloud, first_ids(d + 1));
  const double* q = cloud.point(static_cast<std::size_t>(d + 1));
  const int orientation = reference_orientation(d, simplex);
  EXPECT_EQ(geometry::simplex_orientation(d, simplex.data()), orientation);
  const Frame frame{d, d, nullptr, simplex[0]};
  EXPECT_EQ(geometry::orientation(frame, simplex.data() + 1), orientation);
  const LiftedCase lifted = lifted_case(cloud, first_ids(d + 2));
  EXPECT_EQ(geometry::lifted_sign(frame, lifted.points.data()), reference_lifted_sign(d, lifted.base, lifted.points));
  if (orientation != 0) {
    EXPECT_EQ(geometry::in_sphere(d, simplex.data(), q), reference_in_sphere(d, simplex, q));
  }
  EXPECT_EQ(geometry::simplex_volume_times_factorial(d, simplex.data()),
            [&] {
              std::vector<mpq_class> a;
              for (int r = 1; r <= d; ++r)
                for (int c = 0; c < d; ++c) a.push_back(mpq_class(simplex[static_cast<std::size_t>(r)][c]) - mpq_class(simplex[0][c]));
              return reference_determinant(a, d);
            }());
}

TEST(PredicateTest, RandomPointsAgreeWithRationalReference) {
  for (int d = 2; d <= 6; ++d) {
    for (std::uint64_t seed = 1; seed <= 60; ++seed) {
      SCOPED_TRACE("d=" + std::to_string(d) + " seed=" + std::to_string(seed));
      expect_predicates_agree(random_points(static_cast<std::size_t>(d + 2), d, seed));
    }
  }
}

// Small integer coordinates make coplanar and cospherical subsets common: exact zeros.
TEST(PredicateTest, IntegerPointsWithTiesAgreeWithRationalReference) {
  int zeros = 0;
  for (int d = 2; d <= 6; ++d) {
    for (std::uint64_t seed = 1; seed <= 200; ++seed) {
      SCOPED_TRACE("d=" + std::to_string(d) + " seed=" + std::to_string(seed));
      const PointCloud cloud = random_integer_points(static_cast<std::size_t>(d + 2), d, -2, 2, seed);
      expect_predicates_agree(cloud);
      const std::vector<const double*> simplex = corners(cloud, first_ids(d + 1));
      if (reference_orientation(d, simplex) == 0) ++zeros;
    }
  }
  EXPECT_GT(zeros, 20) << "the integer cases should include flat simplices";
}

// Random points on an axis-parallel hyperplane (the same coordinate, not a small dyadic one,
// on one axis): every orientation is exactly zero, decided without GMP (a planar set embedded
// in 3D, as a circle with its sphere's poles, would otherwise take millions of exact
// evaluations), and points off that hyperplane keep their signs.
TEST(PredicateTest, PointsOnAnAxisParallelHyperplaneAreFlatWithoutGmp) {
  for (int d = 3; d <= 6; ++d) {
    for (std::uint64_t seed = 1; seed <= 30; ++seed) {
      SCOPED_TRACE("d=" + std::to_string(d) + " seed=" + std::to_string(seed));
      PointCloud cloud = random_points(static_cast<std::size_t>(d + 2), d, seed);
      const int axis = static_cast<int>(seed % static_cast<std::uint64_t>(d));
      for (std::size_t i = 0; i < cloud.size(); ++i) cloud.coords[i * static_cast<std::size_t>(d) + static_cast<std::size_t>(axis)] = 0.1;
      const std::uint64_t before = geometry::exact_evaluations();
      expect_predicates_agree(cloud);
      const std::vector<const double*> simplex = corners(cloud, first_ids(d + 1));
      const Frame frame{d, d, nullptr, simplex[0]};
      EXPECT_EQ(geometry::orientation(frame, simplex.data() + 1), 0);
      EXPECT_EQ(geometry::exact_evaluations(), before) << "an orientation went to GMP";
      // One point off it: the reference decides.
      cloud.coords[static_cast<std::size_t>(d) + static_cast<std::size_t>(axis)] = 0.1 + 0x1p-40;
      expect_predicates_agree(cloud);
    }
  }
}

PointCloud cloud_of(int dim, const std::vector<double>& coords) {
  PointCloud c;
  c.dim = dim;
  c.coords = coords;
  return c;
}

TEST(PredicateTest, CosphericalSquareCorners) {
  const PointCloud square = cloud_of(2, {0, 0, 1, 0, 1, 1, 0, 1});
  const std::vector<const double*> triangle = corners(square, {0, 1, 2});
  EXPECT_EQ(geometry::in_sphere(2, triangle.data(), square.point(3)), 0);
  const std::vector<const double*> reversed = corners(square, {0, 2, 1});
  EXPECT_EQ(geometry::in_sphere(2, reversed.data(), square.point(3)), 0);
  const double inside[2] = {0.5, 0.75}, outside[2] = {1.5, 1.5};
  EXPECT_EQ(geometry::in_sphere(2, triangle.data(), inside), 1);
  EXPECT_EQ(geometry::in_sphere(2, reversed.data(), inside), 1);
  EXPECT_EQ(geometry::in_sphere(2, triangle.data(), outside), -1);
}

TEST(PredicateTest, CosphericalIntegerCircle) {
  // All on the circle of radius 5 about the origin.
  const PointCloud circle = cloud_of(2, {3, 4, 5, 0, 0, 5, -4, 3, 4, -3, -5, 0, 0, -5, -3, -4});
  for (int q = 3; q < 8; ++q) {
    const std::vector<const double*> triangle = corners(circle, {0, 1, 2});
    EXPECT_EQ(geometry::in_sphere(2, triangle.data(), circle.point(static_cast<std::size_t>(q))), 0) << "q=" << q;
    const Frame frame{2, 2, nullptr, circle.point(0)};
    const std::vector<const double*> rows = corners(circle, {1, 2, q});
    EXPECT_EQ(geometry::lifted_sign(frame, rows.data()), 0) << "q=" << q;
  }
  const double near_inside[2] = {4.999999999999999, 0}, near_outside[2] = {5.000000000000001, 0};
  const std::vector<const double*> triangle = corners(circle, {0, 2, 3});
  EXPECT_EQ(geometry::in_sphere(2, triangle.data(), near_inside), 1);
  EXPECT_EQ(geometry::in_sphere(2, triangle.data(), near_outside), -1);
}

TEST(PredicateTest, CosphericalCubeCorners) {
  std::vector<double> coords;
  for (int i = 0; i < 8; ++i)
    for (int k = 0; k < 3; ++k) coords.push_back((i >> k) & 1);
  const PointCloud cube = cloud_of(3, coords);
  const std::vector<const double*> tet = corners(cube, {0, 1, 2, 4});
  for (int q = 3; q < 8; ++q) {
    if (q == 4) continue;
    EXPECT_EQ(geometry::in_sphere(3, tet.data(), cube.point(static_cast<std::size_t>(q))), 0) << "q=" << q;
  }
  const double centre[3] = {0.5, 0.5, 0.5};
  EXPECT_EQ(geometry::in_sphere(3, tet.data(), centre), 1);
  // Four coplanar corners: a flat simplex.
  const std::vector<const double*> face = corners(cube, {0, 1, 2, 3});
  EXPECT_EQ(geometry::simplex_orientation(3, face.data()), 0);
  EXPECT_EQ(geometry::simplex_volume_times_factorial(3, face.data()), 0);
}

// Points one unit in the last place apart from degenerate positions, at offsets up to 1e9:
// every double-precision evaluation is wrong or undecided here; only the exact path is right.
TEST(PredicateTest, NearDegenerateAtLargeOffsets) {
  for (const double offset : {0.0, 1.0, 1e3, 1e9, -1e9}) {
    for (const double step : {1e-12, 1e-3, 1.0}) {
      SCOPED_TRACE("offset=" + std::to_string(offset) + " step=" + std::to_string(step));
      // Three collinear points (exactly, when representable), then the middle one nudged.
      const double a = offset, b = offset + step, c = offset + 2 * step;
      for (const int nudge : {-2, -1, 0, 1, 2}) {
        double y = offset;
        for (int i = 0; i < std::abs(nudge); ++i) y = std::nextafter(y, nudge > 0 ? INFINITY : -INFINITY);
        const PointCloud cloud = cloud_of(2, {a, offset, b, y, c, offset, b + step, offset + step});
        expect_predicates_agree(cloud);
      }
      // Four almost cocircular points: a square at the offset with one corner nudged.
      for (const int nudge : {-1, 0, 1}) {
        double x = offset + step;
        if (nudge != 0) x = std::nextafter(x, nudge > 0 ? INFINITY : -INFINITY);
        const PointCloud square = cloud_of(2, {offset, offset, offset + step, offset, offset + step, offset + step, offset, x});
        expect_predicates_agree(square);
      }
    }
  }
}

TEST(PredicateTest, NearDegenerateRandomPerturbationsInHigherDimensions) {
  // d+1 points on the hyperplane x_0 + ... + x_{d-1} = offset*d (integers), then one coordinate
  // of the last point nudged by one ulp: the orientation is decided only exactly.
  for (int d = 3; d <= 6; ++d) {
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
      SCOPED_TRACE("d=" + std::to_string(d) + " seed=" + std::to_string(seed));
      TestRandom random(seed);
      PointCloud cloud;
      cloud.dim = d;
      const double offset = 1e9;
      for (int i = 0; i < d + 2; ++i) {
        double rest = 0;
        for (int k = 0; k + 1 < d; ++k) {
          const double x = offset + static_cast<double>(random.integer(-1000, 1000));
          cloud.coords.push_back(x);
          rest += x - offset;
        }
        cloud.coords.push_back(offset - rest);
      }
      double& last = cloud.coords[static_cast<std::size_t>(d * (d + 1) - 1)];
      last = std::nextafter(last, (seed % 2) ? INFINITY : -INFINITY);
      expect_predicates_agree(cloud);
    }
  }
}

TEST(PredicateTest, ExactRationalIsExact) {
  for (const double x : {0.0, -0.0, 0.1, -1e-310, 1e300, 3.0, std::nextafter(1.0, 2.0)}) {
    EXPECT_EQ(geometry::exact_rational(x), mpq_class(x)) << x;
  }
}

// ---- The symbolic perturbation. ----

std::vector<std::int64_t> ranks_for(std::size_t count, std::uint64_t seed) {
  std::vector<std::int64_t> ranks;
  for (std::size_t i = 0; i < count; ++i) ranks.push_back(static_cast<std::int64_t>(i));
  TestRandom random(seed);
  for (std::size_t i = count; i > 1; --i) std::swap(ranks[i - 1], ranks[static_cast<std::size_t>(random.integer(0, static_cast<std::int64_t>(i) - 1))]);
  return ranks;
}

int perturbed(int d, const std::vector<const double*>& all, const std::vector<std::int64_t>& ranks) {
  const Frame frame{d, d, nullptr, all[0]};
  return geometry::lifted_sign_perturbed(frame, all.data() + 1, ranks.data());
}

// Checks on d+2 cospherical (or any) points: nonzero, equal to the reference, and flipped by
// every transposition of two points (ranks travel with their points).
void expect_perturbation_properties(int d, const std::vector<const double*>& all, std::uint64_t seed) {
  const std::vector<std::int64_t> ranks = ranks_for(all.size(), seed);
  const int sign = perturbed(d, all, ranks);
  EXPECT_NE(sign, 0);
  const std::vector<const double*> rest(all.begin() + 1, all.end());
  EXPECT_EQ(sign, reference_lifted_sign_perturbed(d, all[0], rest, ranks));
  const Frame exact_frame{d, d, nullptr, all[0]};
  EXPECT_EQ(geometry::exact_lifted_sign_perturbed(exact_frame, all.data() + 1, ranks.data()), sign);
  const Frame frame{d, d, nullptr, all[0]};
  const int unperturbed = geometry::lifted_sign(frame, all.data() + 1);
  if (unperturbed != 0) {
    EXPECT_EQ(sign, unperturbed);
  }
  for (std::size_t i = 0; i < all.size(); ++i)
    for (std::size_t j = i + 1; j < all.size(); ++j) {
      std::vector<const double*> swapped = all;
      std::vector<std::int64_t> swapped_ranks = ranks;
      std::swap(swapped[i], swapped[j]);
      std::swap(swapped_ranks[i], swapped_ranks[j]);
      EXPECT_EQ(perturbed(d, swapped, swapped_ranks), -sign) << "swap " << i << "," << j;
    }
}

TEST(PredicateTest, PerturbedLiftedSignOnCocircularPoints) {
  const PointCloud circle = cloud_of(2, {3, 4, 5, 0, 0, 5, -4, 3, 4, -3, -5, 0});
  for (std::uint64_t seed = 1; seed <= 24; ++seed) {
    SCOPED_TRACE("seed=" + std::to_string(seed));
    expect_perturbation_properties(2, corners(circle, {0, 1, 2, 3}), seed);
    expect_perturbation_properties(2, corners(circle, {5, 2, 4, 0}), seed);
  }
  const PointCloud square = cloud_of(2, {0, 0, 1, 0, 1, 1, 0, 1});
  for (std::uint64_t seed = 1; seed <= 24; ++seed) expect_perturbation_properties(2, corners(square, {0, 1, 2, 3}), seed);
}

TEST(PredicateTest, PerturbedLiftedSignOnCubeCornersAndGrids) {
  std::vector<double> coords;
  for (int i = 0; i < 8; ++i)
    for (int k = 0; k < 3; ++k) coords.push_back((i >> k) & 1);
  const PointCloud cube = cloud_of(3, coords);
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    SCOPED_TRACE("seed=" + std::to_string(seed));
    expect_perturbation_properties(3, corners(cube, {0, 1, 2, 4, 7}), seed);
    expect_perturbation_properties(3, corners(cube, {3, 5, 6, 0, 7}), seed);
  }
  // Random grid points in d = 2..4: whenever the d+2 points span E^d the sign is never zero.
  for (int d = 2; d <= 4; ++d) {
    for (std::uint64_t seed = 1; seed <= 80; ++seed) {
      const PointCloud cloud = random_integer_points(static_cast<std::size_t>(d + 2), d, 0, 2, seed);
      const std::vector<const double*> all = corners(cloud, first_ids(d + 2));
      // Spanning: some d+1 of the points have nonzero volume.
      bool spans = false;
      for (int skip = 0; skip < d + 2 && !spans; ++skip) {
        std::vector<const double*> simplex;
        for (int i = 0; i < d + 2; ++i)
          if (i != skip) simplex.push_back(all[static_cast<std::size_t>(i)]);
        spans = reference_orientation(d, simplex) != 0;
      }
      bool distinct = true;
      for (int i = 0; i < d + 2; ++i)
        for (int j = i + 1; j < d + 2; ++j)
          if (std::equal(all[static_cast<std::size_t>(i)], all[static_cast<std::size_t>(i)] + d, all[static_cast<std::size_t>(j)])) distinct = false;
      if (!spans || !distinct) continue;
      SCOPED_TRACE("d=" + std::to_string(d) + " seed=" + std::to_string(seed));
      expect_perturbation_properties(d, all, seed);
    }
  }
}

// lifted_tie_sign told the common sign of the orientations without the last point and without
// the next to last (a facet search's candidate and tested point, both on the facet's open side)
// gives what it computes without being told, whichever point is the most perturbed: cospherical
// integer points (cube corners and a grid's cells) in 2D to 4D, every order of ranks tried.
TEST(PredicateTest, TieSignWithTheOpenSideKnownAgrees) {
  int told = 0;
  for (int d = 2; d <= 4; ++d) {
    std::vector<double> coords;
    for (int i = 0; i < (1 << d); ++i)
      for (int k = 0; k < d; ++k) coords.push_back(2.0 * ((i >> k) & 1) + k);  // a box of side 2
    const PointCloud box = cloud_of(d, coords);
    TestRandom random(static_cast<std::uint64_t>(d) * 101);
    for (int trial = 0; trial < 60; ++trial) {
      // d + 2 distinct corners (all on the box's sphere), in random order.
      std::vector<std::int32_t> ids(static_cast<std::size_t>(1 << d));
      for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = static_cast<std::int32_t>(i);
      for (std::size_t i = ids.size() - 1; i > 0; --i) std::swap(ids[i], ids[static_cast<std::size_t>(random.uniform() * static_cast<double>(i + 1))]);
      ids.resize(static_cast<std::size_t>(d + 2));
      const std::vector<const double*> all = corners(box, ids);
      const Frame frame{d, d, nullptr, all[0]};
      std::vector<const double*> without_last(all.begin() + 1, all.end() - 1);
      std::vector<const double*> without_next(all.begin() + 1, all.end() - 2);
      without_next.push_back(all.back());
      const int a = geometry::orientation(frame, without_last.data()), b = geometry::orientation(frame, without_next.data());
      if (a == 0 || a != b) continue;
      std::vector<std::int64_t> ranks(static_cast<std::size_t>(d + 2));
      for (int order = 0; order < 24; ++order) {
        for (std::size_t i = 0; i < ranks.size(); ++i) ranks[i] = static_cast<std::int64_t>(i);
        for (std::size_t i = ranks.size() - 1; i > 0; --i) std::swap(ranks[i], ranks[static_cast<std::size_t>(random.uniform() * static_cast<double>(i + 1))]);
        SCOPED_TRACE("d=" + std::to_string(d) + " trial=" + std::to_string(trial) + " order=" + std::to_string(order));
        const int computed = geometry::lifted_tie_sign(frame, all.data() + 1, ranks.data());
        ASSERT_EQ(geometry::lifted_tie_sign(frame, all.data() + 1, ranks.data(), a), computed);
        ASSERT_EQ(computed, geometry::lifted_sign_perturbed(frame, all.data() + 1, ranks.data()));
        const std::int64_t top = *std::max_element(ranks.begin(), ranks.end());
        if (ranks[static_cast<std::size_t>(d)] == top || ranks[static_cast<std::size_t>(d + 1)] == top) ++told;
      }
    }
  }
  EXPECT_GT(told, 200) << "the last two points should often be the most perturbed";
}

// In 6D and 7D lifted_tie_sign takes its orientations from cofactors cached per set of rows
// (indexed by their addresses, checked by their coordinates): ties of a decimal box's corners
// (all on one sphere; no filter decides them), each round's points written into the same
// buffers, and within a round the last point varied (the cached rows repeat), against the
// perturbation's definition.
TEST(PredicateTest, TieSignFromCachedOrientationsIn6DAnd7D) {
  for (int d = 6; d <= 7; ++d) {
    TestRandom random(static_cast<std::uint64_t>(d) * 31);
    std::vector<std::vector<double>> buffers(static_cast<std::size_t>(d + 2), std::vector<double>(static_cast<std::size_t>(d)));
    std::vector<const double*> all;
    for (const auto& b : buffers) all.push_back(b.data());
    const auto corner = [&](std::vector<double>& out) {
      for (double& x : out) x = random.uniform() < 0.5 ? 0.3 : 0.7;
    };
    int checked = 0;
    for (int round = 0; round < 60; ++round) {
      for (auto& b : buffers) corner(b);
      for (int last = 0; last < 8; ++last) {
        corner(buffers.back());
        bool distinct = true, spans = false;
        for (int i = 0; i < d + 2; ++i)
          for (int j = i + 1; j < d + 2; ++j)
            if (buffers[static_cast<std::size_t>(i)] == buffers[static_cast<std::size_t>(j)]) distinct = false;
        for (int skip = 0; skip < d + 2 && !spans && distinct; ++skip) {
          std::vector<const double*> simplex;
          for (int i = 0; i < d + 2; ++i)
            if (i != skip) simplex.push_back(all[static_cast<std::size_t>(i)]);
          spans = reference_orientation(d, simplex) != 0;
        }
        if (!distinct || !spans) continue;
        const std::vector<std::int64_t> ranks = ranks_for(all.size(), static_cast<std::uint64_t>(round * 8 + last + 1));
        const Frame frame{d, d, nullptr, all[0]};
        const std::vector<const double*> rest(all.begin() + 1, all.end());
        SCOPED_TRACE("d=" + std::to_string(d) + " round=" + std::to_string(round) + " last=" + std::to_string(last));
        ASSERT_EQ(geometry::lifted_tie_sign(frame, all.data() + 1, ranks.data()), reference_lifted_sign_perturbed(d, all[0], rest, ranks));
        ++checked;
      }
    }
    EXPECT_GT(checked, 100) << "d=" << d;
  }
}

// The exactness proofs read exponents from the bits: against frexp on normal, subnormal and
// negative values, and the limits against ldexp over the whole normal range.
TEST(ErrorBound, LowestBitExponentAndPowerOfTwoLimitMatchTheLibrary) {
  const double values[] = {1.0, -1.0, 3.0, 0.75, -6.0, 0x1p-1022, 0x1p-1074, 3 * 0x1p-1074, 0x1.8p-1030, 1e300, -1e-310,
                           std::nextafter(1.0, 2.0), 0.1, 4503599627370497.0, 9007199254740992.0};
  for (const double x : values) {
    int exponent = 0;
    double mantissa = std::frexp(x, &exponent);  // x = mantissa * 2^exponent, 0.5 <= |mantissa| < 1
    int lowest = exponent;
    while (mantissa != std::trunc(mantissa)) {
      mantissa *= 2;
      --lowest;
    }
    while (std::fmod(mantissa, 2.0) == 0.0) {
      mantissa /= 2;
      ++lowest;
    }
    EXPECT_EQ(geometry::lowest_bit_exponent(x), lowest) << x;
  }
  for (int e = -1022; e <= 1023; ++e) EXPECT_EQ(geometry::power_of_two_limit(e), std::ldexp(1.0, e)) << e;
  EXPECT_EQ(geometry::power_of_two_limit(1024), INFINITY);
  EXPECT_EQ(geometry::power_of_two_limit(-1023), 0.0);  // below the normal range: no limit holds
}

// Integer points whose 2x2 products need more than 53 bits: (a, b) and (a + 1, b + 1) have the
// determinant a - b, tiny beside the products near 2^56. Their entries are exact integers,
// so only the bound on the products and on the whole (small_orientation's proof) keeps a
// rounded zero from being taken for exact. Also with a difference that itself rounds (the
// base far on the other side) and in 3D, where the 2x2 minors are the intermediate terms.
TEST(PredicateTest, RoundedIntegerEvaluationsAreNotTakenForExact) {
  int decided_by_rounding = 0;
  for (const double a : {0x1p27 + 1, 0x1p28 + 3, 0x1p30 + 5, 0x1p26 - 3}) {
    for (const double delta : {-2.0, -1.0, 0.0, 1.0, 2.0}) {
      const double b = a - delta;
      SCOPED_TRACE("a=" + std::to_string(a) + " delta=" + std::to_string(delta));
      expect_predicates_agree(cloud_of(2, {0, 0, a, b, a + 1, b + 1, 1, 2}));
      expect_predicates_agree(cloud_of(3, {0, 0, 0, a, b, 0, a + 1, b + 1, 0, 0, 0, 1, 1, 2, 3}));
      expect_predicates_agree(cloud_of(3, {0, 0, 0, a, 0, b, 0, 1, 0, a + 1, 0, b + 1, 1, 2, 3}));
      // In 4D and 5D (fixed_orientation): the same minor on two axes, unit steps on the others.
      expect_predicates_agree(cloud_of(4, {0, 0, 0, 0, a, b, 0, 0, a + 1, b + 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 1, 2, 3, 4}));
      expect_predicates_agree(cloud_of(5, {0, 0, 0, 0, 0, 0, 0, 1, 0, 0, a, 0, 0, b, 0, 0, 0, 0, 0, 1, a + 1, 0, 0, b + 1, 0,
                                           0, 1, 0, 0, 0, 1, 2, 3, 4, 5}));
      // The base at -(2^52 - a): every difference is 2^52 more than above, and some round.
      const double far = -(0x1p52 - a);
      expect_predicates_agree(cloud_of(2, {far, 0, a, b, a + 1, b + 1, 1, 2}));
      if (a * (b + 1) - b * (a + 1) != a - b) ++decided_by_rounding;
    }
  }
  EXPECT_GT(decided_by_rounding, 0) << "some cases must round in double precision";
}

// The orientations of small integer points in 4D to 7D, flat ones included (the symbolic
// perturbation asks them at every tie of an integer grid): the filter decides every one, by its
// bound or by the proof that nothing rounded, and agrees with the reference.
TEST(PredicateTest, IntegerOrientationsIn4DTo7DAreDecidedByTheFilter) {
  int flat = 0;
  for (int d = 4; d <= 7; ++d) {
    for (std::uint64_t seed = 1; seed <= 300; ++seed) {
      SCOPED_TRACE("d=" + std::to_string(d) + " seed=" + std::to_string(seed));
      const PointCloud cloud = random_integer_points(static_cast<std::size_t>(d + 1), d, 0, 2, seed);
      const std::vector<const double*> simplex = corners(cloud, first_ids(d + 1));
      const Frame frame{d, d, nullptr, simplex[0]};
      const std::optional<int> s = geometry::filtered_orientation(frame, simplex.data() + 1);
      ASSERT_TRUE(s.has_value());
      const int exact = reference_orientation(d, simplex);
      EXPECT_EQ(*s, exact);
      if (exact == 0) ++flat;
    }
  }
  EXPECT_GT(flat, 100) << "most of these small simplices should be flat";
}

// Both products of a 2x2 minor underflow to zero (1e-135 * 1e-190), and a later entry of
// 1e100 multiplies the lost minor: a filter blind to underflow certifies the wrong sign.
TEST(Predicates, UnderflowInsideTheExpansionIsNotCertified) {
  const double a[2] = {0, 0}, b[2] = {1e-135, 0}, c[2] = {1, 1e-190}, q[2] = {1e100, 1e-130};
  const std::vector<const double*> simplex = {a, b, c};
  EXPECT_EQ(geometry::in_sphere(2, simplex.data(), q), reference_in_sphere(2, simplex, q));
  EXPECT_EQ(geometry::in_sphere(2, simplex.data(), q), -1);
}

}  // namespace
}  // namespace drange::test

// MinorTable's flat term tables against the expansion written out: for each subset of r + 1
// columns, along row r, the cofactor signs (-1)^(r + position) and |entry| * |minor| for the
// absolute tree, summed in column order; bit for bit, 2 to 12 columns.
TEST(Minors, FlatTermsMatchTheLaplaceExpansionBitForBit) {
  std::uint64_t state = 12345;
  auto next = [&state] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(static_cast<std::int64_t>(state >> 11) - (std::int64_t{1} << 52)) / 0x1p52;
  };
  for (int columns = 2; columns <= drange::geometry::SubsetTable::kMaxColumns; ++columns) {
    drange::geometry::MinorTable table(columns);
    const std::size_t size = std::size_t{1} << columns;
    std::vector<double> value(size, 0.0), absolute(size, 0.0);
    value[0] = absolute[0] = 1.0;
    for (int r = 0; r < columns; ++r) {
      std::vector<double> row(static_cast<std::size_t>(columns));
      for (double& x : row) x = next();
      table.set_row(r, row.data());
      for (std::uint32_t mask = 1; mask < size; ++mask) {
        if (__builtin_popcount(mask) != r + 1) continue;
        double v = 0.0, a = 0.0;
        int position = 0;
        for (int j = 0; j < columns; ++j) {
          if (!(mask >> j & 1)) continue;
          const std::uint32_t sub = mask & ~(std::uint32_t{1} << j);
          const double term = row[static_cast<std::size_t>(j)] * value[sub];
          if ((r + position) & 1) v -= term; else v += term;
          a += std::fabs(row[static_cast<std::size_t>(j)]) * absolute[sub];
          ++position;
        }
        value[mask] = v;
        absolute[mask] = a;
        ASSERT_EQ(table.minor(mask), v) << columns << " columns, mask " << mask;
        ASSERT_EQ(table.abs_minor(mask), a) << columns << " columns, mask " << mask;
      }
    }
  }
}

// MinorTable::set_row_fixed (the search kernels' facets, C = d + 1 columns) against set_row:
// the same doubles, bit for bit (signed zeros too), row after row, for every column count the
// kernels use; with rows of random values, of small integers (exact cancellations, zeros) and
// with zero entries.
namespace {
template <int C>
void expect_fixed_matches_flat(std::uint64_t seed) {
  std::uint64_t state = seed;
  auto next = [&state] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return state >> 11;
  };
  const auto same_bits = [](double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; };
  for (int kind = 0; kind < 3; ++kind) {
    drange::geometry::MinorTable flat(C), fixed(C);
    for (int r = 0; r < C; ++r) {
      double row[C];
      for (double& x : row) {
        const std::uint64_t bits = next();
        x = kind == 0   ? static_cast<double>(static_cast<std::int64_t>(bits) - (std::int64_t{1} << 52)) / 0x1p52
            : kind == 1 ? static_cast<double>(static_cast<int>(bits % 5) - 2)
                        : (bits % 3 == 0 ? 0.0 : static_cast<double>(bits % 1000) / 7.0);
      }
      flat.set_row(r, row);
      fixed.set_row_fixed<C>(r, row);
      for (std::uint32_t mask = 1; mask < (std::uint32_t{1} << C); ++mask) {
        if (__builtin_popcount(mask) != r + 1) continue;
        ASSERT_TRUE(same_bits(fixed.minor(mask), flat.minor(mask))) << C << " columns, kind " << kind << ", mask " << mask;
        ASSERT_TRUE(same_bits(fixed.abs_minor(mask), flat.abs_minor(mask))) << C << " columns, kind " << kind << ", mask " << mask;
      }
    }
  }
}
}  // namespace

TEST(Minors, FixedTermsMatchTheFlatTermsBitForBit) {
  expect_fixed_matches_flat<3>(1);
  expect_fixed_matches_flat<4>(2);
  expect_fixed_matches_flat<5>(3);
  expect_fixed_matches_flat<6>(4);
  expect_fixed_matches_flat<7>(5);
  expect_fixed_matches_flat<8>(6);
  expect_fixed_matches_flat<9>(7);
}
