// voronoi/voronoi_cells.cpp: drange::voronoi_cells, the cells of some points only, read off
// their Delaunay stars (drange::delaunay_stars) instead of the whole triangulation.
//
// Why the stars suffice for the query points' cells: every simplex incident to a query point p
// is returned, and so is every simplex across a facet through p (it holds p too), so a -1
// neighbour on a facet through p is a true hull facet. The diagram code reads, for p, only
// these: the classes of cospherical simplices around p (the simplices of one empty sphere that
// hold p are connected through facets holding p, so they still merge into one vertex), the hull
// facets through p (the infinite classes), and, for an edge pq, the cells around pq, whose
// vertex sets keep a common point besides p and q exactly when the whole triangulation's do
// (the face of the Delaunay subdivision holding pq is triangulated by faces of simplices around
// pq). The other points' cells are partial (a missing neighbour reads as hull) and are dropped.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "drange/voronoi.hpp"

namespace drange {
namespace {

// The diagram restricted to the regions marked in `keep`: their vertices (renumbered in
// increasing order, so sorted rows stay sorted), the ridges with a kept point at one end, and
// point_region -1 for the points whose region is dropped.
Voronoi restrict_regions(const Voronoi& full, const std::vector<char>& keep) {
  Voronoi out;
  out.dim = full.dim;
  out.num_points = full.num_points;
  std::vector<std::int32_t> new_vertex(full.num_vertices(), -1);
  for (std::size_t r = 0; r < full.regions.size(); ++r)
    if (keep[r])
      for (std::size_t i = 0; i < full.regions.row_size(r); ++i)
        if (full.regions.row(r)[i] >= 0) new_vertex[static_cast<std::size_t>(full.regions.row(r)[i])] = 0;
  std::int32_t count = 0;
  for (std::size_t v = 0; v < new_vertex.size(); ++v) {
    if (new_vertex[v] < 0) continue;
    new_vertex[v] = count++;
    out.vertices.insert(out.vertices.end(), full.vertex(v), full.vertex(v) + full.dim);
  }
  auto copy_row = [&](const IndexLists& from, std::size_t r, IndexLists& to) {
    for (std::size_t i = 0; i < from.row_size(r); ++i) {
      const std::int32_t v = from.row(r)[i];
      to.values.push_back(v < 0 ? -1 : new_vertex[static_cast<std::size_t>(v)]);
    }
    to.end_row();
  };
  std::vector<std::int32_t> new_region(full.regions.size(), -1);
  for (std::size_t r = 0; r < full.regions.size(); ++r) {
    if (!keep[r]) continue;
    new_region[r] = static_cast<std::int32_t>(out.regions.size());
    copy_row(full.regions, r, out.regions);
    out.region_point.push_back(full.region_point[r]);
    if (!full.volumes.empty()) out.volumes.push_back(full.volumes[r]);
  }
  out.point_region.assign(full.num_points, -1);
  for (std::size_t p = 0; p < full.num_points; ++p)
    if (full.point_region[p] >= 0) out.point_region[p] = new_region[static_cast<std::size_t>(full.point_region[p])];
  for (std::size_t r = 0; r < full.num_ridges(); ++r) {
    const std::int32_t p = full.ridge_points[2 * r], q = full.ridge_points[2 * r + 1];
    if (out.point_region[static_cast<std::size_t>(p)] < 0 && out.point_region[static_cast<std::size_t>(q)] < 0) continue;
    out.ridge_points.push_back(p);
    out.ridge_points.push_back(q);
    copy_row(full.ridge_vertices, r, out.ridge_vertices);
  }
  return out;
}

}  // namespace

Voronoi voronoi_cells(PointsView points, const std::vector<std::int64_t>& ids, const VoronoiOptions& options) {
  Options delaunay_options = options.delaunay;
  delaunay_options.compute_neighbors = true;
  const Triangulation stars = delaunay_stars(points, ids, delaunay_options);
  const Voronoi partial = voronoi(points, stars, options);
  // delaunay_stars has checked the ids; a duplicate's id names its original's region.
  std::vector<char> keep(partial.regions.size(), 0);
  for (const std::int64_t id : ids) keep[static_cast<std::size_t>(partial.point_region[static_cast<std::size_t>(id)])] = 1;
  return restrict_regions(partial, keep);
}

}  // namespace drange
