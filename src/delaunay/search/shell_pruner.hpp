// delaunay/search/shell_pruner.hpp: the sphere-shell accelerator (variant no-shell turns it off).
//
// On points near spheres (one sphere, concentric spheres, bubbles: SphereShell, sphere_shell.hpp)
// every candidate's ball of a facet on a sphere holds nearly all its points, within rounding of
// the sphere, so the ball prunes nothing and every filter fails. About the sphere's centre g,
// with y = x - g and each point's stored offset s_x = |x - g|^2 - rho, the in-sphere test is
// exactly linear: sigma I(p, x) = B . y + W S_x + K (geometry::exact_lifted_form). This object
// keeps that form for the current candidate (its coefficients truncated to doubles, with error
// bounds) and uses it three ways:
//   - sign(): a certified sign of sigma I(p, x) for a point on the facet's sphere, before the
//     exact stages (LiftedSphereTest's hint);
//   - prunes(): a kd-tree node whose cone of directions and range of offsets prove every point
//     outside the candidate's sphere;
//   - scan_leaf(): a leaf's points by offset, up to the first whose offset alone proves the
//     rest outside;
// and, for any facet, on_closed_side(): a node whose cone lies on the facet's closed side.
// None of them changes which point a search finds.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include "delaunay/sphere_shell.hpp"
#include "drange/points.hpp"
#include "geometry/error_bound.hpp"
#include "geometry/predicates.hpp"
#include "spatial/kdtree.hpp"

namespace drange::engine {

// An upper bound of |v| from its computed sum of d squares: the roundings, and what underflow
// may take from the squares (each loses less than 2^-1074, so the root of all they lose is
// below 2^-530).
inline double upper_norm(double sum_of_squares, int d) {
  return std::sqrt(sum_of_squares) * (1 + geometry::gamma_bound(d + 2)) + 0x1p-530;
}

template <int D>
class ShellPruner {
 public:
  static constexpr int kMaxRow = kMaxDimension + 1;
  static constexpr double kInfinity = std::numeric_limits<double>::infinity();

  // `shell`: the points' shell, or nullptr when the accelerator is off.
  ShellPruner(int d, const SphereShell* shell, const spatial::KdTree& tree, const double* coords)
      : d_(d), shell_(shell), tree_(tree), coords_(coords) {
    if (shell_ != nullptr) everywhere_ = shell_->node_sphere.front() >= 0;
    point_gamma_ = geometry::gamma_bound(d + 7);
    node_gamma_ = geometry::gamma_bound(d + 8);
    cone_gamma_ = geometry::gamma_bound(8 * d + 40);
    sum_gamma_ = geometry::gamma_bound(6);
  }
  bool enabled() const { return shell_ != nullptr; }

  // A new facet (sorted ids, f0, and the plane's coefficients a of sigma O(x) = a . (x - f0)):
  // the sphere all its vertices are on, if any, and the facet's terms about it.
  void start_facet(const std::int32_t* ids, const double* f0, const double* a) {
    const int d = dim();
    form_ = scan_ = false;
    facet_minors_.ready = false;
    ids_ = ids;
    f0_ = f0;
    a_ = a;
    sphere_ = shell_->point_sphere[static_cast<std::size_t>(ids[0])];
    for (int i = 1; i < d && sphere_ >= 0; ++i)
      if (shell_->point_sphere[static_cast<std::size_t>(ids[i])] != sphere_) sphere_ = -1;
    if (sphere_ < 0) {
      // With one sphere, every node's cone is about its centre (on_closed_side), for the
      // facets with vertices off it too.
      if (shell_->spheres() == 1) facet_on_shell_ = facet_about(shell_->sphere(0).centre);
      return;
    }
    view_ = shell_->sphere(sphere_);
    facet_on_shell_ = facet_about(view_.centre);
  }

