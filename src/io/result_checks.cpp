// io/result_checks.cpp: the shape checks every result writer runs first (result_checks.hpp).
#include "io/result_checks.hpp"

#include <cstdint>
#include <string>
#include <vector>

#include "drange/errors.hpp"

namespace drange::io {
namespace {

[[noreturn]] void fail(const char* writer, const std::string& what) {
  throw UsageError(std::string(writer) + ": " + what);
}

// offsets start at 0, never decrease, and end at `total`, the number of entries they index.
void check_offsets(const std::vector<std::int64_t>& offsets, std::size_t total, const char* name, const char* writer) {
  bool ok = !offsets.empty() && offsets.front() == 0 && offsets.back() == static_cast<std::int64_t>(total);
  for (std::size_t r = 1; ok && r < offsets.size(); ++r) ok = offsets[r - 1] <= offsets[r];
  if (!ok) fail(writer, std::string(name) + ": the offsets do not describe the " + std::to_string(total) + " entries");
}

void check_lists(const IndexLists& lists, const char* name, const char* writer) {
  check_offsets(lists.offsets, lists.values.size(), name, writer);
}

}  // namespace

void check_triangulation(const Triangulation& triangulation, const char* writer) {
  if (triangulation.dim < 1) fail(writer, "the triangulation has dimension " + std::to_string(triangulation.dim));
  const std::size_t width = static_cast<std::size_t>(triangulation.dim) + 1;
  if (triangulation.simplices.size() % width != 0) {
    fail(writer, std::to_string(triangulation.simplices.size()) + " simplex entries do not make rows of " +
                     std::to_string(width));
  }
  if (!triangulation.neighbors.empty() && triangulation.neighbors.size() != triangulation.simplices.size()) {
    fail(writer, "the triangulation has " + std::to_string(triangulation.neighbors.size()) + " neighbour entries for " +
                     std::to_string(triangulation.simplices.size()) + " simplex entries");
  }
  for (std::int32_t v : triangulation.simplices) {
    if (v < 0 || static_cast<std::size_t>(v) >= triangulation.num_points) {
      fail(writer, "a simplex names point " + std::to_string(v) + " of " + std::to_string(triangulation.num_points));
    }
  }
  for (std::int32_t s : triangulation.neighbors) {
    if (s < -1 || (s >= 0 && static_cast<std::size_t>(s) >= triangulation.size())) {
      fail(writer, "a neighbour names simplex " + std::to_string(s) + " of " + std::to_string(triangulation.size()));
    }
  }
}

void check_same_input(PointsView points, int dim, std::size_t num_points, const char* writer) {
  if (points.dim != dim || points.n != num_points) {
    fail(writer, "the points (" + std::to_string(points.n) + " in " + std::to_string(points.dim) +
                     "D) are not the input of the result (" + std::to_string(num_points) + " in " +
                     std::to_string(dim) + "D)");
  }
}

void check_voronoi(const Voronoi& diagram, const char* writer) {
  if (diagram.dim < 1) fail(writer, "the diagram has dimension " + std::to_string(diagram.dim));
  if (diagram.vertices.size() % static_cast<std::size_t>(diagram.dim) != 0) {
    fail(writer, "the vertex coordinates do not make whole points");
  }
  if (diagram.ridge_points.size() % 2 != 0) fail(writer, "ridge_points does not hold pairs");
  check_lists(diagram.ridge_vertices, "ridge_vertices", writer);
  check_lists(diagram.regions, "regions", writer);
  if (diagram.ridge_vertices.size() != diagram.num_ridges()) {
    fail(writer, "ridge_vertices has " + std::to_string(diagram.ridge_vertices.size()) + " rows for " +
                     std::to_string(diagram.num_ridges()) + " ridges");
  }
  if (diagram.point_region.size() != diagram.num_points) {
    fail(writer, "point_region has " + std::to_string(diagram.point_region.size()) + " entries for " +
                     std::to_string(diagram.num_points) + " points");
  }
  // -1: a point whose cell was not computed (drange::voronoi_cells).
  for (std::int32_t region : diagram.point_region) {
    if (region < -1 || (region >= 0 && static_cast<std::size_t>(region) >= diagram.regions.size())) {
      fail(writer,
           "point_region names region " + std::to_string(region) + " of " + std::to_string(diagram.regions.size()));
    }
  }
  if (!diagram.volumes.empty() && diagram.volumes.size() != diagram.regions.size()) {
    fail(writer, std::to_string(diagram.volumes.size()) + " volumes for " + std::to_string(diagram.regions.size()) +
                     " regions");
  }
}

void check_cells(const ClippedCells& cells, const char* writer) {
  if (cells.dim < 1) fail(writer, "the clipped cells have dimension " + std::to_string(cells.dim));
  const std::size_t dim = static_cast<std::size_t>(cells.dim);
  if (cells.points.size() % dim != 0) fail(writer, "the clipped cells' corner coordinates do not make whole points");
  if (cells.box.lower.size() != dim || cells.box.upper.size() != dim)
    fail(writer, "the clipping box is not of the cells' dimension");
  check_lists(cells.faces, "faces", writer);
  check_offsets(cells.cell_faces, cells.faces.size(), "cell_faces", writer);
  const std::size_t corners = cells.points.size() / dim;
  for (std::int32_t corner : cells.faces.values) {
    if (corner < 0 || static_cast<std::size_t>(corner) >= corners) {
      fail(writer, "a face names corner " + std::to_string(corner) + " of " + std::to_string(corners));
    }
  }
  if (cells.volumes.size() != cells.size()) {
    fail(writer,
         std::to_string(cells.volumes.size()) + " volumes for " + std::to_string(cells.size()) + " clipped cells");
  }
}

void check_cells_of(const Voronoi& diagram, const ClippedCells& cells, const char* writer) {
  check_cells(cells, writer);
  if (cells.dim != diagram.dim || cells.size() != diagram.regions.size()) {
    fail(writer, "the clipped cells (" + std::to_string(cells.size()) + " in " + std::to_string(cells.dim) +
                     "D) are not those of the diagram (" + std::to_string(diagram.regions.size()) + " regions in " +
                     std::to_string(diagram.dim) + "D)");
  }
}

// A user's choice rather than a programming error, so the message names no function.
void check_2d_or_3d(int dim, const char* format) {
  if (dim != 2 && dim != 3)
    throw UsageError(std::string(format) + " holds 2D and 3D only; the points have dimension " + std::to_string(dim));
}

void check_drawable(PointsView points, const Triangulation& triangulation, const char* format, const char* writer) {
  check_triangulation(triangulation, writer);
  check_2d_or_3d(triangulation.dim, format);
  check_same_input(points, triangulation.dim, triangulation.num_points, writer);
}

}  // namespace drange::io
