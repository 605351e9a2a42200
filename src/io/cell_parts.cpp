// io/cell_parts.cpp: per-cell views of clipped Voronoi cells (cell_parts.hpp).
#include "io/cell_parts.hpp"

#include <algorithm>

namespace drange::io {

std::vector<std::int32_t> cell_corners(const ClippedCells& cells, std::size_t c) {
  const auto first = static_cast<std::size_t>(cells.cell_faces[c]);
  const auto last = static_cast<std::size_t>(cells.cell_faces[c + 1]);
  std::vector<std::int32_t> corners;
  for (std::size_t f = first; f < last; ++f)
    corners.insert(corners.end(), cells.faces.row(f), cells.faces.row(f) + cells.faces.row_size(f));
  std::sort(corners.begin(), corners.end());
  corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
  return corners;
}

std::vector<std::int32_t> region_points(const Voronoi& diagram) {
  std::vector<std::int32_t> points(diagram.regions.size(), -1);
  // Backwards, so that the first point naming a region is the one kept.
  for (std::size_t i = diagram.point_region.size(); i-- > 0;) {
    if (diagram.point_region[i] >= 0) points[static_cast<std::size_t>(diagram.point_region[i])] = static_cast<std::int32_t>(i);
  }
  return points;
}

}  // namespace drange::io
