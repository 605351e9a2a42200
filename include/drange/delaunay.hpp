// drange/delaunay.hpp: the Delaunay triangulation of points in E^d by the D-Range direct
// algorithm (Tereshchenko and Taran, "An approach for computing the Delaunay triangulation
// and the Voronoi diagram in E^d"), with exact predicates and a symbolic perturbation.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "drange/points.hpp"

namespace drange {

// The names Options::variant accepts, comma-separated, for help texts.
const char* variant_names();

// How often Options::progress is called: every kProgressInterval simplices found.
inline constexpr std::size_t kProgressInterval = std::size_t{1} << 16;

// The names Options::algorithm accepts, comma-separated, for help texts.
const char* algorithm_names();

struct Options {
  // The construction. "direct": the D-Range direct algorithm, a search for the point that
  // closes each open facet (the paper's). "incremental": the points inserted one by one in a
  // biased randomized order, each cavity of cells in conflict refilled (Bowyer-Watson), with the
  // same exact predicates and perturbation, whose work per simplex does not depend on the
  // input's shape. "auto" (the default): see docs/algorithm.md. Both give the same simplices, in
  // another order and numbering. A `variant` other than "full" measures the direct algorithm and
  // selects it; delaunay() throws UsageError for an unknown name, or "incremental" with such a
  // variant.
  std::string algorithm = "auto";
  // The name of an ablation variant, for measurements: "full" (the default, the whole
  // algorithm) or one with a step of the search left out or a fixed facet order (the paper's
  // own steps alone: "paper"; every name: variant_names()). Every variant gives the same
  // simplices; the facet-order ones ("fifo", "spatial", and "scan", "kdtree" and "paper",
  // which use the paper's FIFO order) change only their numbering and order. delaunay()
  // throws UsageError, naming the value and the accepted names, for an unknown name.
  std::string variant = "full";
  bool compute_neighbors = true;  // fill Triangulation::neighbors
  // Called from the computing thread every kProgressInterval simplices with the number of
  // simplices found so far, and once more when the triangulation is complete, with the final
  // count: that last call is the only one whose count is not a multiple of kProgressInterval
  // or repeats the previous count. The CLI draws its progress line with it. It may throw to
  // abandon the run: delaunay() then throws that exception. Empty: never called.
  std::function<void(std::size_t simplices)> progress;
  // Threads to use: 0 means one per hardware thread (std::thread::hardware_concurrency), 1 the
  // serial run. The result, simplex numbers included, is the same for every count; so are the
  // statistics of the result, not those of the work (the times, Statistics::search_calls and
  // Statistics::debug's counters). In 2D and 3D the points are cut into blocks that the
  // threads wrap on their own, and the simplices are listed in a canonical order that does
  // not depend on the cut; from 4D on the facets' searches run on helper threads, ahead of
  // the calling thread, which records the simplices in the serial order. Only the calling
  // thread calls `progress`. A program that runs several
  // triangulations at once on its own threads should give each 1 (or its share of the cores):
  // with 0, each call starts one thread per core, and the cores are oversubscribed.
  int threads = 0;
};

// One input point that is an exact copy of an earlier one; it is left out of the triangulation.
struct Duplicate {
  std::int64_t index;     // the copy (zero-based input index)
  std::int64_t original;  // the first input point with the same coordinates
};

struct Statistics {
  std::size_t points = 0;           // input points
  std::size_t distinct_points = 0;  // points after removing exact duplicates
  std::size_t simplices = 0;
  std::size_t hull_facets = 0;       // facets of the convex hull (their search found nothing)
  // kd-tree nodes entered by all searches: the paper's "Calls" numerator, kept here for that
  // reason although, like the debug counters, it depends on the variant and the threads. For
  // the incremental algorithm: the cells its walks entered.
  std::size_t search_calls = 0;
  std::size_t threads = 1;           // threads used (Options::threads resolved)
  std::string algorithm;             // the construction that ran: "direct" or "incremental"
  double seconds_kdtree = 0;         // building the kd-tree (including sorting and deduplication)
  double seconds_first_facet = 0;    // gift wrapping to the first facet
  double seconds_choice = 0;         // Options::algorithm "auto": the probe that chose the algorithm
  double seconds_search = 0;         // the main loop: searches, facet table, simplices and neighbours
  // The search's threads: each one's busy time (in 2D and 3D, its blocks' wrappings and
  // sorts; otherwise one entry, the search's loop), and the critical path: the busiest
  // thread's time plus what followed it on the calling thread (the blocks' join).
  std::vector<double> seconds_busy;
  double seconds_critical_path = 0;
  double seconds_total = 0;
  std::size_t peak_rss_bytes = 0;    // process peak resident memory at the end of the run

