// delaunay/prepare_points.cpp: validation, duplicates, lexicographic ranks, kd-tree order.
#include "delaunay/prepare_points.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <utility>

#include "drange/errors.hpp"
#include "util/check_points.hpp"
#include "drange/points.hpp"
#include "geometry/error_bound.hpp"
#include "util/for_ranges.hpp"
#include "util/parallel_sort.hpp"
#include "util/uninitialized_vector.hpp"

namespace drange::engine {

namespace {
using util::for_ranges;
using util::sort_by_key;

// The Delaunay triangulation does not change under scaling, and multiplying by a power of two
// is exact unless it leaves the normal range. Bringing the largest magnitude near 1 keeps the
// squared norms of the lifted rows away from overflow (coordinates near 1e300) and underflow
// (near 1e-300), where the floating-point filters cannot decide and every test would be exact.
bool scale_by_power_of_two(util::UninitializedVector<double>& coords, Team& team) {
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
  if (std::ldexp(smallest, -exponent) < std::numeric_limits<double>::min()) return false;  // would lose the smallest
  // Every scaled value is now a normal double, so multiplying by 2^-exponent is exact; when
  // that factor is not a double itself (inputs below 2^-1022), ldexp shifts each value exactly.
  // (The product is measurably cheaper than ldexp on every value.)
  const double factor = std::ldexp(1.0, -exponent);
  const bool multiply = std::isfinite(factor) && factor >= std::numeric_limits<double>::min();
  for_ranges(coords.size(), team, [&](std::size_t, std::size_t begin, std::size_t end) {
    if (multiply) {
      for (std::size_t j = begin; j < end; ++j) coords[j] *= factor;
    } else {
      for (std::size_t j = begin; j < end; ++j) coords[j] = std::ldexp(coords[j], -exponent);
    }
  });
  return true;
}

// Finds the common power-of-two unit of all coordinates; a dyadic point set has its largest
// magnitude below 2^50 units, so that every difference of two coordinates is exact.
void mark_dyadic(const util::UninitializedVector<double>& coords, PointStore& store, Team& team) {
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

// The distinct points in lexicographic order: the input index of each (its position is its
// rank) and its coordinates, rank by rank. Each exact copy goes to `duplicates` with the first
// input index of its coordinates as the original.
struct DistinctPoints {
  util::UninitializedVector<std::int64_t> index;
  util::UninitializedVector<double> coords;
};

// Any d: the input indices are sorted, then the points copied in that order.
DistinctPoints distinct_points(PointsView input, std::vector<Duplicate>& duplicates, Team& team) {
  const int d = input.dim;
  DistinctPoints distinct;
  util::UninitializedVector<std::int64_t>& lex = distinct.index;
  lex.resize(input.n);
  std::iota(lex.begin(), lex.end(), 0);
  const auto first_coordinate = [&](std::int64_t i) { return input.point(static_cast<std::size_t>(i))[0]; };
  sort_by_key(lex, first_coordinate, [&](std::int64_t a, std::int64_t b) {
    const double* p = input.point(static_cast<std::size_t>(a));
    const double* q = input.point(static_cast<std::size_t>(b));
    for (int k = 0; k < d; ++k)
      if (p[k] != q[k]) return p[k] < q[k];
    return a < b;  // equal points: the first input index is the original
  }, team);
  std::size_t kept = 0;  // compacted in place: a duplicate follows its original
  for (std::size_t i = 0; i < lex.size(); ++i) {
    const double* p = input.point(static_cast<std::size_t>(lex[i]));
    if (kept > 0 && std::equal(p, p + d, input.point(static_cast<std::size_t>(lex[kept - 1])))) {
      duplicates.push_back(Duplicate{lex[i], lex[kept - 1]});
      continue;
    }
    lex[kept++] = lex[i];
  }
  lex.resize(kept);
  const auto width = static_cast<std::size_t>(d);
  distinct.coords.resize(kept * width);
  for_ranges(kept, team, [&](std::size_t, std::size_t begin, std::size_t end) {
    for (std::size_t r = begin; r < end; ++r)
      std::copy_n(input.point(static_cast<std::size_t>(lex[r])), d, distinct.coords.begin() + static_cast<std::ptrdiff_t>(r * width));
  });
  return distinct;
}

// Fixed d: the points themselves are sorted next to their index (contiguous memory instead of
// an indirection per comparison), and duplicates are found and the coordinates taken in the
// sorted array's order. The order is total, so the result is distinct_points'.
template <int D>
DistinctPoints distinct_points_fixed(PointsView input, std::vector<Duplicate>& duplicates, Team& team) {
  struct Item {
    double x[D];
    std::int64_t index;
  };
  util::UninitializedVector<Item> items(input.n);
  for_ranges(input.n, team, [&](std::size_t, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      std::copy_n(input.point(i), D, items[i].x);
      items[i].index = static_cast<std::int64_t>(i);
    }
  });
  sort_by_key(items, [](const Item& item) { return item.x[0]; }, [](const Item& a, const Item& b) {
    for (int k = 0; k < D; ++k)
      if (a.x[k] != b.x[k]) return a.x[k] < b.x[k];
    return a.index < b.index;
  }, team);
  std::size_t kept = 0;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (kept > 0 && std::equal(items[i].x, items[i].x + D, items[kept - 1].x)) {
      duplicates.push_back(Duplicate{items[i].index, items[kept - 1].index});
      continue;
    }
    if (kept != i) items[kept] = items[i];
    ++kept;
  }
  DistinctPoints distinct;
  distinct.index.resize(kept);
  distinct.coords.resize(kept * D);
  for_ranges(kept, team, [&](std::size_t, std::size_t begin, std::size_t end) {
    for (std::size_t r = begin; r < end; ++r) {
      distinct.index[r] = items[r].index;
      std::copy_n(items[r].x, D, distinct.coords.begin() + static_cast<std::ptrdiff_t>(r * D));
    }
  });
  return distinct;
}

}  // namespace

