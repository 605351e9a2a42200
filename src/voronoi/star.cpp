// voronoi/star.cpp: see star.hpp.
#include "voronoi/star.hpp"

#include <algorithm>

namespace drange::diagram {

Incidence point_incidence(const Triangulation& t) {
  Incidence out;
  out.offsets.assign(t.num_points + 1, 0);
  for (const std::int32_t v : t.simplices) ++out.offsets[static_cast<std::size_t>(v) + 1];
  for (std::size_t p = 0; p < t.num_points; ++p) out.offsets[p + 1] += out.offsets[p];
  out.simplices.resize(t.simplices.size());
  std::vector<std::int64_t> next(out.offsets.begin(), out.offsets.end() - 1);
  const std::size_t width = static_cast<std::size_t>(t.dim + 1);
  out.order.reserve(t.num_points);
  for (std::size_t i = 0; i < t.simplices.size(); ++i) {
    const auto v = static_cast<std::size_t>(t.simplices[i]);
    if (next[v] == out.offsets[v]) out.order.push_back(static_cast<std::int32_t>(v));
    out.simplices[static_cast<std::size_t>(next[v]++)] = static_cast<std::int32_t>(i / width);
  }
  return out;
}

std::vector<char> hull_points(const Triangulation& t) {
  std::vector<char> on_hull(t.num_points, 0);
  const auto width = static_cast<std::size_t>(t.dim + 1);
  for (std::size_t s = 0; s < t.size(); ++s)
    for (std::size_t k = 0; k < width; ++k)
      if (t.neighbors[s * width + k] < 0)
        for (std::size_t j = 0; j < width; ++j)
          if (j != k) on_hull[static_cast<std::size_t>(t.simplex(s)[j])] = 1;
  return on_hull;
}

// In a positively oriented triangle (v0, v1, v2) the vertices run counter-clockwise. With p
// at position i, the triangle after it counter-clockwise around p shares the edge from p to
// v[i+2], so it is the neighbour opposite v[i+1]; the one before it is opposite v[i+2].
std::vector<std::int32_t> triangles_around(const Triangulation& t, std::int32_t p, std::int32_t start, bool& closed) {
  auto step = [&](std::int32_t s, int ahead) {
    const int i = position_in(t, static_cast<std::size_t>(s), p);
    return t.neighbors[static_cast<std::size_t>(s) * 3 + static_cast<std::size_t>((i + ahead) % 3)];
  };
  // Clockwise to the hull (or all the way round).
  std::int32_t first = start;
  closed = true;
  for (std::int32_t s = step(start, 2); s != start; s = step(s, 2)) {
    if (s < 0) {
      closed = false;
      break;
    }
    first = s;
  }
  std::vector<std::int32_t> order{first};
  for (std::int32_t s = step(first, 1); s >= 0 && s != first; s = step(s, 1)) order.push_back(s);
  return order;
}

// In tetrahedron s with the edge pq, let x and y be the other two vertices. Leaving s through
// the facet opposite x enters the neighbour that shares p, q, y; from there the walk goes on
// through the facet opposite y.
std::vector<std::int32_t> tetrahedra_around(const Triangulation& t, std::int32_t p, std::int32_t q, std::int32_t start,
                                            bool& closed) {
  auto others = [&](std::int32_t s, std::int32_t& x, std::int32_t& y) {
    const std::int32_t* row = t.simplex(static_cast<std::size_t>(s));
    x = y = -1;
    for (int k = 0; k < 4; ++k)
      if (row[k] != p && row[k] != q) (x < 0 ? x : y) = row[k];
  };
  auto across = [&](std::int32_t s, std::int32_t opposite) {
    return t.neighbors[static_cast<std::size_t>(s) * 4 + static_cast<std::size_t>(position_in(t, static_cast<std::size_t>(s), opposite))];
  };
  // Walks from `start` leaving through the facet opposite `exit_vertex`; appends to `out`.
  auto walk = [&](std::int32_t exit_vertex, std::vector<std::int32_t>& out) {
    std::int32_t s = start, leave = exit_vertex;
    for (;;) {
      std::int32_t x, y;
      others(s, x, y);
      const std::int32_t keep = leave == x ? y : x;  // the vertex shared with the next tetrahedron
      const std::int32_t next = across(s, leave);
      if (next < 0) return false;
      if (next == start) return true;
      out.push_back(next);
      // In `next`, the vertex other than p, q, keep is new; leave through the facet opposite keep.
      s = next;
      leave = keep;
    }
  };
  std::int32_t x, y;
  others(start, x, y);
  std::vector<std::int32_t> forward{start};
  closed = walk(x, forward);
  if (closed) return forward;
  std::vector<std::int32_t> backward;
  walk(y, backward);
  std::reverse(backward.begin(), backward.end());
  backward.insert(backward.end(), forward.begin(), forward.end());
  return backward;
}

}  // namespace drange::diagram
