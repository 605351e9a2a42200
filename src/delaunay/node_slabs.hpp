// delaunay/node_slabs.hpp: a thin slab around the points of each flat kd-tree node.
//
// On points sampled from a surface (a scan, a torus, an ellipsoid), a node's points lie on a
// curved patch, and the node's axis-aligned box is as thick as the patch is wide wherever the
// patch is tilted against the axes. The search's empty balls then meet the boxes of many
// patches that run close to their sphere without entering it (a Delaunay ball of a surface
// sample hugs the surface), and every such node is entered and its points scanned.
//
// A slab {x : lo <= n . x <= hi} around the patch, across its normal n, is only as thick as
// the patch is curved: a ball that misses it misses every point of the node. The normal is the
// direction of least variance of the node's points (the smallest eigenvector of their
// covariance, found bottom-up from the leaves' moments); a node keeps its slab only when the
// slab is much thinner than the node's box along n, so uniform input keeps almost none.
//
// The bounds hold for exact arithmetic: lo and hi are widened by the rounding of each computed
// n . x, so a test with its own rounding bound (misses_ball) never drops a point of the ball.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "geometry/error_bound.hpp"
#include "spatial/kdtree.hpp"

namespace drange::engine {

class Team;

class NodeSlabs {
 public:
  NodeSlabs() = default;
  // The slabs of `tree`'s flat nodes, over its points' coordinates `coords` (tree order, `dim`
  // per point); the leaves' moments are taken on the team's threads.
  NodeSlabs(const spatial::KdTree& tree, const double* coords, int dim, Team& team);

  // The slab of `node`: n (dim entries), then lo and hi; nullptr when the node keeps none.
  const double* slab(std::int32_t node) const {
    if (slabs_.empty()) return nullptr;
    const double* s = &slabs_[static_cast<std::size_t>(node) * stride()];
    return s[d_] <= s[d_ + 1] ? s : nullptr;  // lo > hi: none
  }
  // Whether no point of the slab is within `reach` of `centre`, exactly, whatever the rounding
  // here. D > 0: the caller promises dim() == D.
  template <int D = 0>
  bool misses_ball(const double* slab, const double* centre, double reach) const;
  // How many nodes keep a slab.
  std::size_t size() const { return kept_; }

 private:
  std::size_t stride() const { return static_cast<std::size_t>(d_) + 2; }
  int d_ = 0;
  // Per node (when any node keeps one): n, lo, hi, with lo > hi where the node keeps none. A
  // slab per node rather than an index into the kept ones: the search reads one array, not two
  // (measured faster on an ellipsoid).
  std::vector<double> slabs_;
  std::size_t kept_ = 0;
};

template <int D>
bool NodeSlabs::misses_ball(const double* slab, const double* centre, double reach) const {
  const int d = D > 0 ? D : d_;
  // q = n . c, computed within (d + 1) u of sum |n_k c_k| (+ underflow); n is a unit vector
  // within rounding, so a point x of the slab is at least |n . x - n . c| / (1 + 1e-12) from c.
  double q = 0.0, q_abs = 0.0;
  for (int k = 0; k < d; ++k) {
    q += slab[k] * centre[k];
    q_abs += std::fabs(slab[k] * centre[k]);
  }
  const double q_error = (d + 2) * geometry::kUnitRoundoff * q_abs + 0x1p-1000;
  const double gap = std::max(slab[d] - q, q - slab[d + 1]);
  // The gap's own rounding (relative u) and the norm's are far inside the 1e-9.
  return gap > reach * (1 + 1e-9) + 2 * q_error;
}

}  // namespace drange::engine
