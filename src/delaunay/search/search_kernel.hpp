// delaunay/search/search_kernel.hpp: the shrinking kd-tree search for the Delaunay point of an
// open facet (paper, section 2.4), for one dimension D (D = 2..8: loops of fixed length; D = 0:
// any d, read at run time). Included by facet_search.cpp only, which compiles it for each D.
//
// The search keeps a candidate p (the best point met so far) and its sphere through the facet
// F; the kd-tree walk visits only the nodes that meet the candidate's query region and skips
// those an accelerator proves useless. Each phase:
//   1. set_facet: the facet's predicates (geometry/facet_plane_test.hpp for the open side,
//      geometry/lifted_sphere_test.hpp for "x beats p") and the accelerators' facet terms;
//   2. seeds: the apexes of the last searches around the facet's vertices are tried first,
//      so that the first query region is already small (seed_memory.hpp);
//   3. the walk (spatial/kdtree.hpp), bottom-up from the leaf of f_0: prune() decides nodes,
//      leaf() scans points, test() sets a new candidate, which shrinks the region;
//   4. the candidate left is the Delaunay point; -1 when no point is on the open side (a hull
//      facet).
// The arithmetic lives in the two predicates; the kernel only asks their signs and never
// changes which point is found, only the order in which points are met.
//
// The accelerators (known hull facets, seeds, sphere shell) are consulted through one
// interface, accelerators.hpp, where each is registered. The closed-side pruning (paper, 2.4.1),
// the facet's child first (2.4.2), the bottom-up walk and the ball (instead of the paper's box)
// are the search's own, switched by SearchOptions.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>

#include "delaunay/facet_search.hpp"
#include "delaunay/leaf_blocks.hpp"
#include "delaunay/search/accelerators.hpp"
#include "delaunay/search/candidate_ball.hpp"
#include "delaunay/search/lanes.hpp"
#include "geometry/facet_plane_test.hpp"
#include "geometry/lifted_sphere_test.hpp"
#include "geometry/static_exactness.hpp"

namespace drange::engine {
// Internal linkage, as the header has one includer: the compiler may then inline the member
// functions that have one caller (the walk's prune and leaf scans, set_candidate) and drop
// their out-of-line copies, which it does not do for functions other units could call.
namespace {

template <int D>
class SearchKernel final : public FacetSearch::Kernel {
 public:
  static constexpr int kMaxRow = kMaxDimension + 1;

  // wide: the AVX2 lane loops where the CPU has them (FacetSearch::VectorWidth).
  SearchKernel(const PointStore& points, const SearchOptions& options, SeedMemory& seeds, bool wide);
  std::int32_t find_apex(const std::int32_t* facet, int sigma, SearchCounters& counters) override;

  // kd-tree visitor interface (spatial/kdtree.hpp).
  const double* query_lower() const { return region_.lower(); }
  const double* query_upper() const { return region_.upper(); }
  bool prune(std::int32_t node, bool leaf);
  bool right_first(const spatial::KdTree::Node& node) const {
    return options_.visit_facet_child_first && centroid_[static_cast<std::size_t>(node.split_axis)] > node.split_value;
  }
  // The walk hands over the leaf's node, so that the scan needs no lookup of its own.
  void leaf(std::int32_t node, std::int32_t begin, std::int32_t end) {
    if (accelerators_.scan_leaf(node, end, [this](std::int32_t id) { consider(id); }, counters_->points_tested)) return;
    if (region_.ball())
      scan_blocks(node, end);
    else if (candidate_ < 0)  // no candidate yet: every point of the leaf is in the query box
      scan_blocks_for_open_side(node, end);
    else
      scan_points(begin, end);
  }

 private:
  int dim() const { return D > 0 ? D : d_; }
  // What the predicates may prove exact: only with dyadic points whose filters hold (scaled).
  static geometry::StaticExactness exactness_of(const PointStore& points) {
    return geometry::StaticExactness(points.dim, points.dyadic && points.scaled, points.unit_exponent);
  }
  void set_facet(const std::int32_t* facet, int sigma);
  [[gnu::always_inline]] inline void set_candidate(std::int32_t id);
  // A new query region from sigma I(p, x) = w . r_x with errors error(j); false when w gives
  // none that can be trusted.
  template <class Error>
  bool set_region(const double* w, const Error& error) {
    if (!region_.set(w, error, f0_, options_.ball_query)) return false;
    if (region_.ball()) accelerators_.centred(region_.centre());
    return true;
  }

