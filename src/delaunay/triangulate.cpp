// delaunay/triangulate.cpp: the D-Range driver (paper, sections 2.1 to 2.5).
//
//   1. the first facet, by gift wrapping (first_facet.hpp);
//   2. open facets in a FIFO queue and in the facet table keyed by sorted ids (facet_table.hpp);
//   3. for each open facet, the point that closes it into a Delaunay simplex (facet_search.hpp);
//   4. each new simplex is recorded, positively oriented; its other facets are opened, or closed
//      when already open, and closing a facet links the two simplices as neighbours (2.5).
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <deque>
#include <functional>
#include <stdexcept>
#include <utility>
#include <vector>

#include "delaunay/facet_search.hpp"
#include "delaunay/facet_table.hpp"
#include "delaunay/first_facet.hpp"
#include "delaunay/prepare_points.hpp"
#include "drange/delaunay.hpp"
#include "geometry/predicates.hpp"

namespace drange {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

std::size_t peak_rss_bytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<std::size_t>(usage.ru_maxrss) * 1024;  // Linux reports kilobytes
}

// Sorts ids in place and returns the parity of the permutation (+1 even, -1 odd).
int sort_with_parity(std::int32_t* ids, int n) {
  int parity = 1;
  for (int i = 1; i < n; ++i)
    for (int j = i; j > 0 && ids[j - 1] > ids[j]; --j) {
      std::swap(ids[j - 1], ids[j]);
      parity = -parity;
    }
  return parity;
}

// The open facets waiting for their search: sorted ids, the owner, and the open side. Entries
// of d + 3 ints in blocks of kBlock entries: O(1) per push and pop, and a block is freed as soon
// as it has been read, so memory follows the waiting facets (a queue of millions in 5D) without
// the transient doubling of a growing array.
class FacetQueue {
 public:
  explicit FacetQueue(int d) : d_(d), width_(static_cast<std::size_t>(d) + 3) {}
  void push(const std::int32_t* ids, engine::FacetOwner owner, int sigma) {
    if (blocks_.empty() || tail_ == kBlock) {
      blocks_.emplace_back(kBlock * width_);
      tail_ = 0;
    }
    std::int32_t* entry = &blocks_.back()[tail_ * width_];
    std::copy(ids, ids + d_, entry);
    entry[d_] = owner.simplex;
    entry[d_ + 1] = owner.face;
    entry[d_ + 2] = sigma;
    ++tail_;
    ++count_;
  }
  bool empty() const { return count_ == 0; }
  void pop(std::int32_t* ids, engine::FacetOwner& owner, int& sigma) {
    const std::int32_t* entry = &blocks_.front()[head_ * width_];
    std::copy(entry, entry + d_, ids);
    owner.simplex = entry[d_];
    owner.face = entry[d_ + 1];
    sigma = entry[d_ + 2];
    --count_;
    if (++head_ == kBlock || count_ == 0) {  // the front block is read (or the queue is empty)
      blocks_.pop_front();
      head_ = 0;
      if (blocks_.empty()) tail_ = 0;
    }
  }
  std::size_t size() const { return count_; }

 private:
  static constexpr std::size_t kBlock = 4096;
  int d_;
  std::size_t width_;
  std::deque<std::vector<std::int32_t>> blocks_;
  std::size_t head_ = 0;   // next entry to pop in the front block
  std::size_t tail_ = 0;   // next free entry in the back block
  std::size_t count_ = 0;  // waiting entries
};

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
  void finished(std::size_t found) const {
    if (report_) report_(found);
  }

 private:
  const std::function<void(std::size_t)>& report_;
  std::size_t countdown_ = kProgressInterval;
};

}  // namespace