  // A new candidate (its id, sigma, and the rows f_1, ..., f_{d-1}, p): its form, when it is
  // on the facet's sphere. Then the form serves sign(); the scan serves the candidate until
  // its ball turns out not centred (ball_centred).
  void start_candidate(std::int32_t candidate, int sigma, const double* const* rows) {
    candidate_ = candidate;
    if (shell_ != nullptr) set_form(sigma, rows);
    scan_ = form_;
  }
  // The shell's prunes and leaf scan serve the candidate when its ball is about the facet
  // sphere's centre (within a quarter of the sphere's radius): that is the cell inside the
  // sphere, whose every point is a near-tie. A ball elsewhere (between two concentric
  // spheres, or between bubbles) is smaller and its points are not, and the ball's box and
  // lane tests select them better than offsets and cones. The form still decides them (sign).
  void ball_centred(const double* centre) {
    if (!scan_) return;
    const int d = dim();
    double apart2 = 0.0;
    for (int k = 0; k < d; ++k) {
      const double delta = centre[k] - view_.centre[k];
      apart2 += delta * delta;
    }
    scan_ = apart2 <= 0.0625 * view_.rho;
  }
  bool scanning() const { return scan_; }

  // A certified sign of sigma I(p, x) for the point id (0 when undecided).
  int sign(std::int32_t id) const {
    if (!form_) return 0;
    // v = constant + b . fl(x - g) + lift s_x in floating point (s_x: the stored offset). With
    // B, W, K the exact coefficients and S_x the exact offset, sigma I = B . y + W S_x + K, and
    //   |v - sigma I| <= gamma(d + 3) A    (the roundings of fl(x - g), the products, the sums)
    //                  + 2.01 u A          (the coefficients' truncation)
    //                  + |W| (u |s_x| + eta)  (the offset's error: u A and eta_term_)
    // with A = |constant| + sum |b_k| |fl(x_k - g_k)| + |lift| |s_x|: point_gamma_ =
    // gamma_bound(d + 7) covers the A terms. An underflow costs at most 2^-1074 per operation.
    const int d = dim();
    if (shell_->point_sphere[static_cast<std::size_t>(id)] != sphere_) return 0;  // its offset is about another sphere
    const double* x = point(id);
    const double* g = view_.centre;
    const double offset = shell_->offset[static_cast<std::size_t>(id)];
    double v = constant_, a = std::fabs(constant_), coefficients = constant_err_;
    for (int k = 0; k < d; ++k) {
      const double y = x[k] - g[k];
      v += b_[static_cast<std::size_t>(k)] * y;
      a += std::fabs(b_[static_cast<std::size_t>(k)]) * std::fabs(y);
      coefficients += b_err_[static_cast<std::size_t>(k)] * std::fabs(y);
    }
    v += lift_ * offset;
    a += std::fabs(lift_) * std::fabs(offset);
    coefficients += lift_err_ * (std::fabs(offset) + view_.eta);
    if (!(a < geometry::kFilterOverflow)) return 0;  // also NaN
    // The coefficients' errors (float_form's; 0 for GMP's) at |y| and |s_x| + eta.
    const double bound = point_gamma_ * a + eta_term_ + 1.01 * coefficients + 0x1p-1000;
    if (v > bound) return 1;
    if (v < -bound) return -1;
    return 0;
  }

  // Whether the node is in the facet's sphere and its offsets and cone prove every point outside
  // the candidate's sphere (while scanning()).
  bool prunes(std::int32_t node) const { return in_sphere(node) && node_prunes(node); }

  // The leaf's points by offset when the leaf (or some of its blocks) is in the facet's sphere;
  // false if not (then the caller scans it). `consider(id)` tests a point as the search does;
  // `tested` counts the points turned away here.
  template <class Consider>
  bool scan_leaf(std::int32_t leaf, std::int32_t end, const Consider& consider, std::uint64_t& tested) {
    if (in_sphere(leaf)) {
      scan_blocks<true>(leaf, end, consider, tested);
      return true;
    }
    if (shell_->node_sphere[static_cast<std::size_t>(leaf)] != SphereShell::kParts) return false;
    scan_blocks<false>(leaf, end, consider, tested);
    return true;
  }

