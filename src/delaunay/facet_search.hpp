// delaunay/facet_search.hpp: the search for the next simplex (paper, section 2.4).
//
// For an open facet F = (f_0, ..., f_{d-1}) and a point x, let r_x = (x - f_0, |x - f_0|^2) be
// the lifted row relative to f_0 and O(x) = det[f_1 - f_0; ...; f_{d-1} - f_0; x - f_0]. With
// the facet's orientation sign sigma chosen so that the open side is sigma O(x) > 0:
//   - x is a candidate when sigma O(x) > 0 (points on F's hyperplane never are);
//   - a candidate q beats the current candidate p exactly when q is strictly inside the sphere
//     through F and p, which is  sigma I(p, q) < 0  with  I(p, q) = det[r_f1; ...; r_p; r_q].
// The Delaunay point of F beats every other candidate. I(p, q) is bilinear in r_p and r_q: once
// F is fixed, the (d-1)-minors of its lifted rows are computed once (O(2^d d)), once p is fixed
// the d-minors give a vector w with I(p, q) = w . r_q, so testing a point costs O(d). Every
// sign is certified by the error bound of error_bound.hpp and, if that fails, decided exactly
// with the symbolic perturbation (geometry/predicates.hpp).
//
// The kd-tree query box is the bounding box of the current candidate's sphere, enlarged by a
// bound on its rounding error so that no point that may win is missed. Pruning the closed side
// (2.4.1) is safe because the spheres through F shrink on that side as the candidate improves,
// and the simplex already found there has an empty sphere.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "delaunay/point_store.hpp"
#include "drange/delaunay.hpp"
#include "geometry/minors.hpp"

namespace drange::engine {

struct SearchCounters {
  std::uint64_t calls = 0;          // kd-tree nodes entered (their box meets the query box)
  std::uint64_t points_tested = 0;  // points inside the query box (or ball) that were tested
  std::uint64_t candidates = 0;     // improvements of the candidate
};

class FacetSearch {
 public:
  FacetSearch(const PointStore& points, const SearchOptions& options);

  // The id of the point that closes the facet (sorted ids, open side sigma O > 0) into a
  // Delaunay simplex, or -1 when the facet is on the convex hull.
  std::int32_t find_apex(const std::int32_t* facet, int sigma, SearchCounters& counters);

  // kd-tree visitor interface (spatial/kdtree.hpp).
  const double* query_lower() const { return lower_.data(); }
  const double* query_upper() const { return upper_.data(); }
  bool prune(std::int32_t node) const;
  // The sign of sigma O over the computed value, when certified or proved exact; else 0.
  int orientation_sign(double value, double abs_tree) const;
  bool right_first(const spatial::KdTree::Node& node) const {
    return options_.visit_facet_child_first && centroid_[static_cast<std::size_t>(node.split_axis)] > node.split_value;
  }
  void leaf(std::int32_t begin, std::int32_t end) {
    for (std::int32_t id = begin; id < end; ++id) consider(id);
  }

 private:
  void set_facet(const std::int32_t* facet, int sigma);
  void consider(std::int32_t id);
  void set_candidate(std::int32_t id);
  bool on_open_side(std::int32_t id);
  bool beats_candidate(std::int32_t id);
  void reset_box();

  const PointStore& points_;
  SearchOptions options_;
  int d_;
  double orient_gamma_;  // error bound factors (error_bound.hpp) of O(x) and I(p, x)
  double lifted_gamma_;

  // Per facet.
  const std::int32_t* facet_ = nullptr;
  int sigma_ = 1;
  const double* f0_ = nullptr;
  geometry::MinorTable minors_;
  std::vector<double> a_, a_abs_;    // sigma O(x) = a . (x - f0), and its absolute tree
  // True when no underflow, overflow or invalid operation occurred in the facet's minors (and,
  // below, in the candidate's): the fast filters and the query box rely on it.
  bool facet_clean_ = true;
  bool candidate_clean_ = true;
  // True when a_ is exact and O(x) is computed without rounding whenever its absolute tree
  // is below orient_exact_limit_ (dyadic points, see set_facet).
  bool orientation_exact_ = false;
  double orient_exact_limit_ = 0.0;
  std::array<double, 13> exact_limits_{};  // 2^(52 + unit_exponent * size), size = 0..d (dyadic points)
  std::vector<double> centroid_;
  std::vector<const double*> rows_;  // f_1, ..., f_{d-1}, p, q for the exact predicates
  std::vector<std::int64_t> ranks_;  // ranks of f_0, ..., f_{d-1}, p, q

  // Per candidate.
  std::int32_t candidate_ = -1;
  std::vector<double> w_, w_abs_;    // sigma I(p, x) = w . r_x, and its absolute tree
  std::vector<double> centre_;       // of the sphere through F and p
  std::vector<double> lower_, upper_;  // the query box
  bool ball_ = false;                  // also query the ball: |x - centre|^2 <= ball_reach2_
  double ball_reach2_ = 0.0;

  // Per point (scratch).
  std::vector<double> row_;
  // Seeds: for each point, the apexes of the last kSeeds searches whose facet held it (Delaunay
  // neighbours of the point, -1 when none yet); tried before the walk.
  static constexpr int kSeeds = 2;
  std::vector<std::int32_t> recent_;
  SearchCounters* counters_ = nullptr;
};

}  // namespace drange::engine
