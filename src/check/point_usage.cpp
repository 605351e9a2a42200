// check/point_usage.cpp: finite coordinates; every distinct point used.
#include "check/point_usage.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

namespace drange::check {

bool check_coordinates(PointsView points, ProblemLog& log) {
  bool finite = true;
  for (std::size_t i = 0; i < points.n; ++i) {
    const double* p = points.point(i);
    if (std::all_of(p, p + points.dim, [](double x) { return std::isfinite(x); })) continue;
    finite = false;
    log.report([&] { return "point " + std::to_string(i) + " " + format_point(p, points.dim) + " has a non-finite coordinate"; });
  }
  return finite;
}

std::vector<std::int32_t> check_point_usage(PointsView points, const SimplexTable& table, ProblemLog& log) {
  std::vector<char> used(points.n, 0);
  for (const std::int32_t v : table.sorted)
    if (v >= 0 && static_cast<std::size_t>(v) < points.n) used[static_cast<std::size_t>(v)] = 1;
  if (std::all_of(used.begin(), used.end(), [](char u) { return u != 0; })) return {};

  // Sort the points lexicographically; in each run of equal points, the unused ones are fine
  // if some point of the run is used.
  std::vector<std::int32_t> order(points.n);
  std::iota(order.begin(), order.end(), 0);
  const int d = points.dim;
  auto less = [&](std::int32_t a, std::int32_t b) {
    const double* p = points.point(static_cast<std::size_t>(a));
    const double* q = points.point(static_cast<std::size_t>(b));
    return std::lexicographical_compare(p, p + d, q, q + d);
  };
  std::sort(order.begin(), order.end(), less);
  std::vector<std::int32_t> stray;
  for (std::size_t begin = 0; begin < order.size();) {
    std::size_t end = begin + 1;
    while (end < order.size() && !less(order[begin], order[end])) ++end;
    const bool run_used = std::any_of(order.begin() + static_cast<std::ptrdiff_t>(begin), order.begin() + static_cast<std::ptrdiff_t>(end),
                                      [&](std::int32_t i) { return used[static_cast<std::size_t>(i)] != 0; });
    if (!run_used) stray.insert(stray.end(), order.begin() + static_cast<std::ptrdiff_t>(begin), order.begin() + static_cast<std::ptrdiff_t>(end));
    begin = end;
  }
  std::sort(stray.begin(), stray.end());
  for (const std::int32_t i : stray) {
    log.report([&] {
      return "point " + std::to_string(i) + " " + format_point(points.point(static_cast<std::size_t>(i)), d) +
             " is in no simplex (and no exact copy of it is)";
    });
  }
  return stray;
}

}  // namespace drange::check
