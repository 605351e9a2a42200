// delaunay/hull_edges.hpp: the clean edges of a planar point set's convex hull (ours,
// SearchOptions::known_hull_facets).
//
// Why: a hull facet's search proves that its open side holds no point, and on points in convex
// position (an ellipse, a circle) half the facets are hull edges, each searched along the
// boundary, where every kd-tree box near the edge reaches across its line: a large share of the
// search time on points on a circle or an ellipse. In the plane the hull is cheap to
// know beforehand, exactly: Andrew's monotone chain over the points in lexicographic order (the
// engine's ranks), with exact orientations.
//
// A hull edge is clean when no other point lies on its line: every other point is then strictly
// inside, whatever the symbolic perturbation (which moves only the lifted coordinate), so the
// facet on it has no apex on its outer side, and its search can be skipped. An edge with
// points on it is left to the search.
//
// Only the points that may lie on the hull take part: an octagon of extreme points (input
// points, so it lies within the hull) proves the rest strictly inside, whole kd-tree leaves at
// a time, with a floating-point filter that leaves in every point it cannot decide.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace drange::engine {

struct PointStore;

class HullEdges {
 public:
  HullEdges() = default;
  // The clean hull edges of `points` (2D; any other dimension keeps none). Kept only when
  // there are at least `least_edges` of them and one per `points_per_edge` points: a per-point
  // array would cost more than the searches it saves on points with a small hull (uniform
  // input). The tests lower the bounds.
  explicit HullEdges(const PointStore& points, std::size_t least_edges = kLeastEdges,
                     std::size_t points_per_edge = kPointsPerEdge);

  // The sign sigma for which the facet (f0, f1)'s open side, sigma O(x) > 0 with
  // O(x) = det[f1 - f0; x - f0], is the outside of the hull, when f0 f1 is a clean hull edge;
  // 0 otherwise.
  int outer_sigma(std::int32_t f0, std::int32_t f1) const {
    if (next_.empty()) return 0;
    if (next_[static_cast<std::size_t>(f0)] == f1) return -1;  // counter-clockwise f0 -> f1: inside is O > 0
    if (next_[static_cast<std::size_t>(f1)] == f0) return 1;
    return 0;
  }
  bool active() const { return !next_.empty(); }
  // How many clean edges were found (also when too few to keep).
  std::size_t clean_edges() const { return clean_; }
  // How many points the octagon left to the monotone chain.
  std::size_t candidates() const { return candidates_; }

  static constexpr std::size_t kLeastEdges = 256;
  static constexpr std::size_t kPointsPerEdge = 1024;

 private:
  // Per point id: its counter-clockwise successor on the hull when the edge between them is
  // clean, else -1; empty when not kept.
  std::vector<std::int32_t> next_;
  std::size_t clean_ = 0;
  std::size_t candidates_ = 0;
};

}  // namespace drange::engine
