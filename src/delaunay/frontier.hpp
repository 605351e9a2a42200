// delaunay/frontier.hpp: steps 2 and 4 of the driver (triangulate.cpp): the open facets, in
// their queue and in the facet table, and the simplices found, with their neighbours. Every
// thread count shares this part and only the calling thread runs it, in the serial order; the
// searches that feed it are triangulate.cpp's serial loops or, with threads, SearchPipeline.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "delaunay/facet_queue.hpp"
#include "delaunay/facet_table.hpp"
#include "delaunay/first_facet.hpp"
#include "delaunay/simplex_estimate.hpp"
#include "drange/delaunay.hpp"
#include "drange/errors.hpp"
#include "util/cache_size.hpp"

namespace drange::engine {

// Calls Options::progress every kProgressInterval simplices, counting down so that the main
// loop pays one decrement and one test per simplex (no clock read: the callback reads its own
// clock, at most once per call).
class ProgressCountdown {
 public:
  explicit ProgressCountdown(const std::function<void(std::size_t)>& report) : report_(report) {}
  void simplex_found(std::size_t found) {
    if (--countdown_ != 0) return;
    countdown_ = kProgressInterval;
    if (report_) report_(found);
  }

 private:
  const std::function<void(std::size_t)>& report_;
  std::size_t countdown_ = kProgressInterval;
};

// The open facets (section 2.3) and the simplices found (2.5): the part of the driver that
// every thread count shares, run by the calling thread only. Facets leave the queue in its
// order (Queue: FacetQueue, FIFO, or SpatialFacetQueue); when its turn comes, a facet is either
// closed already (the simplex on its other side was found while it waited) or gets the result
// of its search, which close() records.
template <class Queue>
class Frontier {
 public:
  // `record_neighbors` false: Triangulation::neighbors stays empty (Options::compute_neighbors),
  // and the turns skip its writes, one of them to the row of a simplex found long before.
  Frontier(int d, std::int32_t points, Triangulation& result, const std::function<void(std::size_t)>& progress, Queue queue,
           bool record_neighbors = true)
      : d_(d),
        width_(d + 1),
        simplices_(result.simplices),
        neighbors_(result.neighbors),
        stats_(result.stats),
        table_(d),
        queue_(std::move(queue)),
        progress_(progress),
        cached_table_bytes_(util::level2_cache_bytes(kDefaultCachedTableBytes)),
        record_neighbors_(record_neighbors),
        points_(points),
        max_simplices_(engine::simplex_upper_bound(d, static_cast<std::size_t>(points))) {
    // Room for the simplices up front (simplex_estimate.hpp): growing by doubling copies them
    // all once more, on the calling thread, and sets the peak memory in high dimensions.
    const auto width = static_cast<std::size_t>(width_);
    const std::size_t room =
        engine::reservable_simplices(engine::expected_simplices(d, static_cast<std::size_t>(points)), width, 2);
    simplices_.reserve(room * width);
    if (record_neighbors_) neighbors_.reserve(room * width);
  }

  void open_first(const engine::FirstFacet& first) {
    queue_.push(first.ids.data(), engine::facet_hash(first.ids.data(), d_), engine::FacetOwner{-1, -1, 0}, first.sigma, -1);
  }
  bool queue_empty() const { return queue_.empty(); }
  // Takes the next facet of the queue; returns whether it was closed while it waited. With
  // threads, `window` is its position in the search window, where it stays until release().
  bool pop(std::int32_t* ids, FacetInfo& info, std::int64_t window = -1) { return queue_.pop(ids, info, window); }
  void release(const FacetInfo& info) { queue_.release(info.owner.entry); }
  // Asks the cache for the table slot that a later take() or close() of this facet reads,
  // when the table has outgrown the cache (a small frontier, as in 2D, stays cached, and
  // there the prefetches would only add work).
  void prefetch(const FacetInfo& info) const {
    if (table_outgrows_cache()) table_.prefetch(info.hash);
  }
  // The same for the facet `ahead` places after the next pop() (FIFO queue), if there is one.
  void prefetch_ahead(std::uint64_t ahead) const {
    std::uint32_t hash = 0;
    if (table_outgrows_cache() && queue_.hash_ahead(ahead, hash)) table_.prefetch(hash);
  }
  // Asks the cache for the table slots that close() reads for a simplex's other facets
  // (`derived`: derive_other_facets' block), so that work done before close() hides the misses.
  // The callers of close() ask, each as early as its order allows.
  void prefetch_derived(const std::int32_t* derived) const {
    if (!table_outgrows_cache()) return;
    const std::int32_t* hash = derived + d_ * d_ + d_;
    for (int f = 0; f < d_; ++f) table_.prefetch(static_cast<std::uint32_t>(hash[f]));
  }
  // Asks the cache for the neighbour entry of the facet's owner that close() writes: the owner
  // was found many turns ago, and its row has usually left the cache.
  void prefetch_owner(const FacetInfo& info) const {
    if (!record_neighbors_ || info.owner.simplex < 0) return;
    __builtin_prefetch(&neighbors_[static_cast<std::size_t>(info.owner.simplex) * static_cast<std::size_t>(width_) +
                                   static_cast<std::size_t>(info.owner.face)], 1);
  }
  // A facet's turn, in queue order: false when it was closed while it waited (it needs no
  // search); otherwise it leaves the table, and close() must follow with its search's result.
  // Statistics::Debug::max_open_facets counts the open facets as each turn begins.
  bool take(const std::int32_t* ids, const FacetInfo& info, bool closed) {
    count_open_facets(0);
    return take_uncounted(ids, info, closed);
  }
  // take() for a turn taken before the previous turn's simplex is recorded (the spatial serial
  // loop): its count comes after that recording, by count_open_facets(1 if it left the table).
  bool take_uncounted(const std::int32_t* ids, const FacetInfo& info, bool closed) {
    if (closed) return false;
    if (info.owner.simplex < 0 || table_.remove(ids, info.hash)) return true;
    if (mark_closures_) throw InternalError("delaunay: a queued facet is not open");
    return false;  // closed while it waited
  }
  void count_open_facets(std::size_t taken) {
    stats_.debug.max_open_facets = std::max(stats_.debug.max_open_facets, table_.size() + taken);
  }
  // Threads > 1: mark the facets that close while they wait (in the queue, or in
  // closed_after_pop() once they left it). Queues whose marks are cheap (FacetQueue) are marked
  // on one thread too; the serial loop of the spatial queue finds its closed facets by the
  // table lookup that take() makes anyway, since marking its entries would write to a random
  // place of the queue for every closure (a cache miss each on a large 3D frontier).
  void mark_closures() { mark_closures_ = true; }
  // Records the search's result for a facet that take() accepted: the apex, or -1 on the hull;
  // with an apex, `derived` is derive_other_facets' block.
  void close(const std::int32_t* ids, const FacetInfo& info, std::int32_t apex, const std::int32_t* derived);
  // The window positions of the facets closed by close() that had already left the queue
  // (threads > 1: they wait in the search window); the caller marks them and clears the list.
  std::vector<std::uint64_t>& closed_after_pop() { return closed_after_pop_; }
  bool table_empty() const { return table_.size() == 0; }

