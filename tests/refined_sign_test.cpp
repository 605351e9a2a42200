// tests/refined_sign_test.cpp: the double-double stage of the lifted predicate
// (geometry/refined_sign.hpp) against the rational reference (oracle.hpp).
//
// It may leave a case undecided, never decide one wrongly. And it must decide what it is for:
// points within rounding of a sphere, and points moved off one by far less than the double
// filter resolves. Exact ties are left to GMP.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "geometry/double_double.hpp"
#include "geometry/predicates.hpp"
#include "geometry/refined_sign.hpp"
#include "oracle.hpp"

namespace drange::test {
namespace {

using geometry::Frame;

// A point of the sphere of `radius` about `centre` (each coordinate), in direction of d random
// normal-ish values, then its distance from the centre scaled by (1 + nudge).
std::vector<double> on_sphere(TestRandom& random, int d, double centre, double radius, double nudge) {
  std::vector<double> v(static_cast<std::size_t>(d));
  double norm2 = 0.0;
  for (double& x : v) {
    x = 2 * random.uniform() - 1;
    norm2 += x * x;
  }
  const double scale = radius * (1 + nudge) / std::sqrt(norm2);
  for (double& x : v) x = centre + scale * x;
  return v;
}

struct Tally {
  int decided = 0, cases = 0;
};

// d + 2 points, the last one nudged: the refined sign, when it decides, is the exact sign.
void check_case(int d, TestRandom& random, double centre, double radius, double nudge, Tally& tally) {
  std::vector<std::vector<double>> points;
  for (int i = 0; i < d + 1; ++i) points.push_back(on_sphere(random, d, centre, radius, 0.0));
  points.push_back(on_sphere(random, d, centre, radius, nudge));
  std::vector<const double*> rows;
  for (int i = 1; i < d + 2; ++i) rows.push_back(points[static_cast<std::size_t>(i)].data());
  const Frame frame{d, d, nullptr, points[0].data()};
  const int exact = reference_lifted_sign(d, points[0].data(), rows);
  const std::optional<int> refined = geometry::refined_lifted_sign(frame, rows.data());
  ++tally.cases;
  if (refined) {
    ++tally.decided;
    ASSERT_EQ(*refined, exact) << "d=" << d << " centre=" << centre << " radius=" << radius << " nudge=" << nudge;
  }
  // The predicate itself, through whichever stage decides.
  ASSERT_EQ(geometry::lifted_sign(frame, rows.data()), exact) << "d=" << d << " nudge=" << nudge;
}

// Every test runs on both codes of the double-double products: fused multiply-adds (where the
// processor has them) and Dekker's splitting (as on processors without them).
class RefinedSign : public testing::TestWithParam<bool> {
 protected:
  void SetUp() override {
    geometry::set_refined_fma(GetParam());
    // Without FMA the "Fma" run would take Dekker's code again: skipped, not passed twice.
    if (GetParam() && !geometry::refined_fma()) GTEST_SKIP() << "SKIPPED: this CPU has no FMA: the FMA products were NOT tested";
  }
  void TearDown() override { geometry::set_refined_fma(true); }
};

INSTANTIATE_TEST_SUITE_P(Products, RefinedSign, testing::Bool(),
                         [](const testing::TestParamInfo<bool>& info) { return info.param ? "Fma" : "Dekker"; });

TEST(DoubleDouble, ProductsByFmaAndBySplittingAreTheSameBits) {
  // Both products are exact, so their low parts agree; the test's own std::fma is the library's
  // (exact too). Magnitudes from 2^-300 to 2^300, signs mixed.
  TestRandom random(5);
  for (int trial = 0; trial < 20000; ++trial) {
    const auto draw = [&] {
      const double hi = std::ldexp(random.uniform() - 0.5, static_cast<int>(random.uniform() * 600) - 300);
      return geometry::add({hi, 0.0}, {std::ldexp(hi, -55) * (random.uniform() - 0.5), 0.0});
    };
    const geometry::DoubleDouble x = draw(), y = draw();
    const geometry::DoubleDouble by_fma = geometry::multiply<true>(x, y), by_split = geometry::multiply<false>(x, y);
    ASSERT_EQ(by_fma.hi, by_split.hi) << "trial " << trial;
    ASSERT_EQ(by_fma.lo, by_split.lo) << "trial " << trial;
  }
}

TEST(DoubleDouble, OperationsAreWithinTheirBound) {
  TestRandom random(1);
  for (int trial = 0; trial < 2000; ++trial) {
    const geometry::DoubleDouble x = geometry::add({random.uniform() - 0.5, 0.0}, {std::ldexp(random.uniform(), -60), 0.0});
    const geometry::DoubleDouble y = geometry::difference(random.uniform() * 3, std::ldexp(random.uniform(), -57));
    const mpq_class qx = mpq_class(x.hi) + mpq_class(x.lo), qy = mpq_class(y.hi) + mpq_class(y.lo);
    for (const auto& [result, exact] : {std::pair{geometry::add(x, y), mpq_class(qx + qy)}, std::pair{geometry::multiply<true>(x, y), mpq_class(qx * qy)}, std::pair{geometry::multiply<false>(x, y), mpq_class(qx * qy)}}) {
      const mpq_class error = abs(mpq_class(result.hi) + mpq_class(result.lo) - exact);
      ASSERT_LE(error, abs(exact) * mpq_class(geometry::kDoubleDoubleRoundoff)) << "trial " << trial;
    }
  }
}

TEST_P(RefinedSign, AgreesWithTheRationalReferenceOnNearSphericalPoints) {
  // Random points of a sphere, rounded to doubles: within about 2^-53 of it, where the double
  // filter cannot decide and this stage must. Nudged by 2^-30 and 2^-45, where either may.
  for (int d = 2; d <= 5; ++d) {
    for (const double centre : {0.0, 0.3, 1e6}) {
      for (const double nudge : {0.0, 0x1p-30, -0x1p-45}) {
        SCOPED_TRACE("d=" + std::to_string(d) + " centre=" + std::to_string(centre) + " nudge=" + std::to_string(nudge));
        TestRandom random(static_cast<std::uint64_t>(d * 1000) + static_cast<std::uint64_t>(centre) + (nudge != 0.0));
        Tally tally;
        for (int trial = 0; trial < 200; ++trial) check_case(d, random, centre, 1.0, nudge, tally);
        EXPECT_GE(tally.decided, tally.cases * 9 / 10);
      }
    }
  }
}

TEST_P(RefinedSign, CofactorsDecideAsTheWholeDeterminantWithTheTestedRowFirst) {
  // One candidate's rows, many tested points near its sphere: RefinedCofactors gives what
  // refined_lifted_sign gives on the rows with the tested point's first and the candidate's (the
  // last of prepare's) next (the same operations), sign-corrected for the moves, and that is the
  // exact sign whenever it decides. The two-step preparation (the facet's rows once, then each
  // candidate) gives the same.
  for (int d = 2; d <= 5; ++d) {
    for (const double centre : {0.0, 0.3}) {
      TestRandom random(static_cast<std::uint64_t>(d * 77) + (centre != 0.0));
      std::vector<std::vector<double>> points;
      for (int i = 0; i < d + 1; ++i) points.push_back(on_sphere(random, d, centre, 1.0, 0.0));
      std::vector<const double*> rows;
      for (int i = 1; i < d + 1; ++i) rows.push_back(points[static_cast<std::size_t>(i)].data());
      const Frame frame{d, d, nullptr, points[0].data()};
      geometry::RefinedCofactors cofactors, in_two_steps;
      cofactors.prepare(frame, rows.data());
      // Another candidate first, then this one: the facet's minors serve both.
      const std::vector<double> other = on_sphere(random, d, centre, 1.0, 0.0);
      in_two_steps.prepare_facet(frame, rows.data());
      in_two_steps.prepare_candidate(frame, other.data());
      in_two_steps.prepare_candidate(frame, rows.back());
      int decided = 0;
      for (int trial = 0; trial < 300; ++trial) {
        const double nudge = trial % 3 == 0 ? 0.0 : (trial % 3 == 1 ? 0x1p-40 : -0x1p-48);
        const std::vector<double> x = on_sphere(random, d, centre, 1.0, nudge);
        SCOPED_TRACE("d=" + std::to_string(d) + " centre=" + std::to_string(centre) + " trial=" + std::to_string(trial));
        const std::optional<int> fast = cofactors.sign_with(frame, x.data());
        std::vector<const double*> first = {x.data(), rows.back()};
        first.insert(first.end(), rows.begin(), rows.end() - 1);
        std::optional<int> whole = geometry::refined_lifted_sign(frame, first.data());
        if (whole) whole = -*whole;  // [x, candidate, rest] to [rest, candidate, x]: 2d - 1 transpositions
        ASSERT_EQ(fast, whole);
        ASSERT_EQ(in_two_steps.sign_with(frame, x.data()), fast);
        std::vector<const double*> last = rows;
        last.push_back(x.data());
        if (fast) {
          ++decided;
          ASSERT_EQ(*fast, reference_lifted_sign(d, points[0].data(), last));
        }
      }
      EXPECT_GE(decided, 270) << "d=" << d;
    }
  }
  // Too many rows: it declines rather than decide.
  std::vector<std::vector<double>> high(7, std::vector<double>(6, 0.0));
  for (int i = 1; i < 7; ++i) high[static_cast<std::size_t>(i)][static_cast<std::size_t>(i - 1)] = 1.0;
  std::vector<const double*> rows;
  for (int i = 1; i < 7; ++i) rows.push_back(high[static_cast<std::size_t>(i)].data());
  geometry::RefinedCofactors cofactors;
  cofactors.prepare(Frame{6, 6, nullptr, high[0].data()}, rows.data());
  EXPECT_FALSE(cofactors.sign_with(Frame{6, 6, nullptr, high[0].data()}, high[1].data()));
}

TEST_P(RefinedSign, QuickSignDecidesAgainstCandidatesWithinRoundingOfTheFacetsPlane) {
  // A facet and a candidate on one decimal lattice plane (x + y + z = 1.2, or x + y = 0.7 in
  // 2D; within rounding in binary): the candidate's cofactors in doubles are noise, its own
  // double-double ones are not. quick_sign_with must give the exact sign whenever it decides,
  // the same as sign_with, and decide nearly all tested points off the plane (those on it are
  // within rounding of the candidate's huge sphere too, near the facet).
  for (int d = 2; d <= 3; ++d) {
    TestRandom random(static_cast<std::uint64_t>(d * 13));
    const auto on_plane = [&] {
      std::vector<double> p(static_cast<std::size_t>(d));
      int rest = d == 3 ? 120 : 70;  // in hundredths
      for (int k = 0; k + 1 < d; ++k) {
        const int step = static_cast<int>(random.uniform() * 60);
        p[static_cast<std::size_t>(k)] = step / 100.0;
        rest -= step;
      }
      p[static_cast<std::size_t>(d - 1)] = rest / 100.0;
      return p;
    };
    int decided = 0, cases = 0;
    for (int trial = 0; trial < 200; ++trial) {
      std::vector<std::vector<double>> points;
      for (int i = 0; i < d + 1; ++i) points.push_back(on_plane());
      std::vector<const double*> rows;
      for (int i = 1; i < d + 1; ++i) rows.push_back(points[static_cast<std::size_t>(i)].data());
      const Frame frame{d, d, nullptr, points[0].data()};
      geometry::RefinedCofactors cofactors;
      cofactors.prepare(frame, rows.data());
      for (int j = 0; j < 20; ++j) {
        std::vector<double> x = on_plane();
        if (j % 2) x[0] += std::round((random.uniform() - 0.5) * 20) / 100;  // off the plane
        std::vector<const double*> last = rows;
        last.push_back(x.data());
        const int exact = reference_lifted_sign(d, points[0].data(), last);
        const std::optional<int> quick = cofactors.quick_sign_with(frame, x.data());
        SCOPED_TRACE("d=" + std::to_string(d) + " trial=" + std::to_string(trial) + " j=" + std::to_string(j));
        if (j % 2 && exact != 0) ++cases;
        if (quick) {
          decided += j % 2;
          ASSERT_EQ(*quick, exact);
          ASSERT_EQ(cofactors.sign_with(frame, x.data()), quick);
        }
      }
    }
    // With these seeds: 2D 1 825 of 1 911, 3D 1 911 of 1 990 decided.
    EXPECT_GE(decided, cases * 9 / 10) << "d=" << d;
  }
}

TEST_P(RefinedSign, OrientationAgreesWithTheRationalReferenceNearAHyperplane) {
  // d points on a hyperplane through random directions, rounded to doubles (within about 2^-53
  // of it, where the double filter cannot decide), and one more nudged off it by 0, 2^-45 or
  // 2^-60 of its size: whenever the double-double stage decides, it is the exact sign; and it
  // decides nearly all the cases that are not exactly flat.
  for (int d = 2; d <= 5; ++d) {
    TestRandom random(static_cast<std::uint64_t>(d * 31));
    std::vector<double> normal(static_cast<std::size_t>(d));
    for (double& x : normal) x = 2 * random.uniform() - 1;
    int decided = 0, cases = 0;
    for (int trial = 0; trial < 300; ++trial) {
      std::vector<std::vector<double>> points;
      for (int i = 0; i < d + 1; ++i) {
        // A point of the hyperplane normal . x = 0.3: random in all coordinates but the last,
        // which is solved for (normal's last component is not 0 for these seeds).
        std::vector<double> p(static_cast<std::size_t>(d));
        double t = 0.3;
        for (int k = 0; k + 1 < d; ++k) {
          p[static_cast<std::size_t>(k)] = 2 * random.uniform() - 1;
          t -= normal[static_cast<std::size_t>(k)] * p[static_cast<std::size_t>(k)];
        }
        p[static_cast<std::size_t>(d - 1)] = t / normal[static_cast<std::size_t>(d - 1)];
        points.push_back(p);
      }
      const double nudge = trial % 3 == 0 ? 0.0 : (trial % 3 == 1 ? 0x1p-45 : -0x1p-60);
      points.back()[static_cast<std::size_t>(d - 1)] *= 1 + nudge;
      std::vector<const double*> simplex;
      for (const auto& p : points) simplex.push_back(p.data());
      const int exact = reference_orientation(d, simplex);
      const Frame frame{d, d, nullptr, points[0].data()};
      const std::optional<int> refined = geometry::refined_orientation(frame, simplex.data() + 1);
      SCOPED_TRACE("d=" + std::to_string(d) + " trial=" + std::to_string(trial));
      if (d <= geometry::kRefinedMaxRows) {
        // The facet's cofactors (its first d - 1 rows) give what the whole determinant gives with
        // the last point's row first, sign-corrected for the move.
        geometry::RefinedCofactors cofactors;
        cofactors.prepare_orientation(frame, simplex.data() + 1);
        std::vector<const double*> first = {simplex.back()};
        first.insert(first.end(), simplex.begin() + 1, simplex.end() - 1);
        std::optional<int> whole = geometry::refined_orientation(frame, first.data());
        if (whole && d % 2 == 0) whole = -*whole;  // d - 1 transpositions
        ASSERT_EQ(cofactors.sign_with(frame, simplex.back()), whole);
      }
      if (exact != 0) ++cases;
      if (refined) {
        ++decided;
        ASSERT_EQ(*refined, exact);
      }
      ASSERT_EQ(geometry::orientation(frame, simplex.data() + 1), exact);
    }
    EXPECT_GE(decided, cases * 9 / 10) << "d=" << d;
  }
  // Exactly flat: the integer points of a plane in 3D leave it undecided.
  const std::vector<std::vector<double>> flat = {{0, 0, 0}, {1, 2, 3}, {2, 4, 6}, {4, 1, 2}};
  const std::vector<const double*> rows = {flat[1].data(), flat[2].data(), flat[3].data()};
  EXPECT_EQ(reference_orientation(3, {flat[0].data(), flat[1].data(), flat[2].data(), flat[3].data()}), 0);
  EXPECT_FALSE(geometry::refined_orientation(Frame{3, 3, nullptr, flat[0].data()}, rows.data()));
}

TEST_P(RefinedSign, AgreesOnExactlyCosphericalPointsMovedByAFewUlps) {
  // Integer points of a circle, a sphere and a 3-sphere, scaled by 2^20 and moved to an
  // offset (all exact), with one coordinate of the last point moved by k units in the last
  // place (its largest one): the determinant is then about 2^-50 of its terms, or exactly 0 for
  // k = 0.
  const std::vector<std::vector<std::vector<double>>> sets = {
      {{3, 4}, {-4, 3}, {0, -5}, {5, 0}},
      {{1, 2, 2}, {2, -1, 2}, {-2, 2, 1}, {3, 0, 0}, {0, -3, 0}},
      {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}, {-1, 0, 0, 0}, {0, -1, 0, 0}},
  };
  for (const auto& set : sets) {
    const int d = static_cast<int>(set[0].size());
    for (const double offset : {0.0, 1024.0, -0x1p30}) {
      for (const int k : {0, 1, -1, 3, -1000}) {
        std::vector<std::vector<double>> points = set;
        for (auto& p : points)
          for (double& x : p) x = x * 0x1p20 + offset;
        // A nonzero coordinate: one ulp from 0 is a denormal, whose square underflows.
        double& moved = *std::max_element(points.back().begin(), points.back().end(),
                                          [](double a, double b) { return std::fabs(a) < std::fabs(b); });
        for (int step = 0; step < std::abs(k); ++step) moved = std::nextafter(moved, k > 0 ? INFINITY : -INFINITY);
        std::vector<const double*> rows;
        for (std::size_t i = 1; i < points.size(); ++i) rows.push_back(points[i].data());
        const Frame frame{d, d, nullptr, points[0].data()};
        const int exact = reference_lifted_sign(d, points[0].data(), rows);
        const std::optional<int> refined = geometry::refined_lifted_sign(frame, rows.data());
        SCOPED_TRACE("d=" + std::to_string(d) + " offset=" + std::to_string(offset) + " k=" + std::to_string(k));
        if (k == 0) {
          EXPECT_EQ(exact, 0);
          EXPECT_FALSE(refined);
        } else {
          EXPECT_NE(exact, 0);
          ASSERT_TRUE(refined);
          EXPECT_EQ(*refined, exact);
        }
        EXPECT_EQ(geometry::lifted_sign(frame, rows.data()), exact);
      }
    }
  }
}

TEST_P(RefinedSign, LeavesExactTiesUndecided) {
  // Integer points on the circle x^2 + y^2 = 25 and on the sphere of radius 3 through
  // (1, 2, 2): exactly cospherical, so the determinant is 0 and only GMP may say so.
  const std::vector<std::vector<double>> circle = {{3, 4}, {-4, 3}, {0, -5}, {5, 0}};
  std::vector<const double*> rows = {circle[1].data(), circle[2].data(), circle[3].data()};
  EXPECT_FALSE(geometry::refined_lifted_sign(Frame{2, 2, nullptr, circle[0].data()}, rows.data()));
  EXPECT_EQ(geometry::lifted_sign(Frame{2, 2, nullptr, circle[0].data()}, rows.data()), 0);
  const std::vector<std::vector<double>> sphere = {{1, 2, 2}, {2, -1, 2}, {-2, 2, 1}, {3, 0, 0}, {0, -3, 0}};
  rows = {sphere[1].data(), sphere[2].data(), sphere[3].data(), sphere[4].data()};
  EXPECT_FALSE(geometry::refined_lifted_sign(Frame{3, 3, nullptr, sphere[0].data()}, rows.data()));
  EXPECT_EQ(geometry::lifted_sign(Frame{3, 3, nullptr, sphere[0].data()}, rows.data()), 0);
}

TEST_P(RefinedSign, UndecidedWhenOperationsUnderflowOrTheFrameIsTooLarge) {
  // A unit circle scaled to 1e-160: the squares underflow, and the bound no longer holds.
  TestRandom random(5);
  Tally tally;
  for (int trial = 0; trial < 50; ++trial) check_case(2, random, 0.0, 1e-160, 0x1p-70, tally);
  EXPECT_EQ(tally.decided, 0);
  // 6D: seven rows, beyond kRefinedMaxRows.
  static_assert(geometry::kRefinedMaxRows == 6);
  std::vector<std::vector<double>> points;
  for (int i = 0; i < 8; ++i) points.push_back(on_sphere(random, 6, 0.0, 1.0, i == 7 ? 0x1p-70 : 0.0));
  std::vector<const double*> rows;
  for (int i = 1; i < 8; ++i) rows.push_back(points[static_cast<std::size_t>(i)].data());
  EXPECT_FALSE(geometry::refined_lifted_sign(Frame{6, 6, nullptr, points[0].data()}, rows.data()));
}

}  // namespace
}  // namespace drange::test