  // The engine's internal counters, for measuring and debugging the search: what they count
  // follows the implementation and changes with it.
  struct Debug {
    std::size_t points_tested = 0;    // points inside a query box (or ball), tested against the candidate sphere;
                                      // for the incremental algorithm, cells tested for conflict
    std::size_t candidates = 0;       // times a search's candidate point was set or improved
    std::size_t exact_fallbacks = 0;  // decisions left to the integer stage (fixed-width or GMP), set-up included
    std::size_t max_open_facets = 0;  // the largest frontier held in the facet table
    std::size_t shell_spheres = 0;    // spheres the points were found near (the sphere shell; 0: none, or a
                                      // variant without the shell, which is then not fitted)
    std::size_t wasted_searches = 0;  // searches run ahead by a thread for a facet closed before its turn; not
                                      // counted in search_calls, points_tested, candidates, exact_fallbacks
    std::size_t unfiltered_tests = 0; // incremental algorithm: signs its fast filters left to the exact stages
  } debug;

  // Search calls per simplex, the paper's "Calls" column of Table 1.
  double calls_per_simplex() const { return simplices ? double(search_calls) / double(simplices) : 0.0; }
  // One line, "key=value" pairs, for logs and the CLI's --stats (the debug counters included).
  std::string summary() const;
};

// The result, in flat arrays like scipy.spatial.Delaunay:
//   simplices[s*(d+1) + k]  vertex k of simplex s (zero-based input index); every simplex is
//                           positively oriented (det[v1-v0, ..., vd-v0] > 0);
//   neighbors[s*(d+1) + k]  the simplex opposite vertex k of simplex s, -1 on the hull.
struct Triangulation {
  int dim = 0;
  std::size_t num_points = 0;
  std::vector<std::int32_t> simplices;
  std::vector<std::int32_t> neighbors;
  std::vector<Duplicate> duplicates;
  Statistics stats;

  std::size_t size() const { return dim > 0 ? simplices.size() / static_cast<std::size_t>(dim + 1) : 0; }
  const std::int32_t* simplex(std::size_t s) const { return simplices.data() + s * static_cast<std::size_t>(dim + 1); }
};

// Computes the Delaunay triangulation of the points. Exact on every input: ties between
// cospherical points are broken by a symbolic perturbation that depends only on the
// coordinates, so any permutation of the input gives the same simplices.
// Throws InputError (NaN/infinite coordinate, a dimension outside 2..11, 2^31 points or more)
// or DegenerateInputError (fewer than d+1 distinct points, or all points in one hyperplane);
// UsageError for a negative Options::threads or an unknown Options::variant; InternalError
// when one of the engine's own invariants fails (a bug, such as more simplices than n points
// in E^d can have), rather than return a wrong triangulation.
Triangulation delaunay(PointsView points, const Options& options = {});

// The stars of the points `ids` (zero-based input indices): every simplex of delaunay(points)
// incident to one of them, each once, and no other, found without the rest of the
// triangulation (a walk to the points, taken in the kd-tree's order, then a wrapping of the
// facets through them alone: the cost after reading and the kd-tree grows with the stars, not
// with the input, whether they are few or most of it). The same simplices as in the full
// triangulation, as vertex sets; each positively oriented, once, in the order found.
// `neighbors` (Options::compute_neighbors) links the returned simplices among themselves: -1
// where the neighbour is on the hull or is not returned. An exact duplicate's id gives the star
// of the point it copies (the duplicate itself is in no simplex; Triangulation::duplicates
// lists them as delaunay() does). Options::threads speeds up the preparation only;
// Options::algorithm is checked and has no effect (the stars are always found by the direct
// search), Options::variant selects the search's steps. Statistics count this run's work:
// hull_facets is the hull facets through the given points. Throws UsageError naming an id
// out of range or given twice, and whatever delaunay() throws for the points.
Triangulation delaunay_stars(PointsView points, const std::vector<std::int64_t>& ids, const Options& options = {});

// One block of delaunay(points), for a computation split among `blocks` processes: the points
// are numbered in drange's own order (the kd-tree's, spatially coherent) and cut into `blocks`
// ranges of equal size; block `block` has every simplex whose smallest vertex in that order is
// in its range, found by wrapping the stars of its points (as delaunay_stars). Over the blocks
// every simplex of delaunay(points) comes exactly once, as the same vertex set, positively
// oriented. No neighbours (the blocks' union has them: the simplices sharing a facet).
// Statistics: points and distinct_points of the whole input, simplices of this block, the
// block's times and search work. Throws UsageError for a block outside 0..blocks-1, and what
// delaunay() throws for the points.
Triangulation delaunay_block(PointsView points, int block, int blocks, const Options& options = {});

// Fills t.neighbors from t.simplices alone: neighbour k of simplex s is the simplex that shares
// the facet opposite its vertex k, -1 where none does (for the union of delaunay_block's blocks:
// delaunay()'s neighbours, in that union's numbering).
void link_neighbours(Triangulation& t);

}  // namespace drange
