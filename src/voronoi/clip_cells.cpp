// voronoi/clip_cells.cpp: the Voronoi cells clipped to a box (d = 2, 3), and the default box.
//
// The cell of point p is the intersection of the half-spaces |x - p| <= |x - q| over its
// ridge partners q (Voronoi::ridge_points: the only neighbours whose bisectors bound the
// cell); cell_clipper.hpp cuts the box by their bisectors.
//
// The clipping of one cell, its accuracy and tolerance: cell_clipper.cpp.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "drange/errors.hpp"
#include "drange/voronoi.hpp"
#include "voronoi/cell_clipper.hpp"

namespace drange {
namespace {

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
  cells::check_box(box, points.dim);  // NaN or infinite coordinates
  return box;
}

ClippedCells clip_cells(PointsView points, const Voronoi& diagram, const Box& box) {
  if (points.dim != 2 && points.dim != 3)
    throw UsageError("clipped cells are computed in 2D and 3D; the points have dimension " + std::to_string(points.dim));
  check_diagram(points, diagram);
  cells::check_box(box, points.dim);
  ClippedCells out;
  out.dim = points.dim;
  out.box = box;
  const IndexLists partners = ridge_partners(diagram);
  cells::CellClipper clipper(points, out.box);
  for (const std::int32_t point : diagram.region_point) {
    const auto i = static_cast<std::size_t>(point);
    clipper.append(i, partners.values.data() + partners.offsets[i], partners.row_size(i), out);
  }
  return out;
}

}  // namespace drange
