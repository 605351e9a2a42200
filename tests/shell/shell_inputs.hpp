// tests/shell/shell_inputs.hpp: the inputs of the sphere shell's tests (points near a sphere,
// concentric spheres, bubbles, with outliers) and the exact offsets they are checked against.
#pragma once

#include <gmpxx.h>

#include <cstdint>
#include <vector>

#include "delaunay/facet_search.hpp"
#include "delaunay/prepare_points.hpp"
#include "delaunay/sphere_shell.hpp"
#include "delaunay/team.hpp"
#include "drange/generate.hpp"
#include "oracle.hpp"

namespace drange::test::shell {

inline drange::engine::PointStore store_of(const PointCloud& points) {
  drange::engine::Team team(1);
  std::vector<drange::Duplicate> duplicates;
  return drange::engine::prepare_points(points, drange::engine::search_leaf_size(points.dim), duplicates, team);
}

inline mpq_class exact_offset(const double* x, const double* g, int dim, double rho) {
  mpq_class s = -mpq_class(rho);
  for (int k = 0; k < dim; ++k) {
    const mpq_class y = mpq_class(x[k]) - mpq_class(g[k]);
    s += y * y;
  }
  return s;
}

// Points on the unit sphere of dimension d scaled by `radius` about `centre`, each moved off it
// by a relative `noise` (0: cospherical up to rounding).
inline PointCloud sphere(std::size_t n, int d, std::uint64_t seed, double radius = 1.0, double centre = 0.0, double noise = 0.0) {
  PointCloud points = drange::generate_points(Distribution::Sphere, n, d, seed);
  drange::test::TestRandom random(seed + 1);
  for (std::size_t i = 0; i < n; ++i) {
    const double scale = radius * (1 + noise * (2 * random.uniform() - 1));
    for (int k = 0; k < d; ++k) points.coords[i * static_cast<std::size_t>(d) + static_cast<std::size_t>(k)] =
        centre + scale * points.coords[i * static_cast<std::size_t>(d) + static_cast<std::size_t>(k)];
  }
  return points;
}

// The 2^d corners of the cube [-half, half]^d added to `points`: what users add to bound the
// Voronoi cells of points on a sphere. Far from the sphere, they pull its least-squares fit off.
inline PointCloud with_cube_corners(PointCloud points, double half) {
  const int d = points.dim;
  for (int corner = 0; corner < (1 << d); ++corner)
    for (int k = 0; k < d; ++k) points.coords.push_back((corner >> k) & 1 ? half : -half);
  return points;
}

// `n` points on each of the spheres of the given radii about `centre` (the layers of a
// spherical grid; a sphere with a smaller one inside).
inline PointCloud concentric(std::size_t n, int d, std::uint64_t seed, std::vector<double> radii, double centre = 0.0) {
  PointCloud points{d, {}};
  for (double radius : radii) {
    const PointCloud layer = sphere(n, d, seed++, radius, centre);
    points.coords.insert(points.coords.end(), layer.coords.begin(), layer.coords.end());
  }
  return points;
}

// `count` bubbles of `n` points each: spheres of radius `radius` about centres drawn in the
// cube [-1, 1]^d at least 3 radii apart (bubbles3 of bench/degenerate_families.py, smaller).
inline PointCloud bubbles(std::size_t count, std::size_t n, int d, std::uint64_t seed, double radius = 0.05) {
  drange::test::TestRandom random(seed);
  std::vector<std::vector<double>> centres;
  while (centres.size() < count) {
    std::vector<double> c(static_cast<std::size_t>(d));
    for (double& x : c) x = 2 * random.uniform() - 1;
    bool apart = true;
    for (const std::vector<double>& other : centres) {
      double distance2 = 0.0;
      for (int k = 0; k < d; ++k) distance2 += (c[static_cast<std::size_t>(k)] - other[static_cast<std::size_t>(k)]) * (c[static_cast<std::size_t>(k)] - other[static_cast<std::size_t>(k)]);
      apart = apart && distance2 > 9 * radius * radius;
    }
    if (apart) centres.push_back(std::move(c));
  }
  PointCloud points{d, {}};
  for (const std::vector<double>& c : centres) {
    const PointCloud unit = sphere(n, d, seed++);
    for (std::size_t i = 0; i < n; ++i)
      for (int k = 0; k < d; ++k) points.coords.push_back(c[static_cast<std::size_t>(k)] + radius * unit.point(i)[k]);
  }
  return points;
}

// The centre of the shell's sphere k.
inline std::vector<double> centre_of(const drange::engine::SphereShell& shell, std::int32_t k = 0) {
  const double* g = shell.sphere(k).centre;
  return {g, g + shell.dim};
}

// A sphere, and bubbles in a uniform background (several spheres, leaves straddling two, and
// points in none).
inline std::vector<PointCloud> shell_inputs(int d) {
  PointCloud mixed = bubbles(6, 300, d, 70 + static_cast<std::uint64_t>(d));
  const PointCloud background = drange::generate_points(Distribution::Uniform, 500, d, 71);
  mixed.coords.insert(mixed.coords.end(), background.coords.begin(), background.coords.end());
  return {sphere(2000, d, 11, 2.0, -0.5, 1e-12), mixed};
}

// n points on a sphere (radius 2, centre -0.5 on every axis) around n / 4 uniform in its ball:
// one sphere, found by patches (fewer than 9 in 10 points are on it), whose nodes near it mix
// points on it and inside it.
inline PointCloud sphere_around_ball(std::size_t n, int d, std::uint64_t seed) {
  PointCloud points = sphere(n, d, seed, 2.0, -0.5);
  const PointCloud inside = drange::generate_points(Distribution::Ball, n / 4, d, seed + 1);
  for (double x : inside.coords) points.coords.push_back(2.0 * x - 0.5);
  return points;
}

}  // namespace drange::test::shell
