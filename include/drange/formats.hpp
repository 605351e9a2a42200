// drange/formats.hpp: results in the formats other tools read: NumPy (.npy, and .npz
// archives that numpy.load opens as a dict), JSON with scipy.spatial's names, VTK XML
// (.vtu, for ParaView), Geomview's OFF, and Qhull's Voronoi layouts (`qvoronoi o`,
// `qvoronoi Fv`). Points stored with numpy.save are read by drange::read_points (io.hpp).
//
// Every writer streams to a std::ostream; none builds the whole output in memory. The
// dispatchers at the end pick a format from a name or a file extension and write through
// write_file_atomically, so a file is written all or nothing ("-" is standard output, also
// for the binary formats).
#pragma once

#include <cstddef>
#include <cstdint>
#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

#include "drange/delaunay.hpp"
#include "drange/points.hpp"
#include "drange/voronoi.hpp"

namespace drange {

// ------------------------------------------------------------------------------ NumPy

// The element types drange writes: '<i4', '<i8' and '<f8' in NumPy's notation.
enum class NpyType { Int32, Int64, Float64 };

// A non-owning view of one array to write: its element type, its elements in C order, and
// its shape. An empty shape is a 0-d array (one element, a scalar); {n} a vector; {n, m} a
// matrix. `data` may be null only when the shape holds no element.
struct NpyArray {
  NpyType type;
  const void* data;
  std::vector<std::size_t> shape;

  NpyArray(const std::int32_t* values, std::vector<std::size_t> extents)
      : type(NpyType::Int32), data(values), shape(std::move(extents)) {}
  NpyArray(const std::int64_t* values, std::vector<std::size_t> extents)
      : type(NpyType::Int64), data(values), shape(std::move(extents)) {}
  NpyArray(const double* values, std::vector<std::size_t> extents)
      : type(NpyType::Float64), data(values), shape(std::move(extents)) {}

