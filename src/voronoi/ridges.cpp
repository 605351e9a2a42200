// voronoi/ridges.cpp: which pairs of cells share a (d-1)-face, and that face's vertices.
//
// Every ridge is dual to a Delaunay edge pq, but on cospherical input not every Delaunay edge
// has a ridge: the diagonal of a grid square is an edge of the triangulation, yet the cells of
// its ends meet in one point. The Delaunay subdivision (the triangulation with each class of
// cospherical simplices merged into one convex cell, and each class of coplanar hull facets
// into one cell at infinity) is a polyhedral complex, dual to the diagram; in it, the smallest
// face holding the segment pq is the intersection of the cells around pq, and the vertices of
// an intersection of cells are the points common to all of them. So pq has a ridge exactly
// when the cells around it have no point in common but p and q: a test on vertex ids only,
// with no arithmetic, after the exact merging of vertex_classes.
#include <algorithm>
#include <cstddef>
#include <tuple>
#include <vector>

#include "util/for_ranges.hpp"
#include "voronoi/diagram_parts.hpp"

namespace drange::diagram {
namespace {

struct Sharing {
  std::int32_t q;        // the other end of the edge
  std::int32_t cls;      // a class (cell) around the edge pq
  std::int32_t simplex;  // a simplex having p and q, in that class or bounding that hull facet
  bool operator<(const Sharing& o) const { return std::tie(q, cls) < std::tie(o.q, o.cls); }
};

// One range's ridges: ridge_points pairs and ridge_vertices rows.
struct RidgeLists {
  std::vector<std::int32_t> points;
  IndexLists vertices;
};

class RidgeBuilder {
 public:
  RidgeBuilder(const Triangulation& t, const VertexClasses& classes) : t_(t), c_(classes), width_(t.dim + 1) {}

  // The vertex ids of class `cls` (sorted for merged and infinite classes).
  const std::int32_t* members(std::int32_t cls, std::size_t& count) const {
    const std::int32_t set = c_.set_of[static_cast<std::size_t>(cls)];
    if (set >= 0) {
      count = c_.sets.row_size(static_cast<std::size_t>(set));
      return c_.sets.row(static_cast<std::size_t>(set));
    }
    count = static_cast<std::size_t>(width_);
    return t_.simplex(static_cast<std::size_t>(c_.simplex_of[static_cast<std::size_t>(cls)]));
  }

  bool has_point(std::int32_t cls, std::int32_t v) const {
    std::size_t count;
    const std::int32_t* ids = members(cls, count);
    if (c_.set_of[static_cast<std::size_t>(cls)] >= 0) return std::binary_search(ids, ids + count, v);
    return std::find(ids, ids + count, v) != ids + count;
  }

  // True when the cells in [first, last) share no point but p and q.
  bool is_ridge(std::int32_t p, const Sharing* first, const Sharing* last) const {
    std::size_t count;
    const std::int32_t* ids = members(first->cls, count);
    for (std::size_t i = 0; i < count; ++i) {
      const std::int32_t v = ids[i];
      if (v == p || v == first->q) continue;
      bool common = true;
      for (const Sharing* s = first + 1; s != last && common; ++s) common = has_point(s->cls, v);
      if (common) return false;
    }
    return true;
  }

  // The ridge's vertex ids: -1 first when it is unbounded; in 3D the polygon in cyclic order.
  void append_vertices(std::int32_t p, const Sharing* first, const Sharing* last, IndexLists& out) const {
    if (t_.dim == 3) {
      append_cycle(p, first->q, first->simplex, out);
      return;
    }
    const std::size_t row_start = out.values.size();
    for (const Sharing* s = first; s != last; ++s)
      if (c_.is_infinite(s->cls)) {
        out.values.push_back(-1);
        break;
      }
    for (const Sharing* s = first; s != last; ++s)
      if (!c_.is_infinite(s->cls)) out.values.push_back(s->cls);
    std::sort(out.values.begin() + static_cast<std::ptrdiff_t>(row_start), out.values.end());
  }

