// delaunay/block_search.cpp: the blocks' wrappings, their canonical order and their join
// (block_search.hpp says why the output is the same for every cut).
#include "delaunay/block_search.hpp"

#ifdef __GLIBC__
#include <malloc.h>
#endif

#include <algorithm>
#include <atomic>
#include <chrono>
#include <numeric>
#include <thread>
#include <vector>

#include "delaunay/local_star.hpp"
#include "delaunay/simplex_estimate.hpp"

namespace drange::engine {
namespace {

// In a block's links: the facet's other side is not among the block's own simplices (owned by
// another block, or not found by this one); matched after the join.
constexpr std::int32_t kElsewhere = -3;

// One block's share of the result, in engine ids.
struct Block {
  std::int32_t begin = 0, end = 0;  // its points: ids begin..end-1
  std::vector<std::int32_t> rows;   // its simplices, canonical, in canonical order
  // Per row and facet (opposite the vertex at that place): the row across, -1 on the hull, or
  // kElsewhere. Empty without neighbours.
  std::vector<std::int32_t> links;
  SearchCounters counters;
  std::size_t hull_facets = 0, max_open_facets = 0;
};

// The simplices found so far by every block, for Options::progress, and the flag that stops
// the blocks when one has failed.
class SharedProgress {
 public:
  explicit SharedProgress(const std::function<void(std::size_t)>& progress)
      : progress_(progress), caller_(std::this_thread::get_id()) {}
  // `owned` more simplices found by some block. Reports on the calling thread; throws
  // Stopped after another block failed.
  void add(std::size_t owned) {
    if (stopped_.load(std::memory_order_relaxed)) throw Stopped{};
    const std::size_t found = found_.fetch_add(owned) + owned;
    if (std::this_thread::get_id() == caller_) report(found);
  }
  // After the blocks, on the calling thread: the reports it missed while it waited for the
  // others, so that every thread count reports the same counts.
  void finish() { report(found_.load()); }
  void stop() { stopped_ = true; }
  bool stopped() const { return stopped_.load(std::memory_order_relaxed); }
  struct Stopped {};

 private:
  const std::function<void(std::size_t)>& progress_;
  const std::thread::id caller_;
  std::atomic<std::size_t> found_{0};
  std::atomic<bool> stopped_{false};
  std::size_t next_ = kProgressInterval;  // the calling thread's next report

