// io/write_off.cpp: surfaces in Geomview's Object File Format (OFF), as documented in the
// Geomview manual ("OFF files"): the keyword "OFF", then "NVertices NFaces NEdges" (NEdges
// may be 0), one "x y z" line per vertex, and one "k v1 ... vk" line per face, with
// zero-based vertex indices. Viewers (Geomview, MeshLab, Blender) orient a face by its
// vertex order: counter-clockwise seen from the side its normal points to.
#include <cstdint>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "drange/errors.hpp"
#include "drange/formats.hpp"
#include "io/output_buffer.hpp"
#include "io/result_checks.hpp"

namespace drange {
namespace {

using io::OutputBuffer;

void put_header(OutputBuffer& out, std::size_t vertices, std::size_t faces) {
  out.put_text("OFF\n");
  out.put_number(vertices);
  out.put(' ');
  out.put_number(faces);
  out.put_text(" 0\n");
}

// One vertex, padded to three coordinates.
void put_vertex(OutputBuffer& out, const double* point, int dim) {
  for (int k = 0; k < 3; ++k) {
    if (k > 0) out.put(' ');
    out.put_number(k < dim ? point[k] : 0.0);
  }
  out.put('\n');
}

void put_face(OutputBuffer& out, const std::int32_t* ids, std::size_t count) {
  out.put_number(count);
  for (std::size_t k = 0; k < count; ++k) {
    out.put(' ');
    out.put_number(ids[k]);
  }
  out.put('\n');
}

// The hull triangles of a 3D triangulation, oriented outward, as vertex triples.
// A tetrahedron (v0, v1, v2, v3) is positively oriented: v3 lies on the side of triangle
// (v0, v1, v2) that its counter-clockwise normal points to, so that triangle faces inward.
// Dropping vertex k and keeping the order of the others gives an outward face exactly when
// k is even (moving v_k to the end is a permutation of sign (-1)^(3-k)); for odd k two
// vertices are swapped.
std::vector<std::int32_t> hull_triangles(const Triangulation& triangulation) {
  std::vector<std::int32_t> triangles;
  for (std::size_t s = 0; s < triangulation.size(); ++s) {
    const std::int32_t* v = triangulation.simplex(s);
    for (int k = 0; k < 4; ++k) {
      if (triangulation.neighbors[s * 4 + static_cast<std::size_t>(k)] != -1) continue;
      std::int32_t face[3];
      for (int i = 0, j = 0; i < 4; ++i) {
        if (i != k) face[j++] = v[i];
      }
      if (k % 2 == 1) std::swap(face[0], face[1]);
      triangles.insert(triangles.end(), face, face + 3);
    }
  }
  return triangles;
}

}  // namespace

void write_delaunay_off(std::ostream& stream, PointsView points, const Triangulation& triangulation) {
  constexpr const char* kWriter = "write_delaunay_off";
  io::check_drawable(points, triangulation, "OFF", kWriter);
  OutputBuffer out(stream);

  if (triangulation.dim == 2) {
    // The triangles as a flat surface; drange's triangles are counter-clockwise already.
    put_header(out, points.n, triangulation.size());
    for (std::size_t i = 0; i < points.n; ++i) put_vertex(out, points.point(i), 2);
    for (std::size_t s = 0; s < triangulation.size(); ++s) put_face(out, triangulation.simplex(s), 3);
    out.flush();
    return;
  }

  if (triangulation.neighbors.empty()) {
    throw UsageError(std::string(kWriter) +
                     ": the hull of a 3D triangulation is read from its neighbours, "
                     "which were not computed (Options::compute_neighbors)");
  }
  std::vector<std::int32_t> triangles = hull_triangles(triangulation);
  // Only the hull's vertices are written, renumbered in input order.
  std::vector<std::int32_t> renumbered(points.n, -1);
  for (std::int32_t v : triangles) renumbered[static_cast<std::size_t>(v)] = 0;
  std::int32_t next = 0;
  for (std::int32_t& id : renumbered) {
    if (id == 0) id = next++;
  }
  for (std::int32_t& v : triangles) v = renumbered[static_cast<std::size_t>(v)];

  put_header(out, static_cast<std::size_t>(next), triangles.size() / 3);
  for (std::size_t i = 0; i < points.n; ++i) {
    if (renumbered[i] >= 0) put_vertex(out, points.point(i), 3);
  }
  for (std::size_t t = 0; t < triangles.size(); t += 3) put_face(out, triangles.data() + t, 3);
  out.flush();
}

void write_cells_off(std::ostream& stream, const ClippedCells& cells) {
  constexpr const char* kWriter = "write_cells_off";
  io::check_cells(cells, kWriter);
  io::check_2d_or_3d(cells.dim, "OFF");
  const std::size_t corners = cells.points.size() / static_cast<std::size_t>(cells.dim);
  OutputBuffer out(stream);
  put_header(out, corners, cells.faces.size());
  for (std::size_t i = 0; i < corners; ++i)
    put_vertex(out, cells.points.data() + i * static_cast<std::size_t>(cells.dim), cells.dim);
  for (std::size_t f = 0; f < cells.faces.size(); ++f) put_face(out, cells.faces.row(f), cells.faces.row_size(f));
  out.flush();
}

}  // namespace drange
