// tests/generate_test.cpp: the test distributions of drange/generate.hpp: reproducible bit for
// bit (pinned values guard against any change of generator), in the promised region, the grid
// exactly, and the portable log/exp they rely on.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "drange/errors.hpp"
#include "drange/generate.hpp"
#include "io/portable_math.hpp"
#include "io/random.hpp"

namespace drange {
namespace {

const Distribution kAll[] = {Distribution::Uniform,  Distribution::Ball,      Distribution::Sphere,
                             Distribution::Gaussian, Distribution::Clustered, Distribution::Grid};

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

double norm(const PointCloud& cloud, std::size_t i) {
  double sum = 0;
  for (int k = 0; k < cloud.dim; ++k) sum += cloud.point(i)[k] * cloud.point(i)[k];
  return std::sqrt(sum);
}

TEST(Generate, SameSeedSameBits) {
  for (Distribution distribution : kAll) {
    for (int d : {1, 2, 3, 7}) {
      const PointCloud a = generate_points(distribution, 1000, d, 42);
      const PointCloud b = generate_points(distribution, 1000, d, 42);
      EXPECT_EQ(a.dim, d);
      EXPECT_EQ(a.size(), 1000u);
      EXPECT_TRUE(same_bits(a.coords, b.coords)) << "distribution " << static_cast<int>(distribution) << " d " << d;
    }
  }
}

TEST(Generate, DifferentSeedsDiffer) {
  for (Distribution distribution : kAll) {
    if (distribution == Distribution::Grid) continue;  // not random
    const PointCloud a = generate_points(distribution, 100, 3, 1);
    const PointCloud b = generate_points(distribution, 100, 3, 2);
    std::size_t equal = 0;
    for (std::size_t i = 0; i < a.coords.size(); ++i) equal += a.coords[i] == b.coords[i];
    EXPECT_EQ(equal, 0u) << "distribution " << static_cast<int>(distribution);
  }
}

// Pinned outputs: the promise is "the same points on every machine and every version". If this
// test fails, the generator changed, and every published experiment's input with it.
TEST(Generate, PinnedValues) {
  const PointCloud uniform = generate_points(Distribution::Uniform, 2, 2, 1);
  const PointCloud gaussian = generate_points(Distribution::Gaussian, 2, 2, 1);
  const PointCloud ball = generate_points(Distribution::Ball, 1, 3, 7);
  const PointCloud sphere = generate_points(Distribution::Sphere, 1, 3, 5);
  const std::vector<double> want_uniform = {0x1.67e55eda1f8e2p-1, 0x1.0a76ab2c8e6c9p-1, 0x1.25f12eac10548p-1,
                                            0x1.90b871ef099a8p-2};
  const std::vector<double> want_gaussian = {0x1.e267c87ac62ebp+0, 0x1.84abd879d0e18p-3, 0x1.4d55c9633557cp+0,
                                             -0x1.e8d0b0399ee9cp+0};
  const std::vector<double> want_ball = {0x1.03725fed78769p-1, -0x1.1e2fbe15f995cp-1, -0x1.47122ade8be33p-3};
  const std::vector<double> want_sphere = {-0x1.bb8c3b0ebe07cp-1, 0x1.abfc1d8e0f4b7p-2, 0x1.181e6138d155cp-2};
  EXPECT_TRUE(same_bits(uniform.coords, want_uniform));
  EXPECT_TRUE(same_bits(gaussian.coords, want_gaussian));
  EXPECT_TRUE(same_bits(ball.coords, want_ball));
  EXPECT_TRUE(same_bits(sphere.coords, want_sphere));
}

// The generator against the reference outputs published with xoshiro256** (state 1, 2, 3, 4)
// and splitmix64 (seed 0).
TEST(GenerateRandom, MatchesTheReferenceGenerators) {
  io::Random random = io::Random::from_state({1, 2, 3, 4});
  EXPECT_EQ(random.next(), 11520u);
  EXPECT_EQ(random.next(), 0u);
  EXPECT_EQ(random.next(), 1509978240u);
  EXPECT_EQ(random.next(), 1215971899390074240u);
  std::uint64_t splitmix_state = 0;
  EXPECT_EQ(io::Random::splitmix64(splitmix_state), 0xe220a8397b1dcdafu);
}

TEST(GenerateRandom, BelowIsInRangeAndCoversIt) {
  io::Random random(3);
  std::vector<int> seen(7, 0);
  for (int i = 0; i < 7000; ++i) {
    const std::uint64_t x = random.below(7);
    ASSERT_LT(x, 7u);
    ++seen[x];
  }
  for (int count : seen) EXPECT_NEAR(count, 1000, 150);
}

TEST(Generate, PrefixOfALongerRunIsTheShorterRun) {
  for (Distribution distribution : {Distribution::Uniform, Distribution::Ball, Distribution::Sphere,
                                    Distribution::Gaussian}) {
    const PointCloud longer = generate_points(distribution, 500, 3, 9);
    const PointCloud shorter = generate_points(distribution, 200, 3, 9);
    EXPECT_TRUE(same_bits(shorter.coords, std::vector<double>(longer.coords.begin(), longer.coords.begin() + 600)));
  }
}

TEST(Generate, UniformInTheHalfOpenUnitCube) {
  const PointCloud cloud = generate_points(Distribution::Uniform, 20000, 4, 3);
  double sum = 0;
  for (double x : cloud.coords) {
    ASSERT_GE(x, 0.0);
    ASSERT_LT(x, 1.0);
    sum += x;
  }
  EXPECT_NEAR(sum / static_cast<double>(cloud.coords.size()), 0.5, 0.01);
}

TEST(Generate, SphereHasNormOne) {
  for (int d : {1, 2, 3, 4, 6, 10}) {
    const PointCloud cloud = generate_points(Distribution::Sphere, 2000, d, 11);
    for (std::size_t i = 0; i < cloud.size(); ++i) ASSERT_NEAR(norm(cloud, i), 1.0, 1e-12) << "d " << d << " point " << i;
  }
}

TEST(Generate, BallIsInsideAndUniformInRadius) {
  for (int d : {1, 2, 3, 5}) {
    const PointCloud cloud = generate_points(Distribution::Ball, 20000, d, 5);
    // Uniform in volume: the ball of radius 2^(-1/d) holds half of the points.
    const double half_radius = std::pow(0.5, 1.0 / d);
    std::size_t inner = 0;
    for (std::size_t i = 0; i < cloud.size(); ++i) {
      const double r = norm(cloud, i);
      ASSERT_LE(r, 1.0);
      inner += r < half_radius;
    }
    EXPECT_NEAR(static_cast<double>(inner) / static_cast<double>(cloud.size()), 0.5, 0.015) << "d " << d;
  }
}

TEST(Generate, GaussianMoments) {
  const PointCloud cloud = generate_points(Distribution::Gaussian, 100000, 2, 8);
  double sum = 0, sum2 = 0;
  std::size_t beyond_two_sigma = 0;
  for (double x : cloud.coords) {
    sum += x;
    sum2 += x * x;
    beyond_two_sigma += std::fabs(x) > 2.0;
  }
  const double n = static_cast<double>(cloud.coords.size());
  EXPECT_NEAR(sum / n, 0.0, 0.01);
  EXPECT_NEAR(sum2 / n, 1.0, 0.02);
  EXPECT_NEAR(static_cast<double>(beyond_two_sigma) / n, 0.0455, 0.003);
}

TEST(Generate, ClusteredPointsAreCloseToFewCentres) {
  // 10000 points, 100 clusters of deviation 0.01: every point has a neighbour within 0.05
  // in its cluster, and the spread covers the cube.
  const PointCloud cloud = generate_points(Distribution::Clustered, 10000, 2, 4);
  double low = 1, high = 0;
  for (double x : cloud.coords) {
    low = std::min(low, x);
    high = std::max(high, x);
    ASSERT_GT(x, -0.1);
    ASSERT_LT(x, 1.1);
  }
  EXPECT_LT(low, 0.2);
  EXPECT_GT(high, 0.8);
  // Snap to a 0.1 grid of cells: clustered points occupy far fewer cells than uniform ones.
  std::vector<bool> occupied(12 * 12, false);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const int cx = static_cast<int>(std::floor((cloud.point(i)[0] + 0.1) * 10));
    const int cy = static_cast<int>(std::floor((cloud.point(i)[1] + 0.1) * 10));
    occupied[static_cast<std::size_t>(cx * 12 + cy)] = true;
  }
  EXPECT_LT(std::count(occupied.begin(), occupied.end(), true), 100);
}

TEST(Generate, ClusteredWithOnePoint) {
  const PointCloud cloud = generate_points(Distribution::Clustered, 1, 3, 1);
  EXPECT_EQ(cloud.size(), 1u);
}

TEST(Generate, GridIsTheLexicographicPrefix) {
  // n = 10 in 2D: side 4 (3^2 = 9 < 10 <= 16).
  EXPECT_EQ(generate_points(Distribution::Grid, 10, 2, 0).coords,
            (std::vector<double>{0, 0, 0, 1, 0, 2, 0, 3, 1, 0, 1, 1, 1, 2, 1, 3, 2, 0, 2, 1}));
  // n = 8 in 3D: the cube's corners.
  EXPECT_EQ(generate_points(Distribution::Grid, 8, 3, 0).coords,
            (std::vector<double>{0, 0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 1, 0, 0, 1, 0, 1, 1, 1, 0, 1, 1, 1}));
  EXPECT_EQ(generate_points(Distribution::Grid, 9, 2, 0).coords,
            (std::vector<double>{0, 0, 0, 1, 0, 2, 1, 0, 1, 1, 1, 2, 2, 0, 2, 1, 2, 2}));
  EXPECT_EQ(generate_points(Distribution::Grid, 1, 4, 0).coords, (std::vector<double>{0, 0, 0, 0}));
  EXPECT_EQ(generate_points(Distribution::Grid, 3, 1, 0).coords, (std::vector<double>{0, 1, 2}));
  EXPECT_TRUE(generate_points(Distribution::Grid, 0, 3, 0).coords.empty());
}

TEST(Generate, GridSideAtPerfectPowers) {
  // Floating-point cube roots get these wrong (cbrt(1e6) may be 99.99999...).
  const PointCloud full = generate_points(Distribution::Grid, 1000000, 3, 0);
  EXPECT_EQ(std::vector<double>(full.coords.end() - 3, full.coords.end()), (std::vector<double>{99, 99, 99}));
  const PointCloud one_more = generate_points(Distribution::Grid, 1000001, 3, 0);
  // Side 101: point 1000000 = 98*101^2 + 2*101 + 100.
  EXPECT_EQ(std::vector<double>(one_more.coords.end() - 6, one_more.coords.end()),
            (std::vector<double>{98, 2, 99, 98, 2, 100}));
  const PointCloud squares = generate_points(Distribution::Grid, 4096, 12, 0);  // 2^12: side 2
  EXPECT_EQ(std::vector<double>(squares.coords.end() - 12, squares.coords.end()), std::vector<double>(12, 1.0));
}

TEST(Generate, DistributionNames) {
  EXPECT_EQ(distribution_from_name("uniform"), Distribution::Uniform);
  EXPECT_EQ(distribution_from_name("ball"), Distribution::Ball);
  EXPECT_EQ(distribution_from_name("sphere"), Distribution::Sphere);
  EXPECT_EQ(distribution_from_name("gaussian"), Distribution::Gaussian);
  EXPECT_EQ(distribution_from_name("clustered"), Distribution::Clustered);
  EXPECT_EQ(distribution_from_name("grid"), Distribution::Grid);
  EXPECT_STREQ(distribution_names(), "uniform, ball, sphere, gaussian, clustered, grid");
  try {
    distribution_from_name("normal");
    FAIL() << "no error";
  } catch (const UsageError& e) {
    EXPECT_STREQ(e.what(),
                 "unknown distribution 'normal' (expected one of: uniform, ball, sphere, gaussian, clustered, grid)");
  }
}

TEST(Generate, RejectsBadDimension) {
  EXPECT_THROW(generate_points(Distribution::Uniform, 10, 0, 1), UsageError);
  EXPECT_THROW(generate_points(Distribution::Uniform, 10, -3, 1), UsageError);
  EXPECT_THROW(generate_points(Distribution::Uniform, SIZE_MAX / 2, 3, 1), UsageError);
  EXPECT_TRUE(generate_points(Distribution::Uniform, 0, 3, 1).coords.empty());
}

TEST(GeneratePortableMath, LogAgreesWithTheCLibrary) {
  for (double x : {1e-300, 1e-20, 0.001, 0.3, 0.5, 0.7071, 0.9999999, 1.0, 1.0000001, 2.0, 10.0, 12345.678, 1e300,
                   4.9e-324}) {
    const double want = std::log(x);
    EXPECT_NEAR(io::portable_log(x), want, 4e-16 * std::max(1.0, std::fabs(want))) << "x = " << x;
  }
  EXPECT_EQ(io::portable_log(1.0), 0.0);
}

TEST(GeneratePortableMath, ExpAgreesWithTheCLibrary) {
  for (double x : {-745.0, -700.0, -20.5, -1.0, -0.3, -1e-10, 0.0, 1e-10, 0.5, 1.0, 3.7, 100.0, 709.0}) {
    const double want = std::exp(x);
    EXPECT_NEAR(io::portable_exp(x), want, 4e-16 * want) << "x = " << x;
  }
  EXPECT_EQ(io::portable_exp(0.0), 1.0);
  EXPECT_EQ(io::portable_exp(-1000.0), 0.0);
  EXPECT_TRUE(std::isinf(io::portable_exp(1000.0)));
}

}  // namespace
}  // namespace drange
