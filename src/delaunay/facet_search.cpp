// delaunay/facet_search.cpp: the shrinking kd-tree search for the Delaunay point of a facet.
//
// One algorithm, SearchKernel<D>, compiled for D = 2..8 (loops of fixed length, no heap
// indirection in the hot path) and for D = 0 (any d, read at run time). It scans a leaf in the
// blocks of leaf_blocks.hpp.
#include "delaunay/facet_search.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <iterator>
#include <limits>
#include <string>

#include "delaunay/known_ties.hpp"
#include "delaunay/leaf_blocks.hpp"
#include "drange/errors.hpp"
#include "drange/points.hpp"
#include "geometry/error_bound.hpp"
#include "geometry/minors.hpp"
#include "geometry/predicates.hpp"
#include "geometry/refined_sign.hpp"
#include "geometry/wide_determinant.hpp"

namespace drange::engine {

using geometry::certified_sign_with;

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
inline std::uint32_t bit(int j) { return std::uint32_t{1} << j; }
// Rows of d + 1 entries, d + 2 ranks.
constexpr int kMaxRow = kMaxDimension + 1;

// Two doubles as one value (GCC and Clang vector extensions: an SSE2 register on x86-64, a
// NEON one on AArch64); a block's kLanes lanes are kPairs of them. Unaligned loads.
using Pair = double __attribute__((vector_size(2 * sizeof(double))));
// On x86-64, the ball's lane loops (points_in_reach, boxes_in_reach) also have AVX2 versions,
// chosen at run time when the CPU has AVX2.
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define DRANGE_AVX2_LANES 1
#include <immintrin.h>
#else
#define DRANGE_AVX2_LANES 0
#endif
constexpr int kPairs = LeafBlocks::kLanes / 2;
inline Pair load_pair(const double* x) {
  Pair v;
  std::memcpy(&v, x, sizeof v);
  return v;
}
// An upper bound of |v| from its computed sum of d squares: the roundings, and what underflow
// may take from the squares (each loses less than 2^-1074, so the root of all they lose is
// below 2^-530).
inline double upper_norm(double sum_of_squares, int d) {
  return std::sqrt(sum_of_squares) * (1 + geometry::gamma_bound(d + 2)) + 0x1p-530;
}
// The lanes whose distance is not above reach2, as a bit mask.
inline unsigned not_above(const Pair* distance2, double reach2) {
  const Pair reach = {reach2, reach2};
  unsigned mask = 0;
  for (int i = 0; i < kPairs; ++i) {
    const auto above = distance2[i] > reach;
    mask |= static_cast<unsigned>((above[0] & 1) | (above[1] & 2)) << (2 * i);
  }
  return ~mask & ((1u << LeafBlocks::kLanes) - 1);
}

template <int D>
class SearchKernel final : public FacetSearch::Kernel {
 public:
  // wide: the AVX2 lane loops where the CPU has them (FacetSearch::VectorWidth).
  SearchKernel(const PointStore& points, const SearchOptions& options, SeedMemory& seeds, bool wide);
  std::int32_t find_apex(const std::int32_t* facet, int sigma, SearchCounters& counters) override;

  // kd-tree visitor interface (spatial/kdtree.hpp).
  const double* query_lower() const { return lower_.data(); }
  const double* query_upper() const { return upper_.data(); }
  bool prune(std::int32_t node, bool leaf);
  bool right_first(const spatial::KdTree::Node& node) const {
    return options_.visit_facet_child_first && centroid_[static_cast<std::size_t>(node.split_axis)] > node.split_value;
  }
  // The walk hands over the leaf's node: looking it up from a point (KdTree::leaf_of) was a
  // dependent load before every scan could start.
  void leaf(std::int32_t node, std::int32_t begin, std::int32_t end) {
    if (shell_scan_ && shell_leaf(node, end)) return;
    if (ball_)
      scan_blocks(node, end);
    else if (candidate_ < 0)  // no candidate yet: every point of the leaf is in the query box
      scan_blocks_for_open_side(node, end);
    else
      scan_points(begin, end);
  }

 private:
  int dim() const { return D > 0 ? D : d_; }
  void set_facet(const std::int32_t* facet, int sigma);
  // Whether x is in the query region (the ball when there is one, else the box): the cheap
  // test every point of a visited leaf takes, inlined in the leaf scan.
  bool in_query(const double* x) const {
    const int d = dim();
    if (ball_) {
      double distance2 = 0.0;
      for (int k = 0; k < d; ++k) {
        const double delta = x[k] - centre_[static_cast<std::size_t>(k)];
        distance2 += delta * delta;
      }
      return !(distance2 > ball_reach2_);
    }
    for (int k = 0; k < d; ++k)
      if (x[k] < lower_[static_cast<std::size_t>(k)] || x[k] > upper_[static_cast<std::size_t>(k)]) return false;
    return true;
  }
  // The leaf's points one by one, by in_query: where there is a candidate but no ball (the
  // variants without one, or a sphere whose box could not be trusted), and the rest of a leaf
  // after test() lost the ball.
  void scan_points(std::int32_t begin, std::int32_t end) {
    for (std::int32_t id = begin; id < end; ++id)
      if (in_query(points_.point(id))) test(id);
  }
  // The leaf's points block by block (LeafBlocks): a block whose box misses the ball is
  // skipped; in the others, the squared distances of all the block's points are computed at
  // once (in_query's arithmetic, lane by lane: the same points pass).
  void scan_blocks(std::int32_t leaf, std::int32_t end);
  // Before the first candidate, when the query box is all space: every point of the leaf is
  // tested, in order, up to the first on the open side, except those that on_open_side's
  // filter puts on the closed side, which are found block by block with its arithmetic lane
  // by lane (most of a leaf lies on the closed side of a facet, and in high d most searches
  // reach the walk without a candidate on the open side: 6D 1k points, 39 points tested per
  // facet, nearly all on the closed side).
  void scan_blocks_for_open_side(std::int32_t leaf, std::int32_t end);
  // The lanes of a block (its first `count`) that on_open_side's filter does not certify on
  // the closed side.
  unsigned maybe_open_side(const double* lanes, int count) const;
  // The blocks of a group whose box prune's closed-side filter does not certify wholly on the
  // closed side.
  unsigned boxes_maybe_open_side(const double* boxes) const;
  // The lanes (kPairs pairs of a value and its absolute tree) whose sign the orientation's
  // filter certifies negative, as a bit mask.
  unsigned certified_negative(const Pair* value, const Pair* abs_tree, double factor) const;
  // The lanes of a block (transposed coordinates) whose squared distance to the ball's centre
  // is not above reach2, and the blocks of a group whose box's lower bound of it is not (the
  // empty lanes and slots, at infinity, never are), as bit masks. Masks, not distances: a
  // branch per lane on the distance was mispredicted (5D: a fifth of the walk's samples).
  unsigned points_in_reach(const double* lanes, double reach2) const;
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
  unsigned boxes_in_reach(const double* boxes, double reach2) const;
  void consider(std::int32_t id) {
    if (in_query(points_.point(id))) test(id);
  }
  // A point in the query region: is it on the open side, and does it beat the candidate?
  // The facet's own vertices lie on its hyperplane (O = 0 exactly, which no filter certifies)
  // and on every candidate's sphere, so every scan meets them; the candidate may be met again
  // after being tried as a seed (I(p, p) = 0 likewise). Those are turned away here, inline,
  // before the call to the test proper.
  void test(std::int32_t id) {
    for (int i = 0; i < dim(); ++i)
      if (facet_[i] == id) return;
    if (id != candidate_) test_other(id);
  }
  void test_other(std::int32_t id);
  void set_candidate(std::int32_t id);
  bool on_open_side(std::int32_t id);
  bool beats_candidate(std::int32_t id);
  // The signs of sigma O(x) and sigma I(p, x) whose filters failed, exactly: zero when a known
  // tie says so, else from the double-double stage or the integer stages (fixed-width, GMP),
  // in the order the tie balances choose; their zeros teach the known ties (the lifted sign's
  // only on the double-double path: the fixed-width path first neither asks nor teaches them).
  // The lifted sign's ties are broken by the perturbation. rows_ holds x (and p) already;
  // I(p, x) also needs ranks_.
  int exact_open_side(std::int32_t id);
  int exact_beats(std::int32_t id);
  // The facet's flat axes (exact_open_side), as a bit mask; computed at the facet's first exact
  // orientation.
  unsigned facet_flat_axes() const;
  // Whether a node's box [lo, hi] is wholly on the closed side of a facet flat on an axis (a
  // horizontal facet of a terrain's plateau), exactly: its largest O is 0 on the plateau's
  // points, which prune's filter cannot certify negative, so before the first candidate every
  // search from such a facet visited the whole plateau.
  bool flat_closed_side(const double* lo, const double* hi);
  // Whether the node's slab (node_slabs.hpp), if it has one, proves its points outside the
  // candidate's ball, or on the closed side of the facet where its box [lo, hi] (absolute tree
  // box_abs) does not. Out of line: inlined into prune, they grew the walk over points without
  // slabs too (callgrind, 4D 20k uniform points: +0.9% instructions inlined, +0.76% out of
  // line, which is the branch on try_slabs_).
  [[gnu::noinline]] bool slab_misses_ball(std::int32_t node);
  [[gnu::noinline]] bool slab_on_closed_side(std::int32_t node, const double* lo, const double* hi, double box_abs);
  // A search tries slabs while they prune: it starts with kSlabTrials tests, and each test that
  // prunes buys kSlabReward more, so that it goes on while more than one test in kSlabReward + 1
  // prunes. Along a surface that the balls touch along a curve (a cylinder, a torus) no slab
  // separates them from the nodes near it (tests that pruned: torus 2.4%, cylinder 1.9%;
  // ellipsoid 36%), and the search soon stops trying (try_slabs_ = nullptr). But where, over
  // the kernel's recent searches, more than one test in kSlabReward pruned, a search tries
  // every slab: the tests that fail first in a search cost less there than the nodes that
  // later tests prune (ellipsoid 320k: 137 nodes entered per simplex, against 218 with the
  // budget alone).
  bool slab_tried(bool pruned) {
    ++slab_tests_;
    slab_prunes_ += pruned;
    slab_trials_left_ += pruned ? kSlabReward : -1;
    if (slab_trials_left_ == 0) try_slabs_ = nullptr;
    return pruned;
  }
  void start_slab_trials() {
    if (slab_tests_ > kSlabMemory) {  // the recent searches weigh most
      slab_tests_ /= 2;
      slab_prunes_ /= 2;
    }
    slab_trials_left_ = slab_prunes_ * kSlabReward > slab_tests_ ? kSlabNoLimit : kSlabTrials;
    try_slabs_ = slabs_;
  }
  static constexpr int kSlabTrials = 8, kSlabReward = 8, kSlabNoLimit = 1 << 30;
  static constexpr std::uint64_t kSlabMemory = 1 << 16;
  int slab_trials_left_ = kSlabTrials;
  std::uint64_t slab_tests_ = 0, slab_prunes_ = 0;  // over the kernel's searches
  const NodeSlabs* try_slabs_ = nullptr;  // slabs_ while the search tries them
  static constexpr unsigned kFlatAxesUnknown = ~0u;
  unsigned flat_axes_ = kFlatAxesUnknown;
  void reset_box();
  // The candidate's ball from the coefficients w of sigma I(p, x) = w . r_x with error bounds
  // error(j): the centre, the box and the ball's reach; false when w's lift coefficient is not
  // certainly away from 0 (no trustworthy box) or the reach is not finite. Inlined into
  // set_candidate, whose bounds are computed as it reads them.
  template <class Error>
  [[gnu::always_inline]] inline bool set_ball(const double* w, const Error& error);
  // set_ball from the candidate's double-double cofactors (refined_), for a candidate whose
  // doubles give no trustworthy box.
  bool ball_from_refined();
  // refined_ for the current candidate, once.
  void prepare_refined(const geometry::Frame& frame);
  // SphereShell (sphere_shell.hpp): the candidate's form around the shell's centre, and the
  // tests that use it: a point's sign of sigma I(p, x) (0 when undecided), and a node's proof
  // that none of its points beats the candidate.
  void set_shell_form();
  // The form in floating point (sphere_shell.hpp, float_form; d = 2 to 8) with its
  // coefficients' error bounds; false where that declines or the arithmetic under- or
  // overflowed: then set_shell_form asks GMP. 3D sphere, 32 000 points: time_search 0.519 ->
  // 0.232 s; 4D sphere, 5 000 points: 0.905 -> 0.317 s.
  bool float_shell_form();
  int shell_sign(std::int32_t id) const;
  [[gnu::noinline]] bool shell_prunes(std::int32_t node) const;
  // A lower bound of the form's linear part, B . y + K, over the node's box; -infinity if none.
  // (Both bounds always inline: out of line, once shell_prunes had two callers of each, they
  // cost a 3D sphere of 32 000 points 0.9% of all instructions in calls: 3 366 M against
  // 3 335 M.)
  [[gnu::always_inline]] double box_linear_low(std::int32_t node) const;
  // Whether `linear`, a lower bound of the linear part over some points, proves with `range`,
  // bounds of their exact offsets, that none of them beats the candidate.
  bool shell_linear_prunes(const double* range, double linear) const;
  // The same over a cone (SphereShell::cone), for the points whose |y| is within [r_lo, r_hi]
  // (by default the cone's); -infinity if the cone is too wide.
  double cone_linear_low(const double* cone) const { return cone_linear_low(cone, cone[dim() + 2], cone[dim() + 3]); }
  [[gnu::always_inline]] double cone_linear_low(const double* cone, double r_lo, double r_hi) const;
  // shell_prunes for a node with points of two concentric spheres (SphereShell::clusters):
  // each cluster by its own offsets and radii.
  bool shell_clusters_prune(std::int32_t node, const double* clusters) const;
  // The least of sign v . e over the unit vectors e of a cone of axis m (m . e >= cos_lo, as
  // SphereShell::cone, cos_lo > 0), with norm >= |v|. sign v . e is convex along the axis and
  // least (-|v|) at e = -sign v / |v|; when that lies outside the cone, the least is on its rim,
  // at beta cos_lo - |sign v - beta m| sin (beta = sign v . m), lower still with sin_hi. beta is
  // within d u |v| of its exact value; |sign v - beta m| is bounded above from norm and beta
  // alone (see there), which spares a second pass over v and m; the case split has a margin far
  // above beta's rounding error.
  double least_on_cone(const double* v, double sign, double norm, const double* cone) const;
  // A leaf's points block by block (SphereShell::block_ids), each block's by offset from the
  // end whose offsets make the form smallest, up to the first point whose offset alone proves
  // the form positive over the block's cone: the points beyond it are outside the candidate's
  // sphere too. On a sphere most points' offsets do, and the few left are those within
  // rounding of the candidate's sphere.
  // Out of line, as the other shell functions called from leaf() and prune() (shell_prunes,
  // cone_on_closed_side): inlined, they grew the walk that uniform input runs. One thread,
  // time_search, 7 interleaved runs, min / median against the eleventh round's build: inlined
  // 2D 1M +2.7% / +2.5%, 3D 200k +1.4% / +2.2%; out of line +1.9% / +2.5%, +0.8% / +0.3%.
  // kAllInSphere: the leaf is in the facet's sphere (else some of its blocks are, and the
  // others' points are tested one by one). A template parameter: the test per block cost a
  // 3D sphere of 32 000 points 0.7% of all instructions (3 337 M against 3 315 M).
  template <bool kAllInSphere>
  [[gnu::noinline]] void scan_shell_leaf(std::int32_t leaf, std::int32_t end);
  // scan_shell_leaf when the leaf or some of its blocks are in the facet's sphere; false if not.
  bool shell_leaf(std::int32_t leaf, std::int32_t end) {
    if (in_shell(leaf)) {
      scan_shell_leaf<true>(leaf, end);
      return true;
    }
    if (shell_->node_sphere[static_cast<std::size_t>(leaf)] != SphereShell::kParts) return false;
    scan_shell_leaf<false>(leaf, end);
    return true;
  }
  // shell_sign's test for +1 with its absolute tree and coefficient errors bounded once per
  // block (by the block cone's largest |y|) rather than summed per point.
  struct BlockTerms {
    double abs_tree, coefficients;
  };
  BlockTerms block_terms(const double* cone) const;
  bool shell_outside(std::int32_t id, double offset, const BlockTerms& terms) const;
  // Whether the node's cone proves all its points on the closed side of the facet, where its
  // box does not (box_abs: prune's absolute tree over the box). On a sphere the facet's
  // hyperplane cuts it near the facet only, but the boxes of the points near it reach across.
  [[gnu::noinline]] bool cone_on_closed_side(std::int32_t node, double box_abs) const;
  // Its terms that depend on the facet and a sphere's centre g only; for the facet's sphere
  // (shell_sphere_) once per facet, in set_facet_sphere.
  struct FacetOnShell {
    double norm, offset, offset_abs;
  };
  FacetOnShell facet_about(const double* g) const;
  FacetOnShell facet_on_shell_{};
  // The facet's sphere (shell_sphere_, shell_view_) and its terms, once per facet.
  void set_facet_sphere();
  // The sign of sigma O over the computed value, when certified with the bound factor `gamma`
  // or proved exact; else 0.
  int orientation_sign(double value, double abs_tree, double gamma) const;

