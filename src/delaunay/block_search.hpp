// delaunay/block_search.hpp: the direct search as blocks that threads wrap on their own.
//
// The points, in id order (the kd-tree's, spatially coherent), are cut into ranges of equal
// count, which the threads take in turn. A thread wraps the stars of a range's points (local_star.hpp: a walk from the
// first facet, then the facets through those points, with a facet table and a queue of its
// own) and keeps the simplices it owns: those whose smallest vertex id is in its range, so
// that every simplex has exactly one owner. No thread waits for another until the blocks are
// joined, and no thread records for the others: this is what lets the search scale with the
// cores, where one writer of the simplices, the facet table and the queue would not.
//
// The output does not depend on the cut: every simplex is written in its canonical form (its
// vertex ids in increasing order, the first two exchanged when that order is negatively
// oriented) and the simplices in increasing order of those forms. A block's simplices have
// their smallest id in its range, so each block sorts its own (a counting sort by smallest id)
// and the blocks are joined in range order. Each simplex comes from the exact search under the
// one perturbation, so the simplices are those of any other construction; their order and
// their vertices' order are then the same for every thread count.
//
// Neighbours: a block links the simplices found on both sides of each facet through its
// points (its facet table knows both sides). A facet whose other side is owned by another
// block, or that holds none of the block's points, is matched after the join, by sorting those
// facets alone: they lie along the blocks' boundaries, a small part of all the facets.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "delaunay/facet_search.hpp"
#include "delaunay/first_facet.hpp"
#include "delaunay/point_store.hpp"
#include "delaunay/search_options.hpp"
#include "delaunay/team.hpp"
#include "drange/delaunay.hpp"

namespace drange::engine {

// What the blocks counted.
struct BlockSearchTotals {
  SearchCounters counters;
  std::size_t hull_facets = 0;
  std::size_t max_open_facets = 0;  // the largest of any block
  std::vector<double> seconds_busy;  // per thread: its blocks' wrappings and sorts
  double seconds_join = 0;           // the join, on the calling thread
};

// Every simplex of the points' Delaunay triangulation, in engine ids, into result.simplices in
// the canonical order above; with `neighbors`, result.neighbors (-1 on the hull). `blocks`: how
// many ranges the points are cut into (at least 1); the output is the same for every count.
// `progress` (Options::progress) is called on the calling thread only, with each multiple of
// kProgressInterval that the simplices found by all blocks pass while that thread wraps; an
// exception from it stops every block and reaches the caller.
BlockSearchTotals search_in_blocks(const PointStore& points, const FirstFacet& first, const SearchOptions& options,
                                   Team& team, int blocks, bool neighbors,
                                   const std::function<void(std::size_t)>& progress, Triangulation& result);

}  // namespace drange::engine
