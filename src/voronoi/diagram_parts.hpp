// voronoi/diagram_parts.hpp: the steps that fill a drange::Voronoi from a triangulation and
// its vertex classes (vertex_classes.hpp), one file each.
#pragma once

#include <vector>

#include "drange/delaunay.hpp"
#include "drange/points.hpp"
#include "drange/voronoi.hpp"
#include "voronoi/star.hpp"
#include "voronoi/vertex_classes.hpp"

namespace drange::diagram {

// ridges.cpp: ridge_points and ridge_vertices.
void build_ridges(const Triangulation& t, const VertexClasses& classes, const Incidence& incidence, Voronoi& out);

// regions.cpp: regions, point_region and region_point (duplicates share their original's).
// on_hull: hull_points(t).
void build_regions(const Triangulation& t, const VertexClasses& classes, const Incidence& incidence,
                   const std::vector<char>& on_hull, Voronoi& out);

// cell_volumes.cpp: the volume of every region whose cell is bounded, +infinity otherwise.
void compute_cell_volumes(PointsView points, const Triangulation& t, const std::vector<char>& on_hull, Voronoi& out);

}  // namespace drange::diagram
