// delaunay/hull_triangles.cpp: Quickhull in 3D with exact orientations, and the clean facets.
#include "delaunay/hull_triangles.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "delaunay/point_store.hpp"
#include "geometry/predicates.hpp"

namespace drange::engine {

namespace {

// Shewchuk's bound for orient3d's floating-point evaluation, (7 + 56 u) u relative to its
// permanent; the absolute term covers underflow.
constexpr double kOrient3Bound = (7.0 + 56.0 * 0x1p-53) * 0x1p-53;

// The exact sign of det[b - a; c - a; x - a]; `value` gets its floating-point value (a measure
// of x's height above the plane, for choosing the farthest point).
int orientation(const double* a, const double* b, const double* c, const double* x, double& value) {
  const double u0 = b[0] - a[0], u1 = b[1] - a[1], u2 = b[2] - a[2];
  const double v0 = c[0] - a[0], v1 = c[1] - a[1], v2 = c[2] - a[2];
  const double w0 = x[0] - a[0], w1 = x[1] - a[1], w2 = x[2] - a[2];
  value = u0 * (v1 * w2 - v2 * w1) + u1 * (v2 * w0 - v0 * w2) + u2 * (v0 * w1 - v1 * w0);
  const double permanent = std::fabs(u0) * (std::fabs(v1 * w2) + std::fabs(v2 * w1)) +
                           std::fabs(u1) * (std::fabs(v2 * w0) + std::fabs(v0 * w2)) +
                           std::fabs(u2) * (std::fabs(v0 * w1) + std::fabs(v1 * w0));
  const double bound = kOrient3Bound * permanent + 0x1p-1000;
  if (value > bound) return 1;
  if (value < -bound) return -1;
  const geometry::Frame frame{3, 3, nullptr, a};
  const double* rows[] = {b, c, x};
  return geometry::orientation(frame, rows);
}

// Quickhull over a set of point ids. Facets keep their vertices counter-clockwise seen from
// outside (the inside below: orientation < 0), and nb[i] is the facet across the edge
// v[i] -> v[i + 1]. Any exact zero met makes it give up (failed).
class Quickhull {
 public:
  struct Facet {
    std::int32_t v[3];
    std::int32_t nb[3];
    std::vector<std::int32_t> outside;  // points above it, not yet on the hull
    std::int32_t farthest = -1;
    double height = 0.0;
    bool alive = true;
    // (v1 - v0) x (v2 - v0) in floating point, and the sums of its terms' magnitudes: the
    // orientation of x is this . (x - v0), within Shewchuk's bound of the same form.
    double normal[3], normal_abs[3];
  };

  explicit Quickhull(const PointStore& points) : points_(points) {}

  // The hull of `ids` (at least 4 of them); false when it gave up.
  bool build(const std::vector<std::int32_t>& ids);
  const std::vector<Facet>& facets() const { return facets_; }
  // The sign of x against facet f (exact); a zero makes the hull give up.
  int side(const Facet& f, std::int32_t x, double& height) {
    const double* a = point(f.v[0]);
    const double* p = point(x);
    const double w[3] = {p[0] - a[0], p[1] - a[1], p[2] - a[2]};
    height = f.normal[0] * w[0] + f.normal[1] * w[1] + f.normal[2] * w[2];
    const double bound = kOrient3Bound * (f.normal_abs[0] * std::fabs(w[0]) + f.normal_abs[1] * std::fabs(w[1]) +
                                          f.normal_abs[2] * std::fabs(w[2])) + 0x1p-1000;
    if (height > bound) return 1;
    if (height < -bound) return -1;
    const int s = orientation(a, point(f.v[1]), point(f.v[2]), p, height);
    failed_ = failed_ || s == 0;
    return s;
  }
  // Fills in the facet's normal from its vertices.
  void set_normal(Facet& f) const {
    const double* a = point(f.v[0]);
    const double* b = point(f.v[1]);
    const double* c = point(f.v[2]);
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    for (int k = 0; k < 3; ++k) {
      const int i = (k + 1) % 3, j = (k + 2) % 3;
      f.normal[k] = u[i] * v[j] - u[j] * v[i];
      f.normal_abs[k] = std::fabs(u[i] * v[j]) + std::fabs(u[j] * v[i]);
    }
  }
  // The vertex of facet g that is not on its edge shared with f.
  std::int32_t opposite(const Facet& g, const Facet& f) const {
    for (const std::int32_t w : g.v)
      if (w != f.v[0] && w != f.v[1] && w != f.v[2]) return w;
    return -1;
  }

