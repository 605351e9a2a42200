// tests/shell/sphere_fit_test.cpp: which spheres the sphere shell finds (delaunay/shell/
// sphere_fit.hpp, through prepare_points): one sphere, also with outliers that pull a fit off;
// concentric spheres; spheres about several centres (bubbles); and none for uniform, gaussian
// or grid input, a ball, or the caps of a smooth surface.
#include <gtest/gtest.h>

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "shell/shell_inputs.hpp"

namespace {

using drange::Distribution;
using drange::PointCloud;
using namespace drange::test::shell;

TEST(SphereShell, BuiltForPointsNearASphereOnly) {
  for (int d : {2, 3, 4, 5}) {
    EXPECT_TRUE(store_of(sphere(3000, d, 7)).shell.active()) << "d=" << d;
    EXPECT_TRUE(store_of(sphere(3000, d, 8, 3.0, 0.25, 1e-9)).shell.active()) << "noisy, off-centre, d=" << d;
    EXPECT_FALSE(store_of(drange::generate_points(Distribution::Uniform, 3000, d, 9)).shell.active()) << "d=" << d;
    EXPECT_FALSE(store_of(drange::generate_points(Distribution::Gaussian, 3000, d, 9)).shell.active()) << "d=" << d;
  }
  EXPECT_FALSE(store_of(drange::generate_points(Distribution::Grid, 4096, 3, 1)).shell.active());
  EXPECT_FALSE(store_of(drange::generate_points(Distribution::Ball, 3000, 3, 1)).shell.active());
  // One point at the centre: left out of the fit, so the centre stays exact to rounding.
  PointCloud with_centre = sphere(3000, 3, 10);
  with_centre.coords.insert(with_centre.coords.end(), {0.0, 0.0, 0.0});
  const auto store = store_of(with_centre);
  ASSERT_TRUE(store.shell.active());
  for (double c : centre_of(store.shell)) EXPECT_LT(std::fabs(c), 1e-12);
  // The corners of a bounding cube: the least-squares fit of all the points is off by more
  // than the points' tolerance, and a fit to a few points drawn at random finds the sphere.
  for (int d : {2, 3, 4}) {
    const auto boxed = store_of(with_cube_corners(sphere(3000, d, 12), 1.5));
    ASSERT_TRUE(boxed.shell.active()) << "d=" << d;
    ASSERT_EQ(boxed.shell.spheres(), 1) << "d=" << d;
    for (double c : centre_of(boxed.shell)) EXPECT_LT(std::fabs(c), 1e-12) << "d=" << d;
    // The sphere's points (scaled by a power of two, as every input) lie on the fitted sphere.
    const auto on_sphere = std::count_if(boxed.shell.offset.begin(), boxed.shell.offset.end(),
                                         [&](double s) { return std::fabs(s) <= 1e-12 * boxed.shell.rho[0]; });
    EXPECT_EQ(on_sphere, 3000) << "d=" << d;
  }
  // Concentric spheres: the shell is built around their centre, with the offsets taken from the
  // smallest sphere.
  for (int d : {2, 3, 4}) {
    for (const std::vector<double>& radii : {std::vector<double>{1.0, 0.5}, std::vector<double>{1.0, 0.8, 0.6, 0.4, 0.2}}) {
      const auto layered = store_of(concentric(1000, d, 13, radii));
      ASSERT_TRUE(layered.shell.active()) << "d=" << d << ", " << radii.size() << " spheres";
      ASSERT_EQ(layered.shell.spheres(), 1) << "d=" << d;
      for (double c : centre_of(layered.shell)) EXPECT_LT(std::fabs(c), 1e-12) << "d=" << d;
      // The offsets are around the smallest sphere (the points are scaled by a power of two).
      const auto on_smallest = std::count_if(layered.shell.offset.begin(), layered.shell.offset.end(),
                                             [&](double s) { return std::fabs(s) <= 1e-12 * layered.shell.rho[0]; });
      EXPECT_EQ(on_smallest, 1000) << "d=" << d << ", " << radii.size() << " spheres";
      const double outer = radii.front() / radii.back();
      EXPECT_EQ(std::count_if(layered.shell.offset.begin(), layered.shell.offset.end(),
                              [&](double s) { return std::fabs(s - (outer * outer - 1) * layered.shell.rho[0]) <= 1e-12 * layered.shell.rho[0]; }),
                1000)
          << "d=" << d << ", " << radii.size() << " spheres";
    }
  }
  // The eight layers of a spherical grid (Fibonacci points, the same directions at every
  // radius, as in Earth models): balanced, but the sample (every fourth point in the tree's
  // order) is not, and its least-squares fit misses the centre; the fit from pairs finds it.
  PointCloud unbalanced{3, {}};
  const double golden = 3.14159265358979323846 * (3 - std::sqrt(5.0));
  for (int layer = 0; layer < 8; ++layer)
    for (int i = 0; i < 2500; ++i) {
      const double z = 1 - 2 * (i + 0.5) / 2500, r = std::sqrt(1 - z * z), radius = 6371.0 - 300.0 * layer;
      unbalanced.coords.insert(unbalanced.coords.end(), {radius * r * std::cos(golden * i), radius * r * std::sin(golden * i), radius * z});
    }
  EXPECT_TRUE(store_of(unbalanced).shell.active());
  // With the corners of a bounding cube too: they pull the fit off, and the pairs leave them out
  // (their steps in the distance order are large).
  EXPECT_TRUE(store_of(with_cube_corners(concentric(1500, 3, 18, {1.0, 0.5}), 1.5)).shell.active());
  EXPECT_TRUE(store_of(with_cube_corners(std::move(unbalanced), 9000.0)).shell.active());
  // But not a sphere with as many points inside it, nor more than 32 spheres, nor a small grid
  // (whose squared distances from its centre take few values). (Points near spheres about
  // several centres get a sphere each: SpheresAboutSeveralCentres.)
  PointCloud half_inside = sphere(1500, 3, 14);
  const PointCloud ball = drange::generate_points(Distribution::Ball, 1500, 3, 15);
  half_inside.coords.insert(half_inside.coords.end(), ball.coords.begin(), ball.coords.end());
  EXPECT_FALSE(store_of(half_inside).shell.active());
  std::vector<double> many(40);
  for (std::size_t i = 0; i < many.size(); ++i) many[i] = 1.0 - 0.02 * static_cast<double>(i);
  EXPECT_FALSE(store_of(concentric(110, 3, 16, many)).shell.active());
  EXPECT_FALSE(store_of(drange::generate_points(Distribution::Grid, 512, 3, 1)).shell.active());
  // Nor a 4D or 5D grid, whose squared distances from its centre fall on few values each held
  // by many points, like concentric spheres, but whose smallest such sphere holds the grid's
  // middle: the shell only costs there.
  EXPECT_FALSE(store_of(drange::generate_points(Distribution::Grid, 1296, 4, 1)).shell.active());
  PointCloud decimal_grid = drange::generate_points(Distribution::Grid, 10000, 4, 1);
  for (double& x : decimal_grid.coords) x /= 10;  // as read from "0.3": the nearest double
  EXPECT_FALSE(store_of(decimal_grid).shell.active());
  PointCloud grid5 = drange::generate_points(Distribution::Grid, 3125, 5, 1);
  EXPECT_FALSE(store_of(grid5).shell.active());
  for (double& x : grid5.coords) x /= 10;
  EXPECT_FALSE(store_of(grid5).shell.active());
}

TEST(SphereShell, SpheresAboutSeveralCentres) {
  // Bubbles: a sphere each, every point in its own (also those of the leaves that straddle two
  // bubbles), the centres exact to rounding.
  for (int d : {2, 3, 4}) {
    const std::size_t count = 12, n = d == 4 ? 400 : 300;
    const PointCloud points = bubbles(count, n, d, 50 + static_cast<std::uint64_t>(d));
    const auto store = store_of(points);
    const drange::engine::SphereShell& shell = store.shell;
    ASSERT_TRUE(shell.active()) << "d=" << d;
    EXPECT_EQ(shell.spheres(), static_cast<std::int32_t>(count)) << "d=" << d;
    // The input's bubble of each point (the store renumbers the points: by its coordinates).
    std::vector<std::int32_t> bubble_of(count, -1);
    for (std::int32_t id = 0; id < store.size; ++id) {
      const std::int32_t k = shell.point_sphere[static_cast<std::size_t>(id)];
      ASSERT_GE(k, 0) << "d=" << d << ": point " << id << " is in no sphere";
      const auto g = centre_of(shell, k);
      mpq_class offset = exact_offset(store.point(id), g.data(), d, shell.rho[static_cast<std::size_t>(k)]);
      EXPECT_LT(abs(offset), mpq_class(1e-12)) << "d=" << d << ": point " << id << " is off its sphere";
    }
    // Leaves that straddle two bubbles: some, in 3D and 4D (so the parts of leaves are tested).
    std::size_t straddling = 0;
    for (std::size_t i = 0; i < store.tree.nodes().size(); ++i) straddling += shell.node_sphere[i] == drange::engine::SphereShell::kParts;
    if (d > 2) EXPECT_GT(straddling, 0u) << "d=" << d;
  }
  // Bubbles in a uniform background: the bubbles' points are in their spheres, nearly all the
  // others in none.
  PointCloud mixed = bubbles(6, 400, 3, 60);
  const PointCloud background = drange::generate_points(Distribution::Uniform, 3000, 3, 61);
  mixed.coords.insert(mixed.coords.end(), background.coords.begin(), background.coords.end());
  const auto mixed_store = store_of(mixed);
  ASSERT_TRUE(mixed_store.shell.active());
  EXPECT_EQ(mixed_store.shell.spheres(), 6);
  const auto in_spheres = std::count_if(mixed_store.shell.point_sphere.begin(), mixed_store.shell.point_sphere.end(),
                                        [](std::int32_t k) { return k >= 0; });
  EXPECT_GE(in_spheres, 6 * 400);
  EXPECT_LE(in_spheres, 6 * 400 + 30);
}

TEST(SphereShell, NoSpheresFromTheCapsOfASmoothSurface) {
  // Near every point of an ellipsoid a patch lies within 2^-10 of its osculating sphere; those
  // caps are no spheres of the input.
  drange::test::TestRandom random(90);
  PointCloud ellipsoid{3, {}};
  for (int i = 0; i < 20000; ++i) {
    double v[3], norm2 = 0.0;
    for (double& x : v) {
      x = std::sqrt(-2 * std::log(1 - random.uniform())) * std::cos(2 * M_PI * random.uniform());
      norm2 += x * x;
    }
    const double scale = 1 / std::sqrt(norm2);
    ellipsoid.coords.insert(ellipsoid.coords.end(), {v[0] * scale, 0.7 * v[1] * scale, 0.4 * v[2] * scale});
  }
  EXPECT_FALSE(store_of(ellipsoid).shell.active());
  // A small cap of exact sphere points among them is still one: its points lie on it.
  PointCloud with_cap = ellipsoid;
  const PointCloud cap = sphere(8000, 3, 91, 0.05, 2.0);
  for (std::size_t i = 0; i < cap.size(); ++i)
    if (cap.point(i)[2] > 2.0 + 0.0475)  // a cap of 18 degrees: its box 0.88 radii across
      with_cap.coords.insert(with_cap.coords.end(), cap.point(i), cap.point(i) + 3);  // about 200
  const auto store = store_of(with_cap);
  ASSERT_TRUE(store.shell.active());
  EXPECT_EQ(store.shell.spheres(), 1);
}

}  // namespace
