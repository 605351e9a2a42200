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

namespace drange::engine {

namespace {
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
bool scale_by_power_of_two(std::vector<double>& coords) {
  double largest = 0.0, smallest = std::numeric_limits<double>::infinity();
  for (double x : coords) {
    if (x == 0.0) continue;
    largest = std::max(largest, std::fabs(x));
    smallest = std::min(smallest, std::fabs(x));
  }
  if (largest == 0.0) return true;
  int exponent = 0;
  std::frexp(largest, &exponent);
  // ldexp shifts each value exactly, even when 2^-exponent itself is not a double (inputs
  // below 2^-1022).
  if (std::ldexp(smallest, -exponent) < std::numeric_limits<double>::min()) return false;  // would lose the smallest
  for (double& x : coords) x = std::ldexp(x, -exponent);
  return true;
}

// Finds the common power-of-two unit of all coordinates; a dyadic point set has its largest
// magnitude below 2^50 units, so that every difference of two coordinates is exact.
void mark_dyadic(const std::vector<double>& coords, PointStore& store) {
  int unit = std::numeric_limits<int>::max();
  double largest = 0.0;
  for (double x : coords) {
    if (x == 0.0) continue;
    unit = std::min(unit, geometry::lowest_bit_exponent(x));
    largest = std::max(largest, std::fabs(x));
  }
  store.unit_exponent = unit;
  store.dyadic = unit != std::numeric_limits<int>::max() && largest < std::ldexp(1.0, 50 + unit);
}

// The input indices in lexicographic order of the points (ties: the lower index first).
std::vector<std::int64_t> lexicographic_order(PointsView input) {
  const int d = input.dim;
  std::vector<std::int64_t> lex(input.n);
  std::iota(lex.begin(), lex.end(), 0);
  std::sort(lex.begin(), lex.end(), [&](std::int64_t a, std::int64_t b) {
    const double* p = input.point(static_cast<std::size_t>(a));
    const double* q = input.point(static_cast<std::size_t>(b));
    for (int k = 0; k < d; ++k)
      if (p[k] != q[k]) return p[k] < q[k];
    return a < b;  // equal points: the first input index is the original
  });
  return lex;
}

// The same order, sorting the points themselves next to their index (fixed d: contiguous
// memory instead of an indirection per comparison). The order is total, so the result is the
// same permutation.
template <int D>
std::vector<std::int64_t> lexicographic_order_fixed(PointsView input) {
  struct Item {
    double x[D];
    std::int64_t index;
  };
  std::vector<Item> items(input.n);
  for (std::size_t i = 0; i < input.n; ++i) {
    std::copy_n(input.point(i), D, items[i].x);
    items[i].index = static_cast<std::int64_t>(i);
  }
  std::sort(items.begin(), items.end(), [](const Item& a, const Item& b) {
    for (int k = 0; k < D; ++k)
      if (a.x[k] != b.x[k]) return a.x[k] < b.x[k];
    return a.index < b.index;
  });
  std::vector<std::int64_t> lex(input.n);
  for (std::size_t i = 0; i < input.n; ++i) lex[i] = items[i].index;
  return lex;
}

}  // namespace

PointStore prepare_points(PointsView input, int leaf_size, std::vector<Duplicate>& duplicates) {
  check_input(input);
  const int d = input.dim;
  // Distinct points in lexicographic order: their position is their rank. The order is
  // compacted in place (a duplicate follows its original, the first input index).
  std::vector<std::int64_t> distinct = d == 2   ? lexicographic_order_fixed<2>(input)
                                       : d == 3 ? lexicographic_order_fixed<3>(input)
                                       : d == 4 ? lexicographic_order_fixed<4>(input)
                                                : lexicographic_order(input);
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
  for (std::size_t r = 0; r < distinct.size(); ++r)
    std::copy_n(input.point(static_cast<std::size_t>(distinct[r])), d, by_rank.begin() + static_cast<std::ptrdiff_t>(r * static_cast<std::size_t>(d)));
  store.scaled = scale_by_power_of_two(by_rank);
  mark_dyadic(by_rank, store);
  store.tree.build_and_reorder(by_rank.data(), store.size, d, leaf_size);
  store.coords = std::move(by_rank);  // now in tree order
  const std::vector<std::int32_t>& order = store.tree.order();
  store.rank.resize(distinct.size());
  store.input_index.resize(distinct.size());
  for (std::size_t id = 0; id < order.size(); ++id) {
    const auto r = static_cast<std::size_t>(order[id]);
    store.rank[id] = static_cast<std::int64_t>(r);
    store.input_index[id] = distinct[r];
  }
  return store;
}

}  // namespace drange::engine
