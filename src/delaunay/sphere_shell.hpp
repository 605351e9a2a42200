// delaunay/sphere_shell.hpp: for points that lie near one sphere (centre g, squared radius
// rho), each point's offset |x - g|^2 - rho and their range in every kd-tree node (our step,
// SearchOptions::sphere_shell).
//
// Why: on (nearly) cospherical input, every candidate's sphere is within rounding of the input
// sphere, so its ball meets every kd-tree node near that sphere and the search scans nearly
// all the points, for every facet (quadratic: 20 000 points on a circle took 1.3 s, CGAL 9 ms).
// But the search's test, sigma I(p, x), is linear in (x, |x - g|^2) for any fixed g; with g the
// input sphere's centre, a node's points have |x - g|^2 in a range as thin as their distance
// from that sphere, and the minimum of the linear form over the node's box crossed with that
// range proves, for many nodes, that none of their points beats the candidate
// (facet_search.cpp, shell_prunes). A node's box bounds the linear part loosely (the box of an
// arc reaches across the candidate's sphere), so each node also has a cone from g that holds
// its points, which bounds it over the points' cap; and each leaf lists its points by offset,
// in blocks with cones of their own, so that a scan stops where the offsets prove the rest
// outside (scan_shell_leaf). Only the points within rounding of the candidate's sphere are
// then tested: about 30 per simplex on circles and spheres of any size.
//
// The form's terms must be small for the bounds to be tight, so it is computed around g and
// rho, once per candidate: in floating point from the points' offsets with a bound of each
// coefficient's error (float_form, d = 2 to 8), else exactly (geometry::exact_lifted_form);
// and each point's offset from the sphere, |x - g|^2 - rho, once per point in double-double
// arithmetic: the points' tests then resolve their sign to within rounding of those small
// terms, and GMP is left with the true ties. (With the search's own form, whose terms are a
// hundred times the value, most tests near the sphere went to GMP: 3D, 8 000 points, 640 per
// simplex.)
//
// The bounds are sound for any g, but useful only when most points lie near a sphere, or near
// a few spheres about one centre (a node's points then lie near one of them, and its range is
// as thin), so the shell is built only then (a least-squares fit; see sphere_shell.cpp). Else,
// when patches of the tree (nodes of up to 512 points, parts of leaves) lie near spheres about
// several centres (bubbles, or the cells of a foam), each such sphere gets a shell of its own:
// each point near it is in it, its offset taken around it, and so are the ranges and cones of
// the nodes whose points are all in it; a facet whose vertices are all in one sphere is
// searched with that sphere's form.
// It changes which nodes are visited, never the point found.
#pragma once

#include <cstdint>
#include <vector>

namespace drange::spatial {
class KdTree;
}

namespace drange::engine {

// One sphere of the shell: its centre g (dim doubles), the squared radius rho its offsets are
// taken from, and their error bound eta.
struct ShellSphere {
  const double* centre;
  double rho;
  double eta;
};

struct SphereShell {
  int dim = 0;
  // The spheres: centres (dim doubles each), rho and eta each (see ShellSphere); none when the
  // input is not near spheres. One for a sphere or concentric spheres.
  std::vector<double> centres, rho, eta;
  // Per point id and per kd-tree node: the sphere whose shell it is in, or -1 (a node under no
  // patch, or above patches of different spheres), or kParts for a leaf whose points are not
  // all in one sphere but some are (parts of it are patches; see its blocks).
  static constexpr std::int32_t kParts = -2;
  std::vector<std::int32_t> point_sphere, node_sphere;
  // Per point id: s = |x - g|^2 - rho about its sphere, computed in double-double arithmetic
  // and rounded, with | s - exact | <= u |s| + eta (u = 2^-53); 0 for a point in no sphere.
  std::vector<double> offset;
  std::vector<double> range;  // per kd-tree node in a sphere: bounds of the exact |x - g|^2 - rho over its points
  // Per kd-tree node in a sphere, a cone from g that holds its points, stride dim + 4: a unit
  // axis m, then cos_lo (every point's exact direction y / |y|, y = x - g, has m . y >= cos_lo
  // |y|), sin_hi (at least sqrt(1 - cos_lo^2), with a margin for m's rounding), and r_lo <= |y|
  // <= r_hi. cos_lo is -2 where no such cone is narrower than a half-space (or a point is at
  // g), and for a node in no sphere, unless the shell has one sphere: then every node has a
  // cone about its centre, over its points off the sphere too (the closed side's proof uses
  // those: facet_search.cpp, cone_on_closed_side). On a sphere the node's points lie on an
  // arc or a cap, which its box bounds loosely: the cone bounds the form's linear term over
  // them tightly (facet_search.cpp, cone_linear_low).
  std::vector<double> cone;
  // Each leaf cut into runs of points in one sphere (or in none), and each run into blocks the
  // way the build orders its points (halving down to 8 points in 3D, 32 from 4D, the whole
  // run in 2D: near points; sphere_shell.cpp, block_size): block b is [block_start[b],
  // block_start[b + 1]), in sphere block_sphere[b], and a leaf's blocks start at
  // first_block[leaf] (-1 for inner nodes and leaves in no sphere); each block's cone (as
  // `cone`), and its point ids by increasing offset (block_ids over the block's positions)
  // with those offsets. The leaf scan tests, block by block, only the points whose offset can
  // still beat the candidate (facet_search.cpp, scan_shell_leaf).
  std::vector<std::int32_t> block_start, first_block, block_sphere;
  std::vector<double> block_cone;
  std::vector<std::int32_t> block_ids;
  std::vector<double> block_offsets;
  // Concentric spheres: each node's points in two clusters, those near the smallest sphere
  // (offset below cluster_split) and the rest, each with bounds of its exact offsets and of
  // its |y| (stride 8: s_lo, s_hi, r_lo, r_hi for each; an empty cluster has s_lo > s_hi). A
  // node that holds points of two spheres has a range of offsets and of radii over both, which
  // prunes nothing in the search of the cell inside the smallest; per cluster they are as thin
  // as a node's on one sphere (facet_search.cpp, shell_prunes). Empty for one sphere and for
  // spheres about several centres.
  double cluster_split = 0.0;
  std::vector<double> clusters;

