// drange/voronoi.hpp: the Voronoi diagram of points in E^d, read off their Delaunay
// triangulation (paper, section 2.5: the Voronoi vertices are the circumcentres of the
// Delaunay simplices, and two cells touch where their points share a Delaunay edge), with
// the names and meaning of scipy.spatial.Voronoi, and the cells clipped to a box in 2D/3D.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "drange/delaunay.hpp"
#include "drange/points.hpp"

namespace drange {

// Ragged rows of int32 in compressed form: row r is values[offsets[r] .. offsets[r+1]).
struct IndexLists {
  std::vector<std::int64_t> offsets{0};
  std::vector<std::int32_t> values;

  std::size_t size() const { return offsets.size() - 1; }
  std::size_t row_size(std::size_t r) const { return static_cast<std::size_t>(offsets[r + 1] - offsets[r]); }
  const std::int32_t* row(std::size_t r) const { return values.data() + offsets[r]; }
  void end_row() { offsets.push_back(static_cast<std::int64_t>(values.size())); }
};

// The diagram, named as in scipy.spatial.Voronoi. Vertex id -1 is the point at infinity.
//   vertices        num_vertices x dim circumcentres. Simplices sharing one circumsphere
//                   (cospherical points: every cell of an integer grid) share one vertex;
//                   that is decided exactly, by the in-sphere predicate, never by a tolerance.
//   simplex_vertex  for every Delaunay simplex, the id of its (merged) Voronoi vertex.
//   ridge_points    num_ridges x 2 input indices (p < q) whose cells share a (d-1)-face.
//   ridge_vertices  for each ridge, its Voronoi vertex ids, with -1 when it is unbounded; in
//                   2D the two ends, in 3D the polygon in cyclic order.
//   regions         one per distinct input point: its cell's vertex ids, with -1 when the
//                   cell is unbounded; in 2D in counter-clockwise order (-1 stands where the
//                   cell opens to infinity).
//   point_region    for every input point, its region; an exact duplicate shares the
//                   region of the point it copies.
//   volumes         for each region, the d-volume of its cell, +infinity when unbounded
//                   (any d: area in 2D).
struct Voronoi {
  int dim = 0;
  std::size_t num_points = 0;
  std::vector<double> vertices;
  std::vector<std::int32_t> simplex_vertex;
  std::vector<std::int32_t> ridge_points;
  IndexLists ridge_vertices;
  IndexLists regions;
  std::vector<std::int32_t> point_region;
  std::vector<std::int32_t> region_point;  // the input point (the first of its copies) of each region
  std::vector<double> volumes;

  std::size_t num_vertices() const { return dim > 0 ? vertices.size() / static_cast<std::size_t>(dim) : 0; }
  std::size_t num_ridges() const { return ridge_points.size() / 2; }
  const double* vertex(std::size_t v) const { return vertices.data() + v * static_cast<std::size_t>(dim); }
};

// An axis-aligned box: lower corner and upper corner, dim values each.
struct Box {
  std::vector<double> lower, upper;
};

// The default clipping box: the points' bounding box, enlarged by `margin` times its extent
// on every side (at least by 1 ulp-safe absolute amount when the extent is zero).
Box default_clip_box(PointsView points, double margin = 0.1);

// Voronoi cells clipped to a box, for d = 2 and 3. Cell c is the cell of region c
// (Voronoi::regions), intersected with the box; the cells tile the box.
//   points         the cells' corner coordinates, dim per corner; each cell has its own corners.
//   faces          the boundary loops: in 2D one loop per cell, the polygon counter-clockwise;
//                  in 3D one loop per face, counter-clockwise seen from outside the cell.
//                  Values index `points`.
//   cell_faces     cell c owns faces [cell_faces[c], cell_faces[c+1]).
//   volumes        area (2D) or volume (3D) of each clipped cell.
// A cell that misses the box is empty (no faces, volume 0).
struct ClippedCells {
  int dim = 0;
  Box box;
  std::vector<double> points;
  IndexLists faces;
  std::vector<std::int64_t> cell_faces{0};
  std::vector<double> volumes;