  void report(std::size_t found) {
    if (!progress_) return;
    for (; next_ <= found; next_ += kProgressInterval) progress_(next_);
  }
};

// Returns the pages of freed blocks to the system at once. A block's rows are allocated by
// the thread that wrapped it, from that thread's malloc arena, where glibc keeps freed memory
// for reuse: the join, which frees each block as it appends it, would otherwise peak at the
// blocks and the result together.
void give_back_freed_memory() {
#ifdef __GLIBC__
  malloc_trim(0);
#endif
}

// Puts the w ids of `row` in canonical form: increasing, the first two exchanged when the
// sort's permutation is odd (the row was positively oriented, and so stays). place[k] gets the
// new place of the id that was at place k.
void canonicalise(std::int32_t* row, int w, int* place) {
  int from[16];  // from[k]: the old place of the id now at place k (w <= 12)
  for (int k = 0; k < w; ++k) from[k] = k;
  bool odd = false;
  for (int i = 1; i < w; ++i)
    for (int k = i; k > 0 && row[k - 1] > row[k]; --k) {
      std::swap(row[k - 1], row[k]);
      std::swap(from[k - 1], from[k]);
      odd = !odd;
    }
  if (odd) {
    std::swap(row[0], row[1]);
    std::swap(from[0], from[1]);
  }
  for (int k = 0; k < w; ++k) place[from[k]] = k;
}

// Whether canonical row a comes before canonical row b: their sorted ids, compared in order (a
// canonical row is sorted but for its first two ids).
bool canonical_before(const std::int32_t* a, const std::int32_t* b, int w) {
  const std::int32_t a0 = std::min(a[0], a[1]), b0 = std::min(b[0], b[1]);
  if (a0 != b0) return a0 < b0;
  const std::int32_t a1 = std::max(a[0], a[1]), b1 = std::max(b[0], b[1]);
  if (a1 != b1) return a1 < b1;
  return std::lexicographical_compare(a + 2, a + w, b + 2, b + w);
}

// Wraps the stars of block.begin..end-1 and keeps, in canonical order, the simplices it owns.
void search_block(const PointStore& points, const FirstFacet& first, const SearchOptions& options, bool neighbors,
                  SharedProgress& progress, Block& block) {
  const int w = points.dim + 1;
  const auto width = static_cast<std::size_t>(w);
  const auto mine = [&](std::int32_t id) { return id >= block.begin && id < block.end; };
  std::vector<std::int32_t> found, links, hull;
  // Room up front (simplex_estimate.hpp): growing by doubling would copy the rows again.
  const std::size_t room = reservable_simplices(
      expected_simplices(points.dim, static_cast<std::size_t>(block.end - block.begin)) * 9 / 8, width, neighbors ? 4 : 2);
  found.reserve(room * width);
  if (neighbors) links.reserve(room * width);
  {
    FacetSearch search(points, options);
    StarWrapper wrapper(points, search, first);
    // Progress in batches of a few thousand simplices: one shared counter update each.
    wrapper.report_rows(4096, [&](const std::int32_t* rows, std::size_t count) {
      std::size_t owned = 0;
      for (std::size_t r = 0; r < count; ++r) {
        const std::int32_t* row = rows + r * width;
        owned += mine(*std::min_element(row, row + w)) ? 1 : 0;
      }
      progress.add(owned);
    });
    std::vector<std::int32_t> wanted(static_cast<std::size_t>(block.end - block.begin));
    std::iota(wanted.begin(), wanted.end(), block.begin);
    wrapper.stars(wanted, found, block.counters, hull, neighbors ? &links : nullptr);
    block.max_open_facets = wrapper.max_open_facets();
  }
  // A hull facet is counted by the block of its smallest id, which wrapped it (facets sorted).
  for (std::size_t f = 0; f < hull.size(); f += width - 1) block.hull_facets += mine(hull[f]) ? 1 : 0;

  // Canonical rows; the owned ones counted by smallest id, for a counting sort.
  const std::size_t rows = found.size() / width;
  std::vector<signed char> places(neighbors ? found.size() : 0);
  std::vector<std::int32_t> start(static_cast<std::size_t>(block.end - block.begin) + 1, 0);
  for (std::size_t r = 0; r < rows; ++r) {
    std::int32_t* row = &found[r * width];
    int place[16];
    canonicalise(row, w, place);
    if (neighbors)
      for (int k = 0; k < w; ++k) places[r * width + static_cast<std::size_t>(k)] = static_cast<signed char>(place[k]);
    const std::int32_t least = std::min(row[0], row[1]);
    if (mine(least)) ++start[static_cast<std::size_t>(least - block.begin) + 1];
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  const auto owned = static_cast<std::size_t>(start.back());
  // dest[r]: the row that found row r becomes, by smallest id (a counting sort); the rows not
  // owned go after the owned ones. start[k] then ends the rows of smallest id begin + k.
  std::vector<std::int32_t> dest(rows);
  for (std::size_t r = 0, other = owned; r < rows; ++r) {
    const std::int32_t least = std::min(found[r * width], found[r * width + 1]);
    dest[r] = static_cast<std::int32_t>(mine(least) ? static_cast<std::size_t>(start[static_cast<std::size_t>(least - block.begin)]++)
                                                     : other++);
  }
  if (neighbors) {
    // Each link to its row after the counting sort and its facet to its canonical place.
    std::vector<std::int32_t> link(width);
    for (std::size_t r = 0; r < rows; ++r) {
      std::int32_t* at = &links[r * width];
      for (std::size_t k = 0; k < width; ++k) {
        const std::int32_t across = at[k];
        std::int32_t value = kElsewhere;
        if (across == StarWrapper::kHullSide) value = -1;
        else if (across >= 0 && static_cast<std::size_t>(dest[static_cast<std::size_t>(across)]) < owned)
          value = dest[static_cast<std::size_t>(across)];
        link[static_cast<std::size_t>(places[r * width + k])] = value;
      }
      std::copy(link.begin(), link.end(), at);
    }
    std::vector<signed char>().swap(places);
  }
  // The permutation applied in place, cycle by cycle: no second array of rows at the peak.
  for (std::size_t i = 0; i < rows; ++i)
    while (static_cast<std::size_t>(dest[i]) != i) {
      const auto j = static_cast<std::size_t>(dest[i]);
      std::swap_ranges(&found[i * width], &found[i * width] + width, &found[j * width]);
      if (neighbors) std::swap_ranges(&links[i * width], &links[i * width] + width, &links[j * width]);
      std::swap(dest[i], dest[j]);
    }
  found.resize(owned * width);
  if (neighbors) links.resize(owned * width);
  // Within each smallest id's rows (a few), canonical order by insertion; with neighbours,
  // dest[i] follows row i to its place (dest is the identity after the permutation).
  for (std::size_t k = 0, from = 0; k + 1 < start.size(); ++k) {
    const auto to = static_cast<std::size_t>(start[k]);
    for (std::size_t i = from + 1; i < to; ++i)
      for (std::size_t j = i; j > from && canonical_before(&found[j * width], &found[(j - 1) * width], w); --j) {
        std::swap_ranges(&found[j * width], &found[j * width] + width, &found[(j - 1) * width]);
        if (neighbors) {
          std::swap_ranges(&links[j * width], &links[j * width] + width, &links[(j - 1) * width]);
          std::swap(dest[j], dest[j - 1]);
        }
      }
    from = to;
  }
  if (neighbors) {
    // dest[i] is now the row before that sort of the row at i: links name rows by that number.
    std::vector<std::int32_t> moved(owned);
    for (std::size_t i = 0; i < owned; ++i) moved[static_cast<std::size_t>(dest[i])] = static_cast<std::int32_t>(i);
    for (std::int32_t& link : links)
      if (link >= 0) link = moved[static_cast<std::size_t>(link)];
    block.links = std::move(links);
  }
  block.rows = std::move(found);
}

// Links the facets that no block could link alone (`pending`: row * w + facet, in the joined
// result): the two sides of a facet have the same sorted ids; one side alone is the hull.
void match_pending(const std::vector<std::size_t>& pending, int w, Triangulation& result) {
  const auto width = static_cast<std::size_t>(w), d = width - 1;
  std::vector<std::int32_t> keys(pending.size() * d);
  for (std::size_t i = 0; i < pending.size(); ++i) {
    const std::int32_t* row = &result.simplices[pending[i] / width * width];
    const std::size_t omit = pending[i] % width;
    std::int32_t* key = &keys[i * d];
    for (std::size_t k = 0, j = 0; k < width; ++k)
      if (k != omit) key[j++] = row[k];
    std::sort(key, key + d);
  }
  std::vector<std::size_t> order(pending.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  const auto key = [&](std::size_t i) { return keys.begin() + static_cast<std::ptrdiff_t>(i * d); };
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return std::lexicographical_compare(key(a), key(a) + static_cast<std::ptrdiff_t>(d), key(b), key(b) + static_cast<std::ptrdiff_t>(d));
  });
  for (const std::size_t at : pending) result.neighbors[at] = -1;
  for (std::size_t i = 0; i + 1 < order.size(); ++i) {
    const std::size_t a = order[i], b = order[i + 1];
    if (!std::equal(key(a), key(a) + static_cast<std::ptrdiff_t>(d), key(b))) continue;
    result.neighbors[pending[a]] = static_cast<std::int32_t>(pending[b] / width);
    result.neighbors[pending[b]] = static_cast<std::int32_t>(pending[a] / width);
    ++i;
  }
}

}  // namespace

BlockSearchTotals search_in_blocks(const PointStore& points, const FirstFacet& first, const SearchOptions& options,
                                   Team& team, int blocks, bool neighbors,
                                   const std::function<void(std::size_t)>& progress, Triangulation& result) {
  const int w = points.dim + 1;
  const auto width = static_cast<std::size_t>(w);
  std::vector<Block> parts(static_cast<std::size_t>(std::max(1, blocks)));
  for (std::size_t b = 0; b < parts.size(); ++b) {
    parts[b].begin = static_cast<std::int32_t>(static_cast<std::int64_t>(points.size) * static_cast<std::int64_t>(b) / static_cast<std::int64_t>(parts.size()));
    parts[b].end = static_cast<std::int32_t>(static_cast<std::int64_t>(points.size) * static_cast<std::int64_t>(b + 1) / static_cast<std::int64_t>(parts.size()));
  }
  // The blocks in turn on the team's threads. On a failure the team records it, then stops
  // the others (SharedProgress::add throws in them), and the caller gets the failure.
  SharedProgress shared(progress);
  std::atomic<std::size_t> next{0};
  const int threads = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(team.threads()), parts.size()));
  BlockSearchTotals totals;
  totals.seconds_busy.assign(static_cast<std::size_t>(threads), 0.0);
  team.run(
      threads,
      [&](int rank) {
        const auto start = std::chrono::steady_clock::now();
        for (std::size_t b; !shared.stopped() && (b = next.fetch_add(1)) < parts.size();)
          search_block(points, first, options, neighbors, shared, parts[b]);
        totals.seconds_busy[static_cast<std::size_t>(rank)] =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      },
      [&] { shared.stop(); });
  shared.finish();
  const auto join = std::chrono::steady_clock::now();

  // The join, in block order: each block's rows appended to the result, its links shifted by
  // its offset, then freed, so that the peak holds the result and one block more.
  std::size_t total = 0;
  for (const Block& part : parts) total += part.rows.size();
  std::vector<std::size_t> pending;  // facets that no block could link alone
  for (std::size_t b = 0; b < parts.size(); ++b) {
    Block& part = parts[b];
    const std::size_t at = result.simplices.size();
    if (b == 0) {
      result.simplices = std::move(part.rows);
      result.simplices.reserve(total);
      result.neighbors = std::move(part.links);
      if (neighbors) result.neighbors.reserve(total);
    } else {
      result.simplices.insert(result.simplices.end(), part.rows.begin(), part.rows.end());
      const auto shift = static_cast<std::int32_t>(at / width);
      for (const std::int32_t link : part.links) result.neighbors.push_back(link >= 0 ? link + shift : link);
    }
    std::vector<std::int32_t>().swap(part.rows);
    std::vector<std::int32_t>().swap(part.links);
    give_back_freed_memory();
    for (std::size_t i = at; i < result.neighbors.size(); ++i)
      if (result.neighbors[i] == kElsewhere) pending.push_back(i);
  }
  for (std::size_t b = 0; b < parts.size(); ++b) {
    totals.counters.calls += parts[b].counters.calls;
    totals.counters.points_tested += parts[b].counters.points_tested;
    totals.counters.candidates += parts[b].counters.candidates;
    totals.hull_facets += parts[b].hull_facets;
    totals.max_open_facets = std::max(totals.max_open_facets, parts[b].max_open_facets);
  }
  if (neighbors) match_pending(pending, w, result);
  totals.seconds_join = std::chrono::duration<double>(std::chrono::steady_clock::now() - join).count();
  return totals;
}

}  // namespace drange::engine
