// io/generate.cpp: the test distributions of drange/generate.hpp, reproducible bit for bit
// from (distribution, n, d, seed) on every machine: a fixed generator (io/random.hpp) and
// only IEEE-exact arithmetic plus the portable log/exp (io/portable_math.hpp).
//
// Points are drawn in order, coordinate by coordinate, so for the uniform, ball, sphere and
// gaussian distributions the first m of n points are exactly the m points of a smaller run.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "drange/errors.hpp"
#include "drange/generate.hpp"
#include "io/portable_math.hpp"
#include "io/random.hpp"

namespace drange {
namespace {

constexpr double kClusterSigma = 0.01;

struct NamedDistribution {
  const char* name;
  Distribution distribution;
};

constexpr NamedDistribution kDistributions[] = {
    {"uniform", Distribution::Uniform},     {"ball", Distribution::Ball},
    {"sphere", Distribution::Sphere},       {"gaussian", Distribution::Gaussian},
    {"clustered", Distribution::Clustered}, {"grid", Distribution::Grid},
};

// A uniformly random direction: a standard normal vector, normalised (the normal
// distribution is rotation invariant). The zero vector is redrawn.
void random_direction(io::Random& random, double* out, int d) {
  for (;;) {
    double norm2 = 0;
    for (int k = 0; k < d; ++k) {
      out[k] = random.normal();
      norm2 += out[k] * out[k];
    }
    if (norm2 > 0) {
      const double norm = std::sqrt(norm2);
      for (int k = 0; k < d; ++k) out[k] /= norm;
      return;
    }
  }
}

void fill_uniform(io::Random& random, std::vector<double>& coords) {
  for (double& x : coords) x = random.uniform();
}

void fill_gaussian(io::Random& random, std::vector<double>& coords) {
  for (double& x : coords) x = random.normal();
}

void fill_sphere(io::Random& random, std::vector<double>& coords, int d) {
  for (std::size_t i = 0; i < coords.size(); i += static_cast<std::size_t>(d)) random_direction(random, &coords[i], d);
}

// The radius of a uniform point in the d-ball has density proportional to r^(d-1): it is
// U^(1/d). U is taken in (0, 1] so that its log is finite.
void fill_ball(io::Random& random, std::vector<double>& coords, int d) {
  for (std::size_t i = 0; i < coords.size(); i += static_cast<std::size_t>(d)) {
    random_direction(random, &coords[i], d);
    const double u = 1.0 - random.uniform();
    const double radius = io::portable_exp(io::portable_log(u) / d);
    for (int k = 0; k < d; ++k) coords[i + static_cast<std::size_t>(k)] *= radius;
  }
}

// floor(sqrt(n)) in integers: no rounding surprises near perfect squares.
std::uint64_t integer_sqrt(std::uint64_t n) {
  std::uint64_t low = 0, high = std::uint64_t{1} << 32;  // invariant: low^2 <= n < high^2
  while (high - low > 1) {
    const std::uint64_t mid = low + (high - low) / 2;
    if (mid * mid <= n) low = mid; else high = mid;
  }
  return low;
}

// floor(sqrt(n)) clusters (at least one), centres uniform in the unit cube, each point a
// gaussian of deviation 0.01 around a centre chosen uniformly.
void fill_clustered(io::Random& random, std::vector<double>& coords, std::size_t n, int d) {
  const std::size_t dim = static_cast<std::size_t>(d);
  const std::uint64_t clusters = std::max<std::uint64_t>(1, integer_sqrt(n));
  std::vector<double> centres(static_cast<std::size_t>(clusters) * dim);
  fill_uniform(random, centres);
  for (std::size_t i = 0; i < n; ++i) {
    const double* centre = &centres[static_cast<std::size_t>(random.below(clusters)) * dim];
    for (std::size_t k = 0; k < dim; ++k) coords[i * dim + k] = centre[k] + kClusterSigma * random.normal();
  }
}

// true when side^d >= n (side >= 1), computed without overflow.
bool power_reaches(std::uint64_t side, int d, std::uint64_t n) {
  std::uint64_t power = 1;
  for (int k = 0; k < d; ++k) {
    if (power >= n) return true;  // side >= 1: further factors keep it there
    if (power > UINT64_MAX / side) return true;
    power *= side;
  }
  return power >= n;
}

// The smallest side k with k^d >= n (binary search in integers).
std::uint64_t grid_side(std::uint64_t n, int d) {
  std::uint64_t low = 0, high = n;  // power_reaches(high) holds; low is below the answer or 0
  if (n <= 1) return n;
  while (high - low > 1) {
    const std::uint64_t mid = low + (high - low) / 2;
    if (power_reaches(mid, d, n)) high = mid; else low = mid;
  }
  return high;
}

// The first n points of {0..k-1}^d in lexicographic order: point i is i written in base k,
// the first coordinate the most significant digit.
void fill_grid(std::vector<double>& coords, std::size_t n, int d) {
  const std::uint64_t side = grid_side(n, d);
  const std::size_t dim = static_cast<std::size_t>(d);
  for (std::size_t i = 0; i < n; ++i) {
    std::uint64_t rest = i;
    for (std::size_t k = dim; k-- > 0;) {
      coords[i * dim + k] = static_cast<double>(rest % side);
      rest /= side;
    }
  }
}

}  // namespace

Distribution distribution_from_name(const std::string& name) {
  for (const NamedDistribution& entry : kDistributions) {
    if (name == entry.name) return entry.distribution;
  }
  throw UsageError("unknown distribution '" + name + "' (expected one of: " + distribution_names() + ")");
}

const char* distribution_names() { return "uniform, ball, sphere, gaussian, clustered, grid"; }

PointCloud generate_points(Distribution distribution, std::size_t n, int d, std::uint64_t seed) {
  if (d < 1) throw UsageError("generate_points: dimension must be at least 1, got " + std::to_string(d));
  const std::size_t dim = static_cast<std::size_t>(d);
  if (n > SIZE_MAX / sizeof(double) / dim) {
    throw UsageError("generate_points: " + std::to_string(n) + " points of dimension " + std::to_string(d) +
                     " do not fit in memory");
  }
  PointCloud cloud;
  cloud.dim = d;
  cloud.coords.resize(n * dim);
  io::Random random(seed);
  switch (distribution) {
    case Distribution::Uniform: fill_uniform(random, cloud.coords); break;
    case Distribution::Ball: fill_ball(random, cloud.coords, d); break;
    case Distribution::Sphere: fill_sphere(random, cloud.coords, d); break;
    case Distribution::Gaussian: fill_gaussian(random, cloud.coords); break;
    case Distribution::Clustered: fill_clustered(random, cloud.coords, n, d); break;
    case Distribution::Grid: fill_grid(cloud.coords, n, d); break;
  }
  return cloud;
}

}  // namespace drange