  // The number of elements: the product of the extents (1 for a 0-d array).
  std::size_t size() const;
};

// Writes one array as a .npy file, in NumPy's format version 1.0 (numpy/lib/format.py):
// the magic "\x93NUMPY", version 1.0, the header length, the header dict
// {'descr': '<f8', 'fortran_order': False, 'shape': (n, d), } padded with spaces and a
// newline to a multiple of 64 bytes, then the elements, little-endian, in C order.
void write_npy(std::ostream& out, const NpyArray& array);

// One member of an .npz archive: `name` becomes the member "<name>.npy", and the key under
// which numpy.load(path)[name] finds the array.
struct NpzMember {
  std::string name;
  NpyArray array;
};

// Writes an uncompressed .npz: a zip archive (PKWARE APPNOTE, method 0 "stored") holding
// one .npy per member, as numpy.savez writes it. Deterministic: every member is dated
// 1980-01-01 00:00. ZIP64 is not implemented: an archive of 4 GiB or more, or of 65535
// members or more, throws UsageError before anything is written.
void write_npz(std::ostream& out, const std::vector<NpzMember>& members);

// The triangulation as an .npz. Members (scipy.spatial.Delaunay's names):
//   ndim       0-d int64, the dimension d
//   npoints    0-d int64, the number of input points
//   simplices  (m, d+1) int32, positively oriented
//   neighbors  (m, d+1) int32, -1 on the hull; only when the triangulation has them
//   coplanar   (k, 3) int32, one row [index, -1, original] per exact duplicate left out
//              (scipy's layout is [point, nearest simplex, nearest vertex]; drange names no
//              simplex, hence -1, and the point the duplicate copies)
void write_delaunay_npz(std::ostream& out, const Triangulation& triangulation);

// The Voronoi diagram as an .npz. Ragged lists (drange::IndexLists) become two members:
// "<name>" the values (int32) and "<name>_offsets" (int64, rows + 1 entries): row r is
// values[offsets[r]:offsets[r+1]]. Members:
//   ndim, npoints                       0-d int64
//   vertices                            (num_vertices, d) float64
//   ridge_points                        (num_ridges, 2) int32
//   ridge_vertices, ridge_vertices_offsets   ragged, -1 for the point at infinity
//   regions, regions_offsets            ragged, -1 for the point at infinity
//   point_region                        (npoints,) int32, -1 for a cell not held
//   volumes                             (num_regions,) float64, inf when unbounded; only
//                                       when the diagram has volumes
// With `cells` (may be null), also the clipped cells (ClippedCells' fields):
//   clipped_box_lower, clipped_box_upper     (d,) float64
//   clipped_points                      (num_corners, d) float64
//   clipped_faces, clipped_faces_offsets     ragged, indices into clipped_points
//   clipped_cell_faces                  (num_cells + 1,) int64: cell c owns faces
//                                       [clipped_cell_faces[c], clipped_cell_faces[c+1])
//   clipped_volumes                     (num_cells,) float64
void write_voronoi_npz(std::ostream& out, const Voronoi& diagram, const ClippedCells* cells);

// ------------------------------------------------------------------------------ JSON

// One JSON object, streamed; numbers are printed in the shortest form that reads back as
// the same double, integers plainly. The names are scipy.spatial.Delaunay's:
//   {"ndim": d, "npoints": n, "simplices": [[...], ...], "neighbors": [[...], ...],
//    "coplanar": [[index, -1, original], ...]}
// "neighbors" only when the triangulation has them. The points are not repeated.
void write_delaunay_json(std::ostream& out, const Triangulation& triangulation);

// The Voronoi diagram with scipy.spatial.Voronoi's names:
//   {"ndim", "npoints", "vertices": [[x, y], ...], "ridge_points": [[p, q], ...],
//    "ridge_vertices": [[...], ...], "regions": [[...], ...], "point_region": [...],
//    "volumes": [...]}
// -1 in ridge_vertices and regions is the point at infinity; -1 in point_region a point whose
// cell the diagram does not hold (drange::voronoi_cells). JSON has no infinity: an
// unbounded cell's volume (and any other non-finite number) is written as null.
// "volumes" only when the diagram has them. With `cells` (may be null), also
//   "clipped_cells": {"box": {"lower": [...], "upper": [...]},
//                     "cells": [{"point": p, "points": [[x, y], ...], "faces": [[...], ...],
//                                "volume": v}, ...]}
// one entry per region, in region order; "point" is the region's input point, "points" the
// cell's own corners and "faces" its boundary loops indexing them (in 2D one loop, the
// polygon). An empty cell has no points and no faces.
void write_voronoi_json(std::ostream& out, const Voronoi& diagram, const ClippedCells* cells);

// ------------------------------------------------------------------------------ VTK

// The triangulation as a VTK XML UnstructuredGrid (.vtu, ASCII, file version 0.1): the
// input points (z = 0 in 2D) and one cell per simplex, VTK_TRIANGLE (5) in 2D or VTK_TETRA
// (10) in 3D. Throws UsageError for another dimension (VTK holds 2D and 3D only) or when
// `points` is not the triangulation's input.
void write_delaunay_vtu(std::ostream& out, PointsView points, const Triangulation& triangulation);

// The clipped Voronoi cells as a VTK XML UnstructuredGrid: in 2D one VTK_POLYGON (7) per
// cell (z = 0), in 3D one VTK_POLYHEDRON (42) per cell with the "faces" and "faceoffsets"
// arrays of VTK's XML format. Empty cells are left out. Cell data: "volume" (Float64, area
// in 2D) and "point" (Int32, the input point of the cell). Throws UsageError unless
// cells.dim is 2 or 3 and cells and diagram have the same number of regions.
void write_cells_vtu(std::ostream& out, const Voronoi& diagram, const ClippedCells& cells);

// ------------------------------------------------------------------------------ OFF

// Geomview's Object File Format: "OFF", then "nv nf 0", the vertices (x y z), the faces
// ("k i1 ... ik", zero-based). In 2D the triangles as a flat surface (z = 0, counter-
// clockwise); in 3D the boundary of the triangulation, the convex hull, as triangles
// oriented outward (only the hull's vertices are written). The 3D hull is read from the
// neighbours (-1 marks a hull facet): throws UsageError when the triangulation has none
// (compute it with Options::compute_neighbors), for another dimension, or when `points` is
// not the triangulation's input.
void write_delaunay_off(std::ostream& out, PointsView points, const Triangulation& triangulation);

// Every face of every clipped cell: in 2D each cell's polygon at z = 0, in 3D each cell's
// faces, so a face shared by two cells appears twice, once per cell with opposite
// orientations. The vertices are ClippedCells::points. Throws UsageError unless d is 2 or 3.
void write_cells_off(std::ostream& out, const ClippedCells& cells);

// ------------------------------------------------------------------------------ Text cells

// Clipped cells as plain text, one line per cell: the input point of the cell, its volume
// (area in 2D), and with `vertices` its number of corners k and their coordinates, "x y" (2D)
// or "x y z" (3D) each, all on the line: "p v" or "p v k x1 y1 ... xk yk". In 2D the corners
// run counter-clockwise; in 3D they come in no particular order (the cell is convex: their
// convex hull). An empty cell (it misses the box) is "p 0", or "p 0 0". Numbers in the
// shortest form that reads back as the same double. Appends the line of cell c of `cells`,
// that of input point `point` (drange::stream_clipped_cells formats each cell this way).
void append_cell_text(std::string& text, const ClippedCells& cells, std::size_t c, std::int32_t point, bool vertices);

// Whether `path` names a text cells file: it ends in ".txt", in any letter case.
bool is_cells_text_path(const std::string& path);

// ------------------------------------------------------------------------------ Qhull

// The layout of `qvoronoi o`: line 1 the dimension; line 2 "nv+1 n 1" (Voronoi vertices
// plus the point at infinity, input points); then the point at infinity written as
// "-10.101" d times, as Qhull does; then one line per vertex; then one line per input point
// "k v1 ... vk", its region's vertex indices shifted by one so that 0 is the point at
// infinity. An exact duplicate repeats the region of the point it copies. Throws UsageError
// for a diagram without every point's region (drange::voronoi_cells).
void write_qvoronoi_o(std::ostream& out, const Voronoi& diagram);

// The layout of `qvoronoi Fv`: line 1 the number of ridges; then one line per ridge
// "k p q v1 ... vj", where k = j + 2 counts the two input points p, q and the j Voronoi
// vertices, which are shifted by one so that 0 is the point at infinity. As qvoronoi does,
// only ridges with at least d vertex entries (infinity included) are written: in 3D and
// above, the unbounded ridge of a hull edge that lies in a single simplex (one Voronoi
// vertex and infinity) is left out. Voronoi::ridge_points has every ridge.
void write_qvoronoi_fv(std::ostream& out, const Voronoi& diagram);

// ------------------------------------------------------------------------------ choosing

enum class OutputFormat {
  Qhull,  // `qdelaunay i` for a triangulation (write_index_rows), `qvoronoi o` for a diagram
  Json,
  Npz,
  Vtu,
  Off,
};

// Parses "qhull", "json", "npz", "vtu", "off"; throws UsageError naming the bad value and
// the accepted names.
OutputFormat output_format_from_name(const std::string& name);
// The names accepted by output_format_from_name, for help texts.
const char* output_format_names();

// The format that a path's extension names (".json", ".npz", ".vtu", ".off", in any
// letter case); any other path, "-" included, gives `fallback`.
OutputFormat output_format_from_path(const std::string& path, OutputFormat fallback);

// Writes the triangulation of `points` to `path` ("-": standard output) in `format`, all or
// nothing (write_file_atomically). Throws as the writer of the format does.
void write_delaunay(const std::string& path, OutputFormat format, PointsView points,
                    const Triangulation& triangulation);

// Writes the diagram of `points` to `path` in `format`. Vtu and Off draw the clipped cells
// and throw UsageError when `cells` is null; Qhull, Json and Npz write the diagram, and the
// clipped cells too when given (Json and Npz). Throws UsageError when `points` is not the
// diagram's input.
void write_voronoi(const std::string& path, OutputFormat format, PointsView points, const Voronoi& diagram,
                   const ClippedCells* cells);

}  // namespace drange
