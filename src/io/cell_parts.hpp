// io/cell_parts.hpp: what the JSON and VTK writers need to know about clipped cells beyond
// the flat arrays of ClippedCells: which corners one cell uses, and which input point owns
// each region.
#pragma once

#include <cstdint>
#include <vector>

#include "drange/voronoi.hpp"

namespace drange::io {

// The distinct corners (indices into ClippedCells::points) used by the faces of cell c,
// in increasing order.
std::vector<std::int32_t> cell_corners(const ClippedCells& cells, std::size_t c);

// For each region of the diagram, the first input point whose point_region names it
// (-1 for a region that no point names).
std::vector<std::int32_t> region_points(const Voronoi& diagram);

}  // namespace drange::io
