// delaunay/incremental/incremental_delaunay.cpp: drange::IncrementalDelaunay, the kernel's
// insertion kept alive between calls (its state: incremental_state.hpp).
#include "drange/incremental.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <vector>

#include "delaunay/incremental/incremental_state.hpp"
#include "delaunay/incremental/insertion_order.hpp"
#include "drange/errors.hpp"
#include "geometry/predicates.hpp"
#include "hull/initial_simplex.hpp"
#include "util/check_points.hpp"

namespace drange {

using engine::Insertion;
using engine::KernelPoints;

std::vector<std::int32_t> IncrementalDelaunay::State::append(PointsView points) {
  const auto base = static_cast<std::int32_t>(input.size() / static_cast<std::size_t>(dim));
  input.insert(input.end(), points.coords, points.coords + points.n * static_cast<std::size_t>(dim));
  const auto count = static_cast<std::int32_t>(points.n);
  std::vector<std::int32_t> sorted(static_cast<std::size_t>(count));
  std::iota(sorted.begin(), sorted.end(), base);
  std::stable_sort(sorted.begin(), sorted.end(), [&](std::int32_t a, std::int32_t b) { return less(a, b); });
  // A copy's original is the first input index with its coordinates: an earlier point's, or
  // the first of the equal new ones (the sort is stable).
  std::vector<std::int32_t> distinct;
  ranks.resize(input.size() / static_cast<std::size_t>(dim), -1);
  for (const std::int32_t id : sorted) {
    const auto old = std::lower_bound(lex.begin(), lex.end(), id, [&](std::int32_t a, std::int32_t b) { return less(a, b); });
    if (old != lex.end() && same(*old, id)) {
      duplicates.push_back(Duplicate{id, *old});
    } else if (!distinct.empty() && same(distinct.back(), id)) {
      duplicates.push_back(Duplicate{id, distinct.back()});
    } else {
      distinct.push_back(id);
    }
  }
  std::sort(duplicates.begin(), duplicates.end(), [](const Duplicate& a, const Duplicate& b) { return a.index < b.index; });
  std::vector<std::int32_t> merged(lex.size() + distinct.size());
  std::merge(lex.begin(), lex.end(), distinct.begin(), distinct.end(), merged.begin(),
             [&](std::int32_t a, std::int32_t b) { return less(a, b); });
  lex = std::move(merged);
  for (std::size_t r = 0; r < lex.size(); ++r) ranks[static_cast<std::size_t>(lex[r])] = static_cast<std::int32_t>(r);
  for (std::size_t i = static_cast<std::size_t>(base) * static_cast<std::size_t>(dim); i < input.size(); ++i) {
    const double x = std::fabs(input[i]);
    if (x == 0.0) continue;
    largest = std::max(largest, x);
    smallest = std::min(smallest, x);
  }
  rescale(static_cast<std::size_t>(base) * static_cast<std::size_t>(dim));
  return distinct;
}

void IncrementalDelaunay::State::rescale(std::size_t first_new) {
  int wanted = 0;
  if (largest > 0.0) std::frexp(largest, &wanted);
  // Scaling by 2^-wanted is exact while every value stays normal (prepare_points' rule).
  const bool scaled = largest == 0.0 || std::ldexp(smallest, -wanted) >= std::numeric_limits<double>::min();
  const bool again = scaled != view.scaled || (scaled && wanted != exponent) || coords.empty();
  const std::size_t from = again ? 0 : first_new;
  coords.resize(input.size());
  for (std::size_t i = from; i < input.size(); ++i) coords[i] = scaled ? std::ldexp(input[i], -wanted) : input[i];
  exponent = wanted;
  view = KernelPoints{dim, coords.data(), ranks.data(), scaled};
}

std::vector<std::int32_t> IncrementalDelaunay::State::first_simplex(const std::vector<std::int32_t>& distinct) const {
  if (distinct.size() < static_cast<std::size_t>(dim + 1))
    throw DegenerateInputError("only " + std::to_string(distinct.size()) + " distinct point" +
                               (distinct.size() == 1 ? "" : "s") + "; a triangulation in " + std::to_string(dim) +
                               " dimensions needs at least " + std::to_string(dim + 1));
  std::vector<double> rows;
  for (const std::int32_t id : distinct) rows.insert(rows.end(), point(id), point(id) + dim);
  const hull::InitialSimplex simplex = hull::initial_simplex(PointsView(rows.data(), distinct.size(), dim), "a Delaunay triangulation");
  std::vector<std::int32_t> ids;
  std::vector<const double*> corners;
  for (const std::int32_t i : simplex.ids) {
    ids.push_back(distinct[static_cast<std::size_t>(i)]);
    corners.push_back(view.point(ids.back()));
  }
  if (geometry::simplex_orientation(dim, corners.data()) < 0) std::swap(ids[0], ids[1]);
  return ids;
}

void IncrementalDelaunay::State::insert(const std::vector<std::int32_t>& distinct, const std::vector<std::int32_t>& skip) {
  // The new points in the kernel's order (rounds by a hash of the input index, a kd-tree path
  // within each), so that a large batch costs what a fresh incremental run costs.
  std::vector<double> rows;
  std::vector<std::int64_t> keys;
  for (const std::int32_t id : distinct) {
    rows.insert(rows.end(), view.point(id), view.point(id) + dim);
    keys.push_back(id);
  }
  const std::vector<std::int32_t> order =
      engine::insertion_order(rows.data(), keys.data(), static_cast<std::int32_t>(distinct.size()), dim);
  for (const std::int32_t row : order) {
    const std::int32_t id = distinct[static_cast<std::size_t>(row)];
    if (std::find(skip.begin(), skip.end(), id) == skip.end()) insertion->insert(id);
  }
}

namespace {

void check_batch(PointsView points, int dim, std::size_t first_index) {
  if (points.dim != dim)
    throw InputError("the points added have " + std::to_string(points.dim) + " coordinates; the triangulation is in " +
                     std::to_string(dim) + " dimensions");
  util::check_points(points, "triangulates", first_index);
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

IncrementalDelaunay::IncrementalDelaunay(PointsView points, bool furthest_site) : state_(std::make_unique<State>()) {
  const auto start = std::chrono::steady_clock::now();
  State& s = *state_;
  util::check_points(points, "triangulates");
  s.dim = points.dim;
  const std::vector<std::int32_t> distinct = s.append(points);
  const std::vector<std::int32_t> first = s.first_simplex(distinct);
  s.furthest_site = furthest_site;
  s.insertion = std::make_unique<Insertion>(s.view, distinct.size(), s.counters, furthest_site);
  s.insertion->start(first.data());
  s.insert(distinct, first);
  s.seconds += seconds_since(start);
}

IncrementalDelaunay::~IncrementalDelaunay() = default;
IncrementalDelaunay::IncrementalDelaunay(IncrementalDelaunay&&) noexcept = default;
IncrementalDelaunay& IncrementalDelaunay::operator=(IncrementalDelaunay&&) noexcept = default;

void IncrementalDelaunay::add_points(PointsView points) {
  const auto start = std::chrono::steady_clock::now();
  State& s = *state_;
  check_batch(points, s.dim, size());
  if (points.n == 0) return;
  if (size() + points.n >= static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
    throw InputError(std::to_string(size() + points.n) + " points are more than drange's limit of 2^31 - 2");
  s.insert(s.append(points), {});
  s.seconds += seconds_since(start);
}

int IncrementalDelaunay::dim() const { return state_->dim; }

std::size_t IncrementalDelaunay::size() const { return state_->input.size() / static_cast<std::size_t>(state_->dim); }

Triangulation IncrementalDelaunay::triangulation(bool neighbors) const {
  const State& s = *state_;
  Triangulation result;
  result.dim = s.dim;
  result.num_points = size();
  engine::export_cells(s.insertion->cells(), result, neighbors);
  result.duplicates = s.duplicates;
  Statistics& stats = result.stats;
  stats.points = size();
  stats.distinct_points = s.lex.size();
  stats.simplices = result.size();
  stats.search_calls = s.counters.walk_steps;
  stats.threads = 1;
  stats.algorithm = "incremental";
  stats.seconds_search = s.seconds;
  stats.seconds_total = s.seconds;
  stats.debug.points_tested = s.counters.conflict_tests;
  stats.debug.unfiltered_tests = s.insertion->unfiltered_tests();
  return result;
}

}  // namespace drange