  bool active() const { return !rho.empty(); }
  std::int32_t spheres() const { return static_cast<std::int32_t>(rho.size()); }
  ShellSphere sphere(std::int32_t k) const {
    const auto i = static_cast<std::size_t>(k);
    return {&centres[i * static_cast<std::size_t>(dim)], rho[i], eta[i]};
  }
  const double* of(std::int32_t node) const { return &range[2 * static_cast<std::size_t>(node)]; }
  const double* cone_of(std::int32_t node) const { return &cone[static_cast<std::size_t>(node) * static_cast<std::size_t>(dim + 4)]; }
  const double* clusters_of(std::int32_t node) const { return &clusters[8 * static_cast<std::size_t>(node)]; }
  const double* block_cone_of(std::int32_t block) const { return &block_cone[static_cast<std::size_t>(block) * static_cast<std::size_t>(dim + 4)]; }
};

// The lifted determinant det[r_1; ...; r_d; r_x] (rows relative to f0, as in
// geometry::exact_lifted_form) as b . (x - g) + lift (|x - g|^2 - rho) + constant, computed in
// floating point from the points' offsets, with bounds of each coefficient's distance to the
// exact one: for d = 2 to 8. `rows` are the d points after f0, `s0` and `row_offsets` their
// offsets (SphereShell::offset). False when a bound is not small against its terms (a
// near-flat simplex, or points exactly on the fitted sphere, where b is 0) or a value is too
// large; the caller also watches the floating-point flags (an underflow voids the bounds).
constexpr int kFloatFormMaxDim = 8;
struct FloatForm {
  double b[kFloatFormMaxDim], b_err[kFloatFormMaxDim];
  double lift, lift_err, constant, constant_err;
  double b_err_sum;  // sum of b_err
};
// From 4D, the form's cofactors are expanded along the candidate's row (rows[d - 1]), over
// minors of the facet's rows alone: those are the same for every candidate of a facet, and
// `minors`, when given, keeps them from the first call (ready) until the caller resets it for
// another facet. Without it they are computed for this call only; the form is the same.
struct FacetMinors {
  static constexpr int kPairs = kFloatFormMaxDim * (kFloatFormMaxDim - 1) / 2;
  bool ready = false;
  double sub[kFloatFormMaxDim - 1][kPairs][2];  // facet rows but i, columns but a pair: value, tree
  double top[kFloatFormMaxDim][2];              // all the facet rows, columns but c: value, tree
};
bool float_form(const ShellSphere& sphere, int d, const double* f0, double s0, const double* const* rows, const double* row_offsets,
                FloatForm& form, FacetMinors* minors = nullptr);

// The shell of `n` points of dimension `dim` (row-major, in the tree's order: node ranges are
// point ids), with one sphere when 9 in 10 of them lie within a relative 2^-10 of the fitted
// sphere's squared radius, or of the squared radius of one of at most 32 concentric spheres
// (sphere_shell.cpp, spheres_in; the offsets are then around the smallest); else with a sphere
// per group of patches that 9 in 10 of their points lie so near (sphere_shell.cpp,
// spheres_of_patches); else inactive.
SphereShell fit_sphere_shell(const double* coords, std::int32_t n, int dim, const spatial::KdTree& tree);

}  // namespace drange::engine
