// voronoi/convex_polygon.hpp: a convex polygon cut by half-planes (Sutherland-Hodgman),
// the 2D shape of clip_cells. Coordinates are relative to the cell's point.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "voronoi/half_space.hpp"

namespace drange::cells {

class ConvexPolygon {
 public:
  using Corner = std::array<double, 2>;

  // The rectangle [lower, upper], counter-clockwise.
  void set_box(const double* lower, const double* upper);

  // Keeps the part where normal . x <= offset (normal a unit vector); corners within tol of
  // the line are on it (half_space.hpp). Afterwards no edge is tol long or shorter: a corner
  // within tol of the previous one is dropped, and fewer than 3 corners make the polygon empty.
  ClipResult clip(const double* normal, double offset, double tol);

  // The area (shoelace formula relative to the first corner; positive: counter-clockwise).
  double volume() const;

  bool empty() const { return corners_.empty(); }
  std::size_t num_corners() const { return corners_.size(); }
  const double* corner(std::size_t v) const { return corners_[v].data(); }
  // One face: the loop of all corners, in order.
  std::size_t num_faces() const { return corners_.empty() ? 0 : 1; }
  std::size_t face_size(std::size_t) const { return corners_.size(); }
  std::int32_t face_corner(std::size_t, std::size_t i) const { return static_cast<std::int32_t>(i); }

 private:
  // Appends c to next_ unless it is within tol of the last corner there.
  void keep(const Corner& c, double tol);

  std::vector<Corner> corners_;
  double radius_ = 0;  // max_norm(corners_)
  // Scratch space of clip(), kept between calls.
  std::vector<Corner> next_;
  std::vector<double> distance_;
  std::vector<Side> side_;
};

}  // namespace drange::cells
