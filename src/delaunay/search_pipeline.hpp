// delaunay/search_pipeline.hpp: step 3 of the driver (triangulate.cpp) on several threads: the
// searches run ahead of the turns on every thread, in a window of the queue, while the calling
// thread takes the turns in the serial order (SearchPipeline, below). With the two types that
// triangulate.cpp's serial loops share with it: Lookahead, the rule by which facets leave the
// queue, and SearchTotals, what the searches add to the statistics.
#pragma once

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "delaunay/closure_predictor.hpp"
#include "delaunay/derived_facets.hpp"
#include "delaunay/facet_queue.hpp"
#include "delaunay/facet_search.hpp"
#include "delaunay/frontier.hpp"
#include "delaunay/point_store.hpp"
#include "delaunay/seed_memory.hpp"
#include "delaunay/team.hpp"
#include "drange/delaunay.hpp"
#include "drange/errors.hpp"
#include "geometry/predicates.hpp"

namespace drange::engine {

// The facets taken out of the queue ahead of their turn: up to `size` (a power of two) ahead,
// in batches of `batch` facets, each taken out as soon as it fits. For the spatial order both
// are fixed, so that every thread count takes the facets in the same order; for FIFO, where
// the order does not depend on them, size 0 lets SearchPipeline size the window by threads.
struct Lookahead {
  std::size_t size, batch;
};

// What the searches of the facets that were used add to the statistics.
// Thrown by the serial loops when a run exceeds SearchTotals::budget (algorithm_choice.cpp's
// probe, which needs to know only that the work is large).
struct WorkBudgetExceeded {};

struct SearchTotals {
  engine::SearchCounters counters;
  std::uint64_t exact = 0;   // exact predicate evaluations
  std::uint64_t wasted = 0;  // searches whose facet was closed before its turn (threads > 1)
  // On one thread: the kd-tree nodes entered plus points tested beyond which the run stops,
  // throwing WorkBudgetExceeded; 0, none.
  std::uint64_t budget = 0;
  void check_budget() const {
    if (budget != 0 && counters.calls + counters.points_tested > budget) throw WorkBudgetExceeded{};
  }
  void add(const engine::SearchCounters& c, std::uint64_t exact_evaluations) {
    counters.calls += c.calls;
    counters.points_tested += c.points_tested;
    counters.candidates += c.candidates;
    exact += exact_evaluations;
  }
};

// Several threads (Options::threads > 1). The calling thread runs the serial loop's order
// unchanged: facets take their turns in queue order, and it alone records the simplices (the
// facet table, the queue, the simplices and neighbours are its own). The searches are
// read-only (points and kd-tree are shared; each thread has its own FacetSearch scratch, and
// the seeds, hints that never change a result, are shared: seed_memory.hpp) and a
// facet's result depends on that facet only, so they can run ahead: the facets next in the
// queue are copied into a window, a ring of slots, where every thread (the calling one too,
// between the turns it records) claims runs of consecutive facets, searches them in order and
// leaves the results. The output is the serial loop's, simplex numbers included, for every
// thread count; so are the statistics, since only the searches of facets open at their turn
// are counted, exactly those the serial loop makes, except the searches' work counters (points
// tested, candidates): the shared seeds arrive in the order the threads happen to find them.
//
// When facets leave the queue matters for the spatial order (a facet opened meanwhile with a
// smaller key would go first), not for FIFO. So under FIFO the window grows with the thread
// count and is topped up whenever a run fits; under the spatial order it is the Lookahead,
// the serial loop's too: 1024 facets, topped up by batches of 256, for every thread count.
//
// A facet searched ahead can turn out to be closed at its turn (the serial loop would not have
// searched it): a wasted search, counted in Statistics::Debug::wasted_searches. Three things keep
// these few: facets closed before they enter the window carry the queue's mark; facets
// closed in the window get a flag that a thread reads before searching; and each thread
// predicts the closures that its own recent simplices imply (ClosurePredictor). What remains
// are facets closed by a simplex another thread is finding at the same moment.
template <class Queue>
class SearchPipeline {
 public:
  // `lookahead`: size 0 for FIFO, the window then sized here by the thread count; for the
  // spatial order, the fixed window and batch that define the order.
  SearchPipeline(const engine::PointStore& points, const SearchOptions& options, int threads, Frontier<Queue>& frontier,
                 Lookahead lookahead)
      : d_(points.dim),
        threads_(threads),
        whole_runs_(points.dim <= 3),
        points_(points),
        options_(options),
        frontier_(frontier),
        seeds_(options.seed_candidate ? points.size : 0, points.dim) {
    std::size_t window = lookahead.size;
    if (window == 0) {
      window = 64;
      while (window < kRunsPerThread * kRun * static_cast<std::size_t>(threads)) window *= 2;
      refill_step_ = run_;
    } else {
      // Runs short enough for kRunsPerThread each in the window (more than 2 threads).
      while (run_ > 16 && kRunsPerThread * run_ * static_cast<std::size_t>(threads) > window) run_ /= 2;
      refill_step_ = lookahead.batch;
    }
    mask_ = window - 1;
    ids_.resize(window * static_cast<std::size_t>(d_));
    info_.resize(window);
    results_.resize(window);
    derived_.resize(window * derived_block_size(d_));
    closed_.reset(new std::atomic<bool>[window]);
    done_.reset(new std::atomic<std::uint64_t>[window]);
    run_end_.reset(new std::atomic<std::uint64_t>[window]);
    for (std::size_t i = 0; i < window; ++i) {
      closed_[i].store(false, std::memory_order_relaxed);
      done_[i].store(0, std::memory_order_relaxed);
      run_end_[i].store(0, std::memory_order_relaxed);
    }
  }

