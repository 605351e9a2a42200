// voronoi/diagram_parts.hpp: the steps that fill a drange::Voronoi from a triangulation and
// its vertex classes (vertex_classes.hpp), one file each.
#pragma once

#include <cstddef>
#include <vector>

#include "delaunay/team.hpp"
#include "drange/delaunay.hpp"
#include "drange/points.hpp"
#include "drange/voronoi.hpp"
#include "voronoi/star.hpp"
#include "voronoi/vertex_classes.hpp"

namespace drange::diagram {

// The steps below share their points among the team's threads in ranges of at least this many
// (fewer points are not worth a thread); every step's output is the same for every thread count.
inline constexpr std::size_t kPointsPerRange = std::size_t{1} << 13;

// Appends the rows of `from` to `to`.
inline void append_lists(const IndexLists& from, IndexLists& to) {
  const auto base = static_cast<std::int64_t>(to.values.size());
  to.values.insert(to.values.end(), from.values.begin(), from.values.end());
  for (std::size_t r = 1; r < from.offsets.size(); ++r) to.offsets.push_back(base + from.offsets[r]);
}

// ridges.cpp: ridge_points and ridge_vertices.
void build_ridges(const Triangulation& t, const VertexClasses& classes, const Incidence& incidence, Voronoi& out,
                  engine::Team& team);

// regions.cpp: regions, point_region and region_point (duplicates share their original's).
// on_hull: hull_points(t).
void build_regions(const Triangulation& t, const VertexClasses& classes, const Incidence& incidence,
                   const std::vector<char>& on_hull, Voronoi& out, engine::Team& team);

// cell_volumes.cpp: the volume of every region whose cell is bounded, +infinity otherwise.
void compute_cell_volumes(PointsView points, const Triangulation& t, const std::vector<char>& on_hull, Voronoi& out,
                          engine::Team& team);

}  // namespace drange::diagram