Triangulation delaunay(PointsView input, const Options& options) {
  const auto start = Clock::now();
  const std::uint64_t exact_before = geometry::exact_evaluations();
  Triangulation result;
  result.dim = input.dim;
  result.num_points = input.n;
  Statistics& stats = result.stats;
  stats.points = input.n;

  const engine::PointStore points = engine::prepare_points(input, 8, result.duplicates);
  const int d = points.dim;
  const int width = d + 1;
  stats.distinct_points = static_cast<std::size_t>(points.size);
  stats.seconds_kdtree = seconds_since(start);

  auto phase = Clock::now();
  const engine::FirstFacet first = engine::find_first_facet(points);
  stats.seconds_first_facet = seconds_since(phase);

  phase = Clock::now();
  std::vector<std::int32_t>& simplices = result.simplices;
  std::vector<std::int32_t>& neighbors = result.neighbors;
  engine::FacetTable table(d);
  FacetQueue queue(d);
  engine::FacetSearch search(points, options.search);
  engine::SearchCounters counters;
  ProgressCountdown progress(options.progress);
  queue.push(first.ids.data(), engine::FacetOwner{-1, -1}, first.sigma);

  std::vector<std::int32_t> facet(static_cast<std::size_t>(d));
  std::vector<std::int32_t> other_facet(static_cast<std::size_t>(d));
  while (!queue.empty()) {
    stats.max_open_facets = std::max(stats.max_open_facets, table.size());
    engine::FacetOwner owner{};
    int sigma = 0;
    queue.pop(facet.data(), owner, sigma);
    // A facet closed by the simplex on its other side while it waited needs no search.
    if (owner.simplex >= 0 && !table.remove(facet.data())) continue;
    const std::int32_t apex = search.find_apex(facet.data(), sigma, counters);
    if (apex < 0) {
      ++stats.hull_facets;
      continue;
    }
    // The new simplex: the facet's vertices, then the apex, whose orientation is sigma; one
    // transposition of the first two vertices makes it positive.
    const auto s = static_cast<std::int32_t>(simplices.size() / static_cast<std::size_t>(width));
    const std::size_t base = simplices.size();
    simplices.insert(simplices.end(), facet.begin(), facet.end());
    simplices.push_back(apex);
    if (sigma < 0) std::swap(simplices[base], simplices[base + 1]);
    neighbors.insert(neighbors.end(), static_cast<std::size_t>(width), -1);
    neighbors[base + static_cast<std::size_t>(d)] = owner.simplex;
    if (owner.simplex >= 0) neighbors[static_cast<std::size_t>(owner.simplex) * width + static_cast<std::size_t>(owner.face)] = s;
    else ++stats.hull_facets;  // the first facet lies on the hull
    // The other facets: facet f omits vertex f. With the simplex positive, x is on the far side
    // of facet f (its open side) where orientation with x in place of vertex f is negative.
    for (int f = 0; f < d; ++f) {
      std::size_t w = 0;
      for (int i = 0; i < width; ++i)
        if (i != f) other_facet[w++] = simplices[base + static_cast<std::size_t>(i)];
      const int parity = sort_with_parity(other_facet.data(), d);
      engine::FacetOwner seen{};
      if (table.close_or_open(other_facet.data(), engine::FacetOwner{s, f}, &seen)) {
        neighbors[base + static_cast<std::size_t>(f)] = seen.simplex;
        neighbors[static_cast<std::size_t>(seen.simplex) * width + static_cast<std::size_t>(seen.face)] = s;
      } else {
        // Moving x from position f to the end takes d - f transpositions; sorting the rest
        // multiplies by its parity. Open side: that orientation negative.
        const int to_end = ((d - f) & 1) ? -1 : 1;
        queue.push(other_facet.data(), engine::FacetOwner{s, f}, -parity * to_end);
      }
    }
    progress.simplex_found(static_cast<std::size_t>(s) + 1);
  }
  stats.seconds_search = seconds_since(phase);
  if (table.size() != 0) throw std::logic_error("delaunay: open facets left after the search");

  // Back to the caller's numbering.
  for (std::int32_t& v : simplices) v = static_cast<std::int32_t>(points.input_index[static_cast<std::size_t>(v)]);
  if (!options.compute_neighbors) std::vector<std::int32_t>().swap(neighbors);
  stats.simplices = simplices.size() / static_cast<std::size_t>(width);
  stats.search_calls = counters.calls;
  stats.points_tested = counters.points_tested;
  stats.candidates = counters.candidates;
  stats.exact_fallbacks = geometry::exact_evaluations() - exact_before;
  stats.seconds_total = seconds_since(start);
  stats.peak_rss_bytes = peak_rss_bytes();
  progress.finished(stats.simplices);
  return result;
}

}  // namespace drange