  // Whether the node's cone proves all its points on the closed side of the facet, where its
  // box does not (box_abs: the plane's absolute tree over the box, box_gamma its factor). On a
  // sphere the facet's hyperplane cuts it near the facet only, but the boxes of the points near
  // it reach across.
  [[gnu::noinline]] bool on_closed_side(std::int32_t node, double box_gamma, double box_abs) const {
    // sigma O(x) = a . (x - f0) = a . y + a . (g - f0) with y = x - g = r e in the node's cone:
    // a . e is at most -least_on_cone(-a). The rounding here is within cone_gamma_ of the
    // absolute tree; the exact minors differ from a by at most the box's coefficient error,
    // which box_gamma times the box's absolute tree covers (the box holds the points).
    // The cone is about the node's sphere's centre: the facet's sphere's, or another's (then
    // its a . (g - f0) is computed here). With one sphere, every node has a cone about its
    // centre, and every facet its terms about it: the nodes that mix points on the sphere with
    // points inside it have no sphere of their own, and their boxes alone would make a hull
    // facet's search visit them all.
    const int d = dim();
    std::int32_t sphere = everywhere_ ? sphere_ : shell_->node_sphere[static_cast<std::size_t>(node)];
    if (sphere < 0 && shell_->spheres() == 1) sphere = 0;  // every node's cone is about its centre
    const double* cone = shell_->cone_of(node);
    if (sphere < 0 || !(cone[d] > 0.0)) return false;
    const FacetOnShell* facet = &facet_on_shell_;
    FacetOnShell other;
    if (sphere != sphere_ && shell_->spheres() > 1) {
      other = facet_about(shell_->sphere(sphere).centre);
      facet = &other;
    }
    const FacetOnShell& terms = *facet;
    const double norm = terms.norm;
    const double most = -least_on_cone(a_, -1.0, norm, cone);
    const double value = terms.offset + (most > 0.0 ? most * cone[d + 3] : most * cone[d + 2]);
    const double bound = cone_gamma_ * (terms.offset_abs + norm * cone[d + 3]) + box_gamma * box_abs + 0x1p-1000;
    return value < -bound;  // false on NaN
  }

 private:
  int dim() const { return D > 0 ? D : d_; }
  const double* point(std::int32_t id) const { return coords_ + static_cast<std::size_t>(id) * static_cast<std::size_t>(dim()); }
  bool in_sphere(std::int32_t node) const {
    return everywhere_ || shell_->node_sphere[static_cast<std::size_t>(node)] == sphere_;
  }

  // The candidate's form about the facet sphere's centre, sigma folded in: in floating point
  // where float_form can (d = 2 to 8, no under- or overflow), else exactly (GMP).
  void set_form(int sigma, const double* const* rows) {
    const int d = dim();
    form_ = sphere_ >= 0 && shell_->point_sphere[static_cast<std::size_t>(candidate_)] == sphere_;
    if (!form_) return;
    form_ = float_form_of(rows);
    if (!form_) {
      const geometry::Frame frame{d, d, nullptr, f0_};
      form_ = geometry::exact_lifted_form(frame, rows, view_.centre, view_.rho, b_.data(), &lift_, &constant_);
      if (!form_) return;
      b_err_.fill(0.0);
      lift_err_ = constant_err_ = b_err_sum_ = 0.0;
    }
    for (int k = 0; k < d; ++k) b_[static_cast<std::size_t>(k)] *= sigma;
    lift_ *= sigma;
    constant_ *= sigma;
    eta_term_ = 1.01 * (std::fabs(lift_) + lift_err_) * view_.eta;
    double b2 = 0.0;
    for (int k = 0; k < d; ++k) b2 += b_[static_cast<std::size_t>(k)] * b_[static_cast<std::size_t>(k)];
    b_norm_ = upper_norm(b2, d);
  }

