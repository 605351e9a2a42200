// delaunay/triangulate.cpp: the D-Range driver (paper, sections 2.1 to 2.5).
//
//   1. the first facet, by gift wrapping (first_facet.hpp);
//   2. open facets in a queue and in the facet table keyed by sorted ids (facet_table.hpp);
//   3. for each open facet, the point that closes it into a Delaunay simplex (facet_search.hpp);
//   4. each new simplex is recorded, positively oriented; its other facets are opened, or closed
//      when already open, and closing a facet links the two simplices as neighbours (2.5).
// The queue (facet_queue.hpp) is the paper's FIFO or, by default in 3D to 5D, the spatial order
// (SearchOptions::facet_order): least smallest vertex id first, the ids following the kd-tree,
// so that the frontier sweeps through space and stays several times smaller than FIFO's
// growing ball, which keeps the facet table in cache (docs/algorithm.md). Under the spatial order
// the facets leave the queue in batches into a fixed window ahead of their turns (Lookahead),
// the same for every thread count; the order of the turns, and so the output, depends on that
// window and on nothing else. With Options::threads > 1, step 3 runs ahead on helper threads
// (SearchPipeline, search_pipeline.hpp), and the sort, the kd-tree and the first facet's scans
// are split between the threads; steps 2 and 4 (Frontier, frontier.hpp) stay on the calling
// thread, in the serial order, so the output does not change. In 2D and 3D the search runs
// instead as blocks of points that the threads wrap on their own (block_search.hpp), each with
// its own facet table and queue, the output in a canonical order that does not depend on the
// cut; the serial loops serve there the choice's probe and the variants that fix an order.
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "delaunay/algorithm_choice.hpp"
#include "delaunay/block_search.hpp"
#include "delaunay/derived_facets.hpp"
#include "delaunay/facet_queue.hpp"
#include "delaunay/facet_search.hpp"
#include "delaunay/first_facet.hpp"
#include "delaunay/frontier.hpp"
#include "delaunay/incremental/bowyer_watson.hpp"
#include "delaunay/incremental/insertion_order.hpp"
#include "delaunay/prepare_points.hpp"
#include "delaunay/search_pipeline.hpp"
#include "delaunay/team.hpp"
#include "delaunay/triangulate.hpp"
#include "drange/delaunay.hpp"
#include "drange/errors.hpp"
#include "geometry/predicates.hpp"
#include "util/for_ranges.hpp"

