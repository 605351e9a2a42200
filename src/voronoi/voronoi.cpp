// voronoi/voronoi.cpp: drange::voronoi, the diagram read off the Delaunay triangulation
// (paper, section 2.5): vertices are the circumcentres (merged exactly when cospherical,
// vertex_classes.hpp), ridges are the Delaunay edges that bound a (d-1)-face (ridges.cpp),
// regions are the vertices around each point (regions.cpp), and bounded cells get their
// volume (cell_volumes.cpp).
#include "drange/voronoi.hpp"

#include <string>
#include <utility>
#include <vector>

#include "drange/errors.hpp"
#include "voronoi/diagram_parts.hpp"

namespace drange {

Voronoi voronoi(PointsView points, const Triangulation& triangulation, const VoronoiOptions& options) {
  const Triangulation& t = triangulation;
  if (t.dim != points.dim || t.num_points != points.n)
    throw UsageError("voronoi: the triangulation was computed for other points (dimension " + std::to_string(t.dim) +
                     ", " + std::to_string(t.num_points) + " points; given dimension " + std::to_string(points.dim) +
                     ", " + std::to_string(points.n) + " points)");
  if (t.neighbors.size() != t.simplices.size())
    throw UsageError("voronoi: the triangulation has no neighbours (compute it with Options::compute_neighbors)");

  const int threads = options.delaunay.threads;
  if (threads < 0) throw UsageError("voronoi: threads must be 0 (all hardware threads) or a positive count, got " + std::to_string(threads));
  engine::Team team(engine::resolve_threads(threads));

  Voronoi out;
  out.dim = t.dim;
  out.num_points = t.num_points;
  diagram::VertexClasses classes = diagram::classify_vertices(points, t, team);
  const diagram::Incidence incidence = diagram::point_incidence(t);
  diagram::build_ridges(t, classes, incidence, out, team);
  const std::vector<char> on_hull = diagram::hull_points(t);
  diagram::build_regions(t, classes, incidence, on_hull, out, team);
  out.simplex_vertex = std::move(classes.of_simplex);
  out.vertices = std::move(classes.vertices);
  if (options.cell_volumes) diagram::compute_cell_volumes(points, t, on_hull, out, team);  // uses the vertices in 2D/3D
  return out;
}

Voronoi voronoi(PointsView points, const VoronoiOptions& options) {
  Options delaunay_options = options.delaunay;
  delaunay_options.compute_neighbors = true;
  const Triangulation triangulation = delaunay(points, delaunay_options);
  return voronoi(points, triangulation, options);
}

}  // namespace drange
