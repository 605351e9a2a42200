// io/write_json.cpp: triangulations and Voronoi diagrams as JSON (RFC 8259), with the
// attribute names of scipy.spatial.Delaunay and scipy.spatial.Voronoi. Streamed straight
// into the output buffer, without building a document in memory. Doubles are written in
// the shortest form that reads back as the same double (std::to_chars); JSON has no NaN or
// infinity, so those are written as null.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <ostream>
#include <string_view>
#include <vector>

#include "drange/formats.hpp"
#include "io/cell_parts.hpp"
#include "io/output_buffer.hpp"
#include "io/result_checks.hpp"

namespace drange {
namespace {

using io::OutputBuffer;

template <typename Integer>
void put_value(OutputBuffer& out, Integer value) {
  out.put_number(value);
}

void put_value(OutputBuffer& out, double value) {
  if (std::isfinite(value)) {
    out.put_number(value);
  } else {
    out.put_text("null");
  }
}

// [a, b, c]
template <typename T>
void put_array(OutputBuffer& out, const T* values, std::size_t count) {
  out.put('[');
  for (std::size_t i = 0; i < count; ++i) {
    if (i > 0) out.put_text(", ");
    put_value(out, values[i]);
  }
  out.put(']');
}

// [[..], [..]], one row per line.
template <typename T>
void put_rows(OutputBuffer& out, const T* values, std::size_t rows, std::size_t width) {
  out.put('[');
  for (std::size_t r = 0; r < rows; ++r) {
    out.put_text(r > 0 ? ",\n  " : "\n  ");
    put_array(out, values + r * width, width);
  }
  out.put(']');
}

void put_lists(OutputBuffer& out, const IndexLists& lists) {
  out.put('[');
  for (std::size_t r = 0; r < lists.size(); ++r) {
    out.put_text(r > 0 ? ",\n  " : "\n  ");
    put_array(out, lists.row(r), lists.row_size(r));
  }
  out.put(']');
}

// Starts a member of the top-level object: `"name": `, after a comma unless it is the first.
void put_key(OutputBuffer& out, std::string_view name, bool first = false) {
  out.put_text(first ? "{\"" : ",\n\"");
  out.put_text(name);
  out.put_text("\": ");
}

// The members every result starts with.
void put_sizes(OutputBuffer& out, int dim, std::size_t num_points) {
  put_key(out, "ndim", true);
  out.put_number(dim);
  put_key(out, "npoints");
  out.put_number(num_points);
}

// One clipped cell, its corners renumbered from 0 so that the cell stands alone.
void put_cell(OutputBuffer& out, const ClippedCells& cells, std::size_t c, std::int32_t point) {
  const std::size_t dim = static_cast<std::size_t>(cells.dim);
  const std::vector<std::int32_t> corners = io::cell_corners(cells, c);
  out.put_text("{\"point\": ");
  out.put_number(point);
  out.put_text(", \"points\": [");
  for (std::size_t k = 0; k < corners.size(); ++k) {
    if (k > 0) out.put_text(", ");
    put_array(out, cells.points.data() + static_cast<std::size_t>(corners[k]) * dim, dim);
  }
  out.put_text("], \"faces\": [");
  std::vector<std::int32_t> local;
  for (auto f = static_cast<std::size_t>(cells.cell_faces[c]); f < static_cast<std::size_t>(cells.cell_faces[c + 1]);
       ++f) {
    local.clear();
    for (std::size_t k = 0; k < cells.faces.row_size(f); ++k) {
      const auto at = std::lower_bound(corners.begin(), corners.end(), cells.faces.row(f)[k]);
      local.push_back(static_cast<std::int32_t>(at - corners.begin()));
    }
    if (f > static_cast<std::size_t>(cells.cell_faces[c])) out.put_text(", ");
    put_array(out, local.data(), local.size());
  }
  out.put_text("], \"volume\": ");
  put_value(out, cells.volumes[c]);
  out.put('}');
}

void put_clipped_cells(OutputBuffer& out, const Voronoi& diagram, const ClippedCells& cells) {
  const std::vector<std::int32_t> points = io::region_points(diagram);
  out.put_text("{\"box\": {\"lower\": ");
  put_array(out, cells.box.lower.data(), cells.box.lower.size());
  out.put_text(", \"upper\": ");
  put_array(out, cells.box.upper.data(), cells.box.upper.size());
  out.put_text("},\n\"cells\": [");
  for (std::size_t c = 0; c < cells.size(); ++c) {
    out.put_text(c > 0 ? ",\n  " : "\n  ");
    put_cell(out, cells, c, points[c]);
  }
  out.put_text("]}");
}

}  // namespace

void write_delaunay_json(std::ostream& stream, const Triangulation& triangulation) {
  io::check_triangulation(triangulation, "write_delaunay_json");
  const std::size_t width = static_cast<std::size_t>(triangulation.dim) + 1;
  OutputBuffer out(stream);
  put_sizes(out, triangulation.dim, triangulation.num_points);
  put_key(out, "simplices");
  put_rows(out, triangulation.simplices.data(), triangulation.size(), width);
  if (!triangulation.neighbors.empty()) {
    put_key(out, "neighbors");
    put_rows(out, triangulation.neighbors.data(), triangulation.size(), width);
  }
  put_key(out, "coplanar");
  std::vector<std::int64_t> coplanar;
  for (const Duplicate& duplicate : triangulation.duplicates)
    coplanar.insert(coplanar.end(), {duplicate.index, -1, duplicate.original});
  put_rows(out, coplanar.data(), triangulation.duplicates.size(), 3);
  out.put_text("}\n");
  out.flush();
}

void write_voronoi_json(std::ostream& stream, const Voronoi& diagram, const ClippedCells* cells) {
  io::check_voronoi(diagram, "write_voronoi_json");
  if (cells != nullptr) io::check_cells_of(diagram, *cells, "write_voronoi_json");
  OutputBuffer out(stream);
  put_sizes(out, diagram.dim, diagram.num_points);
  put_key(out, "vertices");
  put_rows(out, diagram.vertices.data(), diagram.num_vertices(), static_cast<std::size_t>(diagram.dim));
  put_key(out, "ridge_points");
  put_rows(out, diagram.ridge_points.data(), diagram.num_ridges(), 2);
  put_key(out, "ridge_vertices");
  put_lists(out, diagram.ridge_vertices);
  put_key(out, "regions");
  put_lists(out, diagram.regions);
  put_key(out, "point_region");
  put_array(out, diagram.point_region.data(), diagram.point_region.size());
  if (!diagram.volumes.empty()) {
    put_key(out, "volumes");
    put_array(out, diagram.volumes.data(), diagram.volumes.size());
  }
  if (cells != nullptr) {
    put_key(out, "clipped_cells");
    put_clipped_cells(out, diagram, *cells);
  }
  out.put_text("}\n");
  out.flush();
}

}  // namespace drange
