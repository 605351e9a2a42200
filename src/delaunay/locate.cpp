// delaunay/locate.cpp: exact point location by a stochastic visibility walk (see locate.hpp).
#include "drange/locate.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "delaunay/team.hpp"
#include "drange/errors.hpp"
#include "geometry/predicates.hpp"
#include "spatial/kdtree.hpp"

namespace drange {

struct SimplexLocator::Impl {
  PointsView points;
  const std::int32_t* simplices = nullptr;
  const std::int32_t* neighbors = nullptr;
  std::size_t num_simplices = 0;
  int d = 0;
  std::vector<std::int32_t> vertex_simplex;  // per input point: a simplex holding it, or -1
  // The vertices in kd-tree order, for the nearest-vertex start of each walk.
  spatial::KdTree tree;
  std::vector<std::int32_t> tree_vertex;  // tree position -> input index
  std::vector<double> tree_coords;        // tree position -> coordinates

  std::size_t width() const { return static_cast<std::size_t>(d + 1); }
  const std::int32_t* simplex(std::int32_t s) const { return simplices + static_cast<std::size_t>(s) * width(); }

  std::int32_t nearest_vertex(const double* q) const;
  std::int32_t walk(std::int32_t s, const double* q, std::uint64_t seed) const;
  std::int32_t scan(const double* q) const;
  // Whether q is strictly beyond facet k of simplex s (on the side away from vertex k).
  bool beyond(std::int32_t s, int k, const double* q) const;
};

namespace {

std::uint64_t next_random(std::uint64_t& state) {  // splitmix64
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// Nearest vertex to q in the kd-tree (an approximate answer would do: it only starts the walk).
class NearestVisitor {
 public:
  NearestVisitor(const double* q, int d, const std::vector<double>& coords)
      : q_(q), d_(d), coords_(coords),
        lower_(static_cast<std::size_t>(d), -std::numeric_limits<double>::infinity()),
        upper_(static_cast<std::size_t>(d), std::numeric_limits<double>::infinity()) {}
  const double* query_lower() const { return lower_.data(); }
  const double* query_upper() const { return upper_.data(); }
  bool prune(std::int32_t, bool) const { return false; }
  bool right_first(const spatial::KdTree::Node& node) const { return q_[node.split_axis] > node.split_value; }
  void leaf(std::int32_t /*node*/, std::int32_t begin, std::int32_t end) {
    for (std::int32_t pos = begin; pos < end; ++pos) {
      const double* p = coords_.data() + static_cast<std::size_t>(pos) * static_cast<std::size_t>(d_);
      double dist = 0;
      for (int k = 0; k < d_; ++k) dist += (p[k] - q_[k]) * (p[k] - q_[k]);
      if (dist >= best_) continue;
      best_ = dist;
      best_position_ = pos;
      const double r = std::sqrt(dist);
      for (int k = 0; k < d_; ++k) {
        lower_[static_cast<std::size_t>(k)] = q_[k] - r;
        upper_[static_cast<std::size_t>(k)] = q_[k] + r;
      }
    }
  }
  std::int32_t best_position() const { return best_position_; }

 private:
  const double* q_;
  int d_;
  const std::vector<double>& coords_;
  std::vector<double> lower_, upper_;
  double best_ = std::numeric_limits<double>::infinity();
  std::int32_t best_position_ = 0;
};

}  // namespace

SimplexLocator::SimplexLocator(PointsView points, const std::int32_t* simplices, const std::int32_t* neighbors,
                               std::size_t num_simplices)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  if (points.dim < 2) throw UsageError("locate: points must have a dimension of at least 2");
  if (num_simplices == 0 || !simplices || !neighbors) throw UsageError("locate: the triangulation has no simplices or no neighbours");
  m.points = points;
  m.simplices = simplices;
  m.neighbors = neighbors;
  m.num_simplices = num_simplices;
  m.d = points.dim;
  m.vertex_simplex.assign(points.n, -1);
  for (std::size_t s = 0; s < num_simplices; ++s)
    for (std::size_t k = 0; k < m.width(); ++k) {
      const std::int32_t v = simplices[s * m.width() + k];
      if (v < 0 || static_cast<std::size_t>(v) >= points.n)
        throw UsageError("locate: simplex " + std::to_string(s) + " has vertex " + std::to_string(v) +
                         ", not a point index below " + std::to_string(points.n));
      m.vertex_simplex[static_cast<std::size_t>(v)] = static_cast<std::int32_t>(s);
    }
  std::vector<std::int32_t> vertices;
  std::vector<double> coords;
  for (std::size_t i = 0; i < points.n; ++i)
    if (m.vertex_simplex[i] >= 0) {
      vertices.push_back(static_cast<std::int32_t>(i));
      coords.insert(coords.end(), points.point(i), points.point(i) + m.d);
    }
  m.tree.build(coords.data(), static_cast<std::int32_t>(vertices.size()), m.d);
  for (const std::int32_t index : m.tree.order()) {
    m.tree_vertex.push_back(vertices[static_cast<std::size_t>(index)]);
    const double* p = coords.data() + static_cast<std::size_t>(index) * static_cast<std::size_t>(m.d);
    m.tree_coords.insert(m.tree_coords.end(), p, p + m.d);
  }
}

SimplexLocator::SimplexLocator(PointsView points, const Triangulation& triangulation)
    : SimplexLocator(points, triangulation.simplices.data(),
                     triangulation.neighbors.empty() ? nullptr : triangulation.neighbors.data(), triangulation.size()) {}

SimplexLocator::SimplexLocator(SimplexLocator&&) noexcept = default;
SimplexLocator& SimplexLocator::operator=(SimplexLocator&&) noexcept = default;
SimplexLocator::~SimplexLocator() = default;

std::int32_t SimplexLocator::Impl::nearest_vertex(const double* q) const {
  NearestVisitor visitor(q, d, tree_coords);
  tree.search(visitor);
  return tree_vertex[static_cast<std::size_t>(visitor.best_position())];
}

bool SimplexLocator::Impl::beyond(std::int32_t s, int k, const double* q) const {
  const double* rows[16];
  const std::int32_t* v = simplex(s);
  for (int i = 0; i <= d; ++i) rows[i] = i == k ? q : points.point(static_cast<std::size_t>(v[i]));
  // The simplex is positive; replacing vertex k by q flips the sign exactly when q is on the
  // other side of facet k.
  return geometry::simplex_orientation(d, rows) < 0;
}

std::int32_t SimplexLocator::Impl::walk(std::int32_t s, const double* q, std::uint64_t seed) const {
  // A walk visits each simplex at most a few times in practice; the bound only guards against
  // an unlucky random sequence, after which a scan answers.
  const std::size_t limit = 4 * num_simplices + 64;
  std::int32_t previous = -1;
  for (std::size_t step = 0; step < limit; ++step) {
    const int first = static_cast<int>(next_random(seed) % width());
    std::int32_t next = -2;  // -2: q is in the closed simplex
    for (int t = 0; t <= d && next == -2; ++t) {
      const int k = (first + t) % (d + 1);
      const std::int32_t across = neighbors[static_cast<std::size_t>(s) * width() + static_cast<std::size_t>(k)];
      if (across >= 0 && across == previous) continue;  // q is on this simplex's side of it
      if (beyond(s, k, q)) next = across;
    }
    if (next == -2) return s;
    if (next == -1) return -1;  // beyond a hull facet: outside the convex hull
    previous = s;
    s = next;
  }
  return scan(q);
}

std::int32_t SimplexLocator::Impl::scan(const double* q) const {
  for (std::size_t s = 0; s < num_simplices; ++s) {
    bool inside = true;
    for (int k = 0; k <= d && inside; ++k) inside = !beyond(static_cast<std::int32_t>(s), k, q);
    if (inside) return static_cast<std::int32_t>(s);
  }
  return -1;
}

std::int32_t SimplexLocator::find(const double* q) const {
  const Impl& m = *impl_;
  std::uint64_t seed = 0x5EED;
  for (int k = 0; k < m.d; ++k) {
    if (!std::isfinite(q[k])) return -1;
    seed = seed * 31 + static_cast<std::uint64_t>(std::hash<double>()(q[k]));
  }
  const std::int32_t start = m.vertex_simplex[static_cast<std::size_t>(m.nearest_vertex(q))];
  return m.walk(start, q, seed);
}

namespace {

// The queries in Z order (Morton order of their coordinates quantised over their bounding
// box): consecutive walks then read neighbouring simplices, which are in cache. Non-finite
// queries come last (they need no walk).
std::vector<std::int32_t> spatial_order(PointsView queries) {
  const int d = queries.dim;
  std::vector<double> lo(static_cast<std::size_t>(d), std::numeric_limits<double>::infinity());
  std::vector<double> hi(static_cast<std::size_t>(d), -std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < queries.n; ++i)
    for (int k = 0; k < d; ++k) {
      const double x = queries.point(i)[k];
      if (!std::isfinite(x)) continue;
      lo[static_cast<std::size_t>(k)] = std::min(lo[static_cast<std::size_t>(k)], x);
      hi[static_cast<std::size_t>(k)] = std::max(hi[static_cast<std::size_t>(k)], x);
    }
  const int bits = 63 / d;  // per coordinate; the top code stays free for non-finite queries
  const double cells = std::ldexp(1.0, bits);
  std::vector<std::pair<std::uint64_t, std::int32_t>> keyed(queries.n);
  for (std::size_t i = 0; i < queries.n; ++i) {
    const double* q = queries.point(i);
    bool finite = true;
    for (int k = 0; k < d; ++k) finite = finite && std::isfinite(q[k]);
    std::uint64_t code = finite ? 0 : ~std::uint64_t{0};
    if (finite) {
      for (int k = 0; k < d; ++k) {
        const double extent = hi[static_cast<std::size_t>(k)] - lo[static_cast<std::size_t>(k)];
        const double cell = extent > 0 ? (q[k] - lo[static_cast<std::size_t>(k)]) / extent * cells : 0.0;
        const auto c = static_cast<std::uint64_t>(std::min(std::max(cell, 0.0), cells - 1));
        for (int b = 0; b < bits; ++b) code |= ((c >> b) & 1u) << (b * d + k);
      }
    }
    keyed[i] = {code, static_cast<std::int32_t>(i)};
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<std::int32_t> order(queries.n);
  for (std::size_t i = 0; i < queries.n; ++i) order[i] = keyed[i].second;
  return order;
}

}  // namespace

void SimplexLocator::find(PointsView queries, std::int32_t* out, int threads) const {
  if (queries.dim != impl_->d)
    throw UsageError("locate: query points have dimension " + std::to_string(queries.dim) +
                     ", the triangulation has dimension " + std::to_string(impl_->d));
  if (threads < 0) throw UsageError("locate: threads must be 0 (all hardware threads) or a positive count, got " + std::to_string(threads));
  if (queries.n >= static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
    throw UsageError("locate: " + std::to_string(queries.n) + " queries are more than the limit of 2^31 - 2 at once");
  // Each answer depends on its query alone (the walk starts at the query's nearest vertex, and
  // its random sequence is seeded by the coordinates), so neither the order in which the
  // queries are walked nor their split among the threads changes the output. Many queries are
  // walked in Z order, so that consecutive walks touch nearby simplices (on random queries,
  // several times faster than input order, the sort included); a chunk is long enough that
  // taking it costs nothing next to its walks.
  constexpr std::size_t kChunk = 4096;
  const std::vector<std::int32_t> order = queries.n > kChunk ? spatial_order(queries) : std::vector<std::int32_t>{};
  const std::size_t chunks = (queries.n + kChunk - 1) / kChunk;
  engine::Team team(chunks > 1 ? engine::resolve_threads(threads) : 1);
  team.for_each(chunks, [&](std::size_t chunk) {
    const std::size_t end = std::min(queries.n, (chunk + 1) * kChunk);
    for (std::size_t i = chunk * kChunk; i < end; ++i) {
      const std::size_t q = order.empty() ? i : static_cast<std::size_t>(order[i]);
      out[q] = find(queries.point(q));
    }
  });
}

}  // namespace drange
