// io/write_vtu.cpp: VTK XML UnstructuredGrid files (.vtu), ASCII, as described in VTK's
// "VTK File Formats" (XML formats, UnstructuredGrid), which ParaView opens directly.
// A Piece holds CellData, Points (always 3 components: z = 0 in 2D) and Cells: the
// "connectivity" of all cells one after another, the "offsets" (the end of each cell in
// connectivity) and the "types". Polyhedra (VTK_POLYHEDRON) add the "faces" stream (per
// cell: its face count, then per face its point count and point ids) and the "faceoffsets"
// (the end of each cell in "faces"), the layout that VTK reads for files before version 2.3.
#include <cstdint>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "drange/errors.hpp"
#include "drange/formats.hpp"
#include "io/cell_parts.hpp"
#include "io/output_buffer.hpp"
#include "io/result_checks.hpp"

namespace drange {
namespace {

using io::OutputBuffer;

// VTK's cell type ids (vtkCellType.h).
constexpr int kVtkTriangle = 5;
constexpr int kVtkTetra = 10;
constexpr int kVtkPolygon = 7;
constexpr int kVtkPolyhedron = 42;

void begin_file(OutputBuffer& out, std::size_t points, std::size_t cells) {
  out.put_text(
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n");
  out.put_text("<UnstructuredGrid>\n<Piece NumberOfPoints=\"");
  out.put_number(points);
  out.put_text("\" NumberOfCells=\"");
  out.put_number(cells);
  out.put_text("\">\n");
}

void end_file(OutputBuffer& out) {
  out.put_text("</Piece>\n</UnstructuredGrid>\n</VTKFile>\n");
  out.flush();
}

void begin_array(OutputBuffer& out, std::string_view type, std::string_view name, int components = 1) {
  out.put_text("<DataArray type=\"");
  out.put_text(type);
  out.put_text("\" Name=\"");
  out.put_text(name);
  if (components != 1) {
    out.put_text("\" NumberOfComponents=\"");
    out.put_number(components);
  }
  out.put_text("\" format=\"ascii\">\n");
}

void end_array(OutputBuffer& out) { out.put_text("</DataArray>\n"); }

// The points, padded to three coordinates.
void put_points(OutputBuffer& out, const double* coords, std::size_t n, int dim) {
  out.put_text("<Points>\n");
  begin_array(out, "Float64", "Points", 3);
  for (std::size_t i = 0; i < n; ++i, coords += dim) {
    for (int k = 0; k < 3; ++k) {
      if (k > 0) out.put(' ');
      out.put_number(k < dim ? coords[k] : 0.0);
    }
    out.put('\n');
  }
  end_array(out);
  out.put_text("</Points>\n");
}

// A data array of one value per line.
template <typename T>
void put_values(OutputBuffer& out, std::string_view type, std::string_view name, const std::vector<T>& values) {
  begin_array(out, type, name);
  for (const T& value : values) {
    out.put_number(value);
    out.put('\n');
  }
  end_array(out);
}

// Rows of ids, one row per line.
void put_row(OutputBuffer& out, const std::int32_t* ids, std::size_t count) {
  for (std::size_t k = 0; k < count; ++k) {
    if (k > 0) out.put(' ');
    out.put_number(ids[k]);
  }
  out.put('\n');
}

// The Cells element for the clipped cells listed in `kept`.
void put_cells(OutputBuffer& out, const ClippedCells& cells, const std::vector<std::size_t>& kept) {
  const bool polyhedra = cells.dim == 3;
  std::vector<std::int64_t> offsets, face_offsets;
  std::int64_t connectivity_size = 0, faces_size = 0;

  out.put_text("<Cells>\n");
  begin_array(out, "Int64", "connectivity");
  for (std::size_t c : kept) {
    const auto first_face = static_cast<std::size_t>(cells.cell_faces[c]);
    if (polyhedra) {
      // A polyhedron's connectivity is its distinct points; its shape is in "faces".
      const std::vector<std::int32_t> corners = io::cell_corners(cells, c);
      put_row(out, corners.data(), corners.size());
      connectivity_size += static_cast<std::int64_t>(corners.size());
    } else {
      put_row(out, cells.faces.row(first_face), cells.faces.row_size(first_face));
      connectivity_size += static_cast<std::int64_t>(cells.faces.row_size(first_face));
    }
    offsets.push_back(connectivity_size);
  }
  end_array(out);
  put_values(out, "Int64", "offsets", offsets);
  put_values(out, "UInt8", "types", std::vector<int>(kept.size(), polyhedra ? kVtkPolyhedron : kVtkPolygon));
  if (polyhedra) {
    begin_array(out, "Int64", "faces");
    for (std::size_t c : kept) {
      const auto first = static_cast<std::size_t>(cells.cell_faces[c]);
      const auto last = static_cast<std::size_t>(cells.cell_faces[c + 1]);
      out.put_number(last - first);
      out.put('\n');
      faces_size += 1;
      for (std::size_t f = first; f < last; ++f) {
        out.put_number(cells.faces.row_size(f));
        out.put(' ');
        put_row(out, cells.faces.row(f), cells.faces.row_size(f));
        faces_size += 1 + static_cast<std::int64_t>(cells.faces.row_size(f));
      }
      face_offsets.push_back(faces_size);
    }
    end_array(out);
    put_values(out, "Int64", "faceoffsets", face_offsets);
  }
  out.put_text("</Cells>\n");
}

}  // namespace

void write_delaunay_vtu(std::ostream& stream, PointsView points, const Triangulation& triangulation) {
  constexpr const char* kWriter = "write_delaunay_vtu";
  io::check_drawable(points, triangulation, "VTK", kWriter);
  const std::size_t width = static_cast<std::size_t>(triangulation.dim) + 1;
  const std::size_t m = triangulation.size();

  OutputBuffer out(stream);
  begin_file(out, points.n, m);
  put_points(out, points.coords, points.n, points.dim);
  out.put_text("<Cells>\n");
  begin_array(out, "Int64", "connectivity");
  for (std::size_t s = 0; s < m; ++s) put_row(out, triangulation.simplex(s), width);
  end_array(out);
  std::vector<std::int64_t> offsets(m);
  for (std::size_t s = 0; s < m; ++s) offsets[s] = static_cast<std::int64_t>((s + 1) * width);
  put_values(out, "Int64", "offsets", offsets);
  put_values(out, "UInt8", "types", std::vector<int>(m, triangulation.dim == 2 ? kVtkTriangle : kVtkTetra));
  out.put_text("</Cells>\n");
  end_file(out);
}

void write_cells_vtu(std::ostream& stream, const Voronoi& diagram, const ClippedCells& cells) {
  constexpr const char* kWriter = "write_cells_vtu";
  io::check_voronoi(diagram, kWriter);
  io::check_cells_of(diagram, cells, kWriter);
  io::check_2d_or_3d(cells.dim, "VTK");

  // Empty cells (outside the box) have no VTK representation; the "point" array keeps
  // telling which input point each written cell belongs to.
  std::vector<std::size_t> kept;
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const std::int64_t faces = cells.cell_faces[c + 1] - cells.cell_faces[c];
    if (faces == 0) continue;
    if (cells.dim == 2 && faces != 1) {
      throw UsageError(std::string(kWriter) + ": 2D cell " + std::to_string(c) + " has " + std::to_string(faces) +
                       " boundary loops, not one");
    }
    kept.push_back(c);
  }
  const std::vector<std::int32_t> owners = io::region_points(diagram);
  std::vector<double> volumes;
  std::vector<std::int32_t> points;
  for (std::size_t c : kept) {
    volumes.push_back(cells.volumes[c]);
    points.push_back(owners[c]);
  }

  OutputBuffer out(stream);
  begin_file(out, cells.points.size() / static_cast<std::size_t>(cells.dim), kept.size());
  out.put_text("<CellData Scalars=\"volume\">\n");
  put_values(out, "Float64", "volume", volumes);
  put_values(out, "Int32", "point", points);
  out.put_text("</CellData>\n");
  put_points(out, cells.points.data(), cells.points.size() / static_cast<std::size_t>(cells.dim), cells.dim);
  put_cells(out, cells, kept);
  end_file(out);
}

}  // namespace drange
