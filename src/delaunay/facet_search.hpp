// delaunay/facet_search.hpp: the search for the next simplex (paper, section 2.4).
//
// For an open facet F = (f_0, ..., f_{d-1}) with orientation sign sigma (its open side is
// sigma O(x) > 0, O(x) = det[f_1 - f_0; ...; f_{d-1} - f_0; x - f_0]), find_apex returns the
// point on the open side whose sphere through F holds no other point of the open side: the
// point that closes F into a Delaunay simplex, or -1 when F is on the convex hull.
//
// Where it lives:
//   - search/search_kernel.hpp: the shrinking kd-tree walk and the leaf scans;
//   - geometry/facet_plane_test.hpp, geometry/lifted_sphere_test.hpp: the two predicates it
//     asks (open side; beats the candidate), each with its exact stages;
//   - search/candidate_ball.hpp: the query box and ball, enlarged by their rounding bounds;
//   - search/shell_pruner.hpp, known_hull.hpp, seed_memory.hpp: the accelerators, which
//     change the order in which points are met, never the point found.
// SearchOptions switches each step off, for measurements (--variant).
//
// The kernel is compiled for d = 2..8 (fixed-size loops) and once for any d; the same
// template serves all (facet_search.cpp).
#pragma once

#include <cstdint>
#include <memory>

#include "delaunay/point_store.hpp"
#include "delaunay/search_options.hpp"
#include "delaunay/seed_memory.hpp"

namespace drange::engine {

struct SearchCounters {
  std::uint64_t calls = 0;          // kd-tree nodes entered (their box meets the query box)
  std::uint64_t points_tested = 0;  // points inside the query box (or ball) that were tested
  std::uint64_t candidates = 0;     // improvements of the candidate
};

// The kd-tree leaf size that makes the search fastest in dimension `dim` (measured on uniform
// points). The leaf size changes no result and no point id
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
