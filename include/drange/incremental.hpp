// drange/incremental.hpp: a Delaunay triangulation that grows as points are added.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "drange/delaunay.hpp"
#include "drange/points.hpp"

namespace drange {

// The Delaunay triangulation of every point added so far, kept up to date point by point:
// each new point removes the simplices whose circumspheres hold it and is joined to the
// boundary of the cavity they leave (Bowyer-Watson, with drange's exact predicates and
// symbolic perturbation). After any sequence of add_points, triangulation() has the same
// simplices, as vertex sets, as delaunay() on all the points in the order added: the
// triangulation under the perturbation is unique. The cost of add_points follows the change
// (the simplices created and removed, and a walk to each new point), plus a merge of the new
// points into the lexicographic order and a pass over all the points to renumber their ranks; the initial points are inserted in a
// biased randomized order, as Options::algorithm "incremental" does. One thread.
//
// With `furthest_site`, the furthest-site Delaunay triangulation instead: the simplices whose
// circumspheres hold every point (the upper hull of the lifted points), under the same
// perturbation; its vertices are the extreme points alone (the others are in no simplex), and
// neighbours are -1 on the convex hull, as for the Delaunay triangulation.
class IncrementalDelaunay {
 public:
  // Triangulates `points`. Throws as delaunay(): InputError (NaN or infinite coordinate, a
  // dimension outside 2..11), DegenerateInputError (fewer than d+1 distinct points, or all in
  // one hyperplane).
  explicit IncrementalDelaunay(PointsView points, bool furthest_site = false);
  ~IncrementalDelaunay();
  IncrementalDelaunay(IncrementalDelaunay&&) noexcept;
  IncrementalDelaunay& operator=(IncrementalDelaunay&&) noexcept;

  // Adds `points` (the same dimension), numbered after those added before. An exact copy of
  // a point already there is a duplicate, left out as delaunay() leaves it. Throws InputError,
  // naming the point by its index among all the points, for a wrong dimension or a NaN or
  // infinite coordinate; the triangulation is then unchanged. After any other exception (out
  // of memory, more than 2^31 - 1 cells) the object is not to be used again.
  void add_points(PointsView points);

  // Sibson's natural-neighbour coordinates of each query point x in the triangulation now: the
  // points whose Voronoi cells x's cell would take volume from, each with that volume over the
  // volume of x's cell (positive, summing to 1; sum_i w_i p_i = x). A query outside the closed
  // convex hull of the points or on its boundary, where x's cell is unbounded, has none; one
  // equal to a point has that point (the first with its coordinates) with weight 1. The cells'
  // combinatorics are exact (the perturbed triangulation and x's conflicts in it); the volumes
  // are computed in floating point, from the flag parts of the simplices x's insertion would
  // remove and create (extended precision near flat faces).
  // Throws UsageError for the furthest-site triangulation, InputError for a query of the wrong
  // dimension or with a NaN or infinite coordinate (naming it). It probes the object's own
  // state: like add_points, not to be called while another call on the object runs.
  struct NaturalNeighbours {
    std::vector<std::size_t> offsets;  // query q's neighbours: [offsets[q], offsets[q + 1])
    std::vector<std::int32_t> ids;     // input indices
    std::vector<double> weights;
  };
  NaturalNeighbours natural_neighbours(PointsView queries);

  int dim() const;
  std::size_t size() const;  // points added, duplicates included

  // The triangulation now, in the layout of delaunay()'s result (simplices in the order of the
  // kernel's storage, each positively oriented; neighbours when `neighbors`). Its statistics
  // count the work of every insertion so far (search_calls: the cells the walks entered;
  // debug.points_tested: the cells tested for conflict) and its times are those of all the
  // add_points calls, the constructor's included.
  Triangulation triangulation(bool neighbors = true) const;

  // The engine's state, defined in its sources alone (opaque here).
  struct State;

 private:
  std::unique_ptr<State> state_;
};

}  // namespace drange