  // The form in floating point with its coefficients' error bounds; false where float_form
  // declines or the arithmetic under- or overflowed.
  bool float_form_of(const double* const* rows) {
    const int d = dim();
    if (d > kFloatFormMaxDim) return false;
    std::array<double, kMaxRow> row_offsets{};
    for (int i = 0; i < d; ++i)
      row_offsets[static_cast<std::size_t>(i)] = shell_->offset[static_cast<std::size_t>(i < d - 1 ? ids_[i + 1] : candidate_)];
    FloatForm form;
    const geometry::FloatingPointWatch watch;
    const bool good =
        float_form(view_, d, f0_, shell_->offset[static_cast<std::size_t>(ids_[0])], rows, row_offsets.data(), form, &facet_minors_);
    if (!good || !watch.clean()) return false;
    for (int k = 0; k < d; ++k) {
      b_[static_cast<std::size_t>(k)] = form.b[k];
      b_err_[static_cast<std::size_t>(k)] = form.b_err[k];
    }
    lift_ = form.lift;
    constant_ = form.constant;
    lift_err_ = form.lift_err;
    constant_err_ = form.constant_err;
    b_err_sum_ = form.b_err_sum;
    return true;
  }

  // The linear part's lower bound over the node's cone (tight on a sphere's caps) and, where that
  // does not prune, over its box: the test only grows with the bound, so this prunes where the
  // larger of the two would, and spares the box's sums where the cone suffices.
  [[gnu::noinline]] bool node_prunes(std::int32_t node) const {
    if (!shell_->clusters.empty()) {
      const double* clusters = shell_->clusters_of(node);
      if (clusters[0] <= clusters[1] && clusters[4] <= clusters[5]) return clusters_prune(node, clusters);
    }
    const double* range = shell_->of(node);
    return linear_prunes(range, cone_linear_low(shell_->cone_of(node))) || linear_prunes(range, box_linear_low(node));
  }

  // node_prunes for a node with points of two concentric spheres (SphereShell::clusters): each
  // cluster by its own offsets and radii. The box's bound is computed once, if a cluster needs it.
  bool clusters_prune(std::int32_t node, const double* clusters) const {
    const double* cone = shell_->cone_of(node);
    double box = 0.0;
    bool box_known = false;
    for (int part = 0; part < 2; ++part) {
      const double* cluster = clusters + 4 * part;
      if (linear_prunes(cluster, cone_linear_low(cone, cluster[2], cluster[3]))) continue;
      if (!box_known) {
        box = box_linear_low(node);
        box_known = true;
      }
      if (!linear_prunes(cluster, box)) return false;
    }
    return true;
  }

  // Whether `linear`, a lower bound of the linear part over some points, proves with `range`,
  // bounds of their exact offsets, that every one has sigma I(p, x) > 0 (outside the
  // candidate's sphere, so it cannot win, now or later): the linear part's bound plus the least
  // W S_x over the range. W's truncation (2 u), the product and the sum round by 4 u of the
  // absolute tree: sum_gamma_.
  bool linear_prunes(const double* range, double linear) const {
    const double low = linear + std::min(lift_ * range[0], lift_ * range[1]);
    const double largest = std::max(std::fabs(range[0]), std::fabs(range[1]));
    const double a = std::fabs(linear) + std::fabs(lift_) * largest;
    return low > sum_gamma_ * a + 1.01 * lift_err_ * largest + 0x1p-1000;  // false on -infinity and NaN
  }