 private:
  // A core's L2 cache (util/cache_size.hpp), 1 MiB where the system does not tell: a table
  // larger than that misses the cache at most lookups, and its slots are then worth
  // prefetching; a smaller one stays cached, and prefetches would only add work.
  static constexpr std::size_t kDefaultCachedTableBytes = std::size_t{1} << 20;
  bool table_outgrows_cache() const { return table_.memory_bytes() > cached_table_bytes_; }

  int d_, width_;
  std::vector<std::int32_t>& simplices_;
  std::vector<std::int32_t>& neighbors_;
  Statistics& stats_;
  engine::FacetTable table_;
  Queue queue_;
  ProgressCountdown progress_;
  std::vector<std::uint64_t> closed_after_pop_;
  bool mark_closures_ = Queue::kMarksCheaply;
  std::size_t cached_table_bytes_;  // table_outgrows_cache()
  bool record_neighbors_;
  // More simplices than this for `points_` points: a search returned a wrong apex
  // (simplex_estimate.hpp).
  std::int32_t points_;
  std::size_t max_simplices_;
};

template <class Queue>
void Frontier<Queue>::close(const std::int32_t* ids, const FacetInfo& info, std::int32_t apex, const std::int32_t* derived) {
  if (apex < 0) {
    ++stats_.hull_facets;
    return;
  }
  const engine::FacetOwner owner = info.owner;
  const auto width = static_cast<std::size_t>(width_);
  // The new simplex: the facet's vertices, then the apex, whose orientation is sigma; one
  // transposition of the first two vertices makes it positive.
  const auto s = static_cast<std::int32_t>(simplices_.size() / width);
  if (static_cast<std::size_t>(s) >= max_simplices_)
    throw InternalError("delaunay: more than " + std::to_string(max_simplices_) + " simplices, the most that " +
                        std::to_string(points_) + " points in " + std::to_string(d_) +
                        " dimensions can have (a search returned a wrong apex)");
  const std::size_t base = simplices_.size();
  const bool swapped = info.sigma < 0;
  for (int i = 0; i < d_; ++i) simplices_.push_back(ids[i]);
  simplices_.push_back(apex);
  if (swapped) std::swap(simplices_[base], simplices_[base + 1]);
  if (record_neighbors_) {
    for (int i = 0; i < d_; ++i) neighbors_.push_back(-1);
    neighbors_.push_back(owner.simplex);
    if (owner.simplex >= 0) neighbors_[static_cast<std::size_t>(owner.simplex) * width + static_cast<std::size_t>(owner.face)] = s;
  }
  if (owner.simplex < 0) ++stats_.hull_facets;  // the first facet lies on the hull
  // The other facets, facet f omitting vertex f: closed when open already, else opened.
  const int d = d_;
  const std::int32_t* open_side = derived + d * d;
  const std::int32_t* hash = open_side + d;
  for (int f = 0; f < d; ++f) {
    const std::int32_t* other = derived + f * d;
    engine::FacetOwner seen{};
    const engine::FacetOwner mine{s, f, queue_.next_entry()};
    if (table_.close_or_open(other, static_cast<std::uint32_t>(hash[f]), mine, &seen)) {
      if (record_neighbors_) {
        neighbors_[base + static_cast<std::size_t>(f)] = seen.simplex;
        neighbors_[static_cast<std::size_t>(seen.simplex) * width + static_cast<std::size_t>(seen.face)] = s;
      }
      std::uint64_t window = 0;
      if (mark_closures_ && !queue_.mark_closed(seen.entry, window)) closed_after_pop_.push_back(window);
    } else {
      queue_.push(other, static_cast<std::uint32_t>(hash[f]), mine, open_side[f], simplices_[base + static_cast<std::size_t>(f)]);
    }
  }
  progress_.simplex_found(static_cast<std::size_t>(s) + 1);
}

}  // namespace drange::engine
