// delaunay/hull_edges.cpp: the octagon of extreme points, the monotone chain, the clean edges.
#include "delaunay/hull_edges.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include "delaunay/point_store.hpp"
#include "geometry/predicates.hpp"

namespace drange::engine {

namespace {

// Shewchuk's bound for orient2d's floating-point evaluation, (3 + 16 u) u relative to the sum of
// the two products' magnitudes; the absolute term covers underflow.
constexpr double kOrientBound = (3.0 + 16.0 * 0x1p-53) * 0x1p-53;
constexpr double kUnderflowSlack = 0x1p-1000;

struct Determinant {
  double value, bound;
};

// det[b - a; c - a] in floating point, with a bound of its error.
Determinant orient_float(const double* a, const double* b, const double* c) {
  const double left = (b[0] - a[0]) * (c[1] - a[1]);
  const double right = (b[1] - a[1]) * (c[0] - a[0]);
  return {left - right, kOrientBound * (std::fabs(left) + std::fabs(right)) + kUnderflowSlack};
}

// Whether c lies strictly to the left of the line a -> b, certainly (false when the filter
// cannot tell).
bool certainly_left(const double* a, const double* b, const double* c) {
  const Determinant det = orient_float(a, b, c);
  return det.value > det.bound;
}

// The exact sign of det[b - a; c - a].
int orientation(const double* a, const double* b, const double* c) {
  const Determinant det = orient_float(a, b, c);
  if (det.value > det.bound) return 1;
  if (det.value < -det.bound) return -1;
  const geometry::Frame frame{2, 2, nullptr, a};
  const double* rows[] = {b, c};
  return geometry::orientation(frame, rows);
}

// The ids of points that maximise u . x over the tree, for the eight directions u with
// components in {-1, 0, 1}, counter-clockwise from (1, 0): branch and bound over the boxes.
// Any maximiser of the rounded u . x will do: the octagon only has to be made of input points.
std::array<std::int32_t, 8> extreme_points(const PointStore& points) {
  constexpr int kDirections[8][2] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}};
  const spatial::KdTree& tree = points.tree;
  std::array<std::int32_t, 8> extreme{};
  std::vector<std::int32_t> stack;
  for (int j = 0; j < 8; ++j) {
    const double ux = kDirections[j][0], uy = kDirections[j][1];
    const auto box_best = [&](std::int32_t node) {
      const double* lo = tree.lower<2>(node);
      const double* hi = tree.upper<2>(node);
      return ux * (ux > 0 ? hi[0] : lo[0]) + uy * (uy > 0 ? hi[1] : lo[1]);
    };
    double best = -std::numeric_limits<double>::infinity();
    extreme[static_cast<std::size_t>(j)] = 0;
    stack.assign(1, 0);
    while (!stack.empty()) {
      const std::int32_t node = stack.back();
      stack.pop_back();
      if (!(box_best(node) > best)) continue;
      const spatial::KdTree::Node& n = tree.nodes()[static_cast<std::size_t>(node)];
      if (n.right >= 0) {
        stack.push_back(n.right);
        stack.push_back(node + 1);
        continue;
      }
      for (std::int32_t id = n.begin; id < n.end; ++id) {
        const double* x = points.point(id);
        const double score = ux * x[0] + uy * x[1];
        if (score > best) {
          best = score;
          extreme[static_cast<std::size_t>(j)] = id;
        }
      }
    }
  }
  return extreme;
}