namespace drange {
namespace {

using engine::derive_other_facets;
using engine::derived_block_size;
using engine::FacetInfo;
using engine::FacetOrder;
using engine::FacetQueue;
using engine::Frontier;
using engine::Lookahead;
using engine::SearchOptions;
using engine::SearchPipeline;
using engine::SearchTotals;
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

std::size_t peak_rss_bytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<std::size_t>(usage.ru_maxrss) * 1024;  // Linux reports kilobytes
}

// The spatial order's parameters, chosen from measurements (docs/performance.md). Keys are the
// smallest vertex id >> 3, blocks of 8 points: smaller blocks gained nothing on uniform points,
// larger ones lost on grids, and 8 keeps the bucket array at one int per point. The window is
// the FIFO pipeline's for 2 threads; batches of 2 runs (256) waste about half the searches of
// batches of 1 run on 2 threads, and batches of single facets would cost the calling thread a
// window update per turn.
constexpr int kSpatialBlockShift = 3;
constexpr Lookahead kSpatialLookahead{1024, 256};

// Whether the facets take their turns in the spatial order in dimension d. `automatic`: where
// it is faster, 3D to 5D; not in 2D, where FIFO's frontier is small already (the two are level),
// nor from 6D on, where the frontier is a large part of the triangulation whatever the order.
bool spatial_order(FacetOrder order, int d) {
  if (order == FacetOrder::automatic) return d >= 3 && d <= 5;
  return order == FacetOrder::spatial;
}

// How many turns ahead the serial loops ask the cache for a facet's table slot, which its
// take() reads: on a large frontier each lookup is a miss, and about half the facets popped
// were closed while they waited, so their turn is only that lookup.
constexpr std::uint64_t kPrefetchAhead = 4;

// The blocks of the direct search (block_search.hpp): one on one thread; otherwise four per
// thread, taken in turn, so that a thread that finishes early takes another and the join's
// peak memory holds one small block beyond the result; none with fewer than kMinBlockPoints
// points (a block's walk from the first facet and its boundary cost more than a small block
// saves). The output does not depend on the count.
constexpr std::int32_t kMinBlockPoints = 4096;
int block_count(const engine::Team& team, std::int32_t points) {
  const std::int32_t wanted = team.threads() == 1 ? 1 : 4 * team.threads();
  return static_cast<int>(std::max<std::int32_t>(1, std::min<std::int32_t>(wanted, points / kMinBlockPoints)));
}

// Whether the direct search runs in blocks: in 2D and 3D, where a block's star wrapping costs
// what the whole search does per simplex and its boundary little (from 4D on, stars are large
// and a block's boundary holds a large part of its simplices: the searches are spread over
// the threads by the pipeline instead); not for the choice's budgeted probe, nor when a
// --variant fixes the facet order (fifo, spatial: the order is what they measure).
bool in_blocks(const SearchOptions& options, int d, std::uint64_t work_budget) {
  return d <= 3 && work_budget == 0 && options.facet_order == FacetOrder::automatic;
}

// One thread, FIFO: each facet searched when its turn comes, taken out of the queue then.
// kBudgeted: the run stops at SearchTotals::budget (the choice's probe); a template argument,
// so that every other run's loop carries no test of it.
template <bool kBudgeted>
void search_serially(Frontier<FacetQueue>& frontier, engine::FacetSearch& search, int d, SearchTotals& totals) {
  std::vector<std::int32_t> ids(static_cast<std::size_t>(d)), derived(derived_block_size(d));
  FacetInfo info{};
  const std::uint64_t exact_before = geometry::exact_evaluations();
  while (!frontier.queue_empty()) {
    const bool closed = frontier.pop(ids.data(), info);
    frontier.prefetch_ahead(kPrefetchAhead);
    if (!frontier.take(ids.data(), info, closed)) continue;
    frontier.prefetch_owner(info);
    const std::int32_t apex = search.find_apex(ids.data(), info.sigma, totals.counters);
    if constexpr (kBudgeted) totals.check_budget();
    if (apex >= 0) {
      derive_other_facets(ids.data(), info.sigma, apex, d, derived.data());
      frontier.prefetch_derived(derived.data());
    }
    frontier.close(ids.data(), info, apex, derived.data());
  }
  totals.exact = geometry::exact_evaluations() - exact_before;
}

// Whether `facet` (of hash `hash`) is one of the facets in derive_other_facets' `block`.
bool is_derived(const std::int32_t* facet, std::uint32_t hash, const std::int32_t* block, int d) {
  const std::int32_t* hashes = block + d * d + d;
  for (int f = 0; f < d; ++f)
    if (static_cast<std::uint32_t>(hashes[f]) == hash && std::equal(facet, facet + d, block + f * d)) return true;
  return false;
}

// One thread, spatial order: the same, but the facets leave the queue ahead of their turn,
// into a ring, by the pipeline's rule (Lookahead), on which the order depends. (The loop
// above is this one with a lookahead of 1, without the ring and its bookkeeping; FIFO's queue
// marks the facets closed while they wait, which a ring of facets out of the queue would not
// see.) Each turn's
// simplex is recorded one turn late: the next facet's turn (its table lookup and search) runs
// first, while the table slots that the recording reads (prefetched when the simplex's facets
// were derived) arrive from memory. The two touch different facets of the table, except when
// the next facet is one of the simplex's: then the recording comes first. The turns, and so
// the output, are those of a recording in turn. kBudgeted: as above.
template <bool kBudgeted>
void search_serially(Frontier<engine::SpatialFacetQueue>& frontier, engine::FacetSearch& search, int d, Lookahead lookahead,
                     SearchTotals& totals) {
  const std::size_t ahead = lookahead.size;
  const auto width = static_cast<std::size_t>(d);
  std::vector<std::int32_t> ids(ahead * width), derived(derived_block_size(d));
  std::vector<FacetInfo> info(ahead);
  std::vector<char> closed(ahead);
  // The turn whose simplex waits to be recorded: its ring slot and apex (its facets wait in
  // `derived`, which is written again only after the recording).
  struct Late {
    bool waiting = false;
    std::size_t slot = 0;
    std::int32_t apex = -1;
  } late;
  const auto record_late = [&] {
    if (!late.waiting) return;
    frontier.close(&ids[late.slot * width], info[late.slot], late.apex, derived.data());
    late.waiting = false;
  };
  const std::uint64_t exact_before = geometry::exact_evaluations();
  for (std::size_t turn = 0, filled = 0;; ++turn) {
    const std::size_t s = turn & (ahead - 1);  // ahead: a power of two
    const std::int32_t* facet = &ids[s * width];
    // This turn's facet, when it is in the ring already and the late recording does not touch
    // it (it is not among the late simplex's facets, the only ones that recording opens or
    // closes), is taken and searched before that recording.
    const bool early = turn < filled && !(late.waiting && late.apex >= 0 && is_derived(facet, info[s].hash, derived.data(), d));
    bool taken = early && frontier.take_uncounted(facet, info[s], closed[s] != 0);
    if (taken) frontier.prefetch_owner(info[s]);
    std::int32_t apex = taken ? search.find_apex(facet, info[s].sigma, totals.counters) : -1;
    record_late();
    if (early) frontier.count_open_facets(taken ? 1 : 0);
    // The pipeline's rule: before turn t, if a batch fits, the facets up to t + ahead leave the
    // queue (the ring's slot of turn t - 1, recorded above, is the last one refilled).
    if (filled + lookahead.batch <= turn + ahead)
      for (; filled < turn + ahead && !frontier.queue_empty(); ++filled) {
        const std::size_t f = filled & (ahead - 1);
        closed[f] = frontier.pop(&ids[f * width], info[f]);
      }
    if (turn == filled) break;
    if (turn + kPrefetchAhead < filled) frontier.prefetch(info[(turn + kPrefetchAhead) & (ahead - 1)]);
    if (!early) {
      taken = frontier.take(facet, info[s], closed[s] != 0);
      if (taken) {
        frontier.prefetch_owner(info[s]);
        apex = search.find_apex(facet, info[s].sigma, totals.counters);
      }
    }
    if (!taken) continue;
    if constexpr (kBudgeted) totals.check_budget();
    if (apex >= 0) {
      derive_other_facets(facet, info[s].sigma, apex, d, derived.data());
      frontier.prefetch_derived(derived.data());
    }
    late = Late{true, s, apex};
  }
  totals.exact = geometry::exact_evaluations() - exact_before;
}

// Step 3 from the first facet to the end, on the team's threads. `lookahead`: see SearchPipeline.
template <class Queue>
void search(Frontier<Queue>& frontier, const engine::FirstFacet& first, const engine::PointStore& points,
            const SearchOptions& options, engine::Team& team, Lookahead lookahead, SearchTotals& totals) {
  frontier.open_first(first);
  if (team.threads() == 1) {
    engine::FacetSearch search(points, options);
    const bool budgeted = totals.budget != 0;
    if constexpr (std::is_same_v<Queue, FacetQueue>) {
      if (budgeted) search_serially<true>(frontier, search, points.dim, totals);
      else search_serially<false>(frontier, search, points.dim, totals);
    } else {
      if (budgeted) search_serially<true>(frontier, search, points.dim, lookahead, totals);
      else search_serially<false>(frontier, search, points.dim, lookahead, totals);
    }
  } else {
    frontier.mark_closures();
    SearchPipeline<Queue> pipeline(points, options, team.threads(), frontier, lookahead);
    pipeline.run(team, totals);
  }
  if (!frontier.table_empty()) throw InternalError("delaunay: open facets left after the search");
}

}  // namespace