  void run(engine::Team& team, SearchTotals& totals) {
    team.run(
        threads_,
        [&](int rank) {
          // Each thread makes its own tools: their memory then comes from its own allocator
          // arena, and no two threads write to one cache line while they search.
          Worker worker(points_, options_, seeds_, d_);
          if (rank == 0) {
            lead(worker, totals);
            stop();  // done: the helpers return
          } else {
            help(worker);
          }
        },
        [&] { stop(); });
  }

 private:
  // Facets claimed at once. Long runs keep a thread's searches together: facets next to each
  // other in the queue are next to each other in space, and a search reads the kd-tree nodes
  // and points that the previous one brought into its core's cache. Short runs make the
  // threads alternate so often that each search misses the other core's cache lines. Long
  // runs (up to kRun under FIFO; the spatial order's fixed window keeps them shorter) also
  // waste fewer searches: the facets a thread closes are more often in its own run, where its
  // closure predictor sees them.
  static constexpr std::uint64_t kRun = 512;
  // But a claim takes no more of the unclaimed facets than one run's worth of a window of
  // kRunsPerThread runs per thread, and no fewer than this: on a short frontier, one long run
  // would take all the window holds and leave the other threads waiting.
  static constexpr std::uint64_t kLeastRun = 128;
  // The window, in runs per thread: enough that a thread rarely finds every facet of the window
  // claimed while the turn waits for a run still being searched. The longer the window, the
  // more searches are wasted (a closure flag comes too late more often).
  static constexpr std::size_t kRunsPerThread = 4;
  static constexpr int kSpins = 256;  // pauses before yielding or sleeping
  enum class Outcome : std::uint8_t { closed, predicted, searched };
  struct Result {  // from the thread that claimed the facet
    std::int32_t apex;
    Outcome outcome;
    std::uint32_t calls, points_tested, candidates;  // one search's SearchCounters (each below 2^32)
    std::uint64_t exact;
  };
  // One thread's tools.
  struct Worker {
    Worker(const engine::PointStore& points, const SearchOptions& options, engine::SeedMemory& seeds, int d)
        : search(points, options, seeds), predictor(d), facet(static_cast<std::size_t>(d)) {}
    engine::FacetSearch search;
    ClosurePredictor predictor;
    // The facet being searched, copied out of the window: the search reads its ids for every
    // point it tests, and the window's lines are written by other threads.
    std::vector<std::int32_t> facet;
  };

  std::size_t slot(std::uint64_t k) const { return static_cast<std::size_t>(k) & mask_; }
  std::int32_t* ids(std::size_t slot) { return &ids_[slot * static_cast<std::size_t>(d_)]; }
  std::int32_t* derived(std::size_t slot) { return &derived_[slot * derived_block_size(d_)]; }
  bool done(std::uint64_t k) const { return done_[slot(k)].load(std::memory_order_acquire) == k + 1; }