  // A lower bound of the linear part, B . y + K, over the node's box; -infinity if none. Each
  // term's minimum over the box, summed in floating point: within gamma(d + 3) a of its exact
  // value on the truncated coefficients, and within 2.01 u a of the exact coefficients' (a:
  // its absolute tree), which node_gamma_ covers; plus the float form's coefficient errors at
  // the box's largest |y_k|. Always inline: it has two callers in the prune.
  [[gnu::always_inline]] inline double box_linear_low(std::int32_t node) const {
    const int d = dim();
    const double* lo = tree_.template lower<D>(node);
    const double* hi = tree_.template upper<D>(node);
    const double* g = view_.centre;
    double low = constant_, a = std::fabs(constant_), coefficients = constant_err_;
    for (int k = 0; k < d; ++k) {
      const double b = b_[static_cast<std::size_t>(k)];
      const double ylo = lo[k] - g[k], yhi = hi[k] - g[k];
      low += std::min(b * ylo, b * yhi);
      const double y = std::max(std::fabs(ylo), std::fabs(yhi));
      a += std::fabs(b) * y;
      coefficients += b_err_[static_cast<std::size_t>(k)] * y;
    }
    if (!(a < geometry::kFilterOverflow)) return -kInfinity;  // also NaN
    return low - node_gamma_ * a - 1.01 * coefficients - 0x1p-1000;
  }

  // The same over a cone (SphereShell::cone), for the points whose |y| is within [r_lo, r_hi]
  // (by default the cone's); -infinity if the cone is too wide. y = r e with e in the cone:
  // b . y is at least r times least_on_cone, within cone_gamma_ of cone_a (least_on_cone's
  // errors, b's truncation 2 u |b|, r and the sum 2 u).
  double cone_linear_low(const double* cone) const { return cone_linear_low(cone, cone[dim() + 2], cone[dim() + 3]); }
  [[gnu::always_inline]] inline double cone_linear_low(const double* cone, double r_lo, double r_hi) const {
    const int d = dim();
    if (!(cone[d] > 0.0)) return -kInfinity;
    const double least = least_on_cone(b_.data(), 1.0, b_norm_, cone);
    const double linear = least < 0.0 ? least * r_hi : least * r_lo;
    const double cone_a = std::fabs(constant_) + b_norm_ * r_hi;
    if (!(cone_a < geometry::kFilterOverflow)) return -kInfinity;
    // The coefficients' errors: |(B - b) . y| <= sum |B_k - b_k| |y| <= b_err_sum_ r_hi.
    const double coefficients = b_err_sum_ * r_hi + constant_err_;
    return (constant_ + linear) - cone_gamma_ * cone_a - 1.01 * coefficients - 0x1p-1000;
  }

  // The least of sign v . e over the unit vectors e of a cone of axis m (m . e >= cos_lo, as
  // SphereShell::cone, cos_lo > 0), with norm >= |v|. sign v . e is convex along the axis and
  // least (-|v|) at e = -sign v / |v|; when that lies outside the cone, the least is on its
  // rim, at beta cos_lo - |sign v - beta m| sin (beta = sign v . m), lower still with sin_hi.
  // beta is within d u |v| of its exact value; |sign v - beta m| is bounded above from norm and
  // beta alone, which spares a second pass over v and m; the case split has a margin far above
  // beta's rounding error.
  double least_on_cone(const double* v, double sign, double norm, const double* cone) const {
    const int d = dim();
    const double cos_lo = cone[d];
    double beta = 0.0;
    for (int k = 0; k < d; ++k) beta += sign * v[k] * cone[k];
    if (!(-beta < (cos_lo - 1e-6) * norm)) return -norm;
    // With B the exact sign v . m, |sign v - B m|^2 = |v|^2 - B^2 (2 - |m|^2), and |m|^2 is
    // within 2 (d + 2) u of 1, B within d u norm of beta: so it is at most norm^2 - beta^2 +
    // (4 d + 4) u norm^2, and the slack below covers that and this line's roundings (3 u norm^2
    // in the difference, the sum's and the root's, which (1 + 2 u) undoes).
    constexpr double u = geometry::kUnitRoundoff;
    const double norm2 = norm * norm;
    const double perp2 = std::max(0.0, norm2 - beta * beta) + (4 * d + 16) * u * norm2;
    return beta * cos_lo - std::sqrt(perp2) * (1 + 2 * u) * cone[d + 1];
  }