Triangulation engine::triangulate(PointsView input, const Options& options, const SearchOptions& search_options,
                                  Algorithm algorithm, std::uint64_t work_budget) {
  const auto start = Clock::now();
  const std::uint64_t exact_before = geometry::exact_evaluations();
  Triangulation result;
  result.dim = input.dim;
  result.num_points = input.n;
  Statistics& stats = result.stats;
  stats.points = input.n;
  if (options.threads < 0) throw UsageError("threads must be 0 (all hardware threads) or a positive count, got " + std::to_string(options.threads));
  stats.threads = static_cast<std::size_t>(engine::resolve_threads(options.threads));
  engine::Team team(static_cast<int>(stats.threads));

  // Every search thread reads the store's fields for every node and point it visits: they get
  // cache lines of their own, away from the locals below that the calling thread keeps writing
  // (a precaution against false sharing).
  struct alignas(64) SharedPoints {
    engine::PointStore store;
  };
  const auto shared_points = std::make_unique<const SharedPoints>(SharedPoints{engine::prepare_points(input, engine::search_leaf_size(input.dim), result.duplicates, team, search_options)});
  const engine::PointStore& points = shared_points->store;
  const int d = points.dim;
  const int width = d + 1;
  stats.distinct_points = static_cast<std::size_t>(points.size);
  stats.debug.shell_spheres = static_cast<std::size_t>(points.shell.spheres());
  stats.seconds_kdtree = seconds_since(start);

  auto phase = Clock::now();
  const engine::FirstFacet first = engine::find_first_facet(points, team);
  stats.seconds_first_facet = seconds_since(phase);
  // Exact evaluations before the search, on every thread.
  const std::uint64_t exact_setup = geometry::exact_evaluations() - exact_before + team.helper_exact_evaluations();

  phase = Clock::now();
  if (algorithm == Algorithm::automatic && !engine::worth_probing(points)) algorithm = Algorithm::direct;
  // The insertion order serves both the choice's sample and the incremental kernel.
  const std::vector<std::int32_t> order =
      algorithm == Algorithm::direct ? std::vector<std::int32_t>{} : engine::insertion_order(points);
  const bool incremental = algorithm == Algorithm::incremental ||
                           (algorithm == Algorithm::automatic && engine::prefer_incremental(points, order));
  stats.algorithm = incremental ? "incremental" : "direct";
  stats.seconds_choice = seconds_since(phase);

  phase = Clock::now();
  std::vector<std::int32_t>& simplices = result.simplices;
  SearchTotals totals;
  totals.budget = team.threads() == 1 ? work_budget : 0;
  if (incremental) {
    const engine::IncrementalCounters counters =
        engine::triangulate_incrementally(points, first, order, result, options.compute_neighbors, options.progress);
    totals.counters.calls = counters.walk_steps;
    totals.counters.points_tested = counters.conflict_tests;
    stats.debug.unfiltered_tests = counters.unfiltered_tests;
  } else if (in_blocks(search_options, d, work_budget)) {
    const std::uint64_t helpers_exact = team.helper_exact_evaluations(), exact = geometry::exact_evaluations();
    const engine::BlockSearchTotals blocks = engine::search_in_blocks(
        points, first, search_options, team, block_count(team, points.size), options.compute_neighbors, options.progress, result);
    totals.exact = geometry::exact_evaluations() - exact + team.helper_exact_evaluations() - helpers_exact;
    totals.counters = blocks.counters;
    stats.seconds_busy = blocks.seconds_busy;
    stats.seconds_critical_path = *std::max_element(blocks.seconds_busy.begin(), blocks.seconds_busy.end()) + blocks.seconds_join;
    stats.hull_facets = blocks.hull_facets;
    stats.debug.max_open_facets = blocks.max_open_facets;
  } else if (spatial_order(search_options.facet_order, d)) {
    Frontier<engine::SpatialFacetQueue> frontier(d, points.size, result, options.progress,
                                                 engine::SpatialFacetQueue(d, points.size, kSpatialBlockShift),
                                                 options.compute_neighbors);
    search(frontier, first, points, search_options, team, kSpatialLookahead, totals);
  } else {
    Frontier<FacetQueue> frontier(d, points.size, result, options.progress, FacetQueue(d), options.compute_neighbors);
    search(frontier, first, points, search_options, team, Lookahead{0, 0}, totals);
  }
  stats.seconds_search = seconds_since(phase);
  if (stats.seconds_busy.empty()) {  // one loop: the calling thread's is the critical path
    stats.seconds_busy = {stats.seconds_search};
    stats.seconds_critical_path = stats.seconds_search;
  }

  // Back to the caller's numbering: one lookup per vertex of every simplex, on the threads.
  util::for_ranges(simplices.size(), team, [&](std::size_t, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
      simplices[i] = points.input_index[static_cast<std::size_t>(simplices[i])];
  });
  stats.simplices = simplices.size() / static_cast<std::size_t>(width);
  stats.search_calls = totals.counters.calls;
  stats.debug.points_tested = totals.counters.points_tested;
  stats.debug.candidates = totals.counters.candidates;
  stats.debug.exact_fallbacks = exact_setup + totals.exact;
  stats.debug.wasted_searches = totals.wasted;
  stats.seconds_total = seconds_since(start);
  stats.peak_rss_bytes = peak_rss_bytes();
  if (options.progress) options.progress(stats.simplices);
  return result;
}

const char* algorithm_names() { return "auto, direct, incremental"; }

Triangulation delaunay(PointsView input, const Options& options) {
  const SearchOptions search_options = engine::search_variant(options.variant);
  const bool variant = options.variant != "full";
  if (options.algorithm == "incremental" && variant)
    throw UsageError("the variant '" + options.variant + "' measures the direct algorithm; it cannot be combined with algorithm 'incremental'");
  engine::Algorithm algorithm = engine::Algorithm::direct;
  if (options.algorithm == "incremental") algorithm = engine::Algorithm::incremental;
  else if (options.algorithm == "auto") algorithm = variant ? engine::Algorithm::direct : engine::Algorithm::automatic;
  else if (options.algorithm != "direct")
    throw UsageError("unknown algorithm '" + options.algorithm + "' (expected one of: " + algorithm_names() + ")");
  return engine::triangulate(input, options, search_options, algorithm);
}

}  // namespace drange
