// voronoi/clip_cells.cpp: the Voronoi cells clipped to a box (d = 2, 3), and the default box.
//
// The cell of point p is the intersection of the half-spaces |x - p| <= |x - q| over its
// ridge partners q (Voronoi::ridge_points: the only neighbours whose bisectors bound the
// cell). Clipped to the box, it is the box cut by those half-spaces, one after the other:
// a convex polygon (2D, convex_polygon.hpp) or polyhedron (3D, convex_polyhedron.hpp). Extra
// partners are harmless: a bisector that does not bound the cell only touches it or misses it.
//
// Accuracy: every cell is computed in coordinates relative to its point p, where the
// half-space reads  u . (x - p) <= |q - p| / 2  with u the unit vector from p to q, so that
// the distances compared are those of the cell's own scale, whatever the offset of the
// cloud from the origin.
//
// Tolerance: a corner within tol = 1e-12 * S of a bisector counts as on it, S being the
// largest relative coordinate of the box (max |box corner - p| per axis), the magnitude of
// every number the clip computes. Each corner comes out of a few operations per clip, each
// rounding by about 1.1e-16 * S, and a cell goes through tens of clips: in cells that are not
// slivers the corners carry errors below 1e-13 * S. 1e-12 * S is above this noise, so a
// bisector through a corner is recognised and the cell keeps its clean shape (a grid: the
// bisectors of diagonal neighbours pass through the cells' corners, exactly on an integer
// grid, within rounding on a grid of spacing 0.1), and it is far below any real feature (a
// million cells in a box are about 1e-3 * S wide in 2D, 1e-2 * S in 3D). Edges up to tol long are merged away after every
// clip, so that the next clips see one corner where rounding made several (the Voronoi
// vertices of nearly cospherical points): features below the tolerance are rounding, not
// geometry.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "drange/errors.hpp"
#include "drange/voronoi.hpp"
#include "voronoi/convex_polygon.hpp"
#include "voronoi/convex_polyhedron.hpp"