  // sign()'s sums over a block's points, bounded once per block by the block cone's largest
  // |y| rather than summed per point: sum |b_k| |fl(y_k)| <= |b| |fl(y)| <= |b| (1 + u) r_hi
  // (Cauchy-Schwarz; b_norm_ is at least |b|, r_hi at least every exact |y|), and sum b_err_k
  // |fl(y_k)| <= b_err_sum (1 + u) r_hi. The factor 1 + 4 u covers fl(y)'s rounding and the
  // products' here; the few sums left round less than sign()'s do.
  struct BlockTerms {
    double abs_tree, coefficients;
  };
  BlockTerms block_terms(const double* cone) const {
    const double r_hi = cone[dim() + 3] * (1 + 4 * geometry::kUnitRoundoff);
    return {std::fabs(constant_) + b_norm_ * r_hi, constant_err_ + b_err_sum_ * r_hi};
  }
  // sign()'s test for +1, with the block's terms for its sums of |y|.
  bool outside(std::int32_t id, double offset, const BlockTerms& terms) const {
    const int d = dim();
    const double* x = point(id);
    const double* g = view_.centre;
    double v = constant_;
    for (int k = 0; k < d; ++k) v += b_[static_cast<std::size_t>(k)] * (x[k] - g[k]);
    v += lift_ * offset;
    const double a = terms.abs_tree + std::fabs(lift_) * std::fabs(offset);
    const double coefficients = terms.coefficients + lift_err_ * (std::fabs(offset) + view_.eta);
    if (!(a < geometry::kFilterOverflow)) return false;  // also NaN
    return v > point_gamma_ * a + eta_term_ + 1.01 * coefficients + 0x1p-1000;
  }

  // A leaf's points block by block (SphereShell::block_ids), each block's by offset from the end
  // whose offsets make the form smallest, up to the first point whose offset alone proves the
  // form positive over the block's cone: the points beyond it are outside the candidate's sphere
  // too. For W > 0 the points go by increasing offset s: sigma I(p, x) >= linear + W S_x
  // (linear: the block cone's bound), and once that is certified positive at s, it is at every
  // later point, whose exact offset is no smaller than s - u |s| - eta. For W < 0, by
  // decreasing offset. The bound: node_prunes' roundings, the offset's error u |s| (sum_gamma_
  // has room) and eta (eta_term_). A new candidate changes the form (and perhaps W's sign); the
  // points already considered lie outside its sphere too, or on the closed side, so the scan
  // goes on from the block's ends. kAllInSphere: the leaf is in the facet's sphere (else some
  // of its blocks are, and the others' points are considered one by one). Out of line, as the
  // other functions the walk calls: inlined, they grew the walk that uniform input runs.
  template <bool kAllInSphere, class Consider>
  [[gnu::noinline]] void scan_blocks(std::int32_t leaf, std::int32_t end, const Consider& consider, std::uint64_t& tested) {
    const std::int32_t* ids = shell_->block_ids.data();
    const double* offsets = shell_->block_offsets.data();
    for (std::int32_t block = shell_->first_block[static_cast<std::size_t>(leaf)];
         shell_->block_start[static_cast<std::size_t>(block)] < end; ++block) {
      std::int32_t first = shell_->block_start[static_cast<std::size_t>(block)], last = shell_->block_start[static_cast<std::size_t>(block) + 1];
      if (!kAllInSphere && shell_->block_sphere[static_cast<std::size_t>(block)] != sphere_) {
        for (std::int32_t i = first; i < last; ++i) consider(i);  // a block of another sphere, or of none: its ids are its positions
        continue;
      }
      std::int32_t form_of = -1;  // the candidate whose form `linear` and `terms` bound
      double linear = 0.0;
      BlockTerms terms{};
      while (first < last) {
        if (!form_) {  // the candidate's form could not be computed: the rest one by one
          for (std::int32_t i = first; i < last; ++i) consider(ids[i]);
          break;
        }
        if (form_of != candidate_) {
          linear = cone_linear_low(shell_->block_cone_of(block));
          terms = block_terms(shell_->block_cone_of(block));
          form_of = candidate_;
        }
        const double w = lift_;
        const std::int32_t i = w < 0.0 ? last - 1 : first;
        if (w != 0.0) {
          const double ws = w * offsets[i];
          const double bound = sum_gamma_ * (std::fabs(linear) + std::fabs(ws)) + eta_term_ +
                               1.01 * lift_err_ * (std::fabs(offsets[i]) + view_.eta) + 0x1p-1000;
          if (linear + ws > bound) break;  // false on -infinity and NaN
        }
        if (w < 0.0) --last;
        else ++first;
        // Most points the block's bound lets through are still outside the candidate's sphere
        // by their own form's value: certified so, they are turned away before the query, side
        // and lifted tests (whose filters fail on a sphere) that consider() would run.
        if (outside(ids[i], offsets[i], terms)) {
          ++tested;
          continue;
        }
        consider(ids[i]);
      }
    }
  }

