// delaunay/prepare_points.cpp: validation, duplicates, lexicographic ranks, kd-tree order.
#include "delaunay/prepare_points.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <utility>

#include "drange/errors.hpp"
#include "geometry/error_bound.hpp"
#include "util/for_ranges.hpp"

namespace drange::engine {

namespace {
using util::for_ranges;
constexpr int kMaxDimension = 11;  // the filters' Laplace tables (geometry/minors.hpp) reach d+1 = 12 columns

void check_input(PointsView input) {
  if (input.dim < 2 || input.dim > kMaxDimension)
    throw InputError("dimension " + std::to_string(input.dim) + " is not supported (drange triangulates in 2 to " +
                     std::to_string(kMaxDimension) + " dimensions)");
  if (input.n >= static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
    throw InputError(std::to_string(input.n) + " points are more than drange's limit of 2^31 - 2");
  for (std::size_t i = 0; i < input.n; ++i)
    for (int k = 0; k < input.dim; ++k) {
      const double x = input.point(i)[k];
      if (!std::isfinite(x))
        throw InputError("point " + std::to_string(i) + ", coordinate " + std::to_string(k) + " is " +
                         (std::isnan(x) ? "NaN" : "infinite"));
    }
}

// The Delaunay triangulation does not change under scaling, and multiplying by a power of two
// is exact unless it leaves the normal range. Bringing the largest magnitude near 1 keeps the
// squared norms of the lifted rows away from overflow (coordinates near 1e300) and underflow
// (near 1e-300), where the floating-point filters cannot decide and every test would be exact.
bool scale_by_power_of_two(std::vector<double>& coords, Team& team) {
  // Minimum and maximum are exact: the split does not change them.
  std::vector<double> largest_of(team.threads() * 4 + 1, 0.0), smallest_of(largest_of.size(), std::numeric_limits<double>::infinity());
  const std::size_t ranges = for_ranges(coords.size(), team, [&](std::size_t i, std::size_t begin, std::size_t end) {
    double large = 0.0, small = std::numeric_limits<double>::infinity();  // locals: the threads' slots share a line
    for (std::size_t j = begin; j < end; ++j) {
      const double x = coords[j];
      if (x == 0.0) continue;
      large = std::max(large, std::fabs(x));
      small = std::min(small, std::fabs(x));
    }
    largest_of[i] = large;
    smallest_of[i] = small;
  });
  const double largest = *std::max_element(largest_of.begin(), largest_of.begin() + static_cast<std::ptrdiff_t>(ranges));
  const double smallest = *std::min_element(smallest_of.begin(), smallest_of.begin() + static_cast<std::ptrdiff_t>(ranges));
  if (largest == 0.0) return true;
  int exponent = 0;
  std::frexp(largest, &exponent);
  // ldexp shifts each value exactly, even when 2^-exponent itself is not a double (inputs
  // below 2^-1022).
  if (std::ldexp(smallest, -exponent) < std::numeric_limits<double>::min()) return false;  // would lose the smallest
  for_ranges(coords.size(), team, [&](std::size_t, std::size_t begin, std::size_t end) {
    for (std::size_t j = begin; j < end; ++j) coords[j] = std::ldexp(coords[j], -exponent);
  });
  return true;
}

// Finds the common power-of-two unit of all coordinates; a dyadic point set has its largest
// magnitude below 2^50 units, so that every difference of two coordinates is exact.
void mark_dyadic(const std::vector<double>& coords, PointStore& store, Team& team) {
  std::vector<int> unit_of(team.threads() * 4 + 1, std::numeric_limits<int>::max());
  std::vector<double> largest_of(unit_of.size(), 0.0);
  const std::size_t ranges = for_ranges(coords.size(), team, [&](std::size_t i, std::size_t begin, std::size_t end) {
    int low = std::numeric_limits<int>::max();
    double large = 0.0;
    for (std::size_t j = begin; j < end; ++j) {
      const double x = coords[j];
      if (x == 0.0) continue;
      low = std::min(low, geometry::lowest_bit_exponent(x));
      large = std::max(large, std::fabs(x));
    }
    unit_of[i] = low;
    largest_of[i] = large;
  });
  const int unit = *std::min_element(unit_of.begin(), unit_of.begin() + static_cast<std::ptrdiff_t>(ranges));
  const double largest = *std::max_element(largest_of.begin(), largest_of.begin() + static_cast<std::ptrdiff_t>(ranges));
  store.unit_exponent = unit;
  store.dyadic = unit != std::numeric_limits<int>::max() && largest < std::ldexp(1.0, 50 + unit);
}

// Sorts `values` by `less`, a strict total order (so the result does not depend on how the
// work is split): consecutive parts sorted at the same time, then merged pairwise.
template <class T, class Less>
void sort_in_parallel(std::vector<T>& values, Less less, Team& team) {
  constexpr std::size_t kMinPart = std::size_t{1} << 15;
  const std::size_t parts = std::min(static_cast<std::size_t>(team.threads()), values.size() / kMinPart);
  if (parts < 2) {
    std::sort(values.begin(), values.end(), less);
    return;
  }
  std::vector<std::size_t> bounds;  // part i is [bounds[i], bounds[i + 1])
  for (std::size_t i = 0; i <= parts; ++i) bounds.push_back(values.size() * i / parts);
  const auto at = [](std::vector<T>& v, std::size_t i) { return v.begin() + static_cast<std::ptrdiff_t>(i); };
  team.for_each(parts, [&](std::size_t i) { std::sort(at(values, bounds[i]), at(values, bounds[i + 1]), less); });
  std::vector<T> merged(values.size());
  while (bounds.size() > 2) {
    team.for_each(bounds.size() / 2, [&](std::size_t p) {
      const std::size_t a = bounds[2 * p], b = bounds[std::min(2 * p + 1, bounds.size() - 1)],
                        c = bounds[std::min(2 * p + 2, bounds.size() - 1)];
      std::merge(at(values, a), at(values, b), at(values, b), at(values, c), at(merged, a), less);  // a lone last part is copied
    });
    std::vector<std::size_t> next;
    for (std::size_t i = 0; i < bounds.size(); i += 2) next.push_back(bounds[i]);
    if (next.back() != bounds.back()) next.push_back(bounds.back());
    bounds.swap(next);
    values.swap(merged);
  }
}

// The input indices in lexicographic order of the points (ties: the lower index first).
std::vector<std::int64_t> lexicographic_order(PointsView input, Team& team) {
  const int d = input.dim;
  std::vector<std::int64_t> lex(input.n);
  std::iota(lex.begin(), lex.end(), 0);
  sort_in_parallel(lex, [&](std::int64_t a, std::int64_t b) {
    const double* p = input.point(static_cast<std::size_t>(a));
    const double* q = input.point(static_cast<std::size_t>(b));
    for (int k = 0; k < d; ++k)
      if (p[k] != q[k]) return p[k] < q[k];
    return a < b;  // equal points: the first input index is the original
  }, team);
  return lex;
}

// The same order, sorting the points themselves next to their index (fixed d: contiguous
// memory instead of an indirection per comparison). The order is total, so the result is the
// same permutation.
template <int D>
std::vector<std::int64_t> lexicographic_order_fixed(PointsView input, Team& team) {
  struct Item {
    double x[D];
    std::int64_t index;
  };
  std::vector<Item> items(input.n);
  for_ranges(input.n, team, [&](std::size_t, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      std::copy_n(input.point(i), D, items[i].x);
      items[i].index = static_cast<std::int64_t>(i);
    }
  });
  sort_in_parallel(items, [](const Item& a, const Item& b) {
    for (int k = 0; k < D; ++k)
      if (a.x[k] != b.x[k]) return a.x[k] < b.x[k];
    return a.index < b.index;
  }, team);
  std::vector<std::int64_t> lex(input.n);
  for (std::size_t i = 0; i < input.n; ++i) lex[i] = items[i].index;
  return lex;
}

}  // namespace

PointStore prepare_points(PointsView input, int leaf_size, std::vector<Duplicate>& duplicates, Team& team) {
  check_input(input);
  const int d = input.dim;
  // Distinct points in lexicographic order: their position is their rank. The order is
  // compacted in place (a duplicate follows its original, the first input index).
  std::vector<std::int64_t> distinct = d == 2   ? lexicographic_order_fixed<2>(input, team)
                                       : d == 3 ? lexicographic_order_fixed<3>(input, team)
                                       : d == 4 ? lexicographic_order_fixed<4>(input, team)
                                                : lexicographic_order(input, team);
  duplicates.clear();
  std::size_t kept = 0;
  for (std::size_t i = 0; i < distinct.size(); ++i) {
    const std::int64_t index = distinct[i];
    const double* p = input.point(static_cast<std::size_t>(index));
    if (kept > 0 && std::equal(p, p + d, input.point(static_cast<std::size_t>(distinct[kept - 1])))) {
      duplicates.push_back(Duplicate{index, distinct[kept - 1]});
      continue;
    }
    distinct[kept++] = index;
  }
  distinct.resize(kept);
  std::sort(duplicates.begin(), duplicates.end(), [](const Duplicate& a, const Duplicate& b) { return a.index < b.index; });
  if (distinct.size() < static_cast<std::size_t>(d + 1))
    throw DegenerateInputError("only " + std::to_string(distinct.size()) + " distinct point" +
                               (distinct.size() == 1 ? "" : "s") + "; a triangulation in " + std::to_string(d) +
                               " dimensions needs at least " + std::to_string(d + 1));

  // The kd-tree over the distinct points (in rank order), then ids = tree positions.
  PointStore store;
  store.dim = d;
  store.size = static_cast<std::int32_t>(distinct.size());
  std::vector<double> by_rank(distinct.size() * static_cast<std::size_t>(d));
  for_ranges(distinct.size(), team, [&](std::size_t, std::size_t begin, std::size_t end) {
    for (std::size_t r = begin; r < end; ++r)
      std::copy_n(input.point(static_cast<std::size_t>(distinct[r])), d, by_rank.begin() + static_cast<std::ptrdiff_t>(r * static_cast<std::size_t>(d)));
  });
  store.scaled = scale_by_power_of_two(by_rank, team);
  mark_dyadic(by_rank, store, team);
  store.tree.build_and_reorder(by_rank.data(), store.size, d, leaf_size, team.threads());
  store.coords = std::move(by_rank);  // now in tree order
  const std::vector<std::int32_t>& order = store.tree.order();
  store.rank.resize(distinct.size());
  store.input_index.resize(distinct.size());
  for_ranges(order.size(), team, [&](std::size_t, std::size_t begin, std::size_t end) {
    for (std::size_t id = begin; id < end; ++id) {
      const auto r = static_cast<std::size_t>(order[id]);
      store.rank[id] = static_cast<std::int64_t>(r);
      store.input_index[id] = distinct[r];
    }
  });
  return store;
}

}  // namespace drange::engine