PointStore prepare_points(PointsView input, int leaf_size, std::vector<Duplicate>& duplicates, Team& team,
                          const SearchOptions& accelerators) {
  util::check_points(input, "triangulates");
  const int d = input.dim;
  duplicates.clear();
  DistinctPoints distinct = d == 2   ? distinct_points_fixed<2>(input, duplicates, team)
                            : d == 3 ? distinct_points_fixed<3>(input, duplicates, team)
                            : d == 4 ? distinct_points_fixed<4>(input, duplicates, team)
                                     : distinct_points(input, duplicates, team);
  std::sort(duplicates.begin(), duplicates.end(), [](const Duplicate& a, const Duplicate& b) { return a.index < b.index; });
  const std::size_t kept = distinct.index.size();
  if (kept < static_cast<std::size_t>(d + 1))
    throw DegenerateInputError("only " + std::to_string(kept) + " distinct point" + (kept == 1 ? "" : "s") +
                               "; a triangulation in " + std::to_string(d) + " dimensions needs at least " +
                               std::to_string(d + 1));

  // The kd-tree over the distinct points (in rank order), then ids = tree positions.
  PointStore store;
  store.dim = d;
  store.size = static_cast<std::int32_t>(kept);
  util::UninitializedVector<double> by_rank = std::move(distinct.coords);
  store.scaled = scale_by_power_of_two(by_rank, team);
  mark_dyadic(by_rank, store, team);
  store.tree.build_and_reorder(by_rank.data(), store.size, d, leaf_size, team.threads());
  store.coords = std::move(by_rank);  // now in tree order
  store.blocks = LeafBlocks(store.tree, store.coords.data(), d, team);
  // The search's accelerators, each only when the search will consult it (FacetSearch).
  if (accelerators.use_kdtree && accelerators.sphere_shell) store.shell = fit_sphere_shell(store.coords.data(), store.size, d, store.tree);
  if (accelerators.known_hull_facets) {
    store.hull.edges = HullEdges(store);
    store.hull.triangles = HullTriangles(store);
  }
  const auto& order = store.tree.order();  // the rank of each id (PointStore::rank)
  store.input_index.resize(kept);
  for_ranges(order.size(), team, [&](std::size_t, std::size_t begin, std::size_t end) {
    for (std::size_t id = begin; id < end; ++id)
      store.input_index[id] = static_cast<std::int32_t>(distinct.index[static_cast<std::size_t>(order[id])]);
  });
  return store;
}

}  // namespace drange::engine