  const PointStore& points_;
  SearchOptions options_;
  int d_;
  // The points are scaled below 1 in magnitude (PointStore::scaled): then no operation of the
  // search overflows or is invalid, and what underflow adds to its values stays below
  // geometry::kUnderflowError, which every fast filter's floor absorbs and the query ball
  // allows for. The error bounds of the filters and the ball hold, with no floating-point flag
  // read: a read waits for the arithmetic before it. Reading them after each facet's and each
  // candidate's minors (2.7 candidates per simplex in 2D) cost 5% to 6% of a 2D search's time
  // (200k points, time_search 0.184 -> 0.173 s and 0.189 -> 0.179 s without the reads, min of
  // 7 and 9 interleaved pairs; 3D 50k 0.287 -> 0.283 s); one read per search, after it, still
  // cost 2D 1M 8% (0.909 -> 0.987 s, 7 pairs).
  const bool filters_hold_;
  double orient_gamma_;  // error bound factors (error_bound.hpp) of O(x) and I(p, x)
  double lifted_gamma_;
  // The factor of a box's largest sigma O (prune, boxes_maybe_open_side). That sum takes each
  // term at the box's corner that the *computed* coefficient a_k's sign picks: the value of O at
  // that corner, within orient_gamma_ of its absolute tree. Where a_k's sign is wrong, the
  // exact A_k is no larger than a_k's error, gamma_c |a|_k (gamma_c: the (d-1)-minor's factor),
  // and the other corner is larger by |A_k| (hi_k - lo_k) <= 2.01 gamma_c |a|_k max(|lo_k -
  // f0_k|, |hi_k - f0_k|): the box's largest O is within orient_gamma_ + 2.01 gamma_c of the
  // absolute tree above the computed sum.
  double box_orient_gamma_;
  double minor_gamma_;  // the factor of a_'s entries, (d-1)-minors (flat_closed_side)
  // 2^(52 + unit_exponent * units), dyadic points: the limit below which a minor with that many
  // units (its columns, the lift column counting twice) was computed exactly.
  std::array<double, kMaxRow + 3> exact_limits_{};

  // Per facet.
  const std::int32_t* facet_ = nullptr;
  int sigma_ = 1;
  const double* f0_ = nullptr;
  geometry::MinorTable minors_;
  std::array<double, kMaxRow> a_{}, a_abs_{};  // sigma O(x) = a . (x - f0), and its absolute tree
  // sigma I(p, x) = w . r_x with w_j = sum_c k_[j][c] (r_p)_c (c != j): the Laplace expansion of
  // the d-minors along p's row, with their signs and sigma folded in (negation is exact, so w is
  // the same double as expanding each minor and multiplying by its sign).
  std::array<std::array<double, kMaxRow>, kMaxRow> k_{}, k_abs_{};
  // True when a_ is exact and O(x) is computed without rounding whenever its absolute tree
  // is below orient_exact_limit_ (dyadic points, see set_facet).
  bool orientation_exact_ = false;
  double orient_exact_limit_ = 0.0;
  // The same for the lifted determinants: true when every minor of the facet rows (lift column
  // included) is exact; then the candidate's w (candidate_exact_) and I(p, x) are exact when
  // their absolute trees are below their limits, and a tie I = 0 is known without GMP.
  bool lifted_exact_ = false;
  bool candidate_exact_ = false;
  std::array<double, kMaxRow> centroid_{};
  // 1 / d for the centroid: it only orders the walk (right_first), so its rounding need not be
  // that of f / d. With d^2 divisions per facet its line had 1.5% to 1.8% of the samples of a
  // 5D run (perf, 8 000 points), 0.8% with the product. For d = 2, 4 and 8 the product is the
  // quotient.
  double inverse_d_;
  std::array<const double*, kMaxRow> rows_{};  // f_1, ..., f_{d-1}, p, q for the exact predicates
  std::array<std::int64_t, kMaxRow + 1> ranks_{};  // ranks of f_0, ..., f_{d-1}, p, q
  // The points that the integer stages proved on a facet's hyperplane (on_open_side) or on a candidate's
  // sphere (beats_candidate), remembered for the neighbouring facets' searches, which meet the
  // same ties (SearchOptions::remember_ties).
  KnownTies plane_ties_, sphere_ties_;
  // The double-double stage's cofactors for the candidate's sphere (refined_sign.hpp), computed
  // at its first near-tie (prepare_refined); the facet's part of them at the facet's first.
  geometry::RefinedCofactors refined_;
  bool refined_ready_ = false, refined_facet_ready_ = false;
  // The same for the facet's hyperplane (exact_open_side), computed at the facet's first.
  geometry::RefinedCofactors plane_refined_;
  bool plane_refined_ready_ = false;
  // The fixed-width stage of exact_open_side: the facet's cofactors from 6D, else the whole
  // determinant (rows_ holds x last).
  std::optional<int> fixed_width_open_side(const geometry::Frame& frame, const double* x);
  // Ties minus near-ties among the recent exact lifted tests (tie_balance_, exact_beats) and
  // orientations (plane_tie_balance_, exact_open_side), within +-kTieBalanceLimit: positive, the
  // fixed-width integer stage goes before the double-double one. They order the stages only;
  // every stage's sign is exact.
  static constexpr int kTieBalanceLimit = 16;
  int tie_balance_ = 0, plane_tie_balance_ = 0;
  static void note_outcome(int& balance, bool tie) {
    balance = tie ? std::min(balance + 1, kTieBalanceLimit) : std::max(balance - 1, -kTieBalanceLimit);
  }

  // Per candidate.
  std::int32_t candidate_ = -1;
  std::array<double, kMaxRow> w_{}, w_abs_{};  // sigma I(p, x) = w . r_x, and its absolute tree
  std::array<double, kMaxRow> centre_{};       // of the sphere through F and p
  std::array<double, kMaxRow> lower_{}, upper_{};  // the query box
  bool ball_ = false;                          // also query the ball: |x - centre|^2 <= ball_reach2_
  std::int32_t ball_nodes_ = 0;                // inner nodes this search entered that met a ball (prune)
  // After this many, prune tests the closed side of inner nodes with a ball too (see there).
  static constexpr std::int32_t kClosedSideAfter = 32;
  double ball_reach2_ = 0.0;
  double ball_reach_ = 0.0;                    // the ball's radius: every point that may win is within it
#if DRANGE_AVX2_LANES
  bool avx2_ = false;  // points_in_reach and boxes_in_reach in their AVX2 versions
#endif
  // With y = x - g (g the shell's centre), sigma I(p, x) = b . y + lift (|x - g|^2 - rho) +
  // constant exactly, for the exact coefficients (geometry::exact_lifted_form); these are
  // them truncated to doubles (relative error below 2u), sigma folded in.
  const SphereShell* shell_ = nullptr;  // the points' shell, when active and asked for
  // The sphere of the shell that all the facet's vertices are in (-1: none), and its terms.
  // The candidate's form is computed about it when the candidate is in it too; then it prunes
  // the nodes in that sphere, and decides the points in it (in_shell).
  std::int32_t shell_sphere_ = -1;
  ShellSphere shell_view_{};
  // One sphere over the whole tree (a sphere, concentric spheres): every node is in it, and
  // the walk is spared the lookups (3D sphere, 32 000 points: 0.45% of all instructions).
  bool shell_everywhere_ = false;
  bool in_shell(std::int32_t node) const {
    return shell_everywhere_ || shell_->node_sphere[static_cast<std::size_t>(node)] == shell_sphere_;
  }
  bool shell_form_ = false;             // the candidate's form is computed
  // The shell's prunes and leaf scan serve the candidate (set_candidate): it has a form, and
  // its ball is about the facet sphere's centre (or it has no ball). That is the cell inside
  // the sphere, whose every point is a near-tie; a ball elsewhere (between two concentric
  // spheres, or between bubbles) is smaller and its points are not, and the ball's box and
  // lane tests select them better than offsets and cones. The form still decides them
  // (beats_candidate).
  bool shell_scan_ = false;
  FacetMinors facet_minors_;            // float_form's minors of this facet's rows, once computed
  std::array<double, kMaxRow> shell_b_{};
  double shell_lift_ = 0.0, shell_constant_ = 0.0;
  double shell_eta_term_ = 0.0;  // |lift| times the error bound of the points' offsets, with margin
  double shell_b_norm_ = 0.0;    // an upper bound of |b|
  // Bounds of |B_k - b_k|, |W - lift|, |K - constant| beyond the truncation that the gammas
  // cover (nonzero for float_shell_form's coefficients), and the sum of the first.
  std::array<double, kMaxRow> shell_b_err_{};
  double shell_lift_err_ = 0.0, shell_constant_err_ = 0.0, shell_b_err_sum_ = 0.0;
  // Error bound factors of shell_sign, shell_prunes and box_linear_low (see there).
  double shell_point_gamma_ = 0.0, shell_node_gamma_ = 0.0, shell_cone_gamma_ = 0.0, shell_sum_gamma_ = 0.0;

