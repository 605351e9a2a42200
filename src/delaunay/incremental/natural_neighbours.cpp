// delaunay/incremental/natural_neighbours.cpp: Sibson's natural-neighbour coordinates, from
// the cells a query point would take over if it were inserted.
//
// Inserting x removes the cells in conflict with it (their circumspheres hold x) and joins x to
// the facets of the cavity they leave. x's Voronoi cell V(x) takes from the cell V_i of each
// vertex i of the cavity the part V(x) ∩ V_i, and i's coordinate is its volume over their sum,
// vol(V(x)). A cell's volume is the sum of its parts over the Delaunay simplices around its
// point (the flag decomposition, voronoi/flag_volumes.hpp), and only the removed and the new
// simplices change: what V_i loses is its parts in the removed simplices less its parts in the
// new ones. The identity is local, so it holds for a cell of the hull too (unbounded before and
// after), as long as x is inside the hull and every removed simplex is finite.
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "delaunay/incremental/incremental_state.hpp"
#include "drange/errors.hpp"
#include "util/check_points.hpp"
#include "voronoi/flag_volumes.hpp"

namespace drange {
namespace {

// The probe's point: the query x made point `id` (the caller's coordinates appended, the
// scaled copy, the largest rank) for the length of one probe; its destructor takes it out.
class QueryPoint {
 public:
  QueryPoint(IncrementalDelaunay::State& s, const double* x) : s_(s), id_(static_cast<std::int32_t>(s.ranks.size())) {
    const auto d = static_cast<std::size_t>(s.dim);
    s.input.insert(s.input.end(), x, x + d);
    for (std::size_t k = 0; k < d; ++k) {
      // Every point is below 2^exponent in magnitude: a coordinate as large is outside their
      // box. The scaling is exact but for a coordinate that becomes subnormal, far below the
      // points' scale, which is rounded (by less than the smallest double): the coordinates
      // are continuous in x, so the weights do not notice.
      const double scaled = s.view.scaled ? std::ldexp(x[k], -s.exponent) : x[k];
      if (std::fabs(scaled) >= 1.0 && s.view.scaled) outside_box_ = true;
      s.coords.push_back(scaled);
    }
    s.ranks.push_back(static_cast<std::int32_t>(s.lex.size()));
    s.view = engine::KernelPoints{s.dim, s.coords.data(), s.ranks.data(), s.view.scaled};
  }
  ~QueryPoint() {
    const auto d = static_cast<std::size_t>(s_.dim);
    s_.input.resize(s_.input.size() - d);
    s_.coords.resize(s_.coords.size() - d);
    s_.ranks.pop_back();
    s_.view = engine::KernelPoints{s_.dim, s_.coords.data(), s_.ranks.data(), s_.view.scaled};
  }
  QueryPoint(const QueryPoint&) = delete;
  QueryPoint& operator=(const QueryPoint&) = delete;

  std::int32_t id() const { return id_; }
  bool outside_box() const { return outside_box_; }

 private:
  IncrementalDelaunay::State& s_;
  std::int32_t id_;
  bool outside_box_ = false;
};

// Appends the coordinates of query x to `out`.
void append_coordinates(IncrementalDelaunay::State& s, const double* x,
                        diagram::SimplexCellParts& parts, IncrementalDelaunay::NaturalNeighbours& out) {
  const int d = s.dim;
  const QueryPoint q(s, x);
  if (q.outside_box()) return;
  const auto copy = std::lower_bound(s.lex.begin(), s.lex.end(), q.id(), [&](std::int32_t a, std::int32_t b) { return s.less(a, b); });
  if (copy != s.lex.end() && s.same(*copy, q.id())) {
    out.ids.push_back(*copy);
    out.weights.push_back(1.0);
    return;
  }
  const engine::Insertion& insertion = *s.insertion;
  const engine::CellComplex& cells = insertion.cells();
  s.insertion->probe(q.id());
  for (const std::int32_t c : insertion.conflicts())
    if (cells.infinite_position(c) >= 0) return;  // x is not inside the hull: V(x) is unbounded

  // What each vertex's cell loses: its parts in the removed cells less those in the new ones
  // (the cells around it that stay keep their parts).
  std::vector<std::pair<std::int32_t, double>> lost;
  std::vector<double> part(static_cast<std::size_t>(d + 1));
  const PointsView all(s.input.data(), s.input.size() / static_cast<std::size_t>(d), d);
  for (const std::int32_t c : insertion.conflicts()) {
    parts.compute(all, cells.vertices(c), part.data());
    for (int k = 0; k <= d; ++k) lost.emplace_back(cells.vertices(c)[k], part[static_cast<std::size_t>(k)]);
  }
  std::vector<std::int32_t> joined(static_cast<std::size_t>(d + 1));
  for (const auto& [c, k] : insertion.boundary()) {
    std::copy(cells.vertices(c), cells.vertices(c) + d + 1, joined.begin());
    joined[static_cast<std::size_t>(k)] = q.id();
    parts.compute(all, joined.data(), part.data());
    for (int j = 0; j <= d; ++j)
      if (j != k) lost.emplace_back(joined[static_cast<std::size_t>(j)], -part[static_cast<std::size_t>(j)]);
  }
  std::sort(lost.begin(), lost.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  const std::size_t first = out.ids.size();
  double total = 0.0;
  for (std::size_t begin = 0; begin < lost.size();) {
    double volume = 0.0;
    std::size_t end = begin;
    for (; end < lost.size() && lost[end].first == lost[begin].first; ++end) volume += lost[end].second;
    if (volume > 0.0) {  // a vertex x takes nothing from is left out (a tie: zero up to rounding)
      out.ids.push_back(lost[begin].first);
      out.weights.push_back(volume);
      total += volume;
    }
    begin = end;
  }
  for (std::size_t i = first; i < out.weights.size(); ++i) out.weights[i] /= total;
}

}  // namespace

IncrementalDelaunay::NaturalNeighbours IncrementalDelaunay::natural_neighbours(PointsView queries) {
  State& s = *state_;
  if (s.furthest_site)
    throw UsageError("natural-neighbour coordinates need the Delaunay triangulation, not the furthest-site one");
  if (queries.dim != s.dim)
    throw InputError("the queries have " + std::to_string(queries.dim) + " coordinates; the triangulation is in " +
                     std::to_string(s.dim) + " dimensions");
  util::check_points(queries, "triangulates");
  NaturalNeighbours out;
  out.offsets.push_back(0);
  diagram::SimplexCellParts parts(s.dim);
  for (std::size_t i = 0; i < queries.n; ++i) {
    append_coordinates(s, queries.point(i), parts, out);
    out.offsets.push_back(out.ids.size());
  }
  return out;
}

}  // namespace drange