 private:
  const double* point(std::int32_t id) const { return points_.point(id); }
  // Puts x in the outside set of the first of `candidates` it lies above; false when it lies
  // below them all (then it is inside the hull so far).
  bool assign(std::int32_t x, const std::vector<std::int32_t>& candidates) {
    for (const std::int32_t c : candidates) {
      double height = 0.0;
      if (side(facets_[static_cast<std::size_t>(c)], x, height) <= 0) continue;
      Facet& f = facets_[static_cast<std::size_t>(c)];
      f.outside.push_back(x);
      if (f.farthest < 0 || height > f.height) {
        f.farthest = x;
        f.height = height;
      }
      return true;
    }
    return false;
  }
  bool add_point(std::int32_t facet);

  const PointStore& points_;
  std::vector<Facet> facets_;
  bool failed_ = false;
  // add_point's marks, kept across its calls (clearing them per point would be quadratic).
  std::uint32_t round_ = 0;
  std::vector<std::uint32_t> seen_;
  std::vector<char> visible_;
  // add_point's scratch lists, kept to spare an allocation per point.
  std::vector<std::int32_t> visible_facets_, created_, moved_;
  std::vector<std::int32_t> free_;  // the places of dead facets
  std::vector<std::pair<std::int32_t, std::int32_t>> by_start_, by_end_;
};

bool Quickhull::build(const std::vector<std::int32_t>& ids) {
  // The first simplex: the least and largest x, the point farthest from their line, and the
  // point farthest from their plane (by floating point; the exact sign decides).
  std::int32_t a = ids.front(), b = ids.front();
  for (const std::int32_t id : ids) {
    if (point(id)[0] < point(a)[0]) a = id;
    if (point(id)[0] > point(b)[0]) b = id;
  }
  if (a == b) return false;
  const auto cross2 = [&](std::int32_t x) {
    const double* p = point(a);
    const double u[3] = {point(b)[0] - p[0], point(b)[1] - p[1], point(b)[2] - p[2]};
    const double w[3] = {point(x)[0] - p[0], point(x)[1] - p[1], point(x)[2] - p[2]};
    const double c0 = u[1] * w[2] - u[2] * w[1], c1 = u[2] * w[0] - u[0] * w[2], c2 = u[0] * w[1] - u[1] * w[0];
    return c0 * c0 + c1 * c1 + c2 * c2;
  };
  std::int32_t c = a;
  for (const std::int32_t id : ids)
    if (cross2(id) > cross2(c)) c = id;
  std::int32_t d = a;
  double best = 0.0;
  for (const std::int32_t id : ids) {
    double height = 0.0;
    orientation(point(a), point(b), point(c), point(id), height);
    if (std::fabs(height) > best) {
      best = std::fabs(height);
      d = id;
    }
  }
  double height = 0.0;
  const int s = orientation(point(a), point(b), point(c), point(d), height);
  if (s == 0) return false;
  if (s < 0) std::swap(b, c);  // now d lies above a b c
  const std::int32_t faces[4][3] = {{a, c, b}, {a, b, d}, {b, c, d}, {c, a, d}};
  std::map<std::pair<std::int32_t, std::int32_t>, std::int32_t> edge_facet;
  for (std::int32_t f = 0; f < 4; ++f) {
    Facet facet{};
    for (int i = 0; i < 3; ++i) {
      facet.v[i] = faces[f][i];
      edge_facet[{faces[f][i], faces[f][(i + 1) % 3]}] = f;
    }
    set_normal(facet);
    facets_.push_back(std::move(facet));
  }
  for (Facet& f : facets_)
    for (int i = 0; i < 3; ++i) f.nb[i] = edge_facet.at({f.v[(i + 1) % 3], f.v[i]});
  const std::vector<std::int32_t> first = {0, 1, 2, 3};
  for (const std::int32_t id : ids) {
    if (id == a || id == b || id == c || id == d) continue;
    assign(id, first);
    if (failed_) return false;
  }
  std::vector<std::int32_t> pending = first;
  while (!pending.empty()) {
    const std::int32_t f = pending.back();
    pending.pop_back();
    const Facet& facet = facets_[static_cast<std::size_t>(f)];
    if (!facet.alive || facet.outside.empty()) continue;
    if (!add_point(f)) return false;
    for (const std::int32_t g : created_)
      if (!facets_[static_cast<std::size_t>(g)].outside.empty()) pending.push_back(g);
  }
  // Every edge strictly convex: no hull vertex lies on a neighbour's plane.
  for (const Facet& f : facets_) {
    if (!f.alive) continue;
    for (const std::int32_t g : f.nb) {
      double h = 0.0;
      if (side(f, opposite(facets_[static_cast<std::size_t>(g)], f), h) >= 0) return false;
    }
  }
  return true;
}

bool Quickhull::add_point(std::int32_t start) {
  const std::int32_t p = facets_[static_cast<std::size_t>(start)].farthest;
  // The facets that see p, from the one whose outside set it came from, across edges.
  // seen_[f] == round: f was tested this round, and visible_[f] says how it came out.
  ++round_;
  seen_.resize(facets_.size(), 0);
  visible_.resize(facets_.size(), 0);
  const auto mark = [&](std::int32_t f, bool visible) {
    seen_[static_cast<std::size_t>(f)] = round_;
    visible_[static_cast<std::size_t>(f)] = visible;
  };
  const auto hidden = [&](std::int32_t f) {
    return seen_[static_cast<std::size_t>(f)] == round_ && !visible_[static_cast<std::size_t>(f)];
  };
  std::vector<std::int32_t>& visible = visible_facets_;
  visible.assign(1, start);
  mark(start, true);
  for (std::size_t k = 0; k < visible.size(); ++k)
    for (const std::int32_t g : facets_[static_cast<std::size_t>(visible[k])].nb) {
      if (seen_[static_cast<std::size_t>(g)] == round_) continue;
      double height = 0.0;
      const int s = side(facets_[static_cast<std::size_t>(g)], p, height);
      if (failed_) return false;
      mark(g, s > 0);
      if (s > 0) visible.push_back(g);
    }
  // A new facet (u, v, p) on each horizon edge u -> v (as the visible facet winds it).
  auto& by_start = by_start_;  // vertex -> the new facet that starts there
  auto& by_end = by_end_;      // vertex -> the new facet that ends there
  std::vector<std::int32_t>& created = created_;
  by_start.clear();
  by_end.clear();
  created.clear();
  for (const std::int32_t f : visible)
    for (int i = 0; i < 3; ++i) {
      const std::int32_t g = facets_[static_cast<std::size_t>(f)].nb[i];
      if (!hidden(g)) continue;
      const std::int32_t u = facets_[static_cast<std::size_t>(f)].v[i], v = facets_[static_cast<std::size_t>(f)].v[(i + 1) % 3];
      // In the place of a facet that died at an earlier point, when there is one: the list
      // stays about as long as the hull (a growing one costs copies and page faults that show
      // on an ellipsoid's run).
      std::int32_t n = static_cast<std::int32_t>(facets_.size());
      if (!free_.empty()) {
        n = free_.back();
        free_.pop_back();
      }
      Facet facet{};
      facet.v[0] = u;
      facet.v[1] = v;
      facet.v[2] = p;
      facet.nb[0] = g;
      set_normal(facet);
      for (std::int32_t& back : facets_[static_cast<std::size_t>(g)].nb)
        if (back == f) back = n;
      if (n == static_cast<std::int32_t>(facets_.size())) facets_.push_back(std::move(facet));
      else facets_[static_cast<std::size_t>(n)] = std::move(facet);
      by_start.emplace_back(u, n);
      by_end.emplace_back(v, n);
      created.push_back(n);
    }
  const auto find = [](const std::vector<std::pair<std::int32_t, std::int32_t>>& map, std::int32_t vertex) {
    for (const auto& [key, facet] : map)
      if (key == vertex) return facet;
    return std::int32_t{-1};
  };
  for (const std::int32_t n : created) {
    Facet& facet = facets_[static_cast<std::size_t>(n)];
    facet.nb[1] = find(by_start, facet.v[1]);  // across v -> p: the new facet that starts at v
    facet.nb[2] = find(by_end, facet.v[0]);    // across p -> u: the new facet that ends at u
    if (facet.nb[1] < 0 || facet.nb[2] < 0) return false;
  }
  // The visible facets' outside points go to the new facets, or inside.
  for (const std::int32_t f : visible) {
    Facet& facet = facets_[static_cast<std::size_t>(f)];
    facet.alive = false;
    std::vector<std::int32_t>& outside = moved_;
    outside.swap(facet.outside);
    facet.outside.clear();
    facet.outside.shrink_to_fit();
    for (const std::int32_t x : outside) {
      if (x == p) continue;
      assign(x, created);
      if (failed_) return false;
    }
  }
  free_.insert(free_.end(), visible.begin(), visible.end());
  return true;
}

}  // namespace

HullTriangles::HullTriangles(const PointStore& points, std::size_t sample, std::size_t least_facets) {
  const auto n = static_cast<std::size_t>(points.size);
  if (points.dim != 3 || n < 4) return;
  // The sample: ids spread over the tree order, so over space.
  std::vector<std::int32_t> ids;
  const std::size_t step = std::max<std::size_t>(1, n / std::max<std::size_t>(sample, 4));
  for (std::size_t id = 0; id < n; id += step) ids.push_back(static_cast<std::int32_t>(id));
  if (ids.size() < 4) return;
  if (ids.size() < n) {
    Quickhull trial(points);
    if (!trial.build(ids)) return;
    std::vector<char> vertex(n, 0);
    std::size_t vertices = 0;
    for (const auto& f : trial.facets())
      if (f.alive)
        for (const std::int32_t v : f.v) vertices += vertex[static_cast<std::size_t>(v)]++ == 0;
    if (vertices * 4 <= ids.size() * 3) return;
    ids.resize(n);
    for (std::size_t id = 0; id < n; ++id) ids[id] = static_cast<std::int32_t>(id);
  }
  built_ = true;
  Quickhull hull(points);
  if (!hull.build(ids)) return;
  // Each clean facet under its least id, with the sign of O on the outside.
  std::vector<std::pair<std::int32_t, Entry>> clean;
  for (const auto& f : hull.facets()) {
    if (!f.alive) continue;
    std::int32_t s[3] = {f.v[0], f.v[1], f.v[2]};
    std::sort(s, s + 3);
    // f.v winds counter-clockwise from outside; sorting by id is an even or odd permutation.
    const bool even = (s[0] == f.v[0] && s[1] == f.v[1]) || (s[0] == f.v[1] && s[1] == f.v[2]) || (s[0] == f.v[2] && s[1] == f.v[0]);
    // O(x) = det[f1 - f0; f2 - f0; x - f0] is < 0 inside for the facet's own winding.
    clean.push_back({s[0], Entry{s[1], s[2], even ? 1 : -1}});
  }
  if (clean.size() < least_facets) return;
  std::sort(clean.begin(), clean.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  first_.assign(n + 1, 0);
  for (const auto& [f0, entry] : clean) ++first_[static_cast<std::size_t>(f0) + 1];
  for (std::size_t i = 0; i < n; ++i) first_[i + 1] += first_[i];
  entries_.reserve(clean.size());
  for (const auto& [f0, entry] : clean) entries_.push_back(entry);
}

}  // namespace drange::engine
