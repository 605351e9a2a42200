// voronoi/regions.cpp: each point's cell as the list of its Voronoi vertices.
//
// The cell of p has one vertex per class among the simplices around p, and is unbounded
// exactly when p is on the convex hull (a hull facet holds p). In 2D the triangles around p,
// taken counter-clockwise, give the cell's vertices counter-clockwise.
#include <algorithm>
#include <cstddef>
#include <vector>

#include "util/for_ranges.hpp"
#include "voronoi/diagram_parts.hpp"

namespace drange::diagram {
namespace {

// Appends p's region: -1 first when the cell is unbounded, then its vertices (2D: in
// counter-clockwise order; otherwise ascending).
void append_region(const Triangulation& t, const VertexClasses& classes, const Incidence& incidence,
                   const std::vector<char>& on_hull, std::int32_t p, IndexLists& out) {
  const std::size_t row_start = out.values.size();
  if (t.dim == 2) {
    bool closed;
    const std::vector<std::int32_t> around = triangles_around(t, p, *incidence.begin(static_cast<std::size_t>(p)), closed);
    if (!closed) out.values.push_back(-1);
    for (const std::int32_t s : around) {
      const std::int32_t cls = classes.of_simplex[static_cast<std::size_t>(s)];
      if (out.values.size() == row_start || out.values.back() != cls) out.values.push_back(cls);
    }
    if (closed && out.values.size() - row_start > 1 && out.values.back() == out.values[row_start]) out.values.pop_back();
    return;
  }
  if (on_hull[static_cast<std::size_t>(p)]) out.values.push_back(-1);
  const std::size_t first_vertex = out.values.size();
  for (const std::int32_t* it = incidence.begin(static_cast<std::size_t>(p)); it != incidence.end(static_cast<std::size_t>(p)); ++it)
    out.values.push_back(classes.of_simplex[static_cast<std::size_t>(*it)]);
  std::sort(out.values.begin() + static_cast<std::ptrdiff_t>(first_vertex), out.values.end());
  out.values.erase(std::unique(out.values.begin() + static_cast<std::ptrdiff_t>(first_vertex), out.values.end()),
                   out.values.end());
}

}  // namespace

void build_regions(const Triangulation& t, const VertexClasses& classes, const Incidence& incidence,
                   const std::vector<char>& on_hull, Voronoi& out, engine::Team& team) {
  // Regions are numbered in the order the points are visited (incidence.order, for cache
  // locality); point_region maps each input point to its own. Each range of points gets its own
  // lists, joined in range order: the thread count does not change the output.
  out.point_region.assign(t.num_points, -1);
  out.region_point = incidence.order;
  std::vector<IndexLists> parts(static_cast<std::size_t>(team.threads()) * 4);
  const std::size_t ranges = util::for_ranges(incidence.order.size(), team, [&](std::size_t i, std::size_t begin, std::size_t end) {
    for (std::size_t r = begin; r < end; ++r) {
      const std::int32_t p = incidence.order[r];
      out.point_region[static_cast<std::size_t>(p)] = static_cast<std::int32_t>(r);
      append_region(t, classes, incidence, on_hull, p, parts[i]);
      parts[i].end_row();
    }
  }, kPointsPerRange);
  for (std::size_t i = 0; i < ranges; ++i) {
    append_lists(parts[i], out.regions);
    parts[i] = IndexLists{};
  }
  // A duplicate has no simplex; it shares the region of the point it copies.
  for (const Duplicate& dup : t.duplicates)
    out.point_region[static_cast<std::size_t>(dup.index)] = out.point_region[static_cast<std::size_t>(dup.original)];
}

}  // namespace drange::diagram