  // The calling thread: takes the turns in order as their results come in, and searches runs
  // of facets itself between them. In 2D and 3D it takes a turn in another thread's run only
  // once that whole run is decided (whole_runs_): taking each facet as soon as it was done read
  // the window's lines (done_, results_, derived_) while the other core was still writing the
  // next slots of the same lines, and each line crossed between the cores once per facet
  // instead of once. The turns come later, so more searched facets turn out closed (wasted),
  // which costs more where a search is long: whole runs pay in 2D and 3D, not from 4D on.
  void lead(Worker& worker, SearchTotals& totals) {
    std::uint64_t turn = 0;
    std::uint64_t run_end = 0;                 // the end of the run that holds `turn`, once known
    std::uint64_t own_begin = 0, own_end = 0;  // the last run this thread claimed
    refill(turn);
    // Whether `turn` may be taken: with whole_runs_, whether the run that holds it is decided.
    // Runs tile the facets claimed so far, so a turn past the known run starts the next one,
    // whose claimer records its end.
    auto run_done = [&] {
      if (!whole_runs_) return done(turn);
      if (turn >= own_begin && turn < own_end) {  // its own run: no other core writes there
        run_end = own_end;
        return done(turn);
      }
      if (turn >= run_end) {
        const std::uint64_t end = run_end_[slot(turn)].load(std::memory_order_acquire);
        if (end <= turn) return false;  // not claimed yet (a value from an earlier lap of the ring)
        run_end = end;
      }
      return done(run_end - 1);  // a run is decided in order by one thread
    };
    // Every turn whose result is in.
    auto take_turns = [&] {
      const std::uint64_t before = turn;
      while (turn < filled_.load(std::memory_order_relaxed) && run_done()) {
        take_turn(slot(turn), totals);
        ++turn;
        if (filled_.load(std::memory_order_relaxed) + refill_step_ <= turn + mask_ + 1) refill(turn);
      }
      if (turn == filled_.load(std::memory_order_relaxed)) refill(turn);
      return turn != before;
    };
    for (int idle = 0;;) {
      if (take_turns()) idle = 0;
      if (turn == filled_.load(std::memory_order_relaxed)) return;  // the queue is empty: all recorded
      std::uint64_t begin = 0, end = 0;
      if (claim_run(begin, end)) {
        own_begin = begin;
        own_end = end;
        for (std::uint64_t k = begin; k < end; ++k) {
          process(worker, k);
          take_turns();
        }
        idle = 0;
      } else {
        if (stopped_.load(std::memory_order_relaxed)) return;  // a helper failed: Team::run rethrows
        // The turn's facet is being searched by another thread: wait, letting it run if the
        // machine has fewer free cores than threads.
        if (++idle < kSpins) pause();
        else std::this_thread::yield();
      }
    }
  }

  void take_turn(std::size_t s, SearchTotals& totals) {
    const Result& result = results_[s];
    frontier_.release(info_[s]);  // only the turn's take() and close() read it from here on
    if (!frontier_.take(ids(s), info_[s], closed_[s].load(std::memory_order_relaxed))) {
      if (result.outcome == Outcome::searched) ++totals.wasted;
      return;
    }
    if (result.outcome != Outcome::searched) throw InternalError("delaunay: a facet predicted closed is open");
    totals.add(engine::SearchCounters{result.calls, result.points_tested, result.candidates}, result.exact);
    if (result.apex >= 0) frontier_.prefetch_derived(derived(s));
    frontier_.close(ids(s), info_[s], result.apex, derived(s));
    for (std::uint64_t entry : frontier_.closed_after_pop()) closed_[slot(entry)].store(true, std::memory_order_release);
    frontier_.closed_after_pop().clear();
  }

  // Copies facets from the queue into the window, up to its size ahead of the turn.
  void refill(std::uint64_t turn) {
    std::uint64_t filled = filled_.load(std::memory_order_relaxed);
    const std::uint64_t before = filled;
    while (filled < turn + mask_ + 1 && !frontier_.queue_empty()) {
      const std::size_t s = slot(filled);
      closed_[s].store(frontier_.pop(ids(s), info_[s], static_cast<std::int64_t>(filled)), std::memory_order_relaxed);
      ++filled;
    }
    if (filled == before) return;
    filled_.store(filled);  // sequentially consistent, against sleeping_ (see wait_for_work)
    // Wake sleepers for a whole run only: one wake-up per facet would cost a context switch
    // each on a machine busy with other work.
    if (sleeping_.load() > 0 && filled - claimed_.load() >= run_) {
      { const std::lock_guard<std::mutex> lock(mutex_); }
      wake_.notify_all();
    }
  }

  // Claims the next facets of the window, [begin, end): at most run_, and at most
  // unclaimed / (kRunsPerThread * threads) unless that is below kLeastRun.
  bool claim_run(std::uint64_t& begin, std::uint64_t& end) {
    const std::uint64_t runs_in_window = kRunsPerThread * static_cast<std::uint64_t>(threads_);
    std::uint64_t k = claimed_.load(std::memory_order_relaxed);
    for (;;) {
      const std::uint64_t filled = filled_.load(std::memory_order_acquire);
      if (k >= filled) return false;
      const std::uint64_t share = std::max<std::uint64_t>(kLeastRun, (filled - k) / runs_in_window);
      const std::uint64_t last = std::min({k + run_, k + share, filled});
      if (claimed_.compare_exchange_weak(k, last, std::memory_order_acq_rel)) {
        run_end_[slot(k)].store(last, std::memory_order_release);
        begin = k;
        end = last;
        return true;
      }
    }
  }

