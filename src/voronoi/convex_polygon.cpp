// voronoi/convex_polygon.cpp: see convex_polygon.hpp.
#include "voronoi/convex_polygon.hpp"

namespace drange::cells {

void ConvexPolygon::set_box(const double* lower, const double* upper) {
  corners_ = {{lower[0], lower[1]}, {upper[0], lower[1]}, {upper[0], upper[1]}, {lower[0], upper[1]}};
  radius_ = max_norm(corners_);
}

ClipResult ConvexPolygon::clip(const double* normal, double offset, double tol) {
  if (corners_.empty()) return ClipResult::Empty;
  if (offset - tol >= radius_) return ClipResult::Unchanged;  // no corner reaches the line
  const SidesPresent present = classify(corners_, normal, offset, tol, distance_, side_);
  if (!present.outside) return ClipResult::Unchanged;
  if (!present.inside) {  // all on or beyond the line: nothing of positive area is left
    corners_.clear();
    return ClipResult::Empty;
  }
  // Walk the loop once: keep the corners inside or on the line, and put the crossing point
  // between a kept corner and a removed one. A convex polygon leaves one run of removed corners.
  next_.clear();
  const std::size_t k = corners_.size();
  for (std::size_t i = 0; i < k; ++i) {
    const std::size_t j = i + 1 == k ? 0 : i + 1;
    if (side_[i] != Side::Outside) keep(corners_[i], tol);
    if (!crosses(side_[i], side_[j])) continue;
    keep(side_[i] == Side::Inside ? crossing_point(corners_[i], distance_[i], corners_[j], distance_[j])
                                  : crossing_point(corners_[j], distance_[j], corners_[i], distance_[i]),
         tol);
  }
  while (next_.size() > 1 && distance(next_.back(), next_.front()) <= tol) next_.pop_back();
  if (next_.size() < 3) next_.clear();
  corners_.swap(next_);
  radius_ = max_norm(corners_);
  return corners_.empty() ? ClipResult::Empty : ClipResult::Cut;
}

void ConvexPolygon::keep(const Corner& c, double tol) {
  // Only a crossing point and an on-line corner can be this close: a corner inside is more
  // than tol from the line, where the crossing points are.
  if (next_.empty() || distance(c, next_.back()) > tol) next_.push_back(c);
}

double ConvexPolygon::volume() const {
  double twice = 0;
  for (std::size_t i = 1; i + 1 < corners_.size(); ++i) {
    const double ax = corners_[i][0] - corners_[0][0], ay = corners_[i][1] - corners_[0][1];
    const double bx = corners_[i + 1][0] - corners_[0][0], by = corners_[i + 1][1] - corners_[0][1];
    twice += ax * by - ay * bx;
  }
  return twice / 2;
}

}  // namespace drange::cells