  void consider(std::int32_t id) {
    if (region_.holds(points_.point(id))) test(id);
  }
  // A point in the query region: is it on the open side, and does it beat the candidate?
  // The facet's own vertices lie on its hyperplane and on every candidate's sphere, so every
  // scan meets them; the candidate may be met again after being tried as a seed. Those are
  // turned away here, inline, before the test proper.
  void test(std::int32_t id) {
    for (int i = 0; i < dim(); ++i)
      if (facet_[i] == id) return;
    if (id != candidate_) test_other(id);
  }
  void test_other(std::int32_t id);

  // The leaf's points one by one, by the region: where there is a candidate but no ball, and
  // the rest of a leaf after test() lost the ball.
  void scan_points(std::int32_t begin, std::int32_t end) {
    for (std::int32_t id = begin; id < end; ++id) consider(id);
  }
  // The leaf's points block by block (LeafBlocks): a block whose box misses the ball is
  // skipped; in the others, the squared distances of all the block's points are computed at
  // once (the region's arithmetic, lane by lane: the same points pass).
  void scan_blocks(std::int32_t leaf, std::int32_t end);
  // Before the first candidate, when the query box is all space: every point of the leaf is
  // tested, in order, up to the first on the open side, except those that the plane filter
  // puts on the closed side, found block by block lane by lane (most of a leaf lies on the
  // closed side of a facet).
  void scan_blocks_for_open_side(std::int32_t leaf, std::int32_t end);
  // The lanes of a block in reach of the ball, and the blocks of a group (lanes.hpp).
  [[gnu::always_inline]] inline unsigned points_in_reach(const double* lanes) const;
  [[gnu::always_inline]] inline unsigned boxes_in_reach(const double* boxes) const;
  // The lanes of a block (its first `count`), and the blocks of a group, that the plane's
  // filter does not certify on the closed side.
  unsigned maybe_open_side(const double* lanes, int count) const;
  unsigned boxes_maybe_open_side(const double* boxes) const;
  // Of the lanes `in` (two or more), the one whose point would make the smallest sphere with
  // the facet, by its floating-point value of I(p, x) over its height above the facet (both
  // linear in the pencil of spheres through the facet); -1 when none is above the facet.
  int best_lane(const double* lanes, unsigned in) const;
  // The lanes of the block of ids [from, from + kLanes) that hold the facet's vertices or the
  // candidate: on the sphere, in reach of every ball, and turned away by test().
  unsigned known_lanes(std::int32_t from) const {
    unsigned known = 0;
    for (int i = 0; i < dim(); ++i) {
      const auto lane = static_cast<unsigned>(facet_[i] - from);
      if (lane < static_cast<unsigned>(LeafBlocks::kLanes)) known |= 1u << lane;
    }
    const auto lane = static_cast<unsigned>(candidate_ - from);
    if (lane < static_cast<unsigned>(LeafBlocks::kLanes)) known |= 1u << lane;
    return known;
  }

  const PointStore& points_;
  SearchOptions options_;
  int d_;
  // The points are scaled below 1 in magnitude (PointStore::scaled): then no operation of the
  // search overflows or is invalid, and what underflow adds to its values stays below
  // geometry::kUnderflowError, which every filter's floor absorbs and the query ball allows
  // for. The error bounds hold with no floating-point flag read (a read waits for the
  // arithmetic before it, which the hot loops cannot afford).
  const bool filters_hold_;
  bool avx2_ = false;  // the lane loops in their AVX2 versions
  // 1 / d for the centroid: it only orders the walk (right_first), so its rounding need not be
  // that of f / d, and a product is cheaper than d^2 divisions per facet.
  double inverse_d_;

