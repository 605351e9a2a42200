// voronoi/flag_volumes.hpp: Voronoi cell volumes in any dimension by a flag decomposition.
//
// The cell of an interior point p is cut into simplices by its faces' "flags": for a
// Delaunay simplex S around p and an order v_1..v_d of S's other vertices, the faces
// F_0 = {p} < F_1 = {p, v_1} < ... < F_d = S have circumcentres c_0 = p, c_1, ..., c_d
// (c_k: the point of F_k's affine hull equidistant from its vertices), and the simplex
// [c_0, ..., c_d] is one piece. The steps u_k = c_k - c_{k-1} are mutually orthogonal, so the
// piece's volume is |u_1| ... |u_d| / d!, taken with the sign of u_k . (v_k - p) at each step:
// this is the pyramid formula vol(P) = (1/k) sum over P's facets of height * facet volume,
// applied recursively to the cell, its ridges, and so on down to the Voronoi edges, with
// signed heights so that a circumcentre outside its face still counts right. Summed over
// all flags of all simplices around p it is the cell's volume; on cospherical input the
// pieces of a degenerate face cancel (their heights have opposite signs).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "delaunay/team.hpp"
#include "drange/delaunay.hpp"
#include "drange/points.hpp"

namespace drange::diagram {

// The part of each of a Delaunay simplex's vertices' Voronoi cells that the simplex's flags
// cover (signed; a cell's volume is the sum of its parts over the simplices around it), in
// double, redone in extended precision for a simplex with a nearly flat face. One object is
// reused for many simplices of one dimension; not shared between threads.
class SimplexCellParts {
 public:
  explicit SimplexCellParts(int d);
  ~SimplexCellParts();
  SimplexCellParts(const SimplexCellParts&) = delete;
  SimplexCellParts& operator=(const SimplexCellParts&) = delete;
  // parts[k] (d + 1 of them): vertex k's part.
  void compute(PointsView points, const std::int32_t* simplex, double* parts);

 private:
  struct Pieces;
  int d_;
  std::unique_ptr<Pieces> pieces_;
};

// Simplices per range of a thread: each is worth microseconds in 4D and more above.
inline constexpr std::size_t kSimplicesPerRange = 512;

// The volume of the cell of every point not on the hull (on_hull[p] == 0); 0 for the others.
// The same for every thread count of `team`.
std::vector<double> flag_cell_volumes(PointsView points, const Triangulation& t, const std::vector<char>& on_hull,
                                      engine::Team& team);

}  // namespace drange::diagram