  // Decides facet k: closed (flagged), predicted closed, or searched.
  void process(Worker& worker, std::uint64_t k) {
    const std::size_t s = slot(k);
    Result& result = results_[s];
    for (int k = 0; k < d_; ++k) worker.facet[static_cast<std::size_t>(k)] = ids(s)[k];
    const std::int32_t* facet = worker.facet.data();
    if (closed_[s].load(std::memory_order_acquire)) {
      result.outcome = Outcome::closed;
    } else if (worker.predictor.closes(facet, info_[s].hash, info_[s].opposite)) {
      result.outcome = Outcome::predicted;
    } else {
      const std::uint64_t before = geometry::exact_evaluations();
      engine::SearchCounters counters;
      result.apex = worker.search.find_apex(facet, info_[s].sigma, counters);
      result.calls = static_cast<std::uint32_t>(counters.calls);
      result.points_tested = static_cast<std::uint32_t>(counters.points_tested);
      result.candidates = static_cast<std::uint32_t>(counters.candidates);
      result.exact = geometry::exact_evaluations() - before;
      result.outcome = Outcome::searched;
      if (result.apex >= 0) {
        std::int32_t* block = derived(s);
        derive_other_facets(facet, info_[s].sigma, result.apex, d_, block);
        worker.predictor.found(facet, info_[s].sigma, block);
      }
    }
    done_[s].store(k + 1, std::memory_order_release);
  }

  // A helper thread.
  void help(Worker& worker) {
    while (!stopped_.load(std::memory_order_relaxed)) {
      std::uint64_t begin = 0, end = 0;
      if (!claim_run(begin, end)) {
        wait_for_work();
        continue;
      }
      for (std::uint64_t k = begin; k < end; ++k) process(worker, k);
    }
  }

  // Spins a little (the window refills within microseconds), then sleeps until the window
  // holds a run of unclaimed facets (fewer are left to the calling thread) or the run stops.
  void wait_for_work() {
    for (int spin = 0; spin < kSpins; ++spin) {
      if (stopped_.load() || claimed_.load() < filled_.load()) return;
      pause();
    }
    auto ready = [&] {
      const std::uint64_t claimed = claimed_.load();  // first: claimed <= filled at every moment
      return stopped_.load() || filled_.load() - claimed >= run_;
    };
    std::unique_lock<std::mutex> lock(mutex_);
    ++sleeping_;  // before testing: refill() stores filled_, then reads sleeping_
    wake_.wait(lock, ready);
    --sleeping_;
  }

  void stop() {
    stopped_.store(true);
    { const std::lock_guard<std::mutex> lock(mutex_); }
    wake_.notify_all();
  }

  static void pause() {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
  }

  int d_;
  int threads_;
  bool whole_runs_;                   // see lead()
  std::uint64_t run_ = kRun;          // facets claimed at once
  std::uint64_t refill_step_ = kRun;  // the window is topped up when this many facets fit
  const engine::PointStore& points_;
  const SearchOptions& options_;
  Frontier<Queue>& frontier_;
  engine::SeedMemory seeds_;  // one for all threads (seed_memory.hpp)
  // The window: facet k in slot k mod size. Arrays, not a struct per slot: threads take
  // neighbouring facets in runs, so a cache line moves between cores once for several facets.
  std::size_t mask_ = 0;
  std::vector<std::int32_t> ids_;  // d per slot, written by the calling thread as facets enter
  std::vector<FacetInfo> info_;    // likewise
  std::vector<Result> results_;    // written by the thread that claimed the facet
  std::vector<std::int32_t> derived_;  // likewise: derive_other_facets' block per slot, with an apex
  std::unique_ptr<std::atomic<bool>[]> closed_;         // set by the calling thread: closed since it entered
  std::unique_ptr<std::atomic<std::uint64_t>[]> done_;  // k + 1 once the result of facet k is in
  std::unique_ptr<std::atomic<std::uint64_t>[]> run_end_;  // at a run's first facet: the run's end
  alignas(64) std::atomic<std::uint64_t> filled_{0};   // facets [0, filled) have entered the window
  alignas(64) std::atomic<std::uint64_t> claimed_{0};  // facets [0, claimed) are decided or being decided
  alignas(64) std::atomic<bool> stopped_{false};
  std::atomic<int> sleeping_{0};
  std::mutex mutex_;
  std::condition_variable wake_;
};

}  // namespace drange::engine
