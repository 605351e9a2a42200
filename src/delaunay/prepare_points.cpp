// delaunay/prepare_points.cpp: validation, duplicates, lexicographic ranks, kd-tree order.
#include "delaunay/prepare_points.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

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

// Sorts `values` by `less`, a strict total order (so the result does not depend on how the
// work is split): consecutive parts sorted at the same time, then merged pairwise.
template <class Less>
void sort_in_parallel(std::vector<std::int64_t>& values, Less less, Team& team) {
  constexpr std::size_t kMinPart = std::size_t{1} << 15;
  const std::size_t parts = std::min(static_cast<std::size_t>(team.threads()), values.size() / kMinPart);
  if (parts < 2) {
    std::sort(values.begin(), values.end(), less);
    return;
  }
  std::vector<std::size_t> bounds;  // part i is [bounds[i], bounds[i + 1])
  for (std::size_t i = 0; i <= parts; ++i) bounds.push_back(values.size() * i / parts);
  team.for_each(parts, [&](std::size_t i) {
    std::sort(values.begin() + static_cast<std::ptrdiff_t>(bounds[i]), values.begin() + static_cast<std::ptrdiff_t>(bounds[i + 1]), less);
  });
  std::vector<std::int64_t> merged(values.size());
  while (bounds.size() > 2) {
    team.for_each(bounds.size() / 2, [&](std::size_t p) {
      const auto at = [](std::vector<std::int64_t>& v, std::size_t i) { return v.begin() + static_cast<std::ptrdiff_t>(i); };
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

}  // namespace

PointStore prepare_points(PointsView input, int leaf_size, std::vector<Duplicate>& duplicates, Team& team) {
  check_input(input);
  const int d = input.dim;
  auto less = [&](std::int64_t a, std::int64_t b) {
    const double* p = input.point(static_cast<std::size_t>(a));
    const double* q = input.point(static_cast<std::size_t>(b));
    for (int k = 0; k < d; ++k)
      if (p[k] != q[k]) return p[k] < q[k];
    return a < b;  // equal points: the first input index is the original
  };
  std::vector<std::int64_t> lex(input.n);
  std::iota(lex.begin(), lex.end(), 0);
  sort_in_parallel(lex, less, team);

  // Distinct points in lexicographic order: their position is their rank.
  std::vector<std::int64_t> distinct;
  distinct.reserve(input.n);
  duplicates.clear();
  for (std::size_t i = 0; i < lex.size(); ++i) {
    if (!distinct.empty() &&
        std::equal(input.point(static_cast<std::size_t>(lex[i])), input.point(static_cast<std::size_t>(lex[i])) + d,
                   input.point(static_cast<std::size_t>(distinct.back())))) {
      duplicates.push_back(Duplicate{lex[i], distinct.back()});
      continue;
    }
    distinct.push_back(lex[i]);
  }
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
  store.tree.build(by_rank.data(), store.size, d, leaf_size, team.threads());
  const std::vector<std::int32_t>& order = store.tree.order();
  store.coords.resize(by_rank.size());
  store.rank.resize(distinct.size());
  store.input_index.resize(distinct.size());
  for (std::size_t id = 0; id < order.size(); ++id) {
    const auto r = static_cast<std::size_t>(order[id]);
    std::copy_n(by_rank.begin() + static_cast<std::ptrdiff_t>(r * static_cast<std::size_t>(d)), d,
                store.coords.begin() + static_cast<std::ptrdiff_t>(id * static_cast<std::size_t>(d)));
    store.rank[id] = static_cast<std::int64_t>(r);
    store.input_index[id] = distinct[r];
  }
  return store;
}

}  // namespace drange::engine
