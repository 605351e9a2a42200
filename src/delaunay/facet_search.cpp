// delaunay/facet_search.cpp: the search for the next simplex, compiled for each dimension.
//
// One algorithm, SearchKernel<D> (search/search_kernel.hpp), compiled for D = 2..8 (loops of
// fixed length, no heap indirection in the hot path) and for D = 0 (any d, read at run time).
#include "delaunay/facet_search.hpp"

#include <iterator>
#include <memory>

#include "delaunay/search/search_kernel.hpp"

namespace drange::engine {

int search_leaf_size(int dim) {
  // Larger leaves: fewer kd-tree nodes entered (each a box test, often a cache miss) but more
  // points scanned per leaf (a tight loop over contiguous blocks of lanes, LeafBlocks, which
  // makes a large leaf cheap to scan). The best size grows with d; beyond it the time is flat up
  // to about twice as large, then grows as the scan dominates. The values are the fastest
  // measured on uniform points (docs/performance.md says how to measure); 9D and up take 8D's.
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
