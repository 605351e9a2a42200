// voronoi/convex_polyhedron.hpp: a convex polyhedron cut by half-spaces, the 3D shape of
// clip_cells. Coordinates are relative to the cell's point.
//
// The polyhedron is a list of corners and of faces, each face a loop of corner ids,
// counter-clockwise seen from outside. A clip decides the side of every corner once
// (half_space.hpp) and derives everything else from those sides, never from a second
// floating-point test, so the faces always fit together:
//   - each face keeps its corners inside or on the plane, and gets the crossing point of
//     every edge running from a corner inside to one outside. The crossing point is made once
//     per edge and shared by the two faces of that edge;
//   - a face with no corner strictly inside is dropped (it lay beyond or on the plane);
//   - the new face on the plane (the cap) is closed from the edges that lost their partner:
//     every edge of a closed surface is walked once in each direction, so the kept faces'
//     edges on the plane whose reverse is missing, reversed, are the cap's edges, and they
//     chain into its loop, counter-clockwise seen from outside;
//   - corners joined by an edge at most tol long are merged (only edges on the plane can be
//     that short), so no later clip sees a cluster of corners closer than its tolerance.
// No angles are sorted, so corners that nearly coincide cannot come out in the wrong order.
// Should rounding ever make the edges on the plane not form one loop, the cap's corners are
// ordered by angle instead (a fallback; see add_cap).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "util/uninitialized_vector.hpp"
#include "voronoi/half_space.hpp"

namespace drange::cells {

class ConvexPolyhedron {
 public:
  using Corner = std::array<double, 3>;

  // The box [lower, upper]: 8 corners, 6 quadrilaterals.
  void set_box(const double* lower, const double* upper);

  // Keeps the part where normal . x <= offset (normal a unit vector); corners within tol of
  // the plane are on it. Afterwards no edge is tol long or shorter (they are merged away).
  ClipResult clip(const double* normal, double offset, double tol);

  // The volume: the tetrahedra from the corners' centroid to a fan of every face.
  double volume() const;

  bool empty() const { return faces_.empty(); }
  std::size_t num_corners() const { return corners_.size(); }
  const double* corner(std::size_t v) const { return corners_[v].data(); }
  std::size_t num_faces() const { return face_start_.size() - 1; }
  std::size_t face_size(std::size_t f) const { return static_cast<std::size_t>(face_start_[f + 1] - face_start_[f]); }
  std::int32_t face_corner(std::size_t f, std::size_t i) const { return faces_[static_cast<std::size_t>(face_start_[f]) + i]; }

 private:
  using Edge = std::pair<std::int32_t, std::int32_t>;

  void clear();
  // The id, in the polyhedron being built, of old corner v (given one on first use).
  std::int32_t kept_corner(std::int32_t v, bool on_plane);
  // The id of the crossing point on the edge a-b (made on first use).
  std::int32_t crossing_corner(std::int32_t a, std::int32_t b);
  // Appends to plane_edges_ the edges of a face being built (`face`, k corners) with both ends
  // on the plane.
  void add_plane_edges(const std::int32_t* face, std::size_t k);
  // Merges the corners joined by an edge no longer than tol and drops the faces left with
  // fewer than 3 corners.
  void merge_short_edges(double tol);
  // Starts the corners of the polyhedron being built, with room for `room` of them.
  void begin_corners(std::size_t room);
  // Closes the polyhedron being built with its face on the plane.
  void add_cap(const double* normal);
  bool chain_cap();
  void sort_cap_by_angle(const double* normal);
  // Appends loop_ to the polyhedron being built.
  void end_face();
  // Makes the polyhedron being built the current one.
  void swap_in();

  // The corner arrays leave new entries unset: a clip makes room for the most corners it can
  // make, writes them (next_count_) and trims the rest.
  util::UninitializedVector<Corner> corners_;
  // faces_ and next_faces_ leave new entries unset: clip() makes room for the most corners
  // the faces can keep, writes them and trims the rest.
  std::vector<std::int32_t> face_start_{0};
  util::UninitializedVector<std::int32_t> faces_;
  double radius_ = 0;  // max_norm(corners_)

  // The polyhedron being built by clip() and merge_short_edges(), and their scratch space.
  util::UninitializedVector<Corner> next_corners_;
  util::UninitializedVector<char> next_on_plane_;
  std::size_t next_count_ = 0;  // corners made in next_corners_ and next_on_plane_
  std::vector<std::int32_t> next_face_start_;
  util::UninitializedVector<std::int32_t> next_faces_;
  std::vector<double> distance_;
  std::vector<Side> side_;
  std::vector<std::int32_t> new_id_;
  // The crossing points made by a clip, listed per inside corner: first_crossing_[in] is the
  // last one made on an edge of old corner `in`, and `next` the one made before it there.
  struct Crossing {
    std::int32_t out;  // the edge's old corner outside
    std::int32_t id;
    std::int32_t next;
  };
  std::vector<Crossing> crossings_;
  std::vector<std::int32_t> first_crossing_;
  std::vector<std::int32_t> loop_;
  std::vector<Edge> plane_edges_, cap_edges_;
};

}  // namespace drange::cells
