// cli/split_rounds.hpp: one process's part of a split triangulation. The points go to their
// blocks (cli/split_blocks.hpp), each with a ghost layer: copies of the points within a few mean
// spacings of the block. The process then wraps the stars of its own points among the points it
// holds (drange::delaunay_stars), in rounds: a point's star is final when every simplex in it
// and every hull facet through it is decided as in the whole input (cli/split_regions.hpp);
// for the others, the process asks the processes whose blocks meet the undecided regions for
// all their points there, and wraps those stars again, until no process has one left. It keeps
// the simplices whose smallest vertex (input index) is its own: every simplex is kept by
// exactly one process.
#pragma once

#include <cstdint>
#include <vector>

#include "agreement.hpp"
#include "drange/delaunay.hpp"
#include "processes.hpp"
#include "split_read.hpp"

namespace drange::cli {

struct SplitPart {
  std::vector<std::int32_t> simplices;  // input indices, each simplex positively oriented
  // Own exact copies: pairs of input indices (copy, original).
  std::vector<double> duplicates;
  std::size_t points_owned = 0;
  std::size_t ghost_points = 0;  // points held that belong to other blocks
  int rounds = 0;
  double seconds_search = 0;    // in delaunay_stars, over the rounds
  double bytes_sent = 0;        // points and requests sent to other processes
};

// Every process calls it (it exchanges points); failures stop all (Agreement).
SplitPart triangulate_share(PointShare share, const Processes& group, const Agreement& agree, const Options& options);

}  // namespace drange::cli