namespace drange {
namespace {

constexpr double kRelativeTolerance = 1e-12;

void check_box(const Box& box, int dim) {
  const std::string d = std::to_string(dim);
  if (box.lower.size() != static_cast<std::size_t>(dim) || box.upper.size() != static_cast<std::size_t>(dim))
    throw UsageError("clip_cells: the box has dimension " + std::to_string(box.lower.size()) + " (lower) and " +
                     std::to_string(box.upper.size()) + " (upper); the points have dimension " + d);
  for (int k = 0; k < dim; ++k) {
    const double lo = box.lower[static_cast<std::size_t>(k)], hi = box.upper[static_cast<std::size_t>(k)];
    if (!std::isfinite(lo) || !std::isfinite(hi))
      throw UsageError("clip_cells: the box is not finite on axis " + std::to_string(k) + " (" + std::to_string(lo) +
                       " to " + std::to_string(hi) + ")");
    if (!(lo < hi))
      throw UsageError("clip_cells: the box is empty on axis " + std::to_string(k) + " (lower " + std::to_string(lo) +
                       " is not below upper " + std::to_string(hi) + ")");
  }
}

void check_diagram(PointsView points, const Voronoi& diagram) {
  const bool matches = diagram.dim == points.dim && diagram.num_points == points.n && diagram.ridge_points.size() % 2 == 0 &&
                       diagram.region_point.size() == diagram.regions.size() &&
                       std::all_of(diagram.region_point.begin(), diagram.region_point.end(),
                                   [&](std::int32_t i) { return i >= 0 && static_cast<std::size_t>(i) < points.n; }) &&
                       std::all_of(diagram.ridge_points.begin(), diagram.ridge_points.end(),
                                   [&](std::int32_t i) { return i >= 0 && static_cast<std::size_t>(i) < points.n; });
  if (!matches)
    throw UsageError("clip_cells: the diagram was computed for other points (dimension " + std::to_string(diagram.dim) +
                     ", " + std::to_string(diagram.num_points) + " points; given dimension " +
                     std::to_string(points.dim) + ", " + std::to_string(points.n) + " points)");
}

// Every point's ridge partners, in compressed rows (IndexLists) indexed by input point.
IndexLists ridge_partners(const Voronoi& diagram) {
  std::vector<std::int64_t> count(diagram.num_points + 1, 0);
  for (const std::int32_t i : diagram.ridge_points) ++count[static_cast<std::size_t>(i) + 1];
  IndexLists partners;
  partners.offsets.resize(diagram.num_points + 1);
  for (std::size_t i = 0; i < diagram.num_points; ++i) partners.offsets[i + 1] = partners.offsets[i] + count[i + 1];
  partners.values.resize(diagram.ridge_points.size());
  std::vector<std::int64_t> next(partners.offsets.begin(), partners.offsets.end() - 1);
  for (std::size_t r = 0; r < diagram.num_ridges(); ++r) {
    const std::int32_t p = diagram.ridge_points[2 * r], q = diagram.ridge_points[2 * r + 1];
    partners.values[static_cast<std::size_t>(next[static_cast<std::size_t>(p)]++)] = q;
    partners.values[static_cast<std::size_t>(next[static_cast<std::size_t>(q)]++)] = p;
  }
  return partners;
}

// A bisector in the cell's relative coordinates: u . x <= offset, u a unit vector.
struct Bisector {
  double offset;
  double normal[3];
};

// Appends the clipped cell (coordinates relative to p) to the output.
template <class Shape>
void append_cell(const Shape& shape, const double* p, ClippedCells& out) {
  const auto d = static_cast<std::size_t>(out.dim);
  const std::size_t first = out.points.size() / d;
  if (first + shape.num_corners() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
    throw UsageError("clip_cells: more than 2^31 corners in all the clipped cells");
  // Back to absolute coordinates. Corners a rounding apart relative to p can become the same
  // double once p is added (a cell far from the origin): they are merged into one, and a face
  // edge or a whole face that this collapses is dropped.
  std::vector<std::int32_t> index(shape.num_corners());
  std::size_t added = 0;
  for (std::size_t v = 0; v < shape.num_corners(); ++v) {
    double corner[3];
    for (std::size_t k = 0; k < d; ++k) corner[k] = p[k] + shape.corner(v)[k];
    std::size_t same = 0;
    while (same < added && !std::equal(corner, corner + d, out.points.begin() + static_cast<std::ptrdiff_t>((first + same) * d))) ++same;
    if (same == added) {
      out.points.insert(out.points.end(), corner, corner + d);
      ++added;
    }
    index[v] = static_cast<std::int32_t>(first + same);
  }
  for (std::size_t f = 0; f < shape.num_faces(); ++f) {
    const std::size_t start = out.faces.values.size();
    for (std::size_t i = 0; i < shape.face_size(f); ++i) {
      const std::int32_t c = index[static_cast<std::size_t>(shape.face_corner(f, i))];
      if (out.faces.values.size() == start || out.faces.values.back() != c) out.faces.values.push_back(c);
    }
    if (out.faces.values.size() - start > 1 && out.faces.values.back() == out.faces.values[start]) out.faces.values.pop_back();
    if (out.faces.values.size() - start < 3) {
      out.faces.values.resize(start);
      continue;
    }
    out.faces.end_row();
  }
  out.cell_faces.push_back(static_cast<std::int64_t>(out.faces.size()));
  out.volumes.push_back(shape.empty() ? 0.0 : shape.volume());
}

template <class Shape>
void clip_all(PointsView points, const Voronoi& diagram, const IndexLists& partners, ClippedCells& out) {
  const auto d = static_cast<std::size_t>(points.dim);
  Shape shape;
  std::vector<Bisector> bisectors;
  double lower[3], upper[3];
  for (std::size_t r = 0; r < diagram.regions.size(); ++r) {
    const auto i = static_cast<std::size_t>(diagram.region_point[r]);
    const double* p = points.point(i);
    double scale = 0;
    for (std::size_t k = 0; k < d; ++k) {
      lower[k] = out.box.lower[k] - p[k];
      upper[k] = out.box.upper[k] - p[k];
      scale = std::max({scale, std::fabs(lower[k]), std::fabs(upper[k])});
    }
    const double tol = kRelativeTolerance * scale;
    shape.set_box(lower, upper);
    bisectors.clear();
    for (std::size_t j = static_cast<std::size_t>(partners.offsets[i]); j < static_cast<std::size_t>(partners.offsets[i + 1]); ++j) {
      const double* q = points.point(static_cast<std::size_t>(partners.values[j]));
      Bisector b{0, {0, 0, 0}};
      double length2 = 0;
      for (std::size_t k = 0; k < d; ++k) {
        b.normal[k] = q[k] - p[k];
        length2 += b.normal[k] * b.normal[k];
      }
      if (length2 == 0) continue;  // an exact copy of p: no bisector
      const double length = std::sqrt(length2);
      for (std::size_t k = 0; k < d; ++k) b.normal[k] /= length;
      b.offset = length / 2;
      bisectors.push_back(b);
    }
    // Nearest partners first: they cut the most, and once the shape is small the farther
    // bisectors are dismissed by its radius without looking at its corners.
    std::sort(bisectors.begin(), bisectors.end(), [](const Bisector& a, const Bisector& b) { return a.offset < b.offset; });
    for (const Bisector& b : bisectors)
      if (shape.clip(b.normal, b.offset, tol) == cells::ClipResult::Empty) break;
    append_cell(shape, p, out);
  }
}

}  // namespace

Box default_clip_box(PointsView points, double margin) {
  if (points.dim < 1 || points.n == 0) throw UsageError("default_clip_box: no points");
  if (!std::isfinite(margin) || margin < 0)
    throw UsageError("default_clip_box: the margin must be finite and not negative, got " + std::to_string(margin));
  const auto d = static_cast<std::size_t>(points.dim);
  Box box{std::vector<double>(points.point(0), points.point(0) + d), std::vector<double>(points.point(0), points.point(0) + d)};
  for (std::size_t i = 1; i < points.n; ++i)
    for (std::size_t k = 0; k < d; ++k) {
      box.lower[k] = std::min(box.lower[k], points.point(i)[k]);
      box.upper[k] = std::max(box.upper[k], points.point(i)[k]);
    }
  double largest = 0;
  for (std::size_t k = 0; k < d; ++k) largest = std::max(largest, box.upper[k] - box.lower[k]);
  for (std::size_t k = 0; k < d; ++k) {
    // A flat axis (no valid triangulation has one) borrows the largest extent, or 1.
    const double extent = box.upper[k] > box.lower[k] ? box.upper[k] - box.lower[k] : largest > 0 ? largest : 1.0;
    box.lower[k] -= margin * extent;
    box.upper[k] += margin * extent;
    // With a zero margin on a flat axis, or one too small to move the bound: one ulp each way.
    if (!(box.lower[k] < box.upper[k])) {
      box.lower[k] = std::nextafter(box.lower[k], -std::numeric_limits<double>::infinity());
      box.upper[k] = std::nextafter(box.upper[k], std::numeric_limits<double>::infinity());
    }
  }
  check_box(box, points.dim);  // NaN or infinite coordinates
  return box;
}

ClippedCells clip_cells(PointsView points, const Voronoi& diagram, const Box& box) {
  if (points.dim != 2 && points.dim != 3)
    throw UsageError("clipped cells are computed in 2D and 3D; the points have dimension " + std::to_string(points.dim));
  check_diagram(points, diagram);
  check_box(box, points.dim);
  ClippedCells out;
  out.dim = points.dim;
  out.box = box;
  const IndexLists partners = ridge_partners(diagram);
  if (points.dim == 2) clip_all<cells::ConvexPolygon>(points, diagram, partners, out);
  else clip_all<cells::ConvexPolyhedron>(points, diagram, partners, out);
  return out;
}

}  // namespace drange
