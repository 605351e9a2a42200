// voronoi/cell_clipper.cpp: one clipped cell (cell_clipper.hpp).
//
// The cell of point p is the intersection of the half-spaces |x - p| <= |x - q| over its
// partners q. Clipped to the box, it is the box cut by those half-spaces, one after the other:
// a convex polygon (2D, convex_polygon.hpp) or polyhedron (3D, convex_polyhedron.hpp).
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
#include "voronoi/cell_clipper.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>

#include "drange/errors.hpp"

namespace drange::cells {
namespace {

constexpr double kRelativeTolerance = 1e-12;

// A hash of a corner's coordinates that equal coordinates share (-0 and +0 too).
std::uint64_t corner_hash(const double* corner, std::size_t d) {
  std::uint64_t hash = 0;
  for (std::size_t k = 0; k < d; ++k) {
    const double x = corner[k] + 0.0;  // -0 becomes +0
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    hash = (hash ^ bits) * 0x9E3779B97F4A7C15ull;
  }
  return hash ^ (hash >> 29);
}

}  // namespace

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

CellClipper::CellClipper(PointsView points, const Box& box) : points_(points), box_(box) {}

void CellClipper::append(std::size_t i, const std::int32_t* partners, std::size_t count, ClippedCells& out) {
  const double* p = points_.point(i);
  if (points_.dim == 2) cut(polygon_, p, partners, count, out);
  else cut(polyhedron_, p, partners, count, out);
}

template <class Shape>
void CellClipper::append_cell(const Shape& shape, const double* p, ClippedCells& out) {
  const auto d = static_cast<std::size_t>(out.dim);
  const std::size_t first = out.points.size() / d;
  const std::size_t corners = shape.num_corners();
  if (first + corners > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
    throw UsageError("clip_cells: more than 2^31 corners in all the clipped cells");
  // Back to absolute coordinates. Corners a rounding apart relative to p can become the same
  // double once p is added (a cell far from the origin): they are merged into one, and a face
  // edge or a whole face that this collapses is dropped. The corners added so far are found by
  // a hash of their coordinates (slots_, open addressing): they are distinct, so a corner equals
  // at most one of them.
  std::size_t slots = 16;
  while (slots < 2 * corners) slots *= 2;
  slots_.assign(slots, -1);
  index_.resize(corners);
  std::int32_t added = 0;
  for (std::size_t v = 0; v < corners; ++v) {
    double corner[3];
    for (std::size_t k = 0; k < d; ++k) corner[k] = p[k] + shape.corner(v)[k];
    for (std::size_t s = corner_hash(corner, d) & (slots - 1);; s = (s + 1) & (slots - 1)) {
      if (slots_[s] < 0) {
        slots_[s] = added++;
        out.points.insert(out.points.end(), corner, corner + d);
        index_[v] = static_cast<std::int32_t>(first) + slots_[s];
        break;
      }
      const double* other = out.points.data() + (first + static_cast<std::size_t>(slots_[s])) * d;
      if (std::equal(corner, corner + d, other)) {
        index_[v] = static_cast<std::int32_t>(first) + slots_[s];
        break;
      }
    }
  }
  for (std::size_t f = 0; f < shape.num_faces(); ++f) {
    const std::size_t start = out.faces.values.size();
    for (std::size_t i = 0; i < shape.face_size(f); ++i) {
      const std::int32_t c = index_[static_cast<std::size_t>(shape.face_corner(f, i))];
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
void CellClipper::cut(Shape& shape, const double* p, const std::int32_t* partners, std::size_t count, ClippedCells& out) {
  const auto d = static_cast<std::size_t>(points_.dim);
  double lower[3], upper[3];
  double scale = 0;
  for (std::size_t k = 0; k < d; ++k) {
    lower[k] = box_.lower[k] - p[k];
    upper[k] = box_.upper[k] - p[k];
    scale = std::max({scale, std::fabs(lower[k]), std::fabs(upper[k])});
  }
  const double tol = kRelativeTolerance * scale;
  shape.set_box(lower, upper);
  bisectors_.clear();
  for (std::size_t j = 0; j < count; ++j) {
    const double* q = points_.point(static_cast<std::size_t>(partners[j]));
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
    bisectors_.push_back(b);
  }
  // Nearest partners first: they cut the most, and once the shape is small the farther
  // bisectors are dismissed by its radius without looking at its corners.
  std::sort(bisectors_.begin(), bisectors_.end(), [](const Bisector& a, const Bisector& b) { return a.offset < b.offset; });
  for (const Bisector& b : bisectors_)
    if (shape.clip(b.normal, b.offset, tol) == ClipResult::Empty) break;
  append_cell(shape, p, out);
}

}  // namespace drange::cells
