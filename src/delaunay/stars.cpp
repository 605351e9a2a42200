// delaunay/stars.cpp: drange::delaunay_stars (the stars of given points, local_star.hpp) and
// drange::delaunay_block (one block of the whole triangulation, by the stars of its points), in
// the caller's numbering; drange::link_neighbours, the neighbours simplices have among themselves.
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <set>
#include <string>
#include <vector>

#include "delaunay/facet_search.hpp"
#include "delaunay/first_facet.hpp"
#include "delaunay/local_star.hpp"
#include "delaunay/prepare_points.hpp"
#include "delaunay/search_options.hpp"
#include "delaunay/team.hpp"
#include "drange/delaunay.hpp"
#include "drange/errors.hpp"

namespace drange {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Throws UsageError for an id outside the input or given twice, naming it.
void check_ids(const std::vector<std::int64_t>& ids, std::size_t n) {
  std::vector<std::int64_t> sorted(ids);
  for (const std::int64_t id : ids)
    if (id < 0 || static_cast<std::uint64_t>(id) >= n)
      throw UsageError("point id " + std::to_string(id) + " is out of range: the input has " + std::to_string(n) +
                       " points, ids 0 to " + std::to_string(n - 1));
  std::sort(sorted.begin(), sorted.end());
  const auto twice = std::adjacent_find(sorted.begin(), sorted.end());
  if (twice != sorted.end()) throw UsageError("point id " + std::to_string(*twice) + " is given twice");
}

// Neighbour k of row s: the returned row sharing the facet opposite vertex k, else -1. The
// facets (sorted ids) are sorted, so that the two sides of a shared one are adjacent.
std::vector<std::int32_t> neighbours_among(const std::vector<std::int32_t>& rows, int d) {
  const auto width = static_cast<std::size_t>(d + 1), facet_width = static_cast<std::size_t>(d);
  std::vector<std::int32_t> neighbors(rows.size(), -1);
  std::vector<std::int32_t> facets(rows.size() * facet_width);  // facet `at` = row at / width without vertex at % width
  for (std::size_t at = 0; at < rows.size(); ++at) {
    const std::size_t row = at / width, k = at % width;
    std::int32_t* facet = &facets[at * facet_width];
    for (std::size_t i = 0, j = 0; i < width; ++i)
      if (i != k) facet[j++] = rows[row * width + i];
    std::sort(facet, facet + facet_width);
  }
  std::vector<std::size_t> order(rows.size());
  for (std::size_t at = 0; at < order.size(); ++at) order[at] = at;
  const auto facet = [&](std::size_t at) { return facets.begin() + static_cast<std::ptrdiff_t>(at * facet_width); };
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return std::lexicographical_compare(facet(a), facet(a) + static_cast<std::ptrdiff_t>(facet_width), facet(b),
                                        facet(b) + static_cast<std::ptrdiff_t>(facet_width));
  });
  for (std::size_t i = 0; i + 1 < order.size(); ++i) {
    const std::size_t a = order[i], b = order[i + 1];
    if (!std::equal(facet(a), facet(a) + static_cast<std::ptrdiff_t>(facet_width), facet(b))) continue;
    neighbors[a] = static_cast<std::int32_t>(b / width);
    neighbors[b] = static_cast<std::int32_t>(a / width);
  }
  return neighbors;
}

