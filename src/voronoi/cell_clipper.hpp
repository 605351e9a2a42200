// voronoi/cell_clipper.hpp: one Voronoi cell clipped to a box (d = 2, 3), from its point and
// the points whose bisectors may bound it. Shared by clip_cells (the partners are the whole
// diagram's ridge partners) and stream_clipped_cells (the vertices of the point's Delaunay
// star), so that both cut a cell the same way; cell_clipper.cpp says how, and why the
// tolerance.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "drange/voronoi.hpp"
#include "voronoi/convex_polygon.hpp"
#include "voronoi/convex_polyhedron.hpp"

namespace drange::cells {

// Throws UsageError for a box of another dimension than `dim`, not finite, or empty.
void check_box(const Box& box, int dim);

// Clips cells one after the other, keeping its scratch space between them: one per thread.
// `points` and `box` must outlive it; the box must pass check_box.
class CellClipper {
 public:
  CellClipper(PointsView points, const Box& box);

  // Appends to `out` (dimension and box already set) the cell of input point i cut by the
  // bisectors of i and each of partners[0 .. count) (input indices). The cell is right when
  // the partners include every point whose cell shares a (d-1)-face with i's; extra partners
  // are harmless (their bisectors only touch the cell or miss it), and so are copies of p
  // (no bisector).
  void append(std::size_t i, const std::int32_t* partners, std::size_t count, ClippedCells& out);

 private:
  template <class Shape>
  void cut(Shape& shape, const double* p, const std::int32_t* partners, std::size_t count, ClippedCells& out);
  // Appends the clipped shape (coordinates relative to p) to `out`.
  template <class Shape>
  void append_cell(const Shape& shape, const double* p, ClippedCells& out);

  // A bisector in the cell's relative coordinates: u . x <= offset, u a unit vector.
  struct Bisector {
    double offset;
    double normal[3];
  };

  PointsView points_;
  const Box& box_;
  ConvexPolygon polygon_;
  ConvexPolyhedron polyhedron_;
  std::vector<Bisector> bisectors_;
  std::vector<std::int32_t> slots_, index_;  // append_cell's
};

}  // namespace drange::cells
