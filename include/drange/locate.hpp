// drange/locate.hpp: exact point location in a triangulation (scipy's Delaunay.find_simplex).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>

#include "drange/delaunay.hpp"
#include "drange/points.hpp"

namespace drange {

// Finds, for query points, a simplex of a triangulation that contains them. Every decision is
// an exact orientation test, so a point on a shared face, on a vertex or on the hull is found
// in one of the simplices that hold it (never -1), and a point a rounding error outside the
// hull is outside. Each query walks from a simplex of its nearest vertex (a kd-tree over the
// vertices) across the facets it lies beyond, with a randomised facet order (Devillers, Pion
// and Teillaud's stochastic walk), which ends in any triangulation.
//
// The locator keeps views: the points, simplices and neighbours must outlive it.
class SimplexLocator {
 public:
  // simplices and neighbors: num_simplices rows of d+1 int32, as in Triangulation (neighbour k
  // opposite vertex k, -1 on the hull), with every simplex positively oriented.
  SimplexLocator(PointsView points, const std::int32_t* simplices, const std::int32_t* neighbors,
                 std::size_t num_simplices);
  // The same over a result of drange::delaunay (which must have its neighbours).
  SimplexLocator(PointsView points, const Triangulation& triangulation);
  SimplexLocator(SimplexLocator&&) noexcept;
  SimplexLocator& operator=(SimplexLocator&&) noexcept;
  ~SimplexLocator();

  // The index of a simplex whose closed hull contains q (dim coordinates), or -1 when q lies
  // outside the convex hull or has a NaN or infinite coordinate. Safe to call concurrently.
  std::int32_t find(const double* q) const;
  // find() for each query (queries.dim must be the points' dimension); out has queries.n entries.
  // The queries are shared among `threads` threads (0: every hardware thread); the answers do
  // not depend on it. Throws UsageError on a dimension mismatch or a negative thread count.
  void find(PointsView queries, std::int32_t* out, int threads = 1) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace drange