 private:
  void append_cycle(std::int32_t p, std::int32_t q, std::int32_t start, IndexLists& out) const {
    bool closed;
    const std::vector<std::int32_t> around = tetrahedra_around(t_, p, q, start, closed);
    const std::size_t row_start = out.values.size();
    if (!closed) out.values.push_back(-1);
    for (const std::int32_t s : around) {
      const std::int32_t cls = c_.of_simplex[static_cast<std::size_t>(s)];
      if (out.values.size() == row_start || out.values.back() != cls) out.values.push_back(cls);
    }
    // A class is one arc of the cycle (its cell is convex), so it can only wrap around.
    if (closed && out.values.size() - row_start > 1 && out.values.back() == out.values[row_start]) out.values.pop_back();
  }

  const Triangulation& t_;
  const VertexClasses& c_;
  int width_;
};

// The ridges of the edges pq with p < q, for the points order[begin, end), appended in that order.
void append_ridges(const Triangulation& t, const VertexClasses& classes, const Incidence& incidence,
                   const RidgeBuilder& builder, std::size_t begin, std::size_t end, RidgeLists& out) {
  const int width = t.dim + 1;
  std::vector<Sharing> around;
  for (std::size_t i = begin; i < end; ++i) {
    const std::int32_t pp = incidence.order[i];
    const auto p = static_cast<std::size_t>(pp);
    around.clear();
    for (const std::int32_t* it = incidence.begin(p); it != incidence.end(p); ++it) {
      const std::int32_t s = *it;
      const std::int32_t* row = t.simplex(static_cast<std::size_t>(s));
      const std::int32_t cls = classes.of_simplex[static_cast<std::size_t>(s)];
      for (int j = 0; j < width; ++j)
        if (row[j] > pp) around.push_back({row[j], cls, s});
      // Hull facets of s holding p: the cells at infinity around the edges of p in them.
      for (int k = 0; k < width; ++k) {
        const std::int32_t hull_cls = classes.hull_class(t, static_cast<std::size_t>(s), k);
        if (hull_cls < 0 || row[k] == pp) continue;
        for (int j = 0; j < width; ++j)
          if (j != k && row[j] > pp) around.push_back({row[j], hull_cls, s});
      }
    }
    std::sort(around.begin(), around.end());
    around.erase(std::unique(around.begin(), around.end(),
                             [](const Sharing& a, const Sharing& b) { return a.q == b.q && a.cls == b.cls; }),
                 around.end());
    for (std::size_t a = 0; a < around.size();) {
      std::size_t b = a;
      while (b < around.size() && around[b].q == around[a].q) ++b;
      if (builder.is_ridge(pp, &around[a], &around[b])) {
        out.points.push_back(pp);
        out.points.push_back(around[a].q);
        builder.append_vertices(pp, &around[a], &around[b], out.vertices);
        out.vertices.end_row();
      }
      a = b;
    }
  }
}

}  // namespace

void build_ridges(const Triangulation& t, const VertexClasses& classes, const Incidence& incidence, Voronoi& out,
                  engine::Team& team) {
  const RidgeBuilder builder(t, classes);
  // Each range of points gets its own lists, joined in range order: the thread count does not
  // change the output.
  std::vector<RidgeLists> parts(static_cast<std::size_t>(team.threads()) * 4);
  const std::size_t ranges = util::for_ranges(incidence.order.size(), team, [&](std::size_t i, std::size_t begin, std::size_t end) {
    append_ridges(t, classes, incidence, builder, begin, end, parts[i]);
  }, kPointsPerRange);
  for (std::size_t i = 0; i < ranges; ++i) {
    out.ridge_points.insert(out.ridge_points.end(), parts[i].points.begin(), parts[i].points.end());
    append_lists(parts[i].vertices, out.ridge_vertices);
    parts[i] = RidgeLists{};  // free as we go
  }
}

}  // namespace drange::diagram