  // The facet's terms about a sphere's centre g: |a| (with a margin for its rounding) and
  // a . (g - f0) with its absolute tree.
  struct FacetOnShell {
    double norm, offset, offset_abs;
  };
  FacetOnShell facet_about(const double* g) const {
    const int d = dim();
    double norm2 = 0.0, offset = 0.0, offset_abs = 0.0;
    for (int k = 0; k < d; ++k) {
      const double a = a_[k];
      const double t = g[k] - f0_[k];
      norm2 += a * a;
      offset += a * t;
      offset_abs += std::fabs(a) * std::fabs(t);
    }
    return {upper_norm(norm2, d), offset, offset_abs};
  }

  int d_;
  const SphereShell* shell_;
  const spatial::KdTree& tree_;
  const double* coords_;
  bool everywhere_ = false;  // one sphere over the whole tree (a sphere, concentric spheres)
  // Error bound factors of sign, box_linear_low, the cones and linear_prunes (see there).
  double point_gamma_ = 0.0, node_gamma_ = 0.0, cone_gamma_ = 0.0, sum_gamma_ = 0.0;

  // Per facet.
  const std::int32_t* ids_ = nullptr;
  const double* f0_ = nullptr;
  const double* a_ = nullptr;  // the plane's coefficients (FacetPlaneTest::coefficients)
  // The sphere of the shell that all the facet's vertices are on (-1: none), and its terms.
  std::int32_t sphere_ = -1;
  ShellSphere view_{};
  FacetOnShell facet_on_shell_{};
  FacetMinors facet_minors_;  // float_form's minors of this facet's rows, once computed

  // Per candidate: with y = x - g, sigma I(p, x) = b . y + lift (|x - g|^2 - rho) + constant
  // exactly for the exact coefficients; these are them truncated to doubles (relative error
  // below 2u), sigma folded in, with bounds of |B_k - b_k|, |W - lift|, |K - constant| beyond
  // the truncation (nonzero for float_form's coefficients) and the sum of the first.
  std::int32_t candidate_ = -1;
  bool form_ = false;  // the candidate's form is computed
  bool scan_ = false;  // prunes and scan_leaf serve the candidate
  std::array<double, kMaxRow> b_{}, b_err_{};
  double lift_ = 0.0, constant_ = 0.0;
  double lift_err_ = 0.0, constant_err_ = 0.0, b_err_sum_ = 0.0;
  double eta_term_ = 0.0;  // |lift| times the error bound of the points' offsets, with margin
  double b_norm_ = 0.0;    // an upper bound of |b|
};

}  // namespace drange::engine
