// A consumer of drange's public API: the four corners of the unit square and its centre give
// four triangles, and the centre's Voronoi cell is the diamond through the edges' midpoints,
// of area 1/2. The Voronoi step pulls in the code that needs quadmath (in GCC builds), so the
// link line must carry every private dependency of the static library. Exits 1 on a wrong
// answer.
#include <cmath>
#include <cstdio>

#include "drange/drange.hpp"

int main() {
  drange::PointCloud square;
  square.dim = 2;
  square.coords = {0, 0, 1, 0, 1, 1, 0, 1, 0.5, 0.5};

  const drange::Triangulation triangulation = drange::delaunay(square);
  const drange::Voronoi diagram = drange::voronoi(square);
  const double centre_area = diagram.volumes[static_cast<std::size_t>(diagram.point_region[4])];

  std::printf("triangles %zu, centre cell area %g\n", triangulation.size(), centre_area);
  if (triangulation.size() != 4 || std::fabs(centre_area - 0.5) > 1e-12) {
    std::printf("wrong: expected 4 triangles and area 0.5\n");
    return 1;
  }
  return 0;
}
