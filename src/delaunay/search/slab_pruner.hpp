// delaunay/search/slab_pruner.hpp: the node-slab accelerator (variant no-slab turns it off).
//
// On points sampled from surfaces, a kd-tree node's box is much larger than its points' patch:
// NodeSlabs (node_slabs.hpp) keeps, for the flat nodes, a thin slab n . x in [lo, hi] holding
// their points. A node is pruned when its slab misses the candidate's ball, or lies wholly on
// the facet's closed side, where its box does not. Neither test changes which point a search
// finds: both only skip nodes that hold no point that can win.
//
// A search tries slabs while they prune: it starts with kTrials tests, and each test that
// prunes buys kReward more, so that it goes on while more than one test in kReward + 1
// prunes. Along a surface that the balls touch along a curve (a cylinder, a torus) no slab
// separates them from the nodes near it, and the search soon stops trying. Where, over the
// recent searches, more than one test in kReward pruned, a search tries every slab: the tests
// that fail first cost less there than the nodes that later tests prune.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "delaunay/node_slabs.hpp"
#include "geometry/error_bound.hpp"

namespace drange::engine {

template <int D>
class SlabPruner {
 public:
  // `slabs`: the points' slabs, or nullptr when the accelerator is off (then nothing prunes).
  SlabPruner(int d, const NodeSlabs* slabs) : d_(d), slabs_(slabs) {}

  // Once per search, before its walk.
  void start_search() {
    if (tests_ > kMemory) {  // the recent searches weigh most
      tests_ /= 2;
      prunes_ /= 2;
    }
    trials_left_ = prunes_ * kReward > tests_ ? kNoLimit : kTrials;
    trying_ = slabs_;
  }
  bool trying() const { return trying_ != nullptr; }

  // Whether the node's slab proves its points outside the ball about `centre` of radius `reach`.
  // Out of line, as the test below: inlined into the walk, they grew it for inputs without slabs.
  [[gnu::noinline]] bool misses_ball(std::int32_t node, const double* centre, double reach) {
    const double* slab = trying_->slab(node);
    return slab != nullptr && tried(trying_->misses_ball<D>(slab, centre, reach));
  }

  // Whether the node's slab proves its points on the closed side of the facet (sigma O(x) =
  // a . (x - f0) <= 0, a = `plane`, each coefficient's error within box_gamma times box_abs,
  // the absolute tree of the box [lo, hi]'s largest sigma O).
  [[gnu::noinline]] bool on_closed_side(std::int32_t node, const double* lo, const double* hi, const double* a,
                                        const double* f0, double box_gamma, double box_abs) {
    const double* slab = trying_->slab(node);
    if (slab == nullptr) return false;
    // With n the slab's normal and lambda = a . n, sigma O(x) = a . y (y = x - f0) = b . y +
    // lambda n . y, b = a - lambda n: the box bounds b . y (b is small when the facet's
    // hyperplane runs along the patch), the slab bounds n . y. The rounding of b, of the
    // differences, products and sums is within 2 (d + 3) u of the absolute tree s_abs; the
    // exact minors' distance from a is within box_gamma of the box's.
    const int d = dim();
    double lambda = 0.0, n_f0 = 0.0, n_f0_abs = 0.0;
    for (int k = 0; k < d; ++k) {
      lambda += a[k] * slab[k];
      n_f0 += slab[k] * f0[k];
      n_f0_abs += std::fabs(slab[k] * f0[k]);
    }
    double s = 0.0, s_abs = 0.0;
    for (int k = 0; k < d; ++k) {
      const double b = a[k] - lambda * slab[k];
      const double dlo = lo[k] - f0[k], dhi = hi[k] - f0[k];
      s += b * (b >= 0 ? dhi : dlo);
      s_abs += (std::fabs(a[k]) + std::fabs(lambda * slab[k])) * std::max(std::fabs(dlo), std::fabs(dhi));
    }
    const double t = lambda >= 0 ? slab[d + 1] : slab[d];  // the slab's largest n . x, or least
    s += lambda * (t - n_f0);
    s_abs += std::fabs(lambda) * (std::fabs(t) + n_f0_abs);
    return tried(s < -(box_gamma * box_abs + 2 * (d + 3) * geometry::kUnitRoundoff * s_abs + 0x1p-1000));
  }

 private:
  int dim() const { return D > 0 ? D : d_; }
  bool tried(bool pruned) {
    ++tests_;
    prunes_ += pruned;
    trials_left_ += pruned ? kReward : -1;
    if (trials_left_ == 0) trying_ = nullptr;
    return pruned;
  }

  static constexpr int kTrials = 8, kReward = 8, kNoLimit = 1 << 30;
  static constexpr std::uint64_t kMemory = 1 << 16;
  int d_;
  int trials_left_ = kTrials;
  std::uint64_t tests_ = 0, prunes_ = 0;  // over the kernel's searches
  const NodeSlabs* slabs_;
  const NodeSlabs* trying_ = nullptr;  // slabs_ while the search tries them
};

}  // namespace drange::engine