  // Per point (scratch).
  std::array<double, kMaxRow> row_{};
  SearchCounters* counters_ = nullptr;
  SeedMemory& seeds_;  // SearchOptions::seed_candidate
  static constexpr int kSeeds = D > 0 ? SeedMemory::per_point_in(D) : 0;  // per point; 0: the memory's
  const LeafBlocks& blocks_;  // points_.blocks
  const NodeSlabs* slabs_ = nullptr;  // points_.slabs, unless the options or the points have none
  const KnownHull* hull_ = nullptr;   // points_.hull, when kept and the options ask for it

  // The exact stages' fixed-width cofactors: last, being large (the facet's part of the lifted
  // table: 21 KiB), apart from the members that every search reads (callgrind, 5D 5 000 points:
  // test_other 1.153 -> 1.189 G with them in the middle).
  // A facet's orientation cofactors from 6D (wide_determinant.hpp), at its first use in
  // exact_open_side; plane_wide_usable_ when they fit. Half the fixed-width orientations of a 7D
  // grid of 0.1 k were the search's (the rest the perturbation's): each was a whole 7 x 7
  // determinant.
  geometry::WideOrientationCofactors plane_wide_;
  bool plane_wide_ready_ = false, plane_wide_usable_ = false;
  // The candidate's lifted cofactors, computed at its first exact test that asks them;
  // wide_usable_ when they fit.
  geometry::WideLiftedCofactors wide_;
  bool wide_ready_ = false, wide_usable_ = false;
};

template <int D>
SearchKernel<D>::SearchKernel(const PointStore& points, const SearchOptions& options, SeedMemory& seeds, bool wide)
    : points_(points),
      options_(options),
      d_(points.dim),
      filters_hold_(points.scaled),
      orient_gamma_(geometry::gamma_bound(geometry::laplace_roundings(points.dim, 1))),
      lifted_gamma_(geometry::gamma_bound(
          geometry::laplace_roundings(points.dim + 1, geometry::lifted_entry_roundings(points.dim)))),
      box_orient_gamma_(orient_gamma_ + 2.01 * geometry::gamma_bound(geometry::laplace_roundings(points.dim - 1, 1))),
      minor_gamma_(geometry::gamma_bound(geometry::laplace_roundings(points.dim - 1, 1))),
      minors_(points.dim + 1),
      inverse_d_(1.0 / points.dim),
      plane_ties_(points.dim, points.size),
      sphere_ties_(points.dim + 1, points.size),
      seeds_(seeds),
      blocks_(points.blocks),
      slabs_(options.node_slabs && points.slabs.size() > 0 ? &points.slabs : nullptr),
      hull_(options.known_hull_facets && points.hull.active() ? &points.hull : nullptr) {
  // seed<kSeeds>() and remember<kSeeds>() take the memory's layout on trust.
  if (kSeeds > 0 && seeds.seeds_per_point() != kSeeds)
    throw InternalError("facet search: a seed memory of " + std::to_string(seeds.seeds_per_point()) +
                        " seeds per point for a kernel of " + std::to_string(kSeeds));
  if (options.use_kdtree && options.sphere_shell && points.shell.active()) {
    shell_ = &points.shell;
    shell_everywhere_ = shell_->node_sphere.front() >= 0;
    // Every point near one sphere: its offsets and cones bound each node better than a slab
    // (a hemisphere of 20 000 points: time_search 0.180 -> 0.185 s with slabs tried, medians
    // of 5 interleaved runs).
    if (shell_everywhere_) slabs_ = nullptr;
  }
#if DRANGE_AVX2_LANES
  avx2_ = wide && __builtin_cpu_supports("avx2");
#else
  (void)wide;
#endif
  shell_point_gamma_ = geometry::gamma_bound(d_ + 7);
  shell_node_gamma_ = geometry::gamma_bound(d_ + 8);
  shell_cone_gamma_ = geometry::gamma_bound(8 * d_ + 40);
  shell_sum_gamma_ = geometry::gamma_bound(6);
  if (points_.dyadic) {
    for (int units = 0; units <= d_ + 2; ++units)
      exact_limits_[static_cast<std::size_t>(units)] = geometry::power_of_two_limit(52 + points_.unit_exponent * units);
    orient_exact_limit_ = exact_limits_[static_cast<std::size_t>(d_)];
  }
}

template <int D>
void SearchKernel<D>::set_facet(const std::int32_t* facet, int sigma) {
  const int d = dim();
  facet_ = facet;
  sigma_ = sigma;
  f0_ = points_.point(facet[0]);
  flat_axes_ = kFlatAxesUnknown;
  plane_refined_ready_ = refined_facet_ready_ = plane_wide_ready_ = false;
  for (int k = 0; k < d; ++k) centroid_[static_cast<std::size_t>(k)] = 0.0;
  for (int i = 0; i < d; ++i) {
    const double* f = points_.point(facet[i]);
    for (int k = 0; k < d; ++k) centroid_[static_cast<std::size_t>(k)] += f[k] * inverse_d_;
    if (i == 0) continue;
    rows_[static_cast<std::size_t>(i - 1)] = f;
    double lift = 0.0;
    for (int k = 0; k < d; ++k) {
      row_[static_cast<std::size_t>(k)] = f[k] - f0_[k];
      lift += row_[static_cast<std::size_t>(k)] * row_[static_cast<std::size_t>(k)];
    }
    row_[static_cast<std::size_t>(d)] = lift;
    // The kernels of fixed d expand the minors with their terms laid out at compile time.
    // Callgrind, all instructions of a `drange delaunay` run, output byte-identical: 2D 50 000
    // points -1.8%, 3D 200 000 -3.5%, 4D 30 000 -5.9%, 5D 3 000 -9.4%, 6D 600 -16.7%, 7D 400
    // -25.8%, 8D 150 -35.4%.
    if constexpr (D > 0) minors_.set_row_fixed<D + 1>(i - 1, row_.data());
    else minors_.set_row(i - 1, row_.data());
  }
  // O(x) = det[f_1 - f_0; ...; x - f_0]: Laplace along the last row over the spatial columns.
  const std::uint32_t spatial = bit(d) - 1;
  // Static exactness (as in geometry/predicates.cpp): with dyadic points, every spatial minor
  // of the facet rows is a multiple of unit^size; if each is below 2^52 of that unit, none was
  // rounded, and a later dot product a . (x - f0) is exact when its absolute tree is below
  // 2^52 unit^d. This decides points and kd-tree boxes lying exactly on the facet's hyperplane,
  // which integer grids have in every hull face.
  // The lifted minors likewise, with the lift column counting twice (its entries are squares).
  orientation_exact_ = lifted_exact_ = points_.dyadic && filters_hold_;
  for (std::uint32_t mask = 1; (orientation_exact_ || lifted_exact_) && mask < bit(d + 1); ++mask) {
    const int size = geometry::bit_count(mask);
    if (size >= d) continue;  // the facet has d - 1 rows
    const bool lift = (mask & bit(d)) != 0;
    if (minors_.abs_minor(mask) < exact_limits_[static_cast<std::size_t>(size + lift)]) continue;
    lifted_exact_ = false;
    if (!lift) orientation_exact_ = false;
  }
  for (int j = 0; j < d; ++j) {
    const double sign = ((d - 1 + j) & 1) ? -1.0 : 1.0;
    a_[static_cast<std::size_t>(j)] = sigma * sign * minors_.minor(spatial & ~bit(j));
    a_abs_[static_cast<std::size_t>(j)] = minors_.abs_minor(spatial & ~bit(j));
  }
  // I(p, x) = det[...; r_p; r_x]: Laplace along the last row over all d+1 columns; its
  // d-minors (all but column j), by Laplace along p's row (row d - 1) over the (d-1)-minors.
  const std::uint32_t all = bit(d + 1) - 1;
#pragma GCC unroll 12
  for (int j = 0; j <= d; ++j) {
    const double sign = sigma * (((d + j) & 1) ? -1.0 : 1.0);
    const std::uint32_t mask = all & ~bit(j);
    int position = 0;  // of column c within mask: the cofactor sign (-1)^(d - 1 + position)
#pragma GCC unroll 12
    for (int c = 0; c <= d; ++c) {
      if (c == j) continue;
      const std::uint32_t sub = mask & ~bit(c);
      const double cofactor = ((d - 1 + position) & 1) ? -sign : sign;
      k_[static_cast<std::size_t>(j)][static_cast<std::size_t>(c)] = cofactor * minors_.minor(sub);
      k_abs_[static_cast<std::size_t>(j)][static_cast<std::size_t>(c)] = minors_.abs_minor(sub);
      ++position;
    }
  }
}

template <int D>
void SearchKernel<D>::reset_box() {
  for (int k = 0; k < dim(); ++k) {
    lower_[static_cast<std::size_t>(k)] = -kInfinity;
    upper_[static_cast<std::size_t>(k)] = kInfinity;
  }
  ball_ = false;
}

template <int D>
void SearchKernel<D>::set_candidate(std::int32_t id) {
  const int d = dim();
  candidate_ = id;
  refined_ready_ = wide_ready_ = false;
  ++counters_->candidates;
  const double* p = points_.point(id);
  rows_[static_cast<std::size_t>(d - 1)] = p;
  // row_ holds r_p (consider() computed it). Unrolled for fixed d, the test c == j folds
  // away, which the loops as written kept (with set_facet's loops above: callgrind, 5D 3 000
  // points, the whole run -3.9%).
#pragma GCC unroll 12
  for (int j = 0; j <= d; ++j) {
    double v = 0.0, a = 0.0;
#pragma GCC unroll 12
    for (int c = 0; c <= d; ++c) {
      if (c == j) continue;
      v += k_[static_cast<std::size_t>(j)][static_cast<std::size_t>(c)] * row_[static_cast<std::size_t>(c)];
      a += std::fabs(row_[static_cast<std::size_t>(c)]) * k_abs_[static_cast<std::size_t>(j)][static_cast<std::size_t>(c)];
    }
    w_[static_cast<std::size_t>(j)] = v;
    w_abs_[static_cast<std::size_t>(j)] = a;
  }
  // w_j is a d-minor over all columns but j: d units, plus one for the lift column (j < d).
  candidate_exact_ = lifted_exact_;
  for (int j = 0; candidate_exact_ && j <= d; ++j)
    candidate_exact_ = w_abs_[static_cast<std::size_t>(j)] < exact_limits_[static_cast<std::size_t>(j < d ? d + 1 : d)];
  if (shell_ != nullptr) set_shell_form();
  shell_scan_ = shell_form_;
  // The error bounds of w's entries: its rounding, gamma |w|, and what underflow adds.
  const auto error = [this](int j) { return lifted_gamma_ * w_abs_[static_cast<std::size_t>(j)] + geometry::kUnderflowError; };
  if (filters_hold_ && set_ball(w_.data(), error)) return;
  // No trustworthy box from the doubles: the candidate within rounding of the facet's
  // hyperplane (the four points of a decimal lattice's plane on one circle: every entry of w is
  // then noise). The double-double cofactors give the sphere. On decimal grids it is mostly
  // huge, and the cofactors are spent for nothing (callgrind +0.6% to +1.1% on grids of 0.1 k
  // and 0.01 k in 2D to 4D; the fixed-width cofactors instead, or only where the recent exact
  // tests were mostly ties, cost as much or lost most of the gain on 200 000 points rounded to
  // 0.01 in 3D, 2.09 -> 2.43 s).
  if (filters_hold_ && ball_from_refined()) return;
  reset_box();
}

template <int D>
void SearchKernel<D>::prepare_refined(const geometry::Frame& frame) {
  if (refined_ready_) return;
  // A facet prepares 1.5 candidates (points rounded to 0.05 in 4D): its rows' minors serve them all.
  if (!refined_facet_ready_) {
    refined_.prepare_facet(frame, rows_.data());
    refined_facet_ready_ = true;
  }
  refined_.prepare_candidate(frame, rows_[static_cast<std::size_t>(dim() - 1)]);
  refined_ready_ = true;
}

template <int D>
bool SearchKernel<D>::ball_from_refined() {
  const int d = dim();
  const geometry::Frame frame{d, d, nullptr, f0_};
  prepare_refined(frame);
  // sigma I(p, x) = sum_j sigma coefficient_j r_j(x), each coefficient within its slack (and
  // kUnderflowError for the underflow of the ball's own products, as for w).
  std::array<double, kMaxRow> w, error;
  if (!refined_.linear_form(w.data(), error.data())) return false;
  for (int j = 0; j <= d; ++j) {
    w[static_cast<std::size_t>(j)] *= sigma_;
    error[static_cast<std::size_t>(j)] += geometry::kUnderflowError;
  }
  return set_ball(w.data(), [&error](int j) { return error[static_cast<std::size_t>(j)]; });
}

template <int D>
template <class Error>
bool SearchKernel<D>::set_ball(const double* w, const Error& error) {
  const int d = dim();
  // The sphere through F and p is {x : I(p, x) / O(p) = 0}; I(p, x) / O(p) is the power of x,
  // so its centre is f0 - w_spatial / (2 w_lift) and it passes through f0. The box is the
  // sphere's bounding box, enlarged by the effect of w's error bounds on the centre.
  const double wd = w[d], ewd = error(d);
  if (!(std::fabs(wd) > 2 * ewd) || !std::isfinite(wd)) return false;  // no trustworthy box
  double radius2 = 0.0, centre_error = 0.0, magnitude = 0.0;
  // Two divisions, then products: a reciprocal's rounding adds u to the centre's relative
  // error, which the reach's 8 (d + 4) u of slack below covers, and to its error's, which the
  // factor 1 + 1e-6 does.
  const double minus_half_over_wd = -1 / (2 * wd), half_over_margin = 1 / (2 * (std::fabs(wd) - ewd));
  for (int k = 0; k < d; ++k) {
    const double dc = w[k] * minus_half_over_wd;
    const double err = (error(k) + 2 * std::fabs(dc) * ewd) * half_over_margin;
    centre_[static_cast<std::size_t>(k)] = f0_[k] + dc;
    radius2 += dc * dc;
    centre_error += err;  // the 1-norm of the centre's error: at least its length, without a root
    magnitude = std::max(magnitude, std::fabs(centre_[static_cast<std::size_t>(k)]));
  }
  const double radius = std::sqrt(radius2);
  // Twice the centre's error (the radius moves by at most as much), plus the roundings of
  // computing the centre, the radius and the box bounds, and what underflow can take from the
  // smallest of them (a radius below 2^-511 may lose its squares: at most sqrt(d) 2^-537; a
  // ball needs a reach above 2^-400 anyway).
  const double reach = radius + 2 * centre_error * (1 + 1e-6) +
                       8 * (d + 4) * geometry::kUnitRoundoff * (magnitude + radius) + 0x1p-500;
  if (!std::isfinite(reach)) return false;
  for (int k = 0; k < d; ++k) {
    lower_[static_cast<std::size_t>(k)] = centre_[static_cast<std::size_t>(k)] - reach;
    upper_[static_cast<std::size_t>(k)] = centre_[static_cast<std::size_t>(k)] + reach;
  }
  // The ball of radius reach about the computed centre holds the sphere. A squared distance
  // computed in floating point is within a relative (d + 2) u of the true one (differences,
  // squares and a sum of positive terms; an underflowing term only makes it smaller), so
  // comparing with reach^2 (1 + 1e-10) never drops a point of the ball. Far below 1 (the
  // points are scaled to magnitudes near 1), reach^2 itself could underflow: no ball then.
  // Nor when it overflows: the leaf blocks' lanes past a block's points, at infinity, must
  // stay out of every ball (scan_blocks takes the lanes in reach without their count).
  ball_reach2_ = reach * reach * (1 + 1e-10);
  ball_reach_ = reach;
  ball_ = options_.ball_query && reach > 0x1p-400 && ball_reach2_ < kInfinity;
  if (shell_scan_ && ball_) {
    // Centred: within a quarter of the sphere's radius. Against the scan for every ball with a
    // form, callgrind (all instructions, this rule): five_spheres3 -44.5%, layers3 -21.1%,
    // two_spheres3 -20.9%, two_circles -16.8%, bubbles3 and a 3D sphere +0.1%; time_search
    // (one run each, with 0.2 and 0.5 radii alike, and 0.05): two_spheres4 1.21 -> 0.82 s.
    double apart2 = 0.0;
    for (int k = 0; k < d; ++k) {
      const double delta = centre_[static_cast<std::size_t>(k)] - shell_view_.centre[k];
      apart2 += delta * delta;
    }
    shell_scan_ = apart2 <= 0.0625 * shell_view_.rho;
  }
  return true;
}

template <int D>
void SearchKernel<D>::set_shell_form() {
  const int d = dim();
  shell_form_ = shell_sphere_ >= 0 && shell_->point_sphere[static_cast<std::size_t>(candidate_)] == shell_sphere_;
  if (!shell_form_) return;
  shell_form_ = float_shell_form();
  if (!shell_form_) {
    const geometry::Frame frame{d, d, nullptr, f0_};
    shell_form_ = geometry::exact_lifted_form(frame, rows_.data(), shell_view_.centre, shell_view_.rho, shell_b_.data(),
                                              &shell_lift_, &shell_constant_);
    if (!shell_form_) return;
    shell_b_err_.fill(0.0);
    shell_lift_err_ = shell_constant_err_ = shell_b_err_sum_ = 0.0;
  }
  for (int k = 0; k < d; ++k) shell_b_[static_cast<std::size_t>(k)] *= sigma_;
  shell_lift_ *= sigma_;
  shell_constant_ *= sigma_;
  shell_eta_term_ = 1.01 * (std::fabs(shell_lift_) + shell_lift_err_) * shell_view_.eta;
  double b2 = 0.0;
  for (int k = 0; k < d; ++k) b2 += shell_b_[static_cast<std::size_t>(k)] * shell_b_[static_cast<std::size_t>(k)];
  shell_b_norm_ = upper_norm(b2, d);
}

template <int D>
bool SearchKernel<D>::float_shell_form() {
  const int d = dim();
  if (d > kFloatFormMaxDim) return false;
  std::array<double, kMaxRow> row_offsets{};
  for (int i = 0; i < d; ++i)
    row_offsets[static_cast<std::size_t>(i)] = shell_->offset[static_cast<std::size_t>(i < d - 1 ? facet_[i + 1] : candidate_)];
  FloatForm form;
  const geometry::FloatingPointWatch watch;
  const bool good =
      float_form(shell_view_, d, f0_, shell_->offset[static_cast<std::size_t>(facet_[0])], rows_.data(), row_offsets.data(), form, &facet_minors_);
  if (!good || !watch.clean()) return false;
  for (int k = 0; k < d; ++k) {
    shell_b_[static_cast<std::size_t>(k)] = form.b[k];
    shell_b_err_[static_cast<std::size_t>(k)] = form.b_err[k];
  }
  shell_lift_ = form.lift;
  shell_constant_ = form.constant;
  shell_lift_err_ = form.lift_err;
  shell_constant_err_ = form.constant_err;
  shell_b_err_sum_ = form.b_err_sum;
  return true;
}

template <int D>
int SearchKernel<D>::shell_sign(std::int32_t id) const {
  // v = constant + b . fl(x - g) + lift s_x in floating point (s_x: the stored offset). With B,
  // W, K the exact coefficients and S_x the exact offset, sigma I = B . y + W S_x + K, and
  //   |v - sigma I| <= gamma(d + 3) A    (the roundings of fl(x - g), the products, the sums)
  //                  + 2.01 u A          (the coefficients' truncation)
  //                  + |W| (u |s_x| + eta)  (the offset's error: u A and shell_eta_term_)
  // with A = |constant| + sum |b_k| |fl(x_k - g_k)| + |lift| |s_x|: shell_point_gamma_ =
  // gamma_bound(d + 7) covers the A terms. An underflow costs at most 2^-1074 per operation.
  const int d = dim();
  if (shell_->point_sphere[static_cast<std::size_t>(id)] != shell_sphere_) return 0;  // its offset is about another sphere
  const double* x = points_.point(id);
  const double* g = shell_view_.centre;
  const double offset = shell_->offset[static_cast<std::size_t>(id)];
  double v = shell_constant_, a = std::fabs(shell_constant_), coefficients = shell_constant_err_;
  for (int k = 0; k < d; ++k) {
    const double y = x[k] - g[k];
    v += shell_b_[static_cast<std::size_t>(k)] * y;
    a += std::fabs(shell_b_[static_cast<std::size_t>(k)]) * std::fabs(y);
    coefficients += shell_b_err_[static_cast<std::size_t>(k)] * std::fabs(y);
  }
  v += shell_lift_ * offset;
  a += std::fabs(shell_lift_) * std::fabs(offset);
  coefficients += shell_lift_err_ * (std::fabs(offset) + shell_view_.eta);
  if (!(a < geometry::kFilterOverflow)) return 0;  // also NaN
  // The coefficients' errors (float_shell_form; 0 for GMP's) at |y| and |s_x| + eta.
  const double bound = shell_point_gamma_ * a + shell_eta_term_ + 1.01 * coefficients + 0x1p-1000;
  if (v > bound) return 1;
  if (v < -bound) return -1;
  return 0;
}

template <int D>
inline double SearchKernel<D>::box_linear_low(std::int32_t node) const {
  // With the exact coefficients, sigma I = B . y + W S_x + K (shell_sign), y = x - g.
  // The box: each term's minimum over the node's box, summed in floating point: within
  // gamma(d + 3) a of its exact value on the truncated coefficients, and within 2.01 u a of
  // the exact coefficients' (a: its absolute tree), which shell_node_gamma_ covers; plus the
  // float form's coefficient errors at the box's largest |y_k|.
  const int d = dim();
  const double* lo = points_.tree.template lower<D>(node);
  const double* hi = points_.tree.template upper<D>(node);
  const double* g = shell_view_.centre;
  double low = shell_constant_, a = std::fabs(shell_constant_), coefficients = shell_constant_err_;
  for (int k = 0; k < d; ++k) {
    const double b = shell_b_[static_cast<std::size_t>(k)];
    const double ylo = lo[k] - g[k], yhi = hi[k] - g[k];
    low += std::min(b * ylo, b * yhi);
    const double y = std::max(std::fabs(ylo), std::fabs(yhi));
    a += std::fabs(b) * y;
    coefficients += shell_b_err_[static_cast<std::size_t>(k)] * y;
  }
  if (!(a < geometry::kFilterOverflow)) return -kInfinity;  // also NaN
  return low - shell_node_gamma_ * a - 1.01 * coefficients - 0x1p-1000;
}

template <int D>
double SearchKernel<D>::least_on_cone(const double* v, double sign, double norm, const double* cone) const {
  const int d = dim();
  const double cos_lo = cone[d];
  double beta = 0.0;
  for (int k = 0; k < d; ++k) beta += sign * v[k] * cone[k];
  if (!(-beta < (cos_lo - 1e-6) * norm)) return -norm;
  // With B the exact sign v . m, |sign v - B m|^2 = |v|^2 - B^2 (2 - |m|^2), and |m|^2 is within
  // 2 (d + 2) u of 1, B within d u norm of beta: so it is at most norm^2 - beta^2 +
  // (4 d + 4) u norm^2, and the slack below covers that and this line's roundings (3 u norm^2
  // in the difference, the sum's and the root's, which (1 + 2 u) undoes). Near B = |v| the root
  // is at most 6e-8 norm too large in 4D: far below the differences the cones decide.
  constexpr double u = geometry::kUnitRoundoff;
  const double norm2 = norm * norm;
  const double perp2 = std::max(0.0, norm2 - beta * beta) + (4 * d + 16) * u * norm2;
  return beta * cos_lo - std::sqrt(perp2) * (1 + 2 * u) * cone[d + 1];
}

template <int D>
inline double SearchKernel<D>::cone_linear_low(const double* cone, double r_lo, double r_hi) const {
  // y = r e with r_lo <= r <= r_hi and e in the cone: b . y is at least r times least_on_cone,
  // within shell_cone_gamma_ of cone_a (least_on_cone's errors, b's truncation 2 u |b|, r and
  // the sum 2 u).
  const int d = dim();
  if (!(cone[d] > 0.0)) return -kInfinity;
  const double least = least_on_cone(shell_b_.data(), 1.0, shell_b_norm_, cone);
  const double linear = least < 0.0 ? least * r_hi : least * r_lo;
  const double cone_a = std::fabs(shell_constant_) + shell_b_norm_ * r_hi;
  if (!(cone_a < geometry::kFilterOverflow)) return -kInfinity;
  // The coefficients' errors: |(B - b) . y| <= sum |B_k - b_k| |y| <= shell_b_err_sum_ r_hi.
  const double coefficients = shell_b_err_sum_ * r_hi + shell_constant_err_;
  return (shell_constant_ + linear) - shell_cone_gamma_ * cone_a - 1.01 * coefficients - 0x1p-1000;
}

template <int D>
bool SearchKernel<D>::shell_prunes(std::int32_t node) const {
  // The linear part is bounded over the node's cone (tight on a sphere's caps) and, where that
  // does not prune, over its box: the test below only grows with the bound, so this prunes
  // where the larger of the two would, and spares the box's sums where the cone suffices.
  if (!shell_->clusters.empty()) {
    const double* clusters = shell_->clusters_of(node);
    if (clusters[0] <= clusters[1] && clusters[4] <= clusters[5]) return shell_clusters_prune(node, clusters);
  }
  const double* range = shell_->of(node);
  return shell_linear_prunes(range, cone_linear_low(shell_->cone_of(node))) || shell_linear_prunes(range, box_linear_low(node));
}

template <int D>
bool SearchKernel<D>::shell_clusters_prune(std::int32_t node, const double* clusters) const {
  // The cone's directions and the box hold every point of the node; the radii and offsets are
  // each cluster's. The box's bound is computed once, if a cluster needs it.
  const double* cone = shell_->cone_of(node);
  double box = 0.0;
  bool box_known = false;
  for (int part = 0; part < 2; ++part) {
    const double* cluster = clusters + 4 * part;
    if (shell_linear_prunes(cluster, cone_linear_low(cone, cluster[2], cluster[3]))) continue;
    if (!box_known) {
      box = box_linear_low(node);
      box_known = true;
    }
    if (!shell_linear_prunes(cluster, box)) return false;
  }
  return true;
}

template <int D>
bool SearchKernel<D>::shell_linear_prunes(const double* range, double linear) const {
  // Every point x of the node has sigma I(p, x) > 0 (it is outside the candidate's sphere, so
  // it cannot win, now or later) when a lower bound of it over the node is positive: the linear
  // part's plus the least W S_x over the node's range of exact offsets (sphere_shell.cpp). W's
  // truncation (2 u), the product and the sum round by 4 u of the absolute tree:
  // shell_sum_gamma_.
  const double low = linear + std::min(shell_lift_ * range[0], shell_lift_ * range[1]);
  const double largest = std::max(std::fabs(range[0]), std::fabs(range[1]));
  const double a = std::fabs(linear) + std::fabs(shell_lift_) * largest;
  return low > shell_sum_gamma_ * a + 1.01 * shell_lift_err_ * largest + 0x1p-1000;  // false on -infinity and NaN
}

template <int D>
typename SearchKernel<D>::BlockTerms SearchKernel<D>::block_terms(const double* cone) const {
  // shell_sign's sums over the block's points: sum |b_k| |fl(y_k)| <= |b| |fl(y)| <= |b| (1 + u)
  // r_hi (Cauchy-Schwarz; shell_b_norm_ is at least |b|, r_hi at least every exact |y|), and
  // sum b_err_k |fl(y_k)| <= b_err_sum (1 + u) r_hi. The factor 1 + 4 u covers fl(y)'s
  // rounding and the products' here; the few sums left round less than shell_sign's do.
  const double r_hi = cone[dim() + 3] * (1 + 4 * geometry::kUnitRoundoff);
  return {std::fabs(shell_constant_) + shell_b_norm_ * r_hi, shell_constant_err_ + shell_b_err_sum_ * r_hi};
}

template <int D>
bool SearchKernel<D>::shell_outside(std::int32_t id, double offset, const BlockTerms& terms) const {
  // shell_sign's value and bound (see there), with the block's terms for its sums of |y|.
  const int d = dim();
  const double* x = points_.point(id);
  const double* g = shell_view_.centre;
  double v = shell_constant_;
  for (int k = 0; k < d; ++k) v += shell_b_[static_cast<std::size_t>(k)] * (x[k] - g[k]);
  v += shell_lift_ * offset;
  const double a = terms.abs_tree + std::fabs(shell_lift_) * std::fabs(offset);
  const double coefficients = terms.coefficients + shell_lift_err_ * (std::fabs(offset) + shell_view_.eta);
  if (!(a < geometry::kFilterOverflow)) return false;  // also NaN
  return v > shell_point_gamma_ * a + shell_eta_term_ + 1.01 * coefficients + 0x1p-1000;
}

template <int D>
template <bool kAllInSphere>
void SearchKernel<D>::scan_shell_leaf(std::int32_t leaf, std::int32_t end) {
  // In a block, for W > 0 the points go by increasing offset s: sigma I(p, x) >= linear + W S_x
  // (linear: the block cone's bound), and once that is certified positive at s, it is at every
  // later point, whose exact offset is no smaller than s - u |s| - eta. For W < 0, by
  // decreasing offset. The bound: shell_prunes' roundings, the offset's error u |s|
  // (shell_sum_gamma_ has room) and eta (shell_eta_term_). A new candidate changes the form
  // (and perhaps W's sign); the points already considered lie outside its sphere too, or on
  // the closed side, so the scan goes on from the block's ends.
  const std::int32_t* ids = shell_->block_ids.data();
  const double* offsets = shell_->block_offsets.data();
  for (std::int32_t block = shell_->first_block[static_cast<std::size_t>(leaf)];
       shell_->block_start[static_cast<std::size_t>(block)] < end; ++block) {
    std::int32_t first = shell_->block_start[static_cast<std::size_t>(block)], last = shell_->block_start[static_cast<std::size_t>(block) + 1];
    if (!kAllInSphere && shell_->block_sphere[static_cast<std::size_t>(block)] != shell_sphere_) {
      for (std::int32_t i = first; i < last; ++i) consider(i);  // a block of another sphere, or of none: its ids are its positions
      continue;
    }
    std::int32_t form_of = -1;  // the candidate whose form `linear` and `terms` bound
    double linear = 0.0;
    BlockTerms terms{};
    while (first < last) {
      if (!shell_form_) {  // the candidate's form could not be computed: the rest one by one
        for (std::int32_t i = first; i < last; ++i) consider(ids[i]);
        break;
      }
      if (form_of != candidate_) {
        linear = cone_linear_low(shell_->block_cone_of(block));
        terms = block_terms(shell_->block_cone_of(block));
        form_of = candidate_;
      }
      const double w = shell_lift_;
      const std::int32_t i = w < 0.0 ? last - 1 : first;
      if (w != 0.0) {
        const double ws = w * offsets[i];
        const double bound = shell_sum_gamma_ * (std::fabs(linear) + std::fabs(ws)) + shell_eta_term_ +
                             1.01 * shell_lift_err_ * (std::fabs(offsets[i]) + shell_view_.eta) + 0x1p-1000;
        if (linear + ws > bound) break;  // false on -infinity and NaN
      }
      if (w < 0.0) --last;
      else ++first;
      // Most points the block's bound lets through are still outside the candidate's sphere
      // by their own form's value: certified so, they are turned away before the query, side
      // and lifted tests (whose filters fail on a sphere) that consider() would run.
      if (shell_outside(ids[i], offsets[i], terms)) {
        ++counters_->points_tested;
        continue;
      }
      consider(ids[i]);
    }
  }
}

template <int D>
int SearchKernel<D>::orientation_sign(double value, double abs_tree, double gamma) const {
  const int s = filters_hold_ ? certified_sign_with(value, abs_tree, gamma) : 0;
  if (s != 0 || !orientation_exact_ || !(abs_tree < orient_exact_limit_)) return s;
  return value > 0 ? 1 : -1;  // exact: 0 counts as the closed side, like negative values
}

template <int D>
bool SearchKernel<D>::on_open_side(std::int32_t id) {
  const int d = dim();
  double o = 0.0, o_abs = 0.0;
  for (int k = 0; k < d; ++k) {
    o += a_[static_cast<std::size_t>(k)] * row_[static_cast<std::size_t>(k)];
    o_abs += a_abs_[static_cast<std::size_t>(k)] * std::fabs(row_[static_cast<std::size_t>(k)]);
  }
  int s = orientation_sign(o, o_abs, orient_gamma_);
  if (s == 0) {
    rows_[static_cast<std::size_t>(d - 1)] = points_.point(id);
    s = exact_open_side(id);
    if (candidate_ >= 0) rows_[static_cast<std::size_t>(d - 1)] = points_.point(candidate_);
  }
  return s > 0;
}

template <int D>
int SearchKernel<D>::exact_open_side(std::int32_t id) {
  const int d = dim();
  // The axes on which all the facet's vertices agree (a horizontal facet of a terrain's
  // plateau): a point that agrees too makes a zero column, so O = 0, without the call below.
  if (flat_axes_ == kFlatAxesUnknown) flat_axes_ = facet_flat_axes();
  const double* x = points_.point(id);
  for (unsigned axes = flat_axes_; axes != 0; axes &= axes - 1) {
    const int k = __builtin_ctz(axes);
    if (x[k] == f0_[k]) return 0;
  }
  const geometry::Frame frame{d, d, nullptr, f0_};
  // The generic filters only where the search's own did not run (points not scaled): where it
  // did, they filter the same expansion with the same exactness proof, and decided none of the
  // 10.4 M calls that reached them over 35 inputs (degenerate families, rounded points, grids
  // at offsets and scales; 7.9 M of them on the rings).
  if (!filters_hold_)
    if (const std::optional<int> s = geometry::filtered_orientation(frame, rows_.data())) return sigma_ * *s;
  if (!options_.remember_ties) return sigma_ * geometry::exact_orientation(frame, rows_.data());
  // The facet's vertices are affinely independent: they define its hyperplane. Looked up before
  // the double-double stage, unlike the spheres: a facet's search asks about its one hyperplane
  // many times (a lookup is then a binary search), and half the points that reach here are on
  // it (after it: callgrind, a 10 x 20 x 25 cylindrical grid +4.5%).
  if (plane_ties_.holds(facet_, id)) return 0;
  // As exact_beats: the fixed-width stage first where the recent exact orientations were mostly
  // ties (a grid's coplanar points), which the double-double stage never decides.
  std::optional<int> small;
  if (plane_tie_balance_ > 0) small = fixed_width_open_side(frame, x);
  if (!small) {
    // The double-double stage as the facet's cofactors, computed at its first near-tie: each
    // point then costs a dot product (a 4D lattice's hyperplanes hold many points).
    if (!plane_refined_ready_) {
      plane_refined_.prepare_orientation(frame, rows_.data());
      plane_refined_ready_ = true;
    }
    small = plane_refined_.sign_with(frame, x);
  }
  const int s = small ? *small : geometry::integer_orientation(frame, rows_.data());
  note_outcome(plane_tie_balance_, s == 0);
  if (s == 0) plane_ties_.record(facet_, id);
  return sigma_ * s;
}

template <int D>
std::optional<int> SearchKernel<D>::fixed_width_open_side(const geometry::Frame& frame, const double* x) {
  if (dim() >= geometry::WideOrientationCofactors::kMinDim) {
    if (!plane_wide_ready_) {
      plane_wide_usable_ = plane_wide_.prepare(frame, rows_.data());
      plane_wide_ready_ = true;
    }
    if (plane_wide_usable_) {
      const std::optional<int> s = plane_wide_.sign_with(x);
      if (s) {
        geometry::count_exact_evaluation();
        return s;
      }
    }
  }
  return geometry::small_integer_orientation(frame, rows_.data());
}

template <int D>
unsigned SearchKernel<D>::facet_flat_axes() const {
  const int d = dim();
  unsigned axes = 0;
  for (int k = 0; k < d; ++k) {
    bool flat = true;
    for (int i = 1; i < d && flat; ++i) flat = points_.point(facet_[i])[k] == f0_[k];
    if (flat) axes |= 1u << k;
  }
  return axes;
}

template <int D>
int SearchKernel<D>::exact_beats(std::int32_t id) {
  const int d = dim();
  const geometry::Frame frame{d, d, nullptr, f0_};
  // Where the recent exact tests were mostly ties (grids whose coordinates are not dyadic),
  // the fixed-width integer stage first: it decides ties and near-ties alike, for less than the
  // double-double stage spends on a candidate's cofactors, which decide no tie.
  // The candidate's cofactors in those integers serve its later tests (2.9 per candidate on a
  // cylindrical grid).
  if (tie_balance_ > 0) {
    if (!wide_ready_) {
      wide_usable_ = wide_.prepare(frame, rows_.data());  // 3D to 6D (wide_determinant.hpp)
      wide_ready_ = true;
    }
    std::optional<int> s = wide_usable_ ? wide_.sign_with(points_.point(id)) : std::nullopt;
    if (s) geometry::count_exact_evaluation();
    else s = geometry::small_integer_lifted_sign(frame, rows_.data());
    if (s) {
      note_outcome(tie_balance_, *s == 0);
      return sigma_ * (*s != 0 ? *s : geometry::lifted_tie_sign(frame, rows_.data(), ranks_.data(), sigma_));
    }
  }
  // The double-double stage first: it decides the near-ties, which are most, and never a tie,
  // so the known ties are looked up only for what it leaves (on 100 rings of a cylinder, the
  // lookups before it took 16% of the time).
  prepare_refined(frame);
  // The candidate's cofactors in double-double, applied in doubles first: they decide the tests
  // that the search's filter left only because the candidate's cofactors in doubles are noise
  // (a candidate within rounding of the facet's hyperplane, as a decimal lattice puts it), not
  // near-ties of their own: 98.5% of these tests on 30 000 points rounded to 0.01, 64% on the
  // rings.
  std::optional<int> refined = refined_.quick_sign_with(frame, points_.point(id));
  if (!refined) refined = refined_.sign_with(frame, points_.point(id));
  if (refined) {
    note_outcome(tie_balance_, false);
    return sigma_ * *refined;
  }
  note_outcome(tie_balance_, true);  // most likely a tie: the double-double stage decides no tie
  // The facet and the candidate, strictly on its open side, are affinely independent: they
  // define the candidate's sphere.
  std::array<std::int32_t, kMaxRow + 1> simplex;
  std::copy(facet_, facet_ + d, simplex.begin());
  simplex[static_cast<std::size_t>(d)] = candidate_;
  if (!options_.remember_ties || !sphere_ties_.holds(simplex.data(), id)) {
    const int s = geometry::integer_lifted_sign(frame, rows_.data());
    if (s != 0) return sigma_ * s;
    if (options_.remember_ties) sphere_ties_.record(simplex.data(), id);
  }
  return sigma_ * geometry::lifted_tie_sign(frame, rows_.data(), ranks_.data(), sigma_);
}

template <int D>
bool SearchKernel<D>::beats_candidate(std::int32_t id) {
  const int d = dim();
  double v = 0.0, v_abs = 0.0;
  for (int k = 0; k <= d; ++k) {
    v += w_[static_cast<std::size_t>(k)] * row_[static_cast<std::size_t>(k)];
    v_abs += w_abs_[static_cast<std::size_t>(k)] * std::fabs(row_[static_cast<std::size_t>(k)]);
  }
  int s = filters_hold_ ? certified_sign_with(v, v_abs, lifted_gamma_) : 0;
  if (s == 0 && shell_form_) s = shell_sign(id);
  if (s == 0) {
    rows_[static_cast<std::size_t>(d)] = points_.point(id);
    // The ranks only the symbolic perturbation reads, looked up here: the filter decides
    // nearly every test, and the ranks (the kd-tree's order) are one more array that each
    // candidate would touch.
    for (int i = 0; i < d; ++i) ranks_[static_cast<std::size_t>(i)] = points_.rank(facet_[i]);
    ranks_[static_cast<std::size_t>(d)] = points_.rank(candidate_);
    ranks_[static_cast<std::size_t>(d + 1)] = points_.rank(id);
    const geometry::Frame frame{d, d, nullptr, f0_};
    // I(p, x) has d + 2 units (d spatial columns, the lift twice). Exact and zero: a tie
    // (cospherical points, as in every cell of a grid), which only the perturbation breaks.
    if (candidate_exact_ && v_abs < exact_limits_[static_cast<std::size_t>(d + 2)])
      s = v != 0.0 ? (v > 0 ? 1 : -1) : sigma_ * geometry::lifted_tie_sign(frame, rows_.data(), ranks_.data(), sigma_);
    else if (filters_hold_)  // the filter above was sound and failed: a near-tie, for the exact stages
      s = exact_beats(id);
    else
      s = sigma_ * geometry::lifted_sign_perturbed(frame, rows_.data(), ranks_.data());
  }
  return s < 0;
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
  if (!on_open_side(id)) return;
  if (candidate_ < 0 || beats_candidate(id)) set_candidate(id);
}

template <int D>
void SearchKernel<D>::scan_blocks(std::int32_t leaf, std::int32_t end) {
  const LeafBlocks::Groups groups = blocks_.groups(leaf);
  for (std::int32_t group = groups.first; group < groups.first + groups.count; ++group) {
    // Each new ball re-tests the slots and lanes still ahead (above the current bit), as a
    // branch per lane on the new distances would.
    for (unsigned slots = boxes_in_reach(blocks_.boxes(group), ball_reach2_); slots != 0; slots &= slots - 1) {
      const int slot = __builtin_ctz(slots);
      const std::int32_t from = blocks_.begin(group, slot);
      const double* lanes = blocks_.lanes(group, slot);
      unsigned in = points_in_reach(lanes, ball_reach2_);
      // In 2D, of two or more new points in reach, the best first (best_lane): the others then
      // mostly fall outside its smaller ball, where in index order each could have been a
      // candidate in turn. Candidates per triangle, 2D 1M: 2.81 -> 2.35, time_search 0.861 ->
      // 0.825 s (medians of 5 interleaved runs); 20 000 points on two concentric circles 9.59 ->
      // 4.43, 0.062 -> 0.046 s. Not from 3D on, where the seeds leave fewer candidates to the
      // walk: callgrind, 3D 20k +0.2%, 4D 5k +0.5%, 5D 2k +0.6%, rings on a cylinder +5%.
      const unsigned fresh = dim() == 2 && (in & (in - 1)) != 0 ? in & ~known_lanes(from) : 0;
      if ((fresh & (fresh - 1)) != 0) {
        const int best = best_lane(lanes, fresh);
        if (best >= 0) {
          const std::int32_t candidate = candidate_;
          test(from + best);
          if (!ball_) {  // test() lost the ball: the block and the rest of the leaf by the box
            scan_points(from, end);
            return;
          }
          if (candidate_ != candidate) {  // a new ball: the block's lanes and the slots ahead again
            in = points_in_reach(lanes, ball_reach2_);
            slots = (boxes_in_reach(blocks_.boxes(group), ball_reach2_) & ~((2u << slot) - 1)) | bit(slot);
          }
          in &= ~bit(best);
        }
      }
      for (; in != 0; in &= in - 1) {
        const int j = __builtin_ctz(in);
        const std::int32_t candidate = candidate_;
        test(from + j);
        if (!ball_) {  // test() lost the ball: the rest of the leaf by the box
          scan_points(from + j + 1, end);
          return;
        }
        if (candidate_ != candidate) {  // a new ball
          const unsigned ahead_of_j = ~((2u << j) - 1), ahead_of_slot = ~((2u << slot) - 1);
          in = (points_in_reach(lanes, ball_reach2_) & ahead_of_j) | bit(j);
          slots = (boxes_in_reach(blocks_.boxes(group), ball_reach2_) & ahead_of_slot) | bit(slot);
        }
      }
    }
  }
}

template <int D>
int SearchKernel<D>::best_lane(const double* lanes, unsigned in) const {
  const int d = dim();
  constexpr int kLanes = LeafBlocks::kLanes;
  int best = -1;
  double best_score = kInfinity;
  for (; in != 0; in &= in - 1) {
    const int j = __builtin_ctz(in);
    double height = 0.0, value = 0.0, lift = 0.0;
    for (int k = 0; k < d; ++k) {
      const double delta = lanes[k * kLanes + j] - f0_[k];
      height += a_[static_cast<std::size_t>(k)] * delta;
      value += w_[static_cast<std::size_t>(k)] * delta;
      lift += delta * delta;
    }
    value += w_[static_cast<std::size_t>(d)] * lift;
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
unsigned SearchKernel<D>::certified_negative(const Pair* value, const Pair* abs_tree, double factor) const {
  // certified_sign_with's test for -1 with the error bound factor `factor`, lane by lane: bit l
  // of the result is set when lane l's value is certified negative.
  const Pair gamma = {factor, factor};
  const Pair low = {geometry::kFilterUnderflow, geometry::kFilterUnderflow};
  const Pair high = {geometry::kFilterOverflow, geometry::kFilterOverflow};
  unsigned negative = 0;
  for (int i = 0; i < kPairs; ++i) {
    const auto certified = (abs_tree[i] > low) & (abs_tree[i] < high) & (value[i] < -(gamma * abs_tree[i]));
    negative |= static_cast<unsigned>((certified[0] & 1) | (certified[1] & 2)) << (2 * i);
  }
  return negative;
}

template <int D>
unsigned SearchKernel<D>::boxes_maybe_open_side(const double* boxes) const {
  constexpr unsigned kAll = (1u << LeafBlocks::kLanes) - 1;
  if (!filters_hold_) return kAll;
  // prune's sums: the largest sigma O over the box, at the corner that maximises each term,
  // and its absolute tree; certified_sign_with's test for -1.
  const int d = dim();
  constexpr int kLanes = LeafBlocks::kLanes;
  const Pair zero = {0.0, 0.0};
  Pair m[kPairs], m_abs[kPairs];
  for (int i = 0; i < kPairs; ++i) m[i] = m_abs[i] = zero;
  for (int k = 0; k < d; ++k) {
    const double a = a_[static_cast<std::size_t>(k)];
    const Pair f = {f0_[k], f0_[k]};
    const Pair av = {a, a};
    const Pair a_abs = {a_abs_[static_cast<std::size_t>(k)], a_abs_[static_cast<std::size_t>(k)]};
    const double* lo = boxes + k * kLanes;
    const double* hi = boxes + (d + k) * kLanes;
    for (int i = 0; i < kPairs; ++i) {
      const Pair dlo = load_pair(lo + 2 * i) - f, dhi = load_pair(hi + 2 * i) - f;
      m[i] += av * (a >= 0 ? dhi : dlo);
      const Pair abs_lo = dlo < zero ? -dlo : dlo, abs_hi = dhi < zero ? -dhi : dhi;
      m_abs[i] += a_abs * (abs_lo > abs_hi ? abs_lo : abs_hi);
    }
  }
  return ~certified_negative(m, m_abs, box_orient_gamma_) & kAll;
}

template <int D>
unsigned SearchKernel<D>::maybe_open_side(const double* lanes, int count) const {
  const unsigned all = (1u << count) - 1;
  if (!filters_hold_) return all;  // on_open_side certifies nothing
  // on_open_side's sums o = a . (x - f0) and o_abs = |a| . |x - f0|, in axis order, and
  // certified_sign_with's test for -1.
  const int d = dim();
  constexpr int kLanes = LeafBlocks::kLanes;
  const Pair zero = {0.0, 0.0};
  Pair o[kPairs], o_abs[kPairs];
  for (int i = 0; i < kPairs; ++i) o[i] = o_abs[i] = zero;
  for (int k = 0; k < d; ++k) {
    const Pair f = {f0_[k], f0_[k]};
    const Pair a = {a_[static_cast<std::size_t>(k)], a_[static_cast<std::size_t>(k)]};
    const Pair a_abs = {a_abs_[static_cast<std::size_t>(k)], a_abs_[static_cast<std::size_t>(k)]};
    const double* x = lanes + k * kLanes;
    for (int i = 0; i < kPairs; ++i) {
      const Pair row = load_pair(x + 2 * i) - f;
      o[i] += a * row;
      o_abs[i] += a_abs * (row < zero ? -row : row);
    }
  }
  return ~certified_negative(o, o_abs, orient_gamma_) & all;
}

#if DRANGE_AVX2_LANES
namespace {
// Four doubles as one value, for the AVX2 versions of the two lane loops below: each lane's
// operations, and their order, are the two-double version's (no FMA: the target adds AVX2
// only), so every lane's result is the same double. One thread, time_search, min of 3 to 5
// interleaved runs: 6D 5k 13.28 -> 12.36 s, 7D 1k 10.44 -> 9.96, 8D 300 10.05 -> 9.75; 4D
// 100k and 5D 20k within the noise (+0.4%, -1.5%).
using Quad = double __attribute__((vector_size(4 * sizeof(double))));
constexpr int kQuads = LeafBlocks::kLanes / 4;
__attribute__((target("avx2"))) inline Quad load_quad(const double* x) {
  Quad v;
  std::memcpy(&v, x, sizeof v);
  return v;
}
__attribute__((target("avx2"))) inline Quad broadcast(double x) { return Quad{x, x, x, x}; }

// The lanes whose distance is not above reach2, as a bit mask.
__attribute__((target("avx2"))) inline unsigned not_above(const Quad* distance2, double reach2) {
  unsigned mask = 0;
  for (int i = 0; i < kQuads; ++i)
    mask |= static_cast<unsigned>(_mm256_movemask_pd(_mm256_cmp_pd(reinterpret_cast<__m256d>(distance2[i]), _mm256_set1_pd(reach2), _CMP_NGT_UQ))) << (4 * i);
  return mask;
}

template <int D>
__attribute__((target("avx2"))) unsigned points_in_reach_avx2(const double* lanes, const double* centre, int d, double reach2) {
  if constexpr (D > 0) d = D;
  constexpr int kLanes = LeafBlocks::kLanes;
  Quad sum[kQuads];
  const Quad c0 = broadcast(centre[0]);
  for (int i = 0; i < kQuads; ++i) {
    const Quad delta = load_quad(lanes + 4 * i) - c0;
    sum[i] = delta * delta;
  }
  for (int k = 1; k < d; ++k) {
    const Quad c = broadcast(centre[k]);
    for (int i = 0; i < kQuads; ++i) {
      const Quad delta = load_quad(lanes + k * kLanes + 4 * i) - c;
      sum[i] += delta * delta;
    }
  }
  return not_above(sum, reach2);
}

// The squared distance on one axis from c to four boxes [lo, hi]. MAXPD gives its second
// operand unless the first is greater: these are the selects below > above ? below : above
// and delta > 0 ? delta : 0 (NaN and -0 give 0) of the SSE2 version, one instruction each
// (the second select compiled to a compare and a mask).
__attribute__((target("avx2"))) inline Quad box_square(const double* lo, const double* hi, Quad c) {
  const Quad below = load_quad(lo) - c, above = c - load_quad(hi);
  const __m256d larger = _mm256_max_pd(reinterpret_cast<__m256d>(below), reinterpret_cast<__m256d>(above));
  const Quad delta = reinterpret_cast<Quad>(_mm256_max_pd(larger, _mm256_setzero_pd()));
  return delta * delta;
}

template <int D>
__attribute__((target("avx2"))) unsigned boxes_in_reach_avx2(const double* boxes, const double* centre, int d, double reach2) {
  if constexpr (D > 0) d = D;
  constexpr int kLanes = LeafBlocks::kLanes;
  // The first axis starts the sum: 0 + delta^2 is delta^2 (a square is never -0).
  Quad sum[kQuads];
  for (int i = 0; i < kQuads; ++i) sum[i] = box_square(boxes + 4 * i, boxes + d * kLanes + 4 * i, broadcast(centre[0]));
  for (int k = 1; k < d; ++k) {
    const Quad c = broadcast(centre[k]);
    for (int i = 0; i < kQuads; ++i) sum[i] += box_square(boxes + k * kLanes + 4 * i, boxes + (d + k) * kLanes + 4 * i, c);
  }
  return not_above(sum, reach2);
}
}  // namespace
#endif

template <int D>
unsigned SearchKernel<D>::points_in_reach(const double* lanes, double reach2) const {
#if DRANGE_AVX2_LANES
  if (avx2_) return points_in_reach_avx2<D>(lanes, centre_.data(), dim(), reach2);
#endif
  // in_query's arithmetic, lane by lane: the same points pass.
  const int d = dim();
  constexpr int kLanes = LeafBlocks::kLanes;
  Pair sum[kPairs];
  const Pair c0 = {centre_[0], centre_[0]};
  for (int i = 0; i < kPairs; ++i) {
    const Pair delta = load_pair(lanes + 2 * i) - c0;
    sum[i] = delta * delta;
  }
  for (int k = 1; k < d; ++k) {
    const Pair c = {centre_[static_cast<std::size_t>(k)], centre_[static_cast<std::size_t>(k)]};
    const double* x = lanes + k * kLanes;
    for (int i = 0; i < kPairs; ++i) {
      const Pair delta = load_pair(x + 2 * i) - c;
      sum[i] += delta * delta;
    }
  }
  return not_above(sum, reach2);
}

template <int D>
unsigned SearchKernel<D>::boxes_in_reach(const double* boxes, double reach2) const {
#if DRANGE_AVX2_LANES
  if (avx2_) return boxes_in_reach_avx2<D>(boxes, centre_.data(), dim(), reach2);
#endif
  // prune's arithmetic, lane by lane: a lower bound of the computed distance of every point
  // in the box (rounding is monotonic).
  const int d = dim();
  constexpr int kLanes = LeafBlocks::kLanes;
  const Pair zero = {0.0, 0.0};
  Pair sum[kPairs];
  for (int i = 0; i < kPairs; ++i) sum[i] = zero;
  for (int k = 0; k < d; ++k) {
    const Pair c = {centre_[static_cast<std::size_t>(k)], centre_[static_cast<std::size_t>(k)]};
    const double* lo = boxes + k * kLanes;
    const double* hi = boxes + (d + k) * kLanes;
    for (int i = 0; i < kPairs; ++i) {
      const Pair below = load_pair(lo + 2 * i) - c;
      const Pair above = c - load_pair(hi + 2 * i);
      Pair delta = below > above ? below : above;
      delta = delta > zero ? delta : zero;
      sum[i] += delta * delta;
    }
  }
  return not_above(sum, reach2);
}

template <int D>
bool SearchKernel<D>::prune(std::int32_t node, bool leaf) {
  const int d = dim();
  const double* lo = points_.tree.template lower<D>(node);
  const double* hi = points_.tree.template upper<D>(node);
  if (ball_) {  // the node's box misses the ball (the walk only checked the ball's bounding box)
    // The distance on each axis two axes at a time (vector selects: a branch per axis was
    // mispredicted), the sum in axis order as before.
    std::array<double, kMaxRow> squares{};
    const Pair zero = {0.0, 0.0};
    int k = 0;
    for (; k + 1 < d; k += 2) {
      const Pair c = load_pair(&centre_[static_cast<std::size_t>(k)]);
      const Pair below = load_pair(lo + k) - c, above = c - load_pair(hi + k);
      Pair delta = below > above ? below : above;
      delta = delta > zero ? delta : zero;
      const Pair square = delta * delta;
      std::memcpy(&squares[static_cast<std::size_t>(k)], &square, sizeof square);
    }
    if (k < d) {
      const double c = centre_[static_cast<std::size_t>(k)];
      const double delta = std::max(0.0, std::max(lo[k] - c, c - hi[k]));
      squares[static_cast<std::size_t>(k)] = delta * delta;
    }
    double distance2 = squares[0];
    for (k = 1; k < d; ++k) distance2 += squares[static_cast<std::size_t>(k)];
    if (distance2 > ball_reach2_) return true;
  }
  if (shell_scan_ && in_shell(node) && shell_prunes(node)) return true;
  // A node of a curved patch whose box meets the ball may still lie wholly outside it (after
  // the shell, which decides the nodes near its sphere better).
  if (ball_ && !shell_scan_ && try_slabs_ != nullptr && slab_misses_ball(node)) return true;
  // Within the candidate's ball, the closed side is a thin cap of its sphere, inside the empty
  // sphere of the simplex already found there: nodes wholly on the closed side that meet the
  // ball are rare and hold few points, and testing for them costs more than scanning them
  // (measured). So the closed side is pruned while there is no ball: before the first
  // candidate (the box is then unbounded: hull facets depend on it) or without a trustworthy
  // ball, or without ball queries at all (the paper's search).
  // Except in the searches whose ball has met many nodes: on a curved surface (a cylinder, a
  // torus) a Delaunay ball touches the surface along a whole curve, and its cap on the closed
  // side holds whole subtrees near it. There the inner nodes are tested after the first
  // kClosedSideAfter (leaves: 2.4% of their tests pruned on the cylinder, against 11% of the
  // inner nodes'). time_search, medians of 5 interleaved runs: cylinder 2.46 -> 2.07 s,
  // cylinder_rings 1.78 -> 1.51, torus 1.24 -> 1.13 (mins 1.09 -> 1.07), plateau 0.38 -> 0.35;
  // the other families and uniform 2D to 5D level (a search there meets fewer nodes; callgrind:
  // uniform 2D to 5D -0.07% to -0.70% instructions, as a leaf with a ball now returns first).
  if (ball_ && (leaf || ++ball_nodes_ <= kClosedSideAfter)) return false;
  if (!options_.prune_closed_side || !filters_hold_) return false;
  // The largest value of sigma O over the node's box, at the corner that maximises each term
  // (rounding is monotonic: a * dhi >= a * dlo in floating point too when a >= 0); the bound
  // factor covers a computed a of the wrong sign (box_orient_gamma_).
  double m = 0.0, m_abs = 0.0;
  for (int k = 0; k < d; ++k) {
    const double a = a_[static_cast<std::size_t>(k)];
    const double dlo = lo[k] - f0_[k], dhi = hi[k] - f0_[k];
    m += a * (a >= 0 ? dhi : dlo);
    m_abs += a_abs_[static_cast<std::size_t>(k)] * std::max(std::fabs(dlo), std::fabs(dhi));
  }
  if (orientation_sign(m, m_abs, box_orient_gamma_) < 0) return true;
  if (flat_closed_side(lo, hi)) return true;
  if (shell_ != nullptr && cone_on_closed_side(node, m_abs)) return true;
  return try_slabs_ != nullptr && slab_on_closed_side(node, lo, hi, m_abs);
}

template <int D>
bool SearchKernel<D>::slab_misses_ball(std::int32_t node) {
  const double* slab = slabs_->slab(node);
  return slab != nullptr && slab_tried(slabs_->misses_ball<D>(slab, centre_.data(), ball_reach_));
}

template <int D>
bool SearchKernel<D>::slab_on_closed_side(std::int32_t node, const double* lo, const double* hi, double box_abs) {
  const double* slab = slabs_->slab(node);
  if (slab == nullptr) return false;
  // With n the slab's normal and lambda = a . n, sigma O(x) = a . y (y = x - f0) = b . y +
  // lambda n . y, b = a - lambda n: the box bounds b . y (b is small when the facet's
  // hyperplane runs along the patch), the slab bounds n . y. The rounding of b, of the
  // differences, products and sums is within 2 (d + 3) u of the absolute tree s_abs; the
  // exact minors' distance from a_ is within box_orient_gamma_ of the box's (as in prune).
  const int d = dim();
  double lambda = 0.0, n_f0 = 0.0, n_f0_abs = 0.0;
  for (int k = 0; k < d; ++k) {
    lambda += a_[static_cast<std::size_t>(k)] * slab[k];
    n_f0 += slab[k] * f0_[k];
    n_f0_abs += std::fabs(slab[k] * f0_[k]);
  }
  double s = 0.0, s_abs = 0.0;
  for (int k = 0; k < d; ++k) {
    const double a = a_[static_cast<std::size_t>(k)], b = a - lambda * slab[k];
    const double dlo = lo[k] - f0_[k], dhi = hi[k] - f0_[k];
    s += b * (b >= 0 ? dhi : dlo);
    s_abs += (std::fabs(a) + std::fabs(lambda * slab[k])) * std::max(std::fabs(dlo), std::fabs(dhi));
  }
  const double t = lambda >= 0 ? slab[d + 1] : slab[d];  // the slab's largest n . x, or least
  s += lambda * (t - n_f0);
  s_abs += std::fabs(lambda) * (std::fabs(t) + n_f0_abs);
  return slab_tried(s < -(box_orient_gamma_ * box_abs + 2 * (d + 3) * geometry::kUnitRoundoff * s_abs + 0x1p-1000));
}

template <int D>
bool SearchKernel<D>::flat_closed_side(const double* lo, const double* hi) {
  if (flat_axes_ == kFlatAxesUnknown) flat_axes_ = facet_flat_axes();
  if (flat_axes_ == 0) return false;
  // One flat axis k at most (the facet's vertices are affinely independent), and the
  // hyperplane is x_k = f0_k: every other coefficient of a_ is a minor with a zero column,
  // computed as an exact 0, so sigma O(x) = a_k (x_k - f0_k) exactly where a_k's sign is
  // right, which its own filter certifies (a_k is a (d-1)-minor).
  const int k = __builtin_ctz(flat_axes_);
  const int s = geometry::certified_sign_with(a_[static_cast<std::size_t>(k)], a_abs_[static_cast<std::size_t>(k)], minor_gamma_);
  return s > 0 ? hi[k] <= f0_[k] : s < 0 && lo[k] >= f0_[k];
}

template <int D>
bool SearchKernel<D>::cone_on_closed_side(std::int32_t node, double box_abs) const {
  // sigma O(x) = a . (x - f0) = a . y + a . (g - f0) with y = x - g = r e in the node's cone:
  // a . e is at most -least_on_cone(-a). The rounding here is within shell_cone_gamma_ of the
  // absolute tree; the exact minors differ from a by at most prune's coefficient error, which
  // box_orient_gamma_ times the box's absolute tree covers (the box holds the points).
  // The cone is about the node's sphere's centre: the facet's sphere's, or another's (then its
  // a . (g - f0) is computed here). With one sphere, every node has a cone about its centre,
  // and every facet its terms about it (set_facet_sphere): the nodes that mix points on the
  // sphere with points inside it have no sphere of their own, and before the cones their
  // boxes made a hull facet's search visit 64 nodes (a sphere of 16 000 points around 4 000
  // inside it: 37.2 -> 19.9 nodes per simplex).
  const int d = dim();
  std::int32_t sphere = shell_everywhere_ ? shell_sphere_ : shell_->node_sphere[static_cast<std::size_t>(node)];
  if (sphere < 0 && shell_->spheres() == 1) sphere = 0;  // every node's cone is about its centre
  const double* cone = shell_->cone_of(node);
  if (sphere < 0 || !(cone[d] > 0.0) || !filters_hold_) return false;
  const FacetOnShell* facet = &facet_on_shell_;
  FacetOnShell other;
  if (sphere != shell_sphere_ && shell_->spheres() > 1) {
    other = facet_about(shell_->sphere(sphere).centre);
    facet = &other;
  }
  const FacetOnShell& terms = *facet;
  const double norm = terms.norm;
  const double most = -least_on_cone(a_.data(), -1.0, norm, cone);
  const double value = terms.offset + (most > 0.0 ? most * cone[d + 3] : most * cone[d + 2]);
  const double bound = shell_cone_gamma_ * (terms.offset_abs + norm * cone[d + 3]) + box_orient_gamma_ * box_abs + 0x1p-1000;
  return value < -bound;  // false on NaN
}

template <int D>
typename SearchKernel<D>::FacetOnShell SearchKernel<D>::facet_about(const double* g) const {
  // cone_on_closed_side's terms that depend on the facet and a sphere only: |a| (with a margin
  // for its rounding) and a . (g - f0) with its absolute tree.
  const int d = dim();
  double norm2 = 0.0, offset = 0.0, offset_abs = 0.0;
  for (int k = 0; k < d; ++k) {
    const double a = a_[static_cast<std::size_t>(k)];
    const double t = g[k] - f0_[k];
    norm2 += a * a;
    offset += a * t;
    offset_abs += std::fabs(a) * std::fabs(t);
  }
  return {upper_norm(norm2, d), offset, offset_abs};
}

template <int D>
void SearchKernel<D>::set_facet_sphere() {
  const int d = dim();
  shell_sphere_ = shell_->point_sphere[static_cast<std::size_t>(facet_[0])];
  for (int i = 1; i < d && shell_sphere_ >= 0; ++i)
    if (shell_->point_sphere[static_cast<std::size_t>(facet_[i])] != shell_sphere_) shell_sphere_ = -1;
  if (shell_sphere_ < 0) {
    // With one sphere, every node's cone is about its centre (cone_on_closed_side), for the
    // facets with vertices off it too.
    if (shell_->spheres() == 1) facet_on_shell_ = facet_about(shell_->sphere(0).centre);
    return;
  }
  shell_view_ = shell_->sphere(shell_sphere_);
  facet_on_shell_ = facet_about(shell_view_.centre);
}

template <int D>
std::int32_t SearchKernel<D>::find_apex(const std::int32_t* facet, int sigma, SearchCounters& counters) {
  const int d = dim();
  counters_ = &counters;
  // A clean hull facet's outer side holds no point (known_hull.hpp): nothing to search.
  if (hull_ != nullptr && hull_->outer_sigma(facet) == sigma) return -1;
  ball_nodes_ = 0;
  start_slab_trials();
  set_facet(facet, sigma);
  candidate_ = -1;
  shell_form_ = shell_scan_ = false;
  facet_minors_.ready = false;
  if (shell_ != nullptr) set_facet_sphere();
  reset_box();
  if (options_.seed_candidate) {
    for (int i = 0; i < d; ++i)
      for (int k = 0; k < (kSeeds > 0 ? kSeeds : seeds_.seeds_per_point()); ++k) {
        const std::int32_t seed = seeds_.seed<kSeeds>(facet[i], k);
        if (seed >= 0) consider(seed);
      }
  }
  if (options_.use_kdtree && options_.bottom_up) {
    counters.calls += points_.tree.search_from<D>(*this, points_.tree.leaf_of(facet[0]));
  } else if (options_.use_kdtree) {
    counters.calls += points_.tree.search<D>(*this);
  } else {
    ++counters.calls;
    for (std::int32_t id = 0; id < points_.size; ++id) consider(id);
  }
  if (options_.seed_candidate && candidate_ >= 0) {
    for (int i = 0; i < d; ++i) seeds_.remember<kSeeds>(facet[i], candidate_);
  }
  return candidate_;
}

}  // namespace

int search_leaf_size(int dim) {
  // Larger leaves: fewer kd-tree nodes entered (each a box test, often a cache miss) but more
  // points scanned per leaf (then a tight loop over contiguous coordinates). The
  // search's time on one thread (drange generate uniform N D --seed 1; delaunay --stats
  // --threads 1; best of 2, 2 cores shared, so +-5%) with leaf size 8 -> 16, 32, 64, 128:
  //   2D 1M     0.98 s -> 0.94, 0.89, 0.91, 1.02
  //   3D 200k   1.74 s -> 1.57, 1.50, 1.45, 1.43
  //   4D 30k    2.29 s -> 1.99, 1.77, 1.71, 1.80
  //   5D 5k     3.27 s -> 2.72, 2.43, 2.28, 2.29
  //   6D 2k     9.99 s ->    -, 7.72, 7.82, 7.85 (one run)
  //   7D 1k        -   ->    -, 24.7, 22.8, 23.2 (one run)
  // Beyond the best size the time is flat up to about twice as large, then grows (the scan
  // dominates).
  // From 4D on, the leaf scan then became block by block (LeafBlocks: eight boxes of 8
  // points tested at once, then only the blocks that meet the ball), which makes a large leaf
  // cheap to scan, and the measurements moved. On the AMD EPYC machine, 2026-11-25, min of 3
  // (5 where marked) interleaved runs, leaf size 64 -> 128, 256:
  //   4D 30k    1.146 s -> 1.147, 1.126      4D 100k   4.448 -> 4.105, 4.275
  //   5D 5k     1.623   -> 1.454, 1.449      5D 20k    8.348 -> 8.030, 7.784 (5: 7.169, 7.043)
  //   5D 50k   20.351   -> 19.169, 19.232    6D 5k    15.663 -> 14.517, 14.717 (5: 13.484, 13.325)
  //   7D 1k    11.146   -> 10.779, 10.547    7D 2k    32.735 -> 31.239, 30.524
  //   8D 300   10.804   -> 10.481, 10.406    (5D 20k at 512: 8.221, against 7.924 at 256)
  // 128 and 256 are within the noise of each other from 5D to 6D; 256 won in 7D and 8D, 128
  // in 4D. 3D 200k at 128: 1.046 -> 1.064 s (3D had no blocks then).
  // Since the lane tests give bit masks, the blocks serve 2D and 3D too, and a leaf scan costs
  // less again (min of 3 interleaved runs, blocks against the earlier point-by-point scan):
  //   2D 1M     leaf 32, no blocks 0.788 s -> blocks at 32: 0.911, 64: 0.771, 128: 0.811
  //   3D 200k   leaf 64, no blocks 1.028 s -> blocks at 64: 0.963, 128: 0.933, 256: 0.908 (0.925
  //             at 128 in that pair); 3D 1M 128 -> 256: 4.693 -> 4.705, grid 60^3 1.134 -> 1.117
  //   4D 100k   128 -> 256: 3.696 -> 3.578; 4D 30k 0.961 -> 0.940
  //   5D 20k    256 -> 512: 6.179 -> 6.189; 6D 5k 11.492 -> 11.170 (within the noise: 256 kept)
  // 9D and up take the 8D value.
  constexpr int kByDimension[] = {0, 0, 64, 128, 256, 256, 256, 256, 256};
  return dim < static_cast<int>(std::size(kByDimension)) ? kByDimension[dim] : kByDimension[std::size(kByDimension) - 1];
}

namespace {
std::unique_ptr<FacetSearch::Kernel> make_kernel(const PointStore& points, const SearchOptions& options, SeedMemory& seeds,
                                                 FacetSearch::KernelChoice choice, FacetSearch::VectorWidth width) {
  const bool wide = width == FacetSearch::VectorWidth::Widest;
  switch (choice == FacetSearch::KernelChoice::FixedDimension ? points.dim : 0) {
    case 2: return std::make_unique<SearchKernel<2>>(points, options, seeds, wide);
    case 3: return std::make_unique<SearchKernel<3>>(points, options, seeds, wide);
    case 4: return std::make_unique<SearchKernel<4>>(points, options, seeds, wide);
    case 5: return std::make_unique<SearchKernel<5>>(points, options, seeds, wide);
    case 6: return std::make_unique<SearchKernel<6>>(points, options, seeds, wide);
    case 7: return std::make_unique<SearchKernel<7>>(points, options, seeds, wide);
    case 8: return std::make_unique<SearchKernel<8>>(points, options, seeds, wide);
    default: return std::make_unique<SearchKernel<0>>(points, options, seeds, wide);
  }
}
}  // namespace

FacetSearch::FacetSearch(const PointStore& points, const SearchOptions& options, KernelChoice choice, VectorWidth width)
    : own_seeds_(std::make_unique<SeedMemory>(options.seed_candidate ? points.size : 0, points.dim)),
      kernel_(make_kernel(points, options, *own_seeds_, choice, width)) {}

FacetSearch::FacetSearch(const PointStore& points, const SearchOptions& options, SeedMemory& seeds)
    : kernel_(make_kernel(points, options, seeds, KernelChoice::FixedDimension, VectorWidth::Widest)) {}

FacetSearch::~FacetSearch() = default;

std::int32_t FacetSearch::find_apex(const std::int32_t* facet, int sigma, SearchCounters& counters) {
  return kernel_->find_apex(facet, sigma, counters);
}

}  // namespace drange::engine
