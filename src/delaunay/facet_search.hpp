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
//
// Our steps (SearchOptions; each changes which points are met, or in which order, never the
// point found): the walk goes bottom-up from the leaf of f_0 (KdTree::search_from); the
// apexes of the last searches around the facet's vertices are tried first (seeds), so the
// first query region is already small; points and nodes are tested against the candidate's
// ball, not only its bounding box, and once there is a ball the closed side is no longer
// tested per node (the ball leaves only a thin cap of it); on points near spheres, where every
// candidate's ball of a facet on one of them holds nearly all its points, nodes and points are
// decided by the lifted determinant's exact form around that sphere's centre (sphere_shell.hpp);
// on points sampled from surfaces, a node whose points lie in a thin slab (node_slabs.hpp) is
// skipped when the slab misses the ball or lies on the closed side.
//
// The arithmetic is compiled for d = 2..8 (fixed-size loops) and once for any d; the same
// template serves all (facet_search.cpp).
#pragma once

#include <cstdint>
#include <memory>

#include "delaunay/point_store.hpp"
#include "delaunay/seed_memory.hpp"
#include "drange/delaunay.hpp"

namespace drange::engine {

struct SearchCounters {
  std::uint64_t calls = 0;          // kd-tree nodes entered (their box meets the query box)
  std::uint64_t points_tested = 0;  // points inside the query box (or ball) that were tested
  std::uint64_t candidates = 0;     // improvements of the candidate
};

// The kd-tree leaf size that makes the search fastest in dimension `dim` (measured; the table
// in facet_search.cpp says how). The leaf size changes no result and no point id
// (spatial/kdtree.hpp).
int search_leaf_size(int dim);

class FacetSearch {
 public:
  // Which compilation of the search runs: the one for the points' dimension where there is
  // one (d = 2..8), or the one for any d (the tests compare the two).
  enum class KernelChoice { FixedDimension, AnyDimension };
  // How wide the vector loops over a leaf's blocks are: Widest takes AVX2 where the
  // CPU has it (x86-64), else two doubles (SSE2, NEON); TwoDoubles always the latter. Both
  // give the same doubles (the tests compare them).
  enum class VectorWidth { Widest, TwoDoubles };
  // With seeds of its own (SeedMemory), for a search on one thread.
  FacetSearch(const PointStore& points, const SearchOptions& options,
              KernelChoice choice = KernelChoice::FixedDimension, VectorWidth width = VectorWidth::Widest);
  // Sharing `seeds` with the searches of other threads; `seeds` must outlive this search.
  FacetSearch(const PointStore& points, const SearchOptions& options, SeedMemory& seeds);
  ~FacetSearch();
  FacetSearch(const FacetSearch&) = delete;
  FacetSearch& operator=(const FacetSearch&) = delete;

  // The id of the point that closes the facet (sorted ids, open side sigma O > 0) into a
  // Delaunay simplex, or -1 when the facet is on the convex hull.
  std::int32_t find_apex(const std::int32_t* facet, int sigma, SearchCounters& counters);

  // The search for one dimension (facet_search.cpp).
  class Kernel {
   public:
    virtual ~Kernel() = default;
    virtual std::int32_t find_apex(const std::int32_t* facet, int sigma, SearchCounters& counters) = 0;
  };

 private:
  std::unique_ptr<SeedMemory> own_seeds_;  // when no memory is shared
  std::unique_ptr<Kernel> kernel_;
};

}  // namespace drange::engine
