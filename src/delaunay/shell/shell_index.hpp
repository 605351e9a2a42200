// delaunay/shell/shell_index.hpp: the sphere shell's index (SphereShell), built once per input
// by fit_sphere_shell about the spheres found (sphere_fit.hpp): per point, the sphere it lies
// near and its offset |x - g|^2 - rho from it; per kd-tree node, the range of its points'
// exact offsets, a cone from g that holds them, and for concentric spheres two clusters of
// them; per leaf, its points in blocks listed by offset.
//
// Why each piece: the search's test, sigma I(p, x), is linear in (x, |x - g|^2) for any fixed
// g, so its least value over a node's box crossed with the node's range of offsets (as thin as
// the points' distance from the sphere) proves, for many nodes, that none of their points
// beats the candidate (search/shell_pruner.hpp, node_prunes). A box bounds the linear part loosely
// (the box of an arc reaches across the candidate's sphere), so each node also has a cone from
// g, which bounds it over the points' cap; and each leaf lists its points by offset, in blocks
// with cones of their own, so that a scan stops where the offsets prove the rest outside
// (search/shell_pruner.hpp, scan_blocks). With spheres about several centres, each sphere has a
// shell of its own: each point near it is in it, its offset taken about it, and so are the
// ranges and cones of the nodes whose points are all in it. The search's proofs rest on these
// bounds, so each holds the exact values: the offsets carry a proven error bound (eta), and
// every range, cluster and cone is widened by its roundings.
#pragma once

#include <cstdint>
#include <vector>

#include "delaunay/shell/shell_arithmetic.hpp"

namespace drange::spatial {
class KdTree;
}

namespace drange::engine {

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
  // those: search/shell_pruner.hpp, on_closed_side). On a sphere the node's points lie on an
  // arc or a cap, which its box bounds loosely: the cone bounds the form's linear term over
  // them tightly (search/shell_pruner.hpp, cone_linear_low).
  std::vector<double> cone;
  // Each leaf cut into runs of points in one sphere (or in none), and each run into blocks the
  // way the build orders its points (halving down to 8 points in 3D, 32 from 4D, the whole
  // run in 2D: near points; shell_index.cpp, block_size): block b is [block_start[b],
  // block_start[b + 1]), in sphere block_sphere[b], and a leaf's blocks start at
  // first_block[leaf] (-1 for inner nodes and leaves in no sphere); each block's cone (as
  // `cone`), and its point ids by increasing offset (block_ids over the block's positions)
  // with those offsets. The leaf scan tests, block by block, only the points whose offset can
  // still beat the candidate (search/shell_pruner.hpp, scan_blocks).
  std::vector<std::int32_t> block_start, first_block, block_sphere;
  std::vector<double> block_cone;
  std::vector<std::int32_t> block_ids;
  std::vector<double> block_offsets;
  // Concentric spheres: each node's points in two clusters, those near the smallest sphere
  // (offset below cluster_split) and the rest, each with bounds of its exact offsets and of
  // its |y| (stride 8: s_lo, s_hi, r_lo, r_hi for each; an empty cluster has s_lo > s_hi). A
  // node that holds points of two spheres has a range of offsets and of radii over both, which
  // prunes nothing in the search of the cell inside the smallest; per cluster they are as thin
  // as a node's on one sphere (search/shell_pruner.hpp, node_prunes). Empty for one sphere and for
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

// The shell of `n` points of dimension `dim` (row-major, in the tree's order: node ranges are
// point ids), with one sphere when 9 in 10 of them lie within a relative 2^-10 of the fitted
// sphere's squared radius, or of the squared radius of one of at most 32 concentric spheres
// (one_centre_fit.cpp, spheres_in; the offsets are then around the smallest); else with a
// sphere per group of patches that 9 in 10 of their points lie so near (bubble_fit.cpp,
// spheres_of_patches); else inactive.
SphereShell fit_sphere_shell(const double* coords, std::int32_t n, int dim, const spatial::KdTree& tree);

}  // namespace drange::engine
