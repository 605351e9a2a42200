// io/result_checks.hpp: the consistency of a result's arrays, checked once before a writer
// walks them, so that a hand-built or mismatched struct is a UsageError rather than a read
// past the end of a vector.
#pragma once

#include "drange/delaunay.hpp"
#include "drange/points.hpp"
#include "drange/voronoi.hpp"

namespace drange::io {

// Each throws UsageError("<writer>: <what is inconsistent>").

// dim >= 1, simplices a whole number of rows of dim+1 naming input points, neighbours
// absent or as many, naming simplices or -1.
void check_triangulation(const Triangulation& triangulation, const char* writer);

// `points` is the input of a result of dimension `dim` computed from `num_points` points.
void check_same_input(PointsView points, int dim, std::size_t num_points, const char* writer);

// Rows of the right widths, ragged lists well formed, one point_region entry per input
// point naming an existing region, volumes absent or one per region.
void check_voronoi(const Voronoi& diagram, const char* writer);

// Corners in whole points, faces and cell_faces well formed, face entries naming existing
// corners, one volume per cell, a box of the cells' dimension.
void check_cells(const ClippedCells& cells, const char* writer);

// check_cells, and the cells are those of the diagram: one per region, same dimension.
void check_cells_of(const Voronoi& diagram, const ClippedCells& cells, const char* writer);

// The dimension is 2 or 3, else UsageError "<format> holds 2D and 3D only; the points have dimension <d>".
void check_2d_or_3d(int dim, const char* format);

// For the writers that draw a triangulation (VTK, OFF): check_triangulation, a dimension
// of 2 or 3, and `points` its input.
void check_drawable(PointsView points, const Triangulation& triangulation, const char* format, const char* writer);

}  // namespace drange::io