  // Per facet.
  const std::int32_t* facet_ = nullptr;
  int sigma_ = 1;
  const double* f0_ = nullptr;
  std::array<double, kMaxRow> centroid_{};
  // Per search: inner nodes entered that met a ball. After kClosedSideAfter of them, prune
  // tests the closed side of inner nodes with a ball too (see there).
  std::int32_t ball_nodes_ = 0;
  static constexpr std::int32_t kClosedSideAfter = 32;

  // Per candidate.
  std::int32_t candidate_ = -1;
  CandidateBall<D> region_;
  std::array<double, kMaxRow> row_{};  // r_x of the point being tested (scratch)
  SearchCounters* counters_ = nullptr;

  const LeafBlocks& blocks_;  // points_.blocks
  Accelerators<D> accelerators_;

  // The predicates; last, being large (their exact stages' fixed-width cofactors), apart from
  // the members that every search reads.
  geometry::FacetPlaneTest<D> plane_;
  geometry::LiftedSphereTest<D> sphere_;
};

template <int D>
SearchKernel<D>::SearchKernel(const PointStore& points, const SearchOptions& options, SeedMemory& seeds, bool wide)
    : points_(points),
      options_(options),
      d_(points.dim),
      filters_hold_(points.scaled),
      inverse_d_(1.0 / points.dim),
      region_(points.dim),
      blocks_(points.blocks),
      accelerators_(points, options, seeds),
      plane_(points.dim, points.size, points.scaled, options.remember_ties, exactness_of(points)),
      sphere_(points.dim, points.size, points.tree.order().data(), points.scaled, options.remember_ties, exactness_of(points)) {
#if DRANGE_AVX2_LANES
  avx2_ = wide && __builtin_cpu_supports("avx2");
#else
  (void)wide;
#endif
}

template <int D>
std::int32_t SearchKernel<D>::find_apex(const std::int32_t* facet, int sigma, SearchCounters& counters) {
  counters_ = &counters;
  if (accelerators_.skips(facet, sigma)) return -1;
  ball_nodes_ = 0;
  set_facet(facet, sigma);
  candidate_ = -1;
  region_.reset();
  accelerators_.seeds(facet, [this](std::int32_t id) { consider(id); });
  if (options_.use_kdtree && options_.bottom_up) {
    counters.calls += points_.tree.search_from<D>(*this, points_.tree.leaf_of(facet[0]));
  } else if (options_.use_kdtree) {
    counters.calls += points_.tree.search<D>(*this);
  } else {
    ++counters.calls;
    for (std::int32_t id = 0; id < points_.size; ++id) consider(id);
  }
  accelerators_.found(facet, candidate_);
  return candidate_;
}

template <int D>
void SearchKernel<D>::set_facet(const std::int32_t* facet, int sigma) {
  const int d = dim();
  facet_ = facet;
  sigma_ = sigma;
  f0_ = points_.point(facet[0]);
  std::array<const double*, kMaxRow> vertices{};
  for (int k = 0; k < d; ++k) centroid_[static_cast<std::size_t>(k)] = 0.0;
  for (int i = 0; i < d; ++i) {
    const double* f = points_.point(facet[i]);
    vertices[static_cast<std::size_t>(i)] = f;
    for (int k = 0; k < d; ++k) centroid_[static_cast<std::size_t>(k)] += f[k] * inverse_d_;
  }
  sphere_.set_facet(facet, sigma, vertices.data());
  plane_.set_facet(facet, sigma, f0_, vertices.data() + 1, sphere_.minors(), sphere_.orientation_exact());
  accelerators_.start_facet(facet, f0_, plane_.coefficients());
}

template <int D>
void SearchKernel<D>::set_candidate(std::int32_t id) {
  candidate_ = id;
  ++counters_->candidates;
  sphere_.set_candidate(id, points_.point(id), row_.data());  // row_ holds r_p (test_other computed it)
  accelerators_.start_candidate(id, sigma_, sphere_.rows());
  if (filters_hold_ && set_region(sphere_.w(), [this](int j) { return sphere_.error(j); })) return;
  // No trustworthy box from the doubles: the candidate within rounding of the facet's
  // hyperplane (every entry of w is then noise). The double-double cofactors give the sphere.
  if (filters_hold_) {
    std::array<double, kMaxRow> w, error;
    if (sphere_.refined_form(w.data(), error.data()) &&
        set_region(w.data(), [&error](int j) { return error[static_cast<std::size_t>(j)]; }))
      return;
  }
  region_.reset();
}

template <int D>
void SearchKernel<D>::test_other(std::int32_t id) {
  const int d = dim();
  const double* x = points_.point(id);
  ++counters_->points_tested;
  double lift = 0.0;
  for (int k = 0; k < d; ++k) {
    const double delta = x[k] - f0_[k];
    row_[static_cast<std::size_t>(k)] = delta;
    lift += delta * delta;
  }
  row_[static_cast<std::size_t>(d)] = lift;
  if (!plane_.open_side(id, x, row_.data())) return;
  if (candidate_ < 0 || sphere_.beats(id, x, row_.data(), [this](std::int32_t q) { return accelerators_.sign(q); }))
    set_candidate(id);
}

template <int D>
bool SearchKernel<D>::prune(std::int32_t node, bool leaf) {
  const int d = dim();
  const double* lo = points_.tree.template lower<D>(node);
  const double* hi = points_.tree.template upper<D>(node);
  const bool ball = region_.ball();
  if (ball) {  // the node's box misses the ball (the walk only checked the ball's bounding box)
    // The distance on each axis two axes at a time (vector selects: a branch per axis was
    // mispredicted), the sum in axis order.
    const double* centre = region_.centre();
    std::array<double, kMaxRow> squares{};
    const lanes::Pair zero = {0.0, 0.0};
    int k = 0;
    for (; k + 1 < d; k += 2) {
      const lanes::Pair c = lanes::load_pair(centre + k);
      const lanes::Pair below = lanes::load_pair(lo + k) - c, above = c - lanes::load_pair(hi + k);
      lanes::Pair delta = below > above ? below : above;
      delta = delta > zero ? delta : zero;
      const lanes::Pair square = delta * delta;
      std::memcpy(&squares[static_cast<std::size_t>(k)], &square, sizeof square);
    }
    if (k < d) {
      const double c = centre[k];
      const double delta = std::max(0.0, std::max(lo[k] - c, c - hi[k]));
      squares[static_cast<std::size_t>(k)] = delta * delta;
    }
    double distance2 = squares[0];
    for (k = 1; k < d; ++k) distance2 += squares[static_cast<std::size_t>(k)];
    if (distance2 > region_.reach2()) return true;
  }
  if (accelerators_.beyond_candidate(node)) return true;
  // Within the candidate's ball, the closed side is a thin cap of its sphere, inside the empty
  // sphere of the simplex already found there: nodes wholly on the closed side that meet the
  // ball are rare and hold few points, and testing for them costs more than scanning them.
  // So the closed side is pruned while there is no ball: before the first candidate (the box
  // is then unbounded: hull facets depend on it) or without a trustworthy ball, or without
  // ball queries at all (the paper's search). Except in the searches whose ball has met many
  // nodes: on a curved surface (a cylinder, a torus) a Delaunay ball touches the surface along
  // a whole curve, and its cap on the closed side holds whole subtrees near it. There the
  // inner nodes are tested after the first kClosedSideAfter (leaves seldom prune there).
  if (ball && (leaf || ++ball_nodes_ <= kClosedSideAfter)) return false;
  if (!options_.prune_closed_side || !filters_hold_) return false;
  double box_abs = 0.0;
  if (plane_.box_on_closed_side(lo, hi, box_abs)) return true;
  return accelerators_.closed_side(node, plane_.box_gamma(), box_abs);
}

template <int D>
void SearchKernel<D>::scan_blocks(std::int32_t leaf, std::int32_t end) {
  const auto bit = [](int j) { return 1u << j; };
  const LeafBlocks::Groups groups = blocks_.groups(leaf);
  for (std::int32_t group = groups.first; group < groups.first + groups.count; ++group) {
    // Each new ball re-tests the slots and lanes still ahead (above the current bit), as a
    // branch per lane on the new distances would.
    for (unsigned slots = boxes_in_reach(blocks_.boxes(group)); slots != 0; slots &= slots - 1) {
      const int slot = __builtin_ctz(slots);
      const std::int32_t from = blocks_.begin(group, slot);
      const double* lanes = blocks_.lanes(group, slot);
      unsigned in = points_in_reach(lanes);
      // In 2D, of two or more new points in reach, the best first (best_lane): the others then
      // mostly fall outside its smaller ball, where in index order each could have been a
      // candidate in turn. Not from 3D on, where the seeds leave fewer candidates to the walk
      // and the extra arithmetic did not pay.
      const unsigned fresh = dim() == 2 && (in & (in - 1)) != 0 ? in & ~known_lanes(from) : 0;
      if ((fresh & (fresh - 1)) != 0) {
        const int best = best_lane(lanes, fresh);
        if (best >= 0) {
          const std::int32_t candidate = candidate_;
          test(from + best);
          if (!region_.ball()) {  // test() lost the ball: the block and the rest of the leaf by the box
            scan_points(from, end);
            return;
          }
          if (candidate_ != candidate) {  // a new ball: the block's lanes and the slots ahead again
            in = points_in_reach(lanes);
            slots = (boxes_in_reach(blocks_.boxes(group)) & ~((2u << slot) - 1)) | bit(slot);
          }
          in &= ~bit(best);
        }
      }
      for (; in != 0; in &= in - 1) {
        const int j = __builtin_ctz(in);
        const std::int32_t candidate = candidate_;
        test(from + j);
        if (!region_.ball()) {  // test() lost the ball: the rest of the leaf by the box
          scan_points(from + j + 1, end);
          return;
        }
        if (candidate_ != candidate) {  // a new ball
          const unsigned ahead_of_j = ~((2u << j) - 1), ahead_of_slot = ~((2u << slot) - 1);
          in = (points_in_reach(lanes) & ahead_of_j) | bit(j);
          slots = (boxes_in_reach(blocks_.boxes(group)) & ahead_of_slot) | bit(slot);
        }
      }
    }
  }
}

template <int D>
unsigned SearchKernel<D>::points_in_reach(const double* lanes) const {
#if DRANGE_AVX2_LANES
  if (avx2_) return lanes::points_in_reach_avx2<D>(lanes, region_.centre(), dim(), region_.reach2());
#endif
  return lanes::points_in_reach_pairs<D>(lanes, region_.centre(), dim(), region_.reach2());
}

template <int D>
unsigned SearchKernel<D>::boxes_in_reach(const double* boxes) const {
#if DRANGE_AVX2_LANES
  if (avx2_) return lanes::boxes_in_reach_avx2<D>(boxes, region_.centre(), dim(), region_.reach2());
#endif
  return lanes::boxes_in_reach_pairs<D>(boxes, region_.centre(), dim(), region_.reach2());
}

template <int D>
int SearchKernel<D>::best_lane(const double* lanes, unsigned in) const {
  const int d = dim();
  constexpr int kLanes = LeafBlocks::kLanes;
  const double* a = plane_.coefficients();
  const double* w = sphere_.w();
  int best = -1;
  double best_score = CandidateBall<D>::kInfinity;
  for (; in != 0; in &= in - 1) {
    const int j = __builtin_ctz(in);
    double height = 0.0, value = 0.0, lift = 0.0;
    for (int k = 0; k < d; ++k) {
      const double delta = lanes[k * kLanes + j] - f0_[k];
      height += a[k] * delta;
      value += w[k] * delta;
      lift += delta * delta;
    }
    value += w[d] * lift;
    if (!(height > 0.0)) continue;
    const double score = value / height;
    if (score < best_score) {
      best_score = score;
      best = j;
    }
  }
  return best;
}

template <int D>
void SearchKernel<D>::scan_blocks_for_open_side(std::int32_t leaf, std::int32_t end) {
  const LeafBlocks::Groups groups = blocks_.groups(leaf);
  for (std::int32_t group = groups.first; group < groups.first + groups.count; ++group) {
    for (unsigned blocks = boxes_maybe_open_side(blocks_.boxes(group)); blocks != 0; blocks &= blocks - 1) {
      const int slot = __builtin_ctz(blocks);
      const std::int32_t count = blocks_.count(group, slot);
      if (count == 0) break;  // the empty slots come last
      const std::int32_t from = blocks_.begin(group, slot);
      for (unsigned open = maybe_open_side(blocks_.lanes(group, slot), count); open != 0; open &= open - 1) {
        const int j = __builtin_ctz(open);
        test(from + j);
        if (candidate_ >= 0) {  // the first candidate: the rest of the leaf in its ball (or box)
          scan_points(from + j + 1, end);
          return;
        }
      }
    }
  }
}

template <int D>
unsigned SearchKernel<D>::boxes_maybe_open_side(const double* boxes) const {
  using lanes::Pair;
  if (!filters_hold_) return lanes::kAllLanes;
  // FacetPlaneTest::box_on_closed_side's sums, lane by lane: the largest sigma O over the box,
  // at the corner that maximises each term, and its absolute tree; the filter's test for -1.
  const int d = dim();
  constexpr int kLanes = LeafBlocks::kLanes;
  const double* a_all = plane_.coefficients();
  const double* a_abs_all = plane_.abs_coefficients();
  const Pair zero = {0.0, 0.0};
  Pair m[lanes::kPairs], m_abs[lanes::kPairs];
  for (int i = 0; i < lanes::kPairs; ++i) m[i] = m_abs[i] = zero;
  for (int k = 0; k < d; ++k) {
    const double a = a_all[k];
    const Pair f = {f0_[k], f0_[k]};
    const Pair av = {a, a};
    const Pair a_abs = {a_abs_all[k], a_abs_all[k]};
    const double* lo = boxes + k * kLanes;
    const double* hi = boxes + (d + k) * kLanes;
    for (int i = 0; i < lanes::kPairs; ++i) {
      const Pair dlo = lanes::load_pair(lo + 2 * i) - f, dhi = lanes::load_pair(hi + 2 * i) - f;
      m[i] += av * (a >= 0 ? dhi : dlo);
      const Pair abs_lo = dlo < zero ? -dlo : dlo, abs_hi = dhi < zero ? -dhi : dhi;
      m_abs[i] += a_abs * (abs_lo > abs_hi ? abs_lo : abs_hi);
    }
  }
  return ~lanes::certified_negative(m, m_abs, plane_.box_gamma()) & lanes::kAllLanes;
}

template <int D>
unsigned SearchKernel<D>::maybe_open_side(const double* lanes, int count) const {
  using lanes::Pair;
  const unsigned all = (1u << count) - 1;
  if (!filters_hold_) return all;  // the plane's filter certifies nothing
  // FacetPlaneTest::open_side's sums o = a . (x - f0) and o_abs = |a| . |x - f0|, in axis
  // order, and the filter's test for -1.
  const int d = dim();
  constexpr int kLanes = LeafBlocks::kLanes;
  const double* a_all = plane_.coefficients();
  const double* a_abs_all = plane_.abs_coefficients();
  const Pair zero = {0.0, 0.0};
  Pair o[lanes::kPairs], o_abs[lanes::kPairs];
  for (int i = 0; i < lanes::kPairs; ++i) o[i] = o_abs[i] = zero;
  for (int k = 0; k < d; ++k) {
    const Pair f = {f0_[k], f0_[k]};
    const Pair a = {a_all[k], a_all[k]};
    const Pair a_abs = {a_abs_all[k], a_abs_all[k]};
    const double* x = lanes + k * kLanes;
    for (int i = 0; i < lanes::kPairs; ++i) {
      const Pair row = lanes::load_pair(x + 2 * i) - f;
      o[i] += a * row;
      o_abs[i] += a_abs * (row < zero ? -row : row);
    }
  }
  return ~lanes::certified_negative(o, o_abs, plane_.orient_gamma()) & all;
}

}  // namespace
}  // namespace drange::engine
