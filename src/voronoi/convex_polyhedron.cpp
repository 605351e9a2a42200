// voronoi/convex_polyhedron.cpp: see convex_polyhedron.hpp.
#include "voronoi/convex_polyhedron.hpp"

#include <algorithm>
#include <cmath>

#include "util/union_find.hpp"

namespace drange::cells {
namespace {

using Corner = ConvexPolyhedron::Corner;

Corner minus(const Corner& a, const Corner& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Corner cross(const Corner& a, const Corner& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Corner& a, const Corner& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// Sets values[0 .. n) to -1. The array only grows, so that its size needs no call per clip.
void minus_ones(std::vector<std::int32_t>& values, std::size_t n) {
  if (values.size() < n) values.resize(n);
  std::fill_n(values.begin(), n, -1);
}

}  // namespace

void ConvexPolyhedron::set_box(const double* lower, const double* upper) {
  // Corner i takes upper[k] on the axes k whose bit is set in i.
  corners_.resize(8);
  for (int i = 0; i < 8; ++i)
    for (int k = 0; k < 3; ++k) corners_[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)] = (i >> k & 1) ? upper[k] : lower[k];
  // -x, +x, -y, +y, -z, +z; each counter-clockwise seen from outside.
  faces_ = {0, 4, 6, 2, 1, 3, 7, 5, 0, 1, 5, 4, 2, 6, 7, 3, 0, 2, 3, 1, 4, 5, 7, 6};
  face_start_ = {0, 4, 8, 12, 16, 20, 24};
  radius_ = max_norm(corners_);
}

void ConvexPolyhedron::clear() {
  corners_.clear();
  faces_.clear();
  face_start_.assign(1, 0);
  radius_ = 0;
}

inline std::int32_t ConvexPolyhedron::kept_corner(std::int32_t v, bool on_plane) {
  std::int32_t& id = new_id_[static_cast<std::size_t>(v)];
  if (id < 0) {
    id = static_cast<std::int32_t>(next_count_);
    next_corners_[next_count_] = corners_[static_cast<std::size_t>(v)];
    next_on_plane_[next_count_++] = on_plane;
  }
  return id;
}

ClipResult ConvexPolyhedron::clip(const double* normal, double offset, double tol) {
  if (empty()) return ClipResult::Empty;
  if (offset - tol >= radius_) return ClipResult::Unchanged;  // no corner reaches the plane
  const SidesPresent present = classify(corners_, normal, offset, tol, distance_, side_);
  if (!present.outside) return ClipResult::Unchanged;
  if (!present.inside) {  // all on or beyond the plane: nothing of positive volume is left
    clear();
    return ClipResult::Empty;
  }
  // Each kept corner and at most one crossing point per edge of a face.
  begin_corners(corners_.size() + faces_.size());
  next_face_start_.assign(1, 0);
  // Room for every face's most corners (each corner and a crossing after it), trimmed below.
  next_faces_.resize(2 * faces_.size());
  std::size_t used = 0;
  minus_ones(new_id_, corners_.size());
  crossings_.clear();
  minus_ones(first_crossing_, corners_.size());
  plane_edges_.clear();
  for (std::size_t f = 0; f < num_faces(); ++f) {
    const std::size_t k = face_size(f);
    const std::int32_t* row = faces_.data() + face_start_[f];
    bool has_inside = false, all_inside = true;
    for (std::size_t i = 0; i < k; ++i) {
      const Side side = side_[static_cast<std::size_t>(row[i])];
      has_inside |= side == Side::Inside;
      all_inside &= side == Side::Inside;
    }
    if (!has_inside) continue;
    // A face with a corner inside keeps at least that corner and its two neighbours (or the
    // crossing points next to it): 3 corners or more.
    std::int32_t* face = next_faces_.data() + used;
    std::size_t size = 0;
    if (all_inside) {  // kept whole: no crossing, no corner on the plane
      for (std::size_t i = 0; i < k; ++i) face[size++] = kept_corner(row[i], false);
    } else {
      for (std::size_t i = 0; i < k; ++i) {
        const std::int32_t a = row[i], b = row[i + 1 == k ? 0 : i + 1];
        const Side side_a = side_[static_cast<std::size_t>(a)], side_b = side_[static_cast<std::size_t>(b)];
        if (side_a != Side::Outside) face[size++] = kept_corner(a, side_a == Side::On);
        if (crosses(side_a, side_b)) face[size++] = crossing_corner(a, b);
      }
      add_plane_edges(face, size);
    }
    used += size;
    next_face_start_.push_back(static_cast<std::int32_t>(used));
  }
  next_faces_.resize(used);
  add_cap(normal);
  // Only edges on the plane can be short: an edge from a corner inside to a crossing point is
  // longer than that corner's distance to the plane, more than tol.
  const bool short_edge = std::any_of(plane_edges_.begin(), plane_edges_.end(), [&](const Edge& e) {
    return distance(next_corners_[static_cast<std::size_t>(e.first)], next_corners_[static_cast<std::size_t>(e.second)]) <= tol;
  });
  swap_in();
  if (short_edge) merge_short_edges(tol);
  return empty() ? ClipResult::Empty : ClipResult::Cut;
}

std::int32_t ConvexPolyhedron::crossing_corner(std::int32_t a, std::int32_t b) {
  const auto in = static_cast<std::size_t>(side_[static_cast<std::size_t>(a)] == Side::Inside ? a : b);
  const auto out = static_cast<std::int32_t>(in == static_cast<std::size_t>(a) ? b : a);
  // The crossings made so far on the edges of corner `in` (a corner has few edges).
  for (std::int32_t c = first_crossing_[in]; c >= 0; c = crossings_[static_cast<std::size_t>(c)].next)
    if (crossings_[static_cast<std::size_t>(c)].out == out) return crossings_[static_cast<std::size_t>(c)].id;
  const auto id = static_cast<std::int32_t>(next_count_);
  const auto o = static_cast<std::size_t>(out);
  next_corners_[next_count_] = crossing_point(corners_[in], distance_[in], corners_[o], distance_[o]);
  next_on_plane_[next_count_++] = true;
  crossings_.push_back({out, id, first_crossing_[in]});
  first_crossing_[in] = static_cast<std::int32_t>(crossings_.size() - 1);
  return id;
}

void ConvexPolyhedron::add_plane_edges(const std::int32_t* face, std::size_t k) {
  for (std::size_t i = 0; i < k; ++i) {
    const std::int32_t a = face[i], b = face[i + 1 == k ? 0 : i + 1];
    if (next_on_plane_[static_cast<std::size_t>(a)] && next_on_plane_[static_cast<std::size_t>(b)]) plane_edges_.push_back({a, b});
  }
}

void ConvexPolyhedron::add_cap(const double* normal) {
  // The kept faces' edges with both ends on the plane (plane_edges_, gathered by clip)...
  // ...whose reverse is missing border the cap, which runs along them the other way. (An
  // edge on the plane kept in both directions is a crease the plane only touches.)
  cap_edges_.clear();
  for (const Edge& e : plane_edges_)
    if (std::find(plane_edges_.begin(), plane_edges_.end(), Edge{e.second, e.first}) == plane_edges_.end())
      cap_edges_.push_back({e.second, e.first});
  if (cap_edges_.size() < 3) return;  // the plane only touches the kept part
  if (!chain_cap()) sort_cap_by_angle(normal);
  if (loop_.size() >= 3) end_face();
}

bool ConvexPolyhedron::chain_cap() {
  loop_.clear();
  std::int32_t at = cap_edges_[0].first;
  for (std::size_t step = 0; step < cap_edges_.size(); ++step) {
    loop_.push_back(at);
    std::int32_t to = -1;
    int leaving = 0;
    for (const Edge& e : cap_edges_)
      if (e.first == at) {
        to = e.second;
        ++leaving;
      }
    if (leaving != 1) return false;  // not a simple loop: rounding made the sides inconsistent
    at = to;
    if (at == loop_[0]) return loop_.size() == cap_edges_.size();
  }
  return false;
}

void ConvexPolyhedron::sort_cap_by_angle(const double* normal) {
  loop_.clear();
  for (const Edge& e : cap_edges_) {
    loop_.push_back(e.first);
    loop_.push_back(e.second);
  }
  std::sort(loop_.begin(), loop_.end());
  loop_.erase(std::unique(loop_.begin(), loop_.end()), loop_.end());
  // A basis (e1, e2) of the plane with e1 x e2 = normal: increasing angles then run
  // counter-clockwise seen from outside, the side the normal points to.
  const Corner n{normal[0], normal[1], normal[2]};
  Corner axis{0, 0, 0};
  axis[static_cast<std::size_t>(std::fabs(n[0]) <= std::fabs(n[1]) && std::fabs(n[0]) <= std::fabs(n[2]) ? 0 : std::fabs(n[1]) <= std::fabs(n[2]) ? 1 : 2)] = 1;
  Corner e1 = cross(n, axis);
  const double length = std::sqrt(dot(e1, e1));
  for (double& c : e1) c /= length;
  const Corner e2 = cross(n, e1);
  Corner centre{0, 0, 0};
  for (const std::int32_t v : loop_)
    for (std::size_t k = 0; k < 3; ++k) centre[k] += next_corners_[static_cast<std::size_t>(v)][k] / static_cast<double>(loop_.size());
  std::vector<std::pair<double, std::int32_t>> by_angle;
  for (const std::int32_t v : loop_) {
    const Corner x = minus(next_corners_[static_cast<std::size_t>(v)], centre);
    by_angle.push_back({std::atan2(dot(x, e2), dot(x, e1)), v});
  }
  std::sort(by_angle.begin(), by_angle.end());
  for (std::size_t i = 0; i < loop_.size(); ++i) loop_[i] = by_angle[i].second;
}

void ConvexPolyhedron::end_face() {
  next_faces_.insert(next_faces_.end(), loop_.begin(), loop_.end());
  next_face_start_.push_back(static_cast<std::int32_t>(next_faces_.size()));
}

void ConvexPolyhedron::begin_corners(std::size_t room) {
  next_count_ = 0;
  next_corners_.resize(room);
  next_on_plane_.resize(room);
}

void ConvexPolyhedron::swap_in() {
  next_corners_.resize(next_count_);
  next_on_plane_.resize(next_count_);
  corners_.swap(next_corners_);
  face_start_.swap(next_face_start_);
  faces_.swap(next_faces_);
  if (faces_.empty()) clear();
  radius_ = max_norm(corners_);
}

void ConvexPolyhedron::merge_short_edges(double tol) {
  util::UnionFind same(corners_.size());
  for (std::size_t f = 0; f < num_faces(); ++f)
    for (std::size_t i = 0, k = face_size(f); i < k; ++i) {
      const std::int32_t a = face_corner(f, i), b = face_corner(f, i + 1 == k ? 0 : i + 1);
      if (distance(corners_[static_cast<std::size_t>(a)], corners_[static_cast<std::size_t>(b)]) <= tol)
        same.unite(static_cast<std::size_t>(a), static_cast<std::size_t>(b));
    }
  begin_corners(corners_.size());
  next_face_start_.assign(1, 0);
  next_faces_.clear();
  new_id_.assign(corners_.size(), -1);
  for (std::size_t f = 0; f < num_faces(); ++f) {
    loop_.clear();
    for (std::size_t i = 0; i < face_size(f); ++i) {
      const auto v = static_cast<std::int32_t>(same.find(static_cast<std::size_t>(face_corner(f, i))));
      if (loop_.empty() || loop_.back() != v) loop_.push_back(v);
    }
    while (loop_.size() > 1 && loop_.back() == loop_.front()) loop_.pop_back();
    // A face left with two corners is gone; its two edges are now the same, and the faces
    // on their other sides meet along it.
    if (loop_.size() < 3) continue;
    for (std::int32_t& v : loop_) v = kept_corner(v, false);
    end_face();
  }
  swap_in();
}

double ConvexPolyhedron::volume() const {
  Corner centre{0, 0, 0};
  for (const Corner& x : corners_)
    for (std::size_t k = 0; k < 3; ++k) centre[k] += x[k] / static_cast<double>(corners_.size());
  // Six times the volume: the tetrahedra from the centre to a fan of each face, positive
  // because the faces run counter-clockwise seen from outside.
  double six = 0;
  for (std::size_t f = 0; f < num_faces(); ++f) {
    const Corner a = minus(corners_[static_cast<std::size_t>(face_corner(f, 0))], centre);
    for (std::size_t i = 1; i + 1 < face_size(f); ++i) {
      const Corner b = minus(corners_[static_cast<std::size_t>(face_corner(f, i))], centre);
      const Corner c = minus(corners_[static_cast<std::size_t>(face_corner(f, i + 1))], centre);
      six += dot(a, cross(b, c));
    }
  }
  return six / 6;
}

}  // namespace drange::cells
