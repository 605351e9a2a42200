// voronoi/cell_volumes.cpp: the volume of every bounded Voronoi cell, in any dimension.
//
// In 2D and 3D the ridges are known polygons (segments; cyclic polygons), so the cell of p is
// the union of the pyramids from p over its ridges: vol = (1/d) sum |pq|/2 * area(ridge),
// positive terms only. In higher dimensions the ridges are not built as polytopes; there the
// flag decomposition of flag_volumes.hpp cuts each cell into simplices.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "util/for_ranges.hpp"
#include "voronoi/diagram_parts.hpp"
#include "voronoi/flag_volumes.hpp"

namespace drange::diagram {
namespace {

constexpr std::size_t kRidgesPerRange = std::size_t{1} << 12;

// The (d-1)-measure of a bounded ridge: a segment's length (2D) or a planar polygon's area
// (3D; its vertices in cyclic order).
double ridge_measure(const Voronoi& v, std::size_t r) {
  const std::int32_t* ids = v.ridge_vertices.row(r);
  const std::size_t n = v.ridge_vertices.row_size(r);
  const double* o = v.vertex(static_cast<std::size_t>(ids[0]));
  if (v.dim == 2) {
    const double* a = v.vertex(static_cast<std::size_t>(ids[n - 1]));
    return std::hypot(a[0] - o[0], a[1] - o[1]);
  }
  double normal[3] = {0, 0, 0};
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double* a = v.vertex(static_cast<std::size_t>(ids[i]));
    const double* b = v.vertex(static_cast<std::size_t>(ids[i + 1]));
    const double u[3] = {(double)a[0] - o[0], (double)a[1] - o[1], (double)a[2] - o[2]};
    const double w[3] = {(double)b[0] - o[0], (double)b[1] - o[1], (double)b[2] - o[2]};
    normal[0] += u[1] * w[2] - u[2] * w[1];
    normal[1] += u[2] * w[0] - u[0] * w[2];
    normal[2] += u[0] * w[1] - u[1] * w[0];
  }
  return static_cast<double>(std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]) / 2);
}

// 2D and 3D: pyramids from each point over its ridges. The pyramids of a block of ridges are
// computed on the team's threads, then added to the cells in ridge order, so that every sum
// (and its rounding) is the same for every thread count.
std::vector<double> volumes_from_ridges(PointsView points, const Voronoi& v, engine::Team& team) {
  std::vector<double> volume(points.n, 0.0);
  constexpr std::size_t kBlock = std::size_t{1} << 16;
  std::vector<double> pyramids(std::min(kBlock, v.num_ridges()));
  for (std::size_t first = 0; first < v.num_ridges(); first += kBlock) {
    const std::size_t count = std::min(kBlock, v.num_ridges() - first);
    util::for_ranges(count, team, [&](std::size_t, std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) {
        const std::size_t r = first + i;
        if (v.ridge_vertices.row(r)[0] < 0) continue;  // unbounded: both cells are unbounded
        const auto p = static_cast<std::size_t>(v.ridge_points[2 * r]);
        const auto q = static_cast<std::size_t>(v.ridge_points[2 * r + 1]);
        double distance2 = 0;
        for (int k = 0; k < v.dim; ++k) distance2 += (points.point(q)[k] - points.point(p)[k]) * (points.point(q)[k] - points.point(p)[k]);
        pyramids[i] = std::sqrt(distance2) / 2 * ridge_measure(v, r) / v.dim;
      }
    }, kRidgesPerRange);
    for (std::size_t i = 0; i < count; ++i) {
      const std::size_t r = first + i;
      if (v.ridge_vertices.row(r)[0] < 0) continue;
      volume[static_cast<std::size_t>(v.ridge_points[2 * r])] += pyramids[i];
      volume[static_cast<std::size_t>(v.ridge_points[2 * r + 1])] += pyramids[i];
    }
  }
  return volume;
}

}  // namespace

void compute_cell_volumes(PointsView points, const Triangulation& t, const std::vector<char>& on_hull, Voronoi& out,
                          engine::Team& team) {
  const std::vector<double> volume =
      t.dim <= 3 ? volumes_from_ridges(points, out, team) : flag_cell_volumes(points, t, on_hull, team);
  out.volumes.resize(out.region_point.size());
  for (std::size_t r = 0; r < out.region_point.size(); ++r) {
    const auto p = static_cast<std::size_t>(out.region_point[r]);
    out.volumes[r] = on_hull[p] ? std::numeric_limits<double>::infinity() : volume[p];
  }
}

}  // namespace drange::diagram