// The stars of `wanted(points)` (engine ids); `keep(row)` selects the simplices returned (engine
// ids, d+1 per row). The shared steps of delaunay_stars and delaunay_block.
template <class Wanted, class Keep>
Triangulation wrap_stars(PointsView input, const Options& options, const Wanted& wanted_of, const Keep& keep,
                         Clock::time_point start) {
  const engine::SearchOptions search_options = engine::search_variant(options.variant);
  if (options.algorithm != "auto" && options.algorithm != "direct" && options.algorithm != "incremental")
    throw UsageError("unknown algorithm '" + options.algorithm + "' (expected one of: " + algorithm_names() + ")");
  if (options.threads < 0)
    throw UsageError("threads must be 0 (all hardware threads) or a positive count, got " + std::to_string(options.threads));
  Triangulation result;
  result.dim = input.dim;
  result.num_points = input.n;
  Statistics& stats = result.stats;
  stats.points = input.n;
  stats.algorithm = "direct";
  stats.threads = static_cast<std::size_t>(engine::resolve_threads(options.threads));
  engine::Team team(static_cast<int>(stats.threads));
  const engine::PointStore points =
      engine::prepare_points(input, engine::search_leaf_size(input.dim), result.duplicates, team, search_options);
  const int d = points.dim;
  const auto width = static_cast<std::size_t>(d + 1);
  stats.distinct_points = static_cast<std::size_t>(points.size);
  stats.seconds_kdtree = seconds_since(start);

  auto phase = Clock::now();
  const engine::FirstFacet first = engine::find_first_facet(points, team);
  stats.seconds_first_facet = seconds_since(phase);

  phase = Clock::now();
  engine::FacetSearch search(points, search_options);
  engine::StarWrapper wrapper(points, search, first);
  engine::SearchCounters counters;
  std::vector<std::int32_t> hull, rows;
  wrapper.stars(wanted_of(points, result.duplicates), rows, counters, hull);
  std::size_t kept = 0;
  for (std::size_t r = 0; r < rows.size(); r += width)
    if (keep(&rows[r])) {
      std::copy(rows.begin() + static_cast<std::ptrdiff_t>(r), rows.begin() + static_cast<std::ptrdiff_t>(r + width),
                rows.begin() + static_cast<std::ptrdiff_t>(kept));
      kept += width;
    }
  rows.resize(kept);
  std::set<std::vector<std::int32_t>> hull_facets;  // sorted facets
  for (std::size_t f = 0; f < hull.size(); f += static_cast<std::size_t>(d))
    hull_facets.emplace(hull.begin() + static_cast<std::ptrdiff_t>(f), hull.begin() + static_cast<std::ptrdiff_t>(f) + d);
  for (std::int32_t& v : rows) v = points.input_index[static_cast<std::size_t>(v)];
  result.simplices = std::move(rows);
  if (options.compute_neighbors) link_neighbours(result);
  stats.seconds_search = seconds_since(phase);
  stats.simplices = result.size();
  stats.hull_facets = hull_facets.size();
  stats.search_calls = counters.calls;
  stats.debug.points_tested = counters.points_tested;
  stats.debug.candidates = counters.candidates;
  stats.seconds_total = seconds_since(start);
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  stats.peak_rss_bytes = static_cast<std::size_t>(usage.ru_maxrss) * 1024;  // Linux reports kilobytes
  if (options.progress) options.progress(stats.simplices);
  return result;
}

}  // namespace

void link_neighbours(Triangulation& t) { t.neighbors = neighbours_among(t.simplices, t.dim); }

Triangulation delaunay_stars(PointsView input, const std::vector<std::int64_t>& ids, const Options& options) {
  const auto start = Clock::now();
  check_ids(ids, input.n);
  const auto wanted = [&](const engine::PointStore& points, const std::vector<Duplicate>& duplicates) {
    // The engine id of each input index; a duplicate answers for the point it copies.
    std::vector<std::int32_t> engine_id(input.n, -1);
    for (std::int32_t id = 0; id < points.size; ++id) engine_id[static_cast<std::size_t>(points.input_index[static_cast<std::size_t>(id)])] = id;
    for (const Duplicate& dup : duplicates)
      engine_id[static_cast<std::size_t>(dup.index)] = engine_id[static_cast<std::size_t>(dup.original)];
    std::vector<std::int32_t> result;
    for (const std::int64_t id : ids) result.push_back(engine_id[static_cast<std::size_t>(id)]);
    return result;
  };
  return wrap_stars(input, options, wanted, [](const std::int32_t*) { return true; }, start);
}

Triangulation delaunay_block(PointsView input, int block, int blocks, const Options& options) {
  const auto start = Clock::now();
  if (blocks < 1 || block < 0 || block >= blocks)
    throw UsageError("block " + std::to_string(block) + " of " + std::to_string(blocks) + " does not exist (blocks 0 to " +
                     std::to_string(blocks - 1) + ")");
  // The range of engine ids (kd-tree positions) of the block, set once the points are prepared.
  std::int32_t begin = 0, end = 0;
  const auto wanted = [&](const engine::PointStore& points, const std::vector<Duplicate>&) {
    const auto share = [&](int b) {
      return static_cast<std::int32_t>(static_cast<std::int64_t>(points.size) * b / blocks);
    };
    begin = share(block);
    end = share(block + 1);
    std::vector<std::int32_t> ids(static_cast<std::size_t>(end - begin));
    for (std::int32_t id = begin; id < end; ++id) ids[static_cast<std::size_t>(id - begin)] = id;
    return ids;
  };
  Options own = options;
  own.compute_neighbors = false;
  const int d = input.dim;
  return wrap_stars(input, own, wanted, [&](const std::int32_t* row) {
    const std::int32_t least = *std::min_element(row, row + d + 1);
    return least >= begin && least < end;
  }, start);
}

}  // namespace drange