// The points that the octagon of extreme points cannot prove strictly inside the hull, as
// (rank, id), in rank order (lexicographic). The octagon's edges counter-clockwise; a point
// strictly left of every edge of a closed polygon whose vertices are input points is strictly
// inside their convex hull, convex polygon or not.
std::vector<std::pair<std::int64_t, std::int32_t>> hull_candidates(const PointStore& points) {
  const std::array<std::int32_t, 8> extreme = extreme_points(points);
  std::vector<std::int32_t> octagon;
  for (const std::int32_t id : extreme)
    if (octagon.empty() || octagon.back() != id) octagon.push_back(id);
  while (octagon.size() > 1 && octagon.back() == octagon.front()) octagon.pop_back();
  const auto inside = [&](const double* x) {
    if (octagon.size() < 3) return false;
    for (std::size_t i = 0; i < octagon.size(); ++i) {
      const double* a = points.point(octagon[i]);
      const double* b = points.point(octagon[(i + 1) % octagon.size()]);
      if (!certainly_left(a, b, x)) return false;
    }
    return true;
  };
  const spatial::KdTree& tree = points.tree;
  std::vector<std::pair<std::int64_t, std::int32_t>> candidates;
  std::vector<std::int32_t> stack(1, 0);
  while (!stack.empty()) {
    const std::int32_t node = stack.back();
    stack.pop_back();
    const double* lo = tree.lower<2>(node);
    const double* hi = tree.upper<2>(node);
    const double corners[4][2] = {{lo[0], lo[1]}, {hi[0], lo[1]}, {hi[0], hi[1]}, {lo[0], hi[1]}};
    if (std::all_of(std::begin(corners), std::end(corners), [&](const double* c) { return inside(c); })) continue;
    const spatial::KdTree::Node& n = tree.nodes()[static_cast<std::size_t>(node)];
    if (n.right >= 0) {
      stack.push_back(n.right);
      stack.push_back(node + 1);
      continue;
    }
    for (std::int32_t id = n.begin; id < n.end; ++id)
      if (!inside(points.point(id))) candidates.emplace_back(points.rank(id), id);
  }
  // Into rank order: many candidates (points in convex position) by a scatter over all ranks,
  // which costs a pass over n ints, few by sorting, which then costs much less than that pass.
  const auto n = static_cast<std::size_t>(points.size);
  if (candidates.size() * 8 < n) {
    std::sort(candidates.begin(), candidates.end());
    return candidates;
  }
  std::vector<std::int32_t> id_of_rank(n, -1);
  for (const auto& [rank, id] : candidates) id_of_rank[static_cast<std::size_t>(rank)] = id;
  candidates.clear();
  for (std::size_t rank = 0; rank < n; ++rank)
    if (id_of_rank[rank] >= 0) candidates.emplace_back(static_cast<std::int64_t>(rank), id_of_rank[rank]);
  return candidates;
}

}  // namespace

HullEdges::HullEdges(const PointStore& points, std::size_t least_edges, std::size_t points_per_edge) {
  if (points.dim != 2 || points.size < 3) return;
  const auto candidates = hull_candidates(points);
  candidates_ = candidates.size();
  if (candidates.size() < 3) return;
  const auto point = [&](std::size_t i) { return points.point(candidates[i].second); };
  // Andrew's monotone chain, strict (collinear points are dropped), as positions in
  // `candidates`: the lower hull left to right, then the upper hull right to left, each with
  // the inside on its left. A point certainly above the line from the first to the last is no
  // vertex of the lower hull, and one certainly below none of the upper, so each chain skips
  // them and spares their orientations.
  const double* first = point(0);
  const double* last = point(candidates.size() - 1);
  const auto chain = [&](bool lower) {
    std::vector<std::size_t> hull;
    for (std::size_t step = 0; step < candidates.size(); ++step) {
      const std::size_t i = lower ? step : candidates.size() - 1 - step;
      if (certainly_left(lower ? first : last, lower ? last : first, point(i))) continue;
      while (hull.size() >= 2 && orientation(point(hull[hull.size() - 2]), point(hull.back()), point(i)) <= 0) hull.pop_back();
      hull.push_back(i);
    }
    return hull;
  };
  const std::vector<std::size_t> lower = chain(true), upper = chain(false);
  if (lower.size() + upper.size() < 5) return;  // fewer than 3 hull vertices: all collinear
  // An edge is clean when no point lies on it; such a point lies between its ends in rank
  // order, and is a candidate (the octagon leaves in every point on the hull's boundary).
  std::vector<std::pair<std::int32_t, std::int32_t>> clean;
  clean.reserve(lower.size() + upper.size());
  for (const auto* part : {&lower, &upper})
    for (std::size_t e = 0; e + 1 < part->size(); ++e) {
      const std::size_t a = (*part)[e], b = (*part)[e + 1];
      bool on_edge = false;
      for (std::size_t q = std::min(a, b) + 1; q < std::max(a, b) && !on_edge; ++q)
        on_edge = orientation(point(a), point(b), point(q)) == 0;
      if (!on_edge) clean.emplace_back(candidates[a].second, candidates[b].second);
    }
  clean_ = clean.size();
  if (clean_ < least_edges || clean_ * points_per_edge < static_cast<std::size_t>(points.size)) return;
  next_.assign(static_cast<std::size_t>(points.size), -1);
  for (const auto& [from, to] : clean) next_[static_cast<std::size_t>(from)] = to;
}

}  // namespace drange::engine
