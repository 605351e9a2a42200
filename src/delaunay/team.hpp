// delaunay/team.hpp: the threads of one delaunay() call (Options::threads).
//
// No pool outlives the call and nothing is global: a Team only remembers how many threads it
// may use and how many exact predicate evaluations its helper threads made (the predicates
// count them per thread, geometry/predicates.cpp, and Statistics::Debug::exact_fallbacks must
// cover every thread). Each parallel phase starts its helpers and joins them before
// returning; starting a thread costs tens of microseconds, which no phase worth running in
// parallel notices.
//
// Exceptions: the first exception thrown by any thread (the calling thread included) is the one
// the caller receives, after every helper has been joined. A phase whose threads wait for each
// other gives `run` a `stop` function that makes them all return soon.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

#include "geometry/predicates.hpp"

namespace drange::engine {

// Options::threads to a thread count: 0 means every hardware thread (at least 1).
inline int resolve_threads(int requested) {
  if (requested > 0) return requested;
  const unsigned hardware = std::thread::hardware_concurrency();
  return hardware > 0 ? static_cast<int>(std::min(hardware, 1024u)) : 1;
}

class Team {
 public:
  explicit Team(int threads) : threads_(std::max(1, threads)) {}
  Team(const Team&) = delete;
  Team& operator=(const Team&) = delete;

  int threads() const { return threads_; }
  // Exact predicate evaluations made on helper threads so far.
  std::uint64_t helper_exact_evaluations() const { return helper_exact_.load(); }

  // Runs body(rank) for rank 0..count-1: rank 0 on the calling thread, the others on helper
  // threads. When a thread cannot be started (the system refuses), the ranks started so far
  // run alone: bodies must not count on every rank being present. On an exception, `stop()`
  // is called (from any thread, possibly twice: it must be thread-safe), everything is joined
  // and the first exception is rethrown.
  template <class Body, class Stop>
  void run(int count, Body&& body, Stop&& stop) {
    std::mutex mutex;
    std::exception_ptr error;
    auto fail = [&] {
      {
        const std::lock_guard<std::mutex> lock(mutex);
        if (!error) error = std::current_exception();
      }
      stop();
    };
    std::vector<std::thread> helpers;
    helpers.reserve(static_cast<std::size_t>(std::max(0, count - 1)));
    for (int rank = 1; rank < count; ++rank) {
      try {
        helpers.emplace_back([&, rank] {
          const std::uint64_t before = geometry::exact_evaluations();
          try {
            body(rank);
          } catch (...) {
            fail();
          }
          helper_exact_ += geometry::exact_evaluations() - before;
        });
      } catch (const std::system_error&) {
        break;  // no more threads: the others do the work
      }
    }
    try {
      body(0);
    } catch (...) {
      fail();
    }
    for (std::thread& helper : helpers) helper.join();
    if (error) std::rethrow_exception(error);
  }

  // Runs task(i) for i = 0..tasks-1, each exactly once, on up to threads() threads; tasks are
  // taken in increasing order. After an exception no new task starts.
  template <class Task>
  void for_each(std::size_t tasks, Task&& task) {
    std::atomic<std::size_t> next{0};
    std::atomic<bool> stopped{false};
    const int count = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(threads_), tasks));
    run(
        count,
        [&](int) {
          for (std::size_t i; !stopped.load(std::memory_order_relaxed) && (i = next.fetch_add(1)) < tasks;) task(i);
        },
        [&] { stopped = true; });
  }

 private:
  int threads_;
  std::atomic<std::uint64_t> helper_exact_{0};
};

}  // namespace drange::engine