  std::size_t size() const { return cell_faces.size() - 1; }
};

struct VoronoiOptions {
  // How the triangulation is computed; its `threads` also build the diagram (0: one per
  // hardware thread; the diagram is the same for every count).
  Options delaunay;
  bool cell_volumes = true;  // fill Voronoi::volumes
};

// The Voronoi diagram of the points, computed from their Delaunay triangulation.
// Throws as drange::delaunay does.
Voronoi voronoi(PointsView points, const VoronoiOptions& options = {});

// The same, from a triangulation already computed for these points by drange::delaunay
// (its neighbours must be present). Of options.delaunay only `threads` is read.
// Throws UsageError when the triangulation is for other points or has no neighbours, or for a
// negative thread count.
Voronoi voronoi(PointsView points, const Triangulation& triangulation, const VoronoiOptions& options = {});

// The cells of the points `ids` only (zero-based input indices), computed from their Delaunay
// stars (drange::delaunay_stars) without the rest of the triangulation. The result is the
// whole diagram restricted to these cells: `regions`, `region_point` and `volumes` hold one
// region per distinct cell asked for (a duplicate's id gives its original's cell), each equal to
// the whole diagram's cell (the same vertices, boundedness and volume, up to the rounding of the
// centres and of the volume's sum); `point_region` is -1 for a point whose cell was not asked
// for; `vertices` are those of the cells, `ridge_points`/`ridge_vertices` the ridges with a
// point of `ids` at one end; `simplex_vertex` is empty. Within a cell the vertex ids are
// distinct; a Voronoi vertex shared by two asked-for cells has one id, except when the simplices
// of its (cospherical) sphere around the two points are not connected through the stars'
// simplices: then each cell names its own copy. docs/algorithm.md ("Local stars") says why the
// cells are right.
// Throws as drange::delaunay_stars does.
Voronoi voronoi_cells(PointsView points, const std::vector<std::int64_t>& ids, const VoronoiOptions& options = {});

// Clips every cell of the diagram to the box (d = 2 or 3). Throws UsageError for another
// dimension or a box that is empty, not finite, or of the wrong dimension.
ClippedCells clip_cells(PointsView points, const Voronoi& diagram, const Box& box);

// What stream_clipped_cells did.
struct CellStreamReport {
  std::vector<Duplicate> duplicates;  // exact copies: no cell of their own
  std::size_t cells = 0;              // one per distinct point
  std::size_t star_simplices = 0;     // simplices found, counting those of two batches twice
  std::size_t batches = 0;
  std::size_t threads = 1;
};

// The cell of every distinct point clipped to the box (d = 2, 3), computed a batch of points
// at a time from their Delaunay stars (delaunay/local_star.hpp) without the whole
// triangulation or diagram: memory holds the input, its kd-tree, and per thread the stars of a
// batch, a mark per point and the text of a few batches.
// The cells are clip_cells' cells of the whole diagram, up to rounding: a cell is cut by the
// bisectors of every Delaunay neighbour of its point, which include its ridge partners (the
// others only touch the cell), in another order when offsets tie. Each distinct point has one
// cell, named by its first copy (an exact duplicate shares it, as in clip_cells); a cell that
// misses the box is empty (no faces, volume 0).
// `format(cell, point, text)` appends to the text of its batch the cell of input point `point`
// (`cell` holds that one cell); it runs on the thread that computed the batch, concurrently
// with other batches. `write` receives the batches' texts in batch order, one call at a time.
// The batches follow the kd-tree's order of the points, so the output is the same for every
// thread count. Of `options`, threads, variant and algorithm are read.
// Throws UsageError for another dimension than 2 or 3, a bad box or options; as drange::delaunay
// for bad or degenerate points; and whatever format or write throws (no batch is written after).
CellStreamReport stream_clipped_cells(PointsView points, const Box& box, const Options& options,
                                      const std::function<void(const ClippedCells& cell, std::int32_t point, std::string& text)>& format,
                                      const std::function<void(const std::string&)>& write);

}  // namespace drange
