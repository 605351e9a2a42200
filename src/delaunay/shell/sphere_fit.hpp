// delaunay/shell/sphere_fit.hpp: finding the spheres that the points lie near, for the sphere
// shell (delaunay/sphere_shell.hpp). Two searches: spheres about one centre, that is one sphere
// or concentric spheres (one_centre_fit.cpp), and spheres about several centres, found patch
// by patch in the kd-tree: bubbles, the cells of a foam (bubble_fit.cpp); and the tools they
// share (sphere_fit.cpp): the least-squares sphere and the tests of a point's nearness.
//
// Why apart from the index: a fit only decides which sphere each point belongs to; the index
// (shell_index.cpp) then takes every offset about the spheres found with a proven error bound.
// So the fit works in plain floating point with loose thresholds: a poor fit costs time, never
// a wrong result (the shell changes which nodes are visited, never the point found). Every
// choice here is deterministic (fixed draws, stable orders), so that the work is too.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "drange/points.hpp"

namespace drange::spatial {
class KdTree;
}

namespace drange::engine::sphere_fit {

struct Sphere {
  std::vector<double> centre;
  double radius2 = 0.0;
};

// A point is near the sphere when | |x - g|^2 - R^2 | <= kNear R^2: far looser than rounding,
// so that points a little off a sphere (measured, then normalised in single precision) count.
constexpr double kNear = 0x1p-10;
// The share of the points that must lie near the spheres found ("most").
constexpr double kInlierShare = 0.9;
// The fewest points of a sphere: fewer are not taken for one (one_centre_fit.cpp, spheres_in;
// bubble_fit.cpp, spheres_of_patches).
constexpr std::size_t kSpherePoints = 64;
// The widest sphere taken, relative to the bounding box of the points it is fitted to: a
// sphere much larger than the points is near a hyperplane, and the points of any input lie
// near a few of those.
constexpr double kMaxRadiusOverExtent = 16.0;
// The fit's unknowns: the centre and one more.
constexpr int kMaxUnknowns = kMaxDimension + 1;

// Solves the m x m system a z = b (row-major, both overwritten) by Gaussian elimination with
// partial pivoting; the solution is left in b. False when a pivot is zero or not finite.
bool solve(double* a, double* b, int m);

// The algebraic least-squares sphere of the points `ids`, refined once on its residuals (with
// `passes` 2). False when the system is singular (points in a hyperplane).
bool fit(const double* coords, int dim, const std::vector<std::int32_t>& ids, Sphere& sphere, int passes = 2);

inline double distance2(const double* x, const std::vector<double>& g) {
  double t = 0.0;
  for (std::size_t k = 0; k < g.size(); ++k) t += (x[k] - g[k]) * (x[k] - g[k]);
  return t;
}

// Whether a squared distance t from the centre is near the sphere of squared radius r2.
inline bool is_near(double t, double r2) { return std::fabs(t - r2) <= kNear * r2; }

inline bool is_near(const double* coords, int dim, std::int32_t id, const Sphere& sphere) {
  return is_near(distance2(coords + static_cast<std::size_t>(id) * static_cast<std::size_t>(dim), sphere.centre), sphere.radius2);
}

// The ids among `ids` near the sphere.
std::vector<std::int32_t> near(const double* coords, int dim, const std::vector<std::int32_t>& ids, const Sphere& sphere);

inline bool mostly(std::size_t part, std::size_t whole) { return static_cast<double>(part) >= kInlierShare * static_cast<double>(whole); }

// Whether most of `ids` lie near the sphere.
bool mostly_near(const double* coords, int dim, const std::vector<std::int32_t>& ids, const Sphere& sphere);

// The squared diagonal of the points' bounding box.
double bounding_diagonal2(const double* coords, int dim, const std::vector<std::int32_t>& ids);

// One sphere, or concentric spheres, that most of the `n` points lie near (one_centre_fit.cpp):
// `sphere` receives the smallest of them, `radii2` the squared radii of all of them (smallest
// first; empty or one for a single sphere). False when there is none.
bool one_centre(const double* coords, std::int32_t n, int dim, Sphere& sphere, std::vector<double>& radii2);

// Spheres about several centres, each fitted to patches of the tree (bubble_fit.cpp): the
// spheres, and per point (in the tree's order) the sphere it is in, or -1. False when no
// sphere is found.
bool spheres_of_patches(const double* coords, std::int32_t n, int dim, const spatial::KdTree& tree, std::vector<Sphere>& spheres,
                        std::vector<std::int32_t>& point_sphere);

}  // namespace drange::engine::sphere_fit
