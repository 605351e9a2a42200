// io/write_qvoronoi.cpp: the Voronoi diagram in the text layouts of Qhull's qvoronoi, as
// documented in Qhull's qvoronoi.htm (options "o" and "Fv") and as qvoronoi (Qhull 2020.2) prints
// them, so that scripts written for qvoronoi read drange's output unchanged:
//   o:  the dimension; "nv+1 n 1"; the point at infinity, written as -10.101 in every
//       coordinate; the Voronoi vertices; one line per input point: "k v1 ... vk";
//   Fv: the number of ridges; one line per ridge: "k p q v1 ... v(k-2)".
// Vertex indices are shifted by one so that 0 is the point at infinity. Coordinates are
// written in the shortest exact form rather than Qhull's %6.16g, so they read back exactly.
#include <cstdint>
#include <ostream>

#include "drange/errors.hpp"
#include "drange/formats.hpp"
#include "io/output_buffer.hpp"
#include "io/result_checks.hpp"

namespace drange {
namespace {

using io::OutputBuffer;

// How Qhull writes the coordinates of the point at infinity (qh_INFINITE in libqhull).
constexpr double kQhullInfinity = -10.101;

// " v1+1 v2+1 ...": drange's -1 (infinity) becomes Qhull's 0.
void put_shifted_vertices(OutputBuffer& out, const std::int32_t* ids, std::size_t count) {
  for (std::size_t k = 0; k < count; ++k) {
    out.put(' ');
    out.put_number(static_cast<std::int64_t>(ids[k]) + 1);
  }
}

void put_coordinates(OutputBuffer& out, const double* point, int dim) {
  for (int k = 0; k < dim; ++k) {
    if (k > 0) out.put(' ');
    out.put_number(point[k]);
  }
  out.put('\n');
}

}  // namespace

void write_qvoronoi_o(std::ostream& stream, const Voronoi& diagram) {
  io::check_voronoi(diagram, "write_qvoronoi_o");
  for (std::int32_t region : diagram.point_region)
    if (region < 0)
      throw UsageError("write_qvoronoi_o: the layout needs every point's region, and this diagram (voronoi_cells) "
                       "holds only some; write it as json or npz");
  OutputBuffer out(stream);
  out.put_number(diagram.dim);
  out.put('\n');
  out.put_number(diagram.num_vertices() + 1);
  out.put(' ');
  out.put_number(diagram.num_points);
  out.put_text(" 1\n");
  for (int k = 0; k < diagram.dim; ++k) {
    if (k > 0) out.put(' ');
    out.put_number(kQhullInfinity);
  }
  out.put('\n');
  for (std::size_t v = 0; v < diagram.num_vertices(); ++v) put_coordinates(out, diagram.vertex(v), diagram.dim);
  for (std::int32_t region : diagram.point_region) {
    const auto r = static_cast<std::size_t>(region);
    out.put_number(diagram.regions.row_size(r));
    put_shifted_vertices(out, diagram.regions.row(r), diagram.regions.row_size(r));
    out.put('\n');
  }
  out.flush();
}

void write_qvoronoi_fv(std::ostream& stream, const Voronoi& diagram) {
  io::check_voronoi(diagram, "write_qvoronoi_fv");
  // Qhull reports a ridge only when its two sites share at least d Voronoi vertices, the
  // point at infinity counted once (qh_eachvoronoi in io_r.c). In 3D and above this leaves
  // out the unbounded ridges of hull edges that lie in a single simplex (one vertex and
  // infinity); they are left out here too, so that the output is qvoronoi's.
  const auto reported = [&](std::size_t r) {
    return diagram.ridge_vertices.row_size(r) >= static_cast<std::size_t>(diagram.dim);
  };
  std::size_t count = 0;
  for (std::size_t r = 0; r < diagram.num_ridges(); ++r) count += reported(r) ? 1 : 0;
  OutputBuffer out(stream);
  out.put_number(count);
  out.put('\n');
  for (std::size_t r = 0; r < diagram.num_ridges(); ++r) {
    if (!reported(r)) continue;
    out.put_number(diagram.ridge_vertices.row_size(r) + 2);
    out.put(' ');
    out.put_number(diagram.ridge_points[2 * r]);
    out.put(' ');
    out.put_number(diagram.ridge_points[2 * r + 1]);
    put_shifted_vertices(out, diagram.ridge_vertices.row(r), diagram.ridge_vertices.row_size(r));
    out.put('\n');
  }
  out.flush();
}

}  // namespace drange
