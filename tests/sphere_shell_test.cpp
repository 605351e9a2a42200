// tests/sphere_shell_test.cpp: the search's shortcut for points near one sphere
// (delaunay/sphere_shell.hpp, geometry::exact_lifted_form, facet_search.cpp's shell tests).
//
// Each piece against exact rationals: the points' offsets from the fitted sphere within their
// stated bound, every node's range holding its points' exact offsets, and the lifted form equal
// to the lifted determinant within the truncation of its coefficients. Then the whole: the
// shell is built for points near a sphere (with an outlier too) and not for others, and the
// triangulation with it is the one without it, valid, on spheres, caps, noisy spheres and the
// exactly cocircular integer points, with far less work (a count, not a time).
#include <gtest/gtest.h>

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "delaunay/facet_search.hpp"
#include "delaunay/prepare_points.hpp"
#include "delaunay/sphere_shell.hpp"
#include "delaunay/team.hpp"
#include "drange/check.hpp"
#include "drange/delaunay.hpp"
#include "drange/generate.hpp"
#include "geometry/predicates.hpp"
#include "oracle.hpp"

namespace {

using drange::Distribution;
using drange::PointCloud;

drange::engine::PointStore store_of(const PointCloud& points) {
  drange::engine::Team team(1);
  std::vector<drange::Duplicate> duplicates;
  return drange::engine::prepare_points(points, drange::engine::search_leaf_size(points.dim), duplicates, team);
}

mpq_class exact_offset(const double* x, const double* g, int dim, double rho) {
  mpq_class s = -mpq_class(rho);
  for (int k = 0; k < dim; ++k) {
    const mpq_class y = mpq_class(x[k]) - mpq_class(g[k]);
    s += y * y;
  }
  return s;
}

// Points on the unit sphere of dimension d scaled by `radius` about `centre`, each moved off it
// by a relative `noise` (0: cospherical up to rounding).
PointCloud sphere(std::size_t n, int d, std::uint64_t seed, double radius = 1.0, double centre = 0.0, double noise = 0.0) {
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
PointCloud with_cube_corners(PointCloud points, double half) {
  const int d = points.dim;
  for (int corner = 0; corner < (1 << d); ++corner)
    for (int k = 0; k < d; ++k) points.coords.push_back((corner >> k) & 1 ? half : -half);
  return points;
}

// `n` points on each of the spheres of the given radii about `centre` (the layers of a
// spherical grid; a sphere with a smaller one inside).
PointCloud concentric(std::size_t n, int d, std::uint64_t seed, std::vector<double> radii, double centre = 0.0) {
  PointCloud points{d, {}};
  for (double radius : radii) {
    const PointCloud layer = sphere(n, d, seed++, radius, centre);
    points.coords.insert(points.coords.end(), layer.coords.begin(), layer.coords.end());
  }
  return points;
}

// `count` bubbles of `n` points each: spheres of radius `radius` about centres drawn in the
// cube [-1, 1]^d at least 3 radii apart (bubbles3 of bench/degenerate_families.py, smaller).
PointCloud bubbles(std::size_t count, std::size_t n, int d, std::uint64_t seed, double radius = 0.05) {
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
std::vector<double> centre_of(const drange::engine::SphereShell& shell, std::int32_t k = 0) {
  const double* g = shell.sphere(k).centre;
  return {g, g + shell.dim};
}

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
  // middle: the shell only costs time there.
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
  // caps are no spheres of the input (a looser test would take hundreds of them on a large one).
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

// A sphere, and bubbles in a uniform background (several spheres, leaves straddling two, and
// points in none).
std::vector<PointCloud> shell_inputs(int d) {
  PointCloud mixed = bubbles(6, 300, d, 70 + static_cast<std::uint64_t>(d));
  const PointCloud background = drange::generate_points(Distribution::Uniform, 500, d, 71);
  mixed.coords.insert(mixed.coords.end(), background.coords.begin(), background.coords.end());
  return {sphere(2000, d, 11, 2.0, -0.5, 1e-12), mixed};
}

// n points on a sphere (radius 2, centre -0.5 on every axis) around n / 4 uniform in its ball:
// one sphere, found by patches (fewer than 9 in 10 points are on it), whose nodes near it mix
// points on it and inside it.
PointCloud sphere_around_ball(std::size_t n, int d, std::uint64_t seed) {
  PointCloud points = sphere(n, d, seed, 2.0, -0.5);
  const PointCloud inside = drange::generate_points(Distribution::Ball, n / 4, d, seed + 1);
  for (double x : inside.coords) points.coords.push_back(2.0 * x - 0.5);
  return points;
}

TEST(SphereShell, OffsetsAndNodeRangesBoundTheExactOffsets) {
  // Each point's offset about its own sphere; each node's range, in a node in a sphere.
  for (int d : {2, 3, 5}) {
    for (const PointCloud& points : shell_inputs(d)) {
      const auto store = store_of(points);
      ASSERT_TRUE(store.shell.active());
      const drange::engine::SphereShell& shell = store.shell;
      std::vector<mpq_class> exact(static_cast<std::size_t>(store.size));
      for (std::int32_t id = 0; id < store.size; ++id) {
        const std::int32_t k = shell.point_sphere[static_cast<std::size_t>(id)];
        if (k < 0) continue;
        const double s = shell.offset[static_cast<std::size_t>(id)];
        const drange::engine::ShellSphere sphere = shell.sphere(k);
        exact[static_cast<std::size_t>(id)] = exact_offset(store.point(id), sphere.centre, d, sphere.rho);
        const mpq_class error = abs(exact[static_cast<std::size_t>(id)] - mpq_class(s));
        EXPECT_LE(error, mpq_class(0x1p-53 * std::fabs(s)) + mpq_class(sphere.eta)) << "d=" << d << " id=" << id;
      }
      const auto& nodes = store.tree.nodes();
      std::size_t in_sphere = 0;
      for (std::size_t i = 0; i < nodes.size(); ++i) {
        const std::int32_t k = shell.node_sphere[i];
        if (k < 0) continue;
        ++in_sphere;
        for (std::int32_t id = nodes[i].begin; id < nodes[i].end; ++id) {
          ASSERT_EQ(shell.point_sphere[static_cast<std::size_t>(id)], k) << "node " << i;
          ASSERT_LE(mpq_class(shell.of(static_cast<std::int32_t>(i))[0]), exact[static_cast<std::size_t>(id)]) << "node " << i;
          ASSERT_GE(mpq_class(shell.of(static_cast<std::int32_t>(i))[1]), exact[static_cast<std::size_t>(id)]) << "node " << i;
        }
      }
      EXPECT_GT(in_sphere, nodes.size() / 4) << "d=" << d;
    }
  }
}

TEST(SphereShell, ConcentricClustersBoundTheirPointsExactly) {
  // Each node's two clusters (near the smallest sphere, the rest) hold the exact offset and
  // |y| of each of its points, by the point's side of cluster_split; and nodes that mix the
  // two spheres exist (the case the clusters are for).
  for (int d : {2, 3, 4}) {
    const auto store = store_of(concentric(1500, d, 60 + static_cast<std::uint64_t>(d), {1.0, 0.5}, 0.25));
    const drange::engine::SphereShell& shell = store.shell;
    ASSERT_TRUE(shell.active()) << "d=" << d;
    ASSERT_FALSE(shell.clusters.empty()) << "d=" << d;
    const std::vector<double> g = centre_of(shell);
    std::size_t mixed = 0;
    const auto& nodes = store.tree.nodes();
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      const double* clusters = shell.clusters_of(static_cast<std::int32_t>(i));
      mixed += clusters[0] <= clusters[1] && clusters[4] <= clusters[5];
      for (std::int32_t id = nodes[i].begin; id < nodes[i].end; ++id) {
        const double* cluster = clusters + (shell.offset[static_cast<std::size_t>(id)] < shell.cluster_split ? 0 : 4);
        const mpq_class offset = exact_offset(store.point(id), g.data(), d, shell.rho[0]);
        const mpq_class y2 = offset + mpq_class(shell.rho[0]);
        ASSERT_LE(mpq_class(cluster[0]), offset) << "d=" << d << " node " << i;
        ASSERT_GE(mpq_class(cluster[1]), offset) << "d=" << d << " node " << i;
        ASSERT_LE(mpq_class(cluster[2]) * mpq_class(cluster[2]), y2) << "d=" << d << " node " << i;
        ASSERT_GE(mpq_class(cluster[3]) * mpq_class(cluster[3]), y2) << "d=" << d << " node " << i;
      }
    }
    EXPECT_GT(mixed, 0u) << "d=" << d;
  }
  // One sphere: no clusters.
  EXPECT_TRUE(store_of(sphere(2000, 3, 11)).shell.clusters.empty());
}

TEST(SphereShell, ConesHoldTheirPointsExactly) {
  // For every node and block with a cone: each point's exact y = x - g has m . y >= cos_lo |y| and
  // r_lo <= |y| <= r_hi, and sin_hi^2 >= 1 - cos_lo^2 / |m|^2 (the rim's sine for m as stored).
  // With one sphere, every node's cone is about its centre, over the points off it too.
  for (int d : {2, 3, 5}) {
    for (const PointCloud& points : {sphere(2000, d, 13), sphere(2000, d, 14, 2.0, -0.5, 1e-12), shell_inputs(d)[1],
                                     sphere_around_ball(2000, d, 15)}) {
      const auto store = store_of(points);
      ASSERT_TRUE(store.shell.active());
      const drange::engine::SphereShell& shell = store.shell;
      const auto& nodes = store.tree.nodes();
      const bool one_sphere = shell.spheres() == 1;
      // Whether the cone holds the points [begin, end) (true for a cone too wide to be used),
      // about their sphere's centre.
      const auto holds = [&](const double* cone, std::int32_t begin, std::int32_t end) {
        const double cos_lo = cone[d], sin_hi = cone[d + 1], r_lo = cone[d + 2], r_hi = cone[d + 3];
        if (!(cos_lo > 0.0)) return true;
        mpq_class m2 = 0;
        for (int k = 0; k < d; ++k) m2 += mpq_class(cone[k]) * mpq_class(cone[k]);
        EXPECT_LT(abs(m2 - 1), mpq_class(1e-12));
        EXPECT_GE(mpq_class(sin_hi) * mpq_class(sin_hi), 1 - mpq_class(cos_lo) * mpq_class(cos_lo) / m2);
        for (std::int32_t id = begin; id < end; ++id) {
          const std::int32_t sphere_of_id = shell.point_sphere[static_cast<std::size_t>(id)];
          if (!one_sphere && (sphere_of_id != shell.point_sphere[static_cast<std::size_t>(begin)] || sphere_of_id < 0)) {
            ADD_FAILURE() << "d=" << d << ": a cone over points of several spheres, or of none";
            return false;
          }
          const std::vector<double> g = centre_of(shell, one_sphere ? 0 : sphere_of_id);
          mpq_class dot = 0, y2 = 0;
          for (int k = 0; k < d; ++k) {
            const mpq_class y = mpq_class(store.point(id)[k]) - mpq_class(g[static_cast<std::size_t>(k)]);
            dot += mpq_class(cone[k]) * y;
            y2 += y * y;
          }
          if (dot < 0 || dot * dot < mpq_class(cos_lo) * mpq_class(cos_lo) * y2 || mpq_class(r_lo) * mpq_class(r_lo) > y2 ||
              mpq_class(r_hi) * mpq_class(r_hi) < y2) {
            ADD_FAILURE() << "d=" << d << ": point " << id << " is outside its cone";
            return false;
          }
        }
        return !::testing::Test::HasFailure();
      };
      std::size_t leaves = 0, leaf_cones = 0;
      for (std::size_t i = 0; i < nodes.size(); ++i) {
        const double* cone = shell.cone_of(static_cast<std::int32_t>(i));
        const double cos_lo = cone[d];
        if (nodes[i].right < 0) ++leaves;
        if (!(cos_lo > 0.0)) continue;
        if (nodes[i].right < 0) ++leaf_cones;
        ASSERT_TRUE(holds(cone, nodes[i].begin, nodes[i].end)) << "node " << i;
      }
      // (Around a ball, a leaf inside it may hold points in every direction.)
      const bool all_on_it = std::count(shell.point_sphere.begin(), shell.point_sphere.end(), -1) == 0;
      if (d <= 3 && one_sphere && all_on_it) EXPECT_EQ(leaf_cones, leaves) << "d=" << d << ": a leaf holds a small cap of the sphere";
      std::size_t block_cones = 0, blocks_in_spheres = 0;
      for (std::size_t b = 0; b + 1 < shell.block_start.size(); ++b) {
        if (shell.block_sphere[b] < 0) continue;
        ++blocks_in_spheres;
        const double* cone = shell.block_cone_of(static_cast<std::int32_t>(b));
        if (!holds(cone, shell.block_start[b], shell.block_start[b + 1])) return;
        block_cones += cone[d] > 0.0;
      }
      // (In the background of bubbles, a point in a bubble's patch may lie in any direction.)
      if (one_sphere) EXPECT_EQ(block_cones, blocks_in_spheres) << "d=" << d << ": a block holds a few near points";
    }
  }
}

TEST(SphereShell, BlocksCutTheLeavesAndListTheirPointsByOffset) {
  for (int d : {2, 3, 4}) {
   for (const PointCloud& points : {sphere(3000, d, 15, 1.0, 0.0, 1e-10), shell_inputs(d)[1]}) {
    const auto store = store_of(points);
    const drange::engine::SphereShell& shell = store.shell;
    ASSERT_TRUE(shell.active());
    const auto& nodes = store.tree.nodes();
    ASSERT_EQ(shell.block_start.back(), store.size);
    for (std::size_t leaf = 0; leaf < nodes.size(); ++leaf) {
      if (nodes[leaf].right >= 0) continue;
      if (shell.first_block[leaf] < 0) {  // a leaf in no sphere
        ASSERT_EQ(shell.node_sphere[leaf], -1);
        continue;
      }
      // The leaf's blocks: consecutive, of 1 to 8 points in 3D, 32 from 4D (a whole run of one
      // sphere's points in 2D), from its first point to its last.
      auto block = static_cast<std::size_t>(shell.first_block[leaf]);
      ASSERT_EQ(shell.block_start[block], nodes[leaf].begin);
      for (; shell.block_start[block] < nodes[leaf].end; ++block) {
        const std::int32_t begin = shell.block_start[block], end = shell.block_start[block + 1];
        ASSERT_GE(end - begin, 1);
        if (d > 2 && shell.block_sphere[block] >= 0) ASSERT_LE(end - begin, d == 3 ? 8 : 32);
        std::vector<std::int32_t> ids(shell.block_ids.begin() + begin, shell.block_ids.begin() + end);
        for (std::int32_t id : ids) ASSERT_EQ(shell.point_sphere[static_cast<std::size_t>(id)], shell.block_sphere[block]);
        for (std::int32_t i = begin; i < end; ++i) {
          const auto at = static_cast<std::size_t>(i);
          EXPECT_EQ(shell.block_offsets[at], shell.offset[static_cast<std::size_t>(shell.block_ids[at])]);
          if (i > begin) EXPECT_LE(shell.block_offsets[at - 1], shell.block_offsets[at]);
        }
        std::sort(ids.begin(), ids.end());
        for (std::size_t j = 0; j < ids.size(); ++j) ASSERT_EQ(ids[j], begin + static_cast<std::int32_t>(j));
      }
      ASSERT_EQ(shell.block_start[block], nodes[leaf].end);
    }
   }
  }
}

TEST(SphereShell, LiftedFormEqualsTheLiftedDeterminant) {
  // det[r_1; ...; r_d; r_x] against b . (x - g) + lift (|x - g|^2 - rho) + constant, exactly,
  // with the coefficients' truncation (a relative 2^-52 each) as the only allowed difference.
  drange::test::TestRandom random(12);
  for (int d : {2, 3, 4, 6}) {
    for (int trial = 0; trial < 20; ++trial) {
      const PointCloud points = sphere(static_cast<std::size_t>(d + 2), d, 100 + static_cast<std::uint64_t>(trial), 1.5, 0.125,
                                       trial % 2 ? 1e-6 : 0.0);
      std::vector<double> g(static_cast<std::size_t>(d));
      for (double& c : g) c = 0.125 + (random.uniform() - 0.5) * 1e-9;
      const double rho = 2.25 * (1 + (random.uniform() - 0.5) * 1e-9);
      std::vector<const double*> rows;
      for (int i = 1; i <= d; ++i) rows.push_back(points.point(static_cast<std::size_t>(i)));
      const drange::geometry::Frame frame{d, d, nullptr, points.point(0)};
      std::vector<double> b(static_cast<std::size_t>(d));
      double lift = 0.0, constant = 0.0;
      ASSERT_TRUE(drange::geometry::exact_lifted_form(frame, rows.data(), g.data(), rho, b.data(), &lift, &constant));
      const double* x = points.point(static_cast<std::size_t>(d + 1));
      // The determinant, exactly.
      std::vector<mpq_class> m;
      for (int r = 0; r <= d; ++r) {
        const double* p = r < d ? rows[static_cast<std::size_t>(r)] : x;
        mpq_class lifted = 0;
        for (int k = 0; k < d; ++k) {
          const mpq_class delta = mpq_class(p[k]) - mpq_class(points.point(0)[k]);
          m.push_back(delta);
          lifted += delta * delta;
        }
        m.push_back(lifted);
      }
      const mpq_class det = drange::test::reference_determinant(m, d + 1);
      mpq_class form = mpq_class(constant), magnitude = abs(mpq_class(constant));
      for (int k = 0; k < d; ++k) {
        const mpq_class term = mpq_class(b[static_cast<std::size_t>(k)]) * (mpq_class(x[k]) - mpq_class(g[static_cast<std::size_t>(k)]));
        form += term;
        magnitude += abs(term);
      }
      const mpq_class offset_term = mpq_class(lift) * exact_offset(x, g.data(), d, rho);
      form += offset_term;
      magnitude += abs(offset_term);
      EXPECT_LE(abs(form - det), magnitude * mpq_class(0x1p-51)) << "d=" << d << " trial " << trial;
      EXPECT_EQ(sgn(form), sgn(det)) << "d=" << d << " trial " << trial;
    }
  }
}

TEST(SphereShell, FloatFormIsWithinItsBoundsOfTheExactForm) {
  // The exact coefficients from the lifted determinant's cofactors along x's row (C_c for the
  // spatial columns, C_L for the lift), rewritten around g: B_c = C_c - 2 C_L y0_c, W = C_L,
  // K = C_L (rho + |y0|^2) - C . y0 with y0 = f0 - g. Each float coefficient must be within
  // its bound of them; and most simplices must get a float form at all (2D to 8D).
  drange::test::TestRandom random(41);
  for (int d : {2, 3, 4, 5, 6, 7, 8}) {
    for (double noise : {0.0, 1e-12, 1e-9}) {
      const auto store = store_of(sphere(3000, d, 42 + static_cast<std::uint64_t>(d), 1.5, 0.25, noise));
      const drange::engine::SphereShell& shell = store.shell;
      ASSERT_TRUE(shell.active());
      int accepted = 0;
      const int trials = 200;
      for (int trial = 0; trial < trials; ++trial) {
        // d + 1 points near each other (a random point and the next ids, 1 to 13 apart:
        // neighbours in the tree), all within the store.
        const auto first = static_cast<std::int32_t>(random.uniform() * (store.size - 13 * d - 1));
        std::vector<std::int32_t> ids;
        for (int i = 0; i <= d; ++i) ids.push_back(first + i * (1 + trial % 13));
        const double* f0 = store.point(ids[0]);
        std::vector<const double*> rows;
        std::vector<double> row_offsets;
        for (int i = 1; i <= d; ++i) {
          rows.push_back(store.point(ids[static_cast<std::size_t>(i)]));
          row_offsets.push_back(shell.offset[static_cast<std::size_t>(ids[static_cast<std::size_t>(i)])]);
        }
        drange::engine::FloatForm form{};
        if (!drange::engine::float_form(shell.sphere(0), d, f0, shell.offset[static_cast<std::size_t>(ids[0])], rows.data(), row_offsets.data(),
                                        form))
          continue;
        ++accepted;
        {
          // The facet's minors kept from another candidate's form give this form bit for bit.
          drange::engine::FacetMinors minors;
          std::vector<const double*> other_rows = rows;
          std::vector<double> other_offsets = row_offsets;
          const std::int32_t other = ids[0] > 0 ? ids[0] - 1 : ids[static_cast<std::size_t>(d)] + 1;
          other_rows.back() = store.point(other);
          other_offsets.back() = shell.offset[static_cast<std::size_t>(other)];
          drange::engine::FloatForm first{}, again{};
          drange::engine::float_form(shell.sphere(0), d, f0, shell.offset[static_cast<std::size_t>(ids[0])], other_rows.data(), other_offsets.data(),
                                     first, &minors);
          ASSERT_TRUE(drange::engine::float_form(shell.sphere(0), d, f0, shell.offset[static_cast<std::size_t>(ids[0])], rows.data(),
                                                 row_offsets.data(), again, &minors));
          for (int c = 0; c < d; ++c) {
            EXPECT_EQ(again.b[c], form.b[c]) << "d=" << d << " trial " << trial;
            EXPECT_EQ(again.b_err[c], form.b_err[c]) << "d=" << d << " trial " << trial;
          }
          EXPECT_EQ(again.lift, form.lift);
          EXPECT_EQ(again.lift_err, form.lift_err);
          EXPECT_EQ(again.constant, form.constant);
          EXPECT_EQ(again.constant_err, form.constant_err);
        }
        // Cofactors of the last row of the (d + 1) x (d + 1) lifted matrix, exactly.
        std::vector<std::vector<mpq_class>> r(static_cast<std::size_t>(d));
        for (int i = 0; i < d; ++i) {
          mpq_class lift = 0;
          for (int k = 0; k < d; ++k) {
            const mpq_class delta = mpq_class(rows[static_cast<std::size_t>(i)][k]) - mpq_class(f0[k]);
            r[static_cast<std::size_t>(i)].push_back(delta);
            lift += delta * delta;
          }
          r[static_cast<std::size_t>(i)].push_back(lift);
        }
        std::vector<mpq_class> cofactor(static_cast<std::size_t>(d + 1));
        for (int j = 0; j <= d; ++j) {
          std::vector<mpq_class> minor;
          for (int i = 0; i < d; ++i)
            for (int c = 0; c <= d; ++c)
              if (c != j) minor.push_back(r[static_cast<std::size_t>(i)][static_cast<std::size_t>(c)]);
          const mpq_class m = drange::test::reference_determinant(minor, d);
          cofactor[static_cast<std::size_t>(j)] = ((d + j) % 2 == 0) ? m : mpq_class(-m);
        }
        const mpq_class& cl = cofactor[static_cast<std::size_t>(d)];
        mpq_class y0_2 = 0, k_exact = 0;
        for (int c = 0; c < d; ++c) {
          const mpq_class y0 = mpq_class(f0[c]) - mpq_class(shell.sphere(0).centre[c]);
          y0_2 += y0 * y0;
          k_exact -= cofactor[static_cast<std::size_t>(c)] * y0;
          const mpq_class b_exact = cofactor[static_cast<std::size_t>(c)] - 2 * cl * y0;
          ASSERT_LE(abs(mpq_class(form.b[c]) - b_exact), mpq_class(form.b_err[c])) << "d=" << d << " noise " << noise << " trial " << trial;
        }
        k_exact += cl * (mpq_class(shell.rho[0]) + y0_2);
        ASSERT_LE(abs(mpq_class(form.lift) - cl), mpq_class(form.lift_err)) << "d=" << d << " trial " << trial;
        ASSERT_LE(abs(mpq_class(form.constant) - k_exact), mpq_class(form.constant_err)) << "d=" << d << " trial " << trial;
      }
      EXPECT_GT(accepted, trials * 9 / 10) << "d=" << d << " noise " << noise;
    }
  }
}

std::vector<drange::test::Simplex> canonical(const drange::Triangulation& t) { return drange::test::canonical(t.simplices, t.dim); }

drange::Triangulation triangulate(const PointCloud& points, const char* variant) {
  drange::Options options;
  options.search = drange::search_variant(variant);
  options.threads = 1;
  return drange::delaunay(points, options);
}

TEST(SphereShell, SameValidTriangulationWithAndWithoutIt) {
  std::vector<std::pair<std::string, PointCloud>> cases = {
      {"circle", sphere(3000, 2, 21)},
      {"sphere 3D", sphere(1500, 3, 22)},
      {"sphere 4D", sphere(300, 4, 23)},
      // 4D and 5D: the leaf scan's blocks of 32, whose point test bounds its error once per
      // block (facet_search.cpp, block_terms), and the 5D floating-point form.
      {"noisy sphere 4D", sphere(600, 4, 29, 1.0, 0.0, 1e-9)},
      {"sphere 5D", sphere(120, 5, 30)},
      {"off-centre sphere 3D", sphere(1500, 3, 24, 0.75, 3.0)},
      {"noisy sphere 3D", sphere(1500, 3, 25, 1.0, 0.0, 1e-9)},
      {"noisy circle", sphere(3000, 2, 26, 1.0, 0.0, 1e-7)},
  };
  {
    // A cap: the points of a sphere with z > 0.5.
    const PointCloud all = sphere(4000, 3, 27);
    PointCloud cap{3, {}};
    for (std::size_t i = 0; i < all.size(); ++i)
      if (all.point(i)[2] > 0.5) cap.coords.insert(cap.coords.end(), all.point(i), all.point(i) + 3);
    cases.emplace_back("cap", cap);
  }
  {
    PointCloud c = sphere(1500, 3, 28);  // and its centre
    c.coords.insert(c.coords.end(), {0.0, 0.0, 0.0});
    cases.emplace_back("sphere and centre", c);
  }
  cases.emplace_back("sphere and its bounding cube's corners", with_cube_corners(sphere(1500, 3, 32), 1.0));
  cases.emplace_back("circle and its bounding square's corners", with_cube_corners(sphere(2000, 2, 33), 1.0));
  cases.emplace_back("two concentric circles", concentric(1500, 2, 34, {1.0, 0.5}));
  cases.emplace_back("three concentric spheres 3D", concentric(600, 3, 36, {1.0, 0.7, 0.4}, 0.5));
  cases.emplace_back("two concentric spheres 4D", concentric(200, 4, 40, {1.0, 0.5}));
  // Spheres about several centres: bubbles (leaves straddle two of them), and in a uniform
  // background.
  cases.emplace_back("bubbles 2D", bubbles(10, 300, 2, 80));
  cases.emplace_back("bubbles 3D", bubbles(10, 300, 3, 81));
  cases.emplace_back("bubbles 4D", bubbles(6, 150, 4, 82));
  cases.emplace_back("bubbles in a uniform background 3D", shell_inputs(3)[1]);

  {
    // Every integer point of the circle x^2 + y^2 = 5^4 13^2 (exactly cocircular: ties that
    // only the perturbation breaks).
    PointCloud c{2, {}};
    const long r2 = 625L * 169L;
    for (long x = -325; x <= 325; ++x)
      for (long y = -325; y <= 325; ++y)
        if (x * x + y * y == r2) c.coords.insert(c.coords.end(), {double(x), double(y)});
    cases.emplace_back("integer circle", c);
  }
  for (const auto& [name, points] : cases) {
    const drange::engine::PointStore store = store_of(points);
    EXPECT_TRUE(store.shell.active()) << name;
    const drange::Triangulation with = triangulate(points, "full"), without = triangulate(points, "no-shell");
    EXPECT_EQ(canonical(with), canonical(without)) << name;
    const drange::CheckReport report = drange::check_triangulation(points, with.simplices);
    EXPECT_TRUE(report.valid) << name << ": " << (report.problems.empty() ? "" : report.problems.front());
    // Two threads: the same simplices.
    drange::Options two;
    two.threads = 2;
    EXPECT_EQ(canonical(drange::delaunay(points, two)), canonical(with)) << name;
  }
}

TEST(SphereShell, ConesProveTheHullFacetsOfASphereAroundABall) {
  // 6 400 points on a sphere around 1 600 in its ball: the shell has one sphere, from patches,
  // and the nodes that mix points on it and inside it have no sphere. Their cones about its
  // centre let the search of a hull facet prune them (a sphere's hull facet has no point beyond
  // it, and the boxes of the nodes near it reach across its plane).
  const PointCloud points = sphere_around_ball(6400, 3, 16);
  const auto store = store_of(points);
  ASSERT_TRUE(store.shell.active());
  EXPECT_EQ(store.shell.spheres(), 1);
  const drange::Triangulation with = triangulate(points, "full");
  EXPECT_EQ(canonical(with), canonical(triangulate(points, "no-shell")));
  const drange::CheckReport report = drange::check_triangulation(points, with.simplices);
  EXPECT_TRUE(report.valid) << (report.problems.empty() ? "" : report.problems.front());
  // Nodes entered per simplex (a deterministic work counter, not a time): the bound lies between
  // the count with the cones of the mixed nodes and the higher one without them.
  EXPECT_LT(with.stats.calls_per_simplex(), 15.0);
}

TEST(SphereShell, CutsTheWorkOnSpheres) {
  // Counters, not times: without the shell every search scans nearly every point, and the
  // double filter cannot decide the points near the candidate's sphere (the double-double
  // stage does, geometry/refined_sign.hpp). With the shell, the leaves' offset order and the
  // nodes' cones leave few points and nodes: on these inputs, per triangle, tens of times fewer
  // points tested and several times fewer nodes entered than without, and in 3D tens of times
  // fewer points tested per tetrahedron.
  for (int d : {2, 3}) {
    const PointCloud points = sphere(d == 2 ? 8000 : 2000, d, 31);
    const drange::Statistics with = triangulate(points, "full").stats, without = triangulate(points, "no-shell").stats;
    EXPECT_LT(with.points_tested * (d == 2 ? 20 : 5), without.points_tested) << "d=" << d;
    if (d == 2) EXPECT_LT(with.search_calls * 4, without.search_calls);
    // Within rounding of one sphere but not exactly on it: GMP is hardly ever needed, with the
    // shell or without, as the double-double stage decides those tests.
    EXPECT_LT(with.exact_fallbacks * 1000, with.points_tested) << "d=" << d;
    EXPECT_LT(without.exact_fallbacks * 1000, without.points_tested) << "d=" << d;
  }
  // Two concentric spheres: the inner one's ball is a cell of cospherical points, as above
  // (with the shell, an order of magnitude fewer points tested than without).
  for (int d : {2, 3}) {
    const PointCloud points = concentric(d == 2 ? 4000 : 1000, d, 42, {1.0, 0.5});
    const drange::Statistics with = triangulate(points, "full").stats, without = triangulate(points, "no-shell").stats;
    EXPECT_LT(with.points_tested * 3, without.points_tested) << "d=" << d;
  }
  // Bubbles: each bubble's ball is a cell of cospherical points; with a sphere per bubble, as
  // with one sphere (with the shell, several times fewer points tested than without).
  for (int d : {2, 3}) {
    const PointCloud points = bubbles(10, 400, d, 90);
    const drange::Statistics with = triangulate(points, "full").stats, without = triangulate(points, "no-shell").stats;
    EXPECT_LT(with.points_tested * 3, without.points_tested) << "d=" << d;
  }
}

}  // namespace
