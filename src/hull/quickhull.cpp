// hull/quickhull.cpp: the construction (quickhull.hpp).
#include "hull/quickhull.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>

#include "drange/errors.hpp"
#include "geometry/error_bound.hpp"

namespace drange::hull {

Quickhull::Quickhull(const double* coords, std::int32_t n, int d, bool filters, InitialSimplex simplex)
    : coords_(coords),
      n_(n),
      d_(d),
      filters_(filters),
      // O(x) = normal . (x - v0) is the Laplace expansion of a d x d determinant whose entries
      // are differences (one rounding each), as the search's facet-plane filter.
      gamma_(geometry::gamma_bound(geometry::laplace_roundings(d, 1))),
      simplex_(std::move(simplex)),
      perturbation_(coords, d, simplex_.ids, simplex_.interior),
      minors_(d),
      tuple_(static_cast<std::size_t>(d)),
      ids_(static_cast<std::size_t>(d + 1)) {}

std::int32_t Quickhull::new_facet() {
  std::int32_t f;
  if (!free_.empty()) {
    f = free_.back();
    free_.pop_back();
    sets_[static_cast<std::size_t>(f)] = Sets{};
  } else {
    f = static_cast<std::int32_t>(sets_.size());
    const auto size = (sets_.size() + 1) * static_cast<std::size_t>(d_);
    vertices_.resize(size);
    neighbors_.resize(size);
    normal_.resize(size);
    normal_abs_.resize(size);
    sets_.emplace_back();
    seen_.push_back(0);
    visible_.push_back(0);
    walk_index_.push_back(-1);
  }
  seen_[static_cast<std::size_t>(f)] = 0;
  return f;
}

void Quickhull::compute_normal(const std::int32_t* v, double* a, double* a_abs) {
  const double* v0 = point(v[0]);
  std::array<double, geometry::SubsetTable::kMaxColumns> row{};
  for (int r = 1; r < d_; ++r) {
    const double* x = point(v[r]);
    for (int k = 0; k < d_; ++k) row[static_cast<std::size_t>(k)] = x[k] - v0[k];
    set_row(r - 1, row.data());
  }
  // Expansion of det[v1 - v0; ...; x - v0] along its last row (row d-1).
  const std::uint32_t all = (std::uint32_t{1} << d_) - 1;
  for (int j = 0; j < d_; ++j) {
    const std::uint32_t mask = all & ~(std::uint32_t{1} << j);
    const double sign = ((d_ - 1 + j) & 1) ? -1.0 : 1.0;
    a[j] = sign * minors_.minor(mask);
    a_abs[j] = minors_.abs_minor(mask);
  }
}

void Quickhull::set_row(int r, const double* row) {
  // The compile-time expansion where the table is small enough: the same minors, fewer
  // instructions (geometry/minors.hpp).
  switch (d_) {
    case 2: minors_.set_row_fixed<2>(r, row); break;
    case 3: minors_.set_row_fixed<3>(r, row); break;
    case 4: minors_.set_row_fixed<4>(r, row); break;
    case 5: minors_.set_row_fixed<5>(r, row); break;
    case 6: minors_.set_row_fixed<6>(r, row); break;
    case 7: minors_.set_row_fixed<7>(r, row); break;
    default: minors_.set_row(r, row); break;
  }
}

void Quickhull::set_normal(std::int32_t f) {
  const std::size_t base = static_cast<std::size_t>(f) * static_cast<std::size_t>(d_);
  compute_normal(vertices(f), normal_.data() + base, normal_abs_.data() + base);
}

int Quickhull::tuple_side(const std::int32_t* v, const double* a, const double* a_abs, std::int32_t x, const double* px,
                          double& height, bool& on_plane) {
  on_plane = false;
  const int s = filter(point(v[0]), a, a_abs, px, height);
  if (s != 0) return s;
  std::copy(v, v + d_, ids_.begin());
  ids_[static_cast<std::size_t>(d_)] = x;
  const int unperturbed = perturbation_.unperturbed(ids_.data());
  on_plane = unperturbed == 0;
  return perturbation_.sign(ids_.data(), unperturbed);
}

int Quickhull::side(std::int32_t f, std::int32_t x, const double* px, double& height, bool& on_plane) {
  const std::size_t base = static_cast<std::size_t>(f) * static_cast<std::size_t>(d_);
  return tuple_side(vertices(f), normal_.data() + base, normal_abs_.data() + base, x, px, height, on_plane);
}

bool Quickhull::on_plane(std::int32_t f, std::int32_t x) {
  const std::size_t base = static_cast<std::size_t>(f) * static_cast<std::size_t>(d_);
  double height = 0.0;
  if (filter(point(vertices(f)[0]), normal_.data() + base, normal_abs_.data() + base, point(x), height) != 0) return false;
  std::copy(vertices(f), vertices(f) + d_, ids_.begin());
  ids_[static_cast<std::size_t>(d_)] = x;
  return perturbation_.unperturbed(ids_.data()) == 0;
}

void Quickhull::add_outside(std::int32_t f, std::int32_t x, const double* px, double height) {
  Sets& sets = sets_[static_cast<std::size_t>(f)];
  sets.outside.push_back(x);
  sets.outside.insert(sets.outside.end(), px, px + d_);
  if (sets.farthest < 0 || height > sets.height) {
    sets.farthest = x;
    sets.height = height;
  }
}

void Quickhull::assign(std::int32_t x, const double* px, const std::vector<std::int32_t>& facets) {
  std::int32_t holds = -1;
  for (const std::int32_t f : facets) {
    double height = 0.0;
    bool on = false;
    if (side(f, x, px, height, on) > 0) {
      add_outside(f, x, px, height);
      return;
    }
    if (on && holds < 0) holds = f;
  }
  if (holds >= 0) sets_[static_cast<std::size_t>(holds)].coplanar.push_back(x);
}

void Quickhull::keep_if_on_boundary(std::int32_t x, const std::vector<std::int32_t>& facets) {
  for (const std::int32_t f : facets)
    if (on_plane(f, x)) {
      sets_[static_cast<std::size_t>(f)].coplanar.push_back(x);
      return;
    }
}

HullFacets Quickhull::run() {
  const int d = d_;
  const std::vector<std::int32_t>& s = simplex_.ids;
  // The first simplex's facets: facet i leaves out s_i. Moving s_i from place i to the end of
  // (s_0..s_d) takes d - i transpositions, so facet i in increasing order has O(s_i) of sign
  // (-1)^(d-i) times the simplex's orientation; swapping its first two vertices makes O
  // negative at s_i, inside.
  std::array<std::int32_t, kMaxDimension + 1> all{};
  std::copy(s.begin(), s.end(), all.begin());
  const int orientation = perturbation_.unperturbed(all.data());
  if (orientation == 0) throw InternalError("convex hull: the first simplex is flat");
  std::vector<std::int32_t> first;
  for (int i = 0; i <= d; ++i) first.push_back(new_facet());
  for (int i = 0; i <= d; ++i) {
    std::int32_t* v = vertices(first[static_cast<std::size_t>(i)]);
    std::int32_t* nb = neighbors(first[static_cast<std::size_t>(i)]);
    std::array<int, kMaxDimension + 1> place{};  // which s_j is at each vertex place
    for (int j = 0, m = 0; j <= d; ++j)
      if (j != i) place[static_cast<std::size_t>(m++)] = j;
    if (((d - i) % 2 == 0 ? orientation : -orientation) > 0) std::swap(place[0], place[1]);
    for (int m = 0; m < d; ++m) {
      v[m] = s[static_cast<std::size_t>(place[static_cast<std::size_t>(m)])];
      nb[m] = first[static_cast<std::size_t>(place[static_cast<std::size_t>(m)])];
    }
    set_normal(first[static_cast<std::size_t>(i)]);
  }
  in_cone_.assign(static_cast<std::size_t>(n_), 0);
  std::vector<char> in_simplex(static_cast<std::size_t>(n_), 0);
  for (const std::int32_t id : s) in_simplex[static_cast<std::size_t>(id)] = 1;
  for (std::int32_t x = 0; x < n_; ++x)
    if (!in_simplex[static_cast<std::size_t>(x)]) assign(x, point(x), first);
  for (const std::int32_t f : first)
    if (!sets_[static_cast<std::size_t>(f)].outside.empty()) pending_.push_back(f);

  // Oldest first: the first simplex's large outside sets are split by their farthest points
  // before the new facets' smaller ones (a run over a 3D ball took a fifth less time than
  // newest first).
  for (std::size_t next = 0; next < pending_.size(); ++next) {
    const std::int32_t f = pending_[next];
    const Sets& sets = sets_[static_cast<std::size_t>(f)];
    if (sets.alive && !sets.outside.empty()) add_point(f);
  }

  // The live facets, numbered compactly.
  std::vector<std::int32_t> number(sets_.size(), -1);
  HullFacets result;
  std::int32_t count = 0;
  for (std::size_t f = 0; f < sets_.size(); ++f)
    if (sets_[f].alive) number[f] = count++;
  for (std::size_t f = 0; f < sets_.size(); ++f) {
    if (!sets_[f].alive) continue;
    const auto id = static_cast<std::int32_t>(f);
    for (int k = 0; k < d; ++k) {
      result.vertices.push_back(vertices(id)[k]);
      const std::int32_t g = number[static_cast<std::size_t>(neighbors(id)[k])];
      if (g < 0) throw InternalError("convex hull: a live facet's neighbour is dead");
      result.neighbors.push_back(g);
    }
    result.coplanar.push_back(std::move(sets_[f].coplanar));
  }
  return result;
}

void Quickhull::add_point(std::int32_t start) {
  const int d = d_;
  const std::int32_t p = sets_[static_cast<std::size_t>(start)].farthest;
  ++addition_;
  // The facets that see p: from `start`, across ridges, testing each neighbour once.
  std::vector<std::int32_t>& visible = visible_facets_;
  visible.assign(1, start);
  apex_on_plane_.assign(1, 0);
  seen_[static_cast<std::size_t>(start)] = addition_;
  visible_[static_cast<std::size_t>(start)] = 1;
  for (std::size_t i = 0; i < visible.size(); ++i) {
    const std::int32_t f = visible[i];
    for (int k = 0; k < d; ++k) {
      const std::int32_t g = neighbors(f)[k];
      if (seen_[static_cast<std::size_t>(g)] == addition_) continue;
      double height = 0.0;
      bool on = false;
      const bool sees = side(g, p, point(p), height, on) > 0;
      seen_[static_cast<std::size_t>(g)] = addition_;
      visible_[static_cast<std::size_t>(g)] = sees;
      if (sees) {
        visible.push_back(g);
        apex_on_plane_.push_back(on);
      }
    }
  }
  // A new facet on each horizon ridge: the visible facet's vertices with p in the place of the
  // vertex opposite the ridge, and the hidden facet beyond it as its neighbour there.
  created_.clear();
  apex_place_.clear();
  creator_.clear();
  for (std::size_t i = 0; i < visible.size(); ++i)
    for (int k = 0; k < d; ++k) {
      const std::int32_t f = visible[i];
      const std::int32_t g = neighbors(f)[k];
      if (visible_[static_cast<std::size_t>(g)]) continue;  // every neighbour was tested during this addition
      const std::int32_t n = new_facet();
      std::copy(vertices(f), vertices(f) + d, vertices(n));
      vertices(n)[k] = p;
      std::fill(neighbors(n), neighbors(n) + d, -1);  // link_new_facets sets the others
      neighbors(n)[k] = g;
      std::int32_t* back = std::find(neighbors(g), neighbors(g) + d, f);
      if (back == neighbors(g) + d) throw InternalError("convex hull: a neighbour does not point back");
      *back = n;
      set_normal(n);
      created_.push_back(n);
      apex_place_.push_back(k);
      creator_.push_back(static_cast<std::int32_t>(i));
      for (int j = 0; j < d; ++j) in_cone_[static_cast<std::size_t>(vertices(n)[j])] = addition_;
    }
  index_horizon();
  link_new_facets();
  // p on the hyperplane of a visible facet (a degenerate step) may leave points of the old
  // boundary on the new one; otherwise every vertex that leaves the hull is strictly inside.
  bool apex_on_plane = on_plane(start, p);
  for (std::size_t i = 1; i < visible.size() && !apex_on_plane; ++i) apex_on_plane = apex_on_plane_[i];
  // The visible facets die. Their outside points go to the new facets or inside; their
  // coplanar points and the vertices that leave the hull stay on its boundary exactly when a
  // new facet's hyperplane holds them.
  for (const std::int32_t f : visible) sets_[static_cast<std::size_t>(f)].alive = false;
  for (std::size_t i = 0; i < visible.size(); ++i) {
    const std::int32_t f = visible[i];
    // The walks add to the new facets' sets only: `sets` stays in place while it is read.
    const Sets& sets = sets_[static_cast<std::size_t>(f)];
    const std::size_t stride = static_cast<std::size_t>(d) + 1;
    for (std::size_t o = 0; o < sets.outside.size(); o += stride) {
      const auto x = static_cast<std::int32_t>(sets.outside[o]);
      const double* px = sets.outside.data() + o + 1;
      if (x != p && !walk(x, px, static_cast<std::int32_t>(i), p)) assign(x, px, created_);
    }
    for (const std::int32_t x : sets.coplanar) keep_if_on_boundary(x, created_);
    if (apex_on_plane)
      for (int k = 0; k < d; ++k) {
        const std::int32_t v = vertices(f)[k];
        if (in_cone_[static_cast<std::size_t>(v)] == addition_) continue;
        in_cone_[static_cast<std::size_t>(v)] = addition_;  // once, though several dead facets hold it
        keep_if_on_boundary(v, created_);
      }
    sets_[static_cast<std::size_t>(f)] = Sets{};  // frees the sets' memory
    sets_[static_cast<std::size_t>(f)].alive = false;
  }
  free_.insert(free_.end(), visible.begin(), visible.end());
  for (const std::int32_t n : created_)
    if (!sets_[static_cast<std::size_t>(n)].outside.empty()) pending_.push_back(n);
}

void Quickhull::index_horizon() {
  const int d = d_;
  const std::size_t v = visible_facets_.size();
  for (std::size_t i = 0; i < v; ++i) walk_index_[static_cast<std::size_t>(visible_facets_[i])] = static_cast<std::int32_t>(i);
  horizon_.assign(v * static_cast<std::size_t>(d), -1);
  ridge_ready_.assign(v * static_cast<std::size_t>(d), 0);
  if (ridge_normal_.size() < v * static_cast<std::size_t>(d * d)) {
    ridge_normal_.resize(v * static_cast<std::size_t>(d * d));
    ridge_abs_.resize(v * static_cast<std::size_t>(d * d));
  }
  for (std::size_t c = 0; c < created_.size(); ++c)
    horizon_[static_cast<std::size_t>(creator_[c]) * static_cast<std::size_t>(d) + static_cast<std::size_t>(apex_place_[c])] = created_[c];
}

bool Quickhull::walk(std::int32_t x, const double* px, std::int32_t from, std::int32_t p) {
  const int d = d_;
  std::int32_t i = from;
  int entered_by = -1;  // the place, in facet i, of the ridge the walk came across
  const std::size_t limit = visible_facets_.size() + 8;
  for (std::size_t step = 0; step < limit; ++step) {
    const std::int32_t g = visible_facets_[static_cast<std::size_t>(i)];
    random_ ^= random_ << 13;
    random_ ^= random_ >> 7;
    random_ ^= random_ << 17;
    const int offset = static_cast<int>(random_ % static_cast<std::uint64_t>(d));
    int across = -1;
    double across_height = 0.0;
    for (int t = 0; t < d && across < 0; ++t) {
      const int k = (offset + t) % d;
      if (k == entered_by) continue;
      const std::size_t ridge = static_cast<std::size_t>(i) * static_cast<std::size_t>(d) + static_cast<std::size_t>(k);
      const std::int32_t n = horizon_[ridge];
      // T_k: g's vertices with p at place k. O_{T_k} is negative at g's vertex k (it is
      // -O_g(p)), so positive exactly beyond the hyperplane through p and the ridge; on a
      // horizon ridge T_k is the new facet n itself.
      // T_k's vertices are g's with p at place k (built only when needed).
      const auto build_tuple = [&] {
        std::copy(vertices(g), vertices(g) + d, tuple_.begin());
        tuple_[static_cast<std::size_t>(k)] = p;
      };
      const double* a;
      const double* a_abs;
      if (n >= 0) {
        a = normal_.data() + static_cast<std::size_t>(n) * static_cast<std::size_t>(d);
        a_abs = normal_abs_.data() + static_cast<std::size_t>(n) * static_cast<std::size_t>(d);
      } else {
        a = ridge_normal_.data() + ridge * static_cast<std::size_t>(d);
        a_abs = ridge_abs_.data() + ridge * static_cast<std::size_t>(d);
        if (!ridge_ready_[ridge]) {
          build_tuple();
          compute_normal(tuple_.data(), ridge_normal_.data() + ridge * static_cast<std::size_t>(d),
                         ridge_abs_.data() + ridge * static_cast<std::size_t>(d));
          ridge_ready_[ridge] = 1;
        }
      }
      // Unperturbed: a hyperplane through p and an inner ridge may pass through the interior
      // point, where the perturbation is undefined. A tie ends the walk: the scan decides, and
      // sees coplanarity.
      double height = 0.0;
      int s = filter(point(k == 0 ? p : vertices(g)[0]), a, a_abs, px, height);
      if (s == 0) {
        build_tuple();
        std::copy(tuple_.begin(), tuple_.end(), ids_.begin());
        ids_[static_cast<std::size_t>(d)] = x;
        s = perturbation_.unperturbed(ids_.data());
        if (s == 0) return false;
      }
      if (s > 0) {
        across = k;
        across_height = height;
      }
    }
    if (across < 0) return true;  // in the pyramid from p over g: inside the new hull
    const std::size_t ridge = static_cast<std::size_t>(i) * static_cast<std::size_t>(d) + static_cast<std::size_t>(across);
    if (horizon_[ridge] >= 0) {
      add_outside(horizon_[ridge], x, px, across_height);
      return true;
    }
    const std::int32_t next = neighbors(g)[across];
    i = walk_index_[static_cast<std::size_t>(next)];
    entered_by = static_cast<int>(std::find(neighbors(next), neighbors(next) + d, g) - neighbors(next));
  }
  return false;  // the walk may cycle in a triangulation that is not Delaunay: the scan decides
}

void Quickhull::link_new_facets() {
  // New facet n = f with p at place k (f visible). Its ridge opposite place j != k holds p and
  // e = f less places j and k, a (d-2)-face on the horizon; the other new facet through it
  // comes from the visible facets around e: start across f's ridge opposite j (e and f's
  // vertex u at k), and while the facet beyond is visible, cross its other ridge through e
  // (the one without the vertex of the ridge just crossed that is not in e). The first hidden
  // facet beyond visible g, across place t, makes the new facet g with p at t; its ridge
  // through p and e is opposite the vertex of g that is neither in e nor at t.
  const int d = d_;
  for (std::size_t c = 0; c < created_.size(); ++c) {
    const std::int32_t n = created_[c];
    const int k = apex_place_[c];
    for (int j = 0; j < d; ++j) {
      if (j == k || neighbors(n)[j] >= 0) continue;
      std::int32_t g = visible_facets_[static_cast<std::size_t>(creator_[c])];
      int through = j;
      std::int32_t kept = vertices(g)[k];  // the crossed ridge's vertex that is not in e
      for (std::size_t step = 0;; ++step) {
        if (step > visible_facets_.size()) throw InternalError("convex hull: the horizon does not close around a face");
        const std::int32_t h = neighbors(g)[through];
        const std::size_t slot = static_cast<std::size_t>(h);
        if (!(seen_[slot] == addition_ && visible_[slot])) break;
        // h = e + kept + its own vertex y: its other ridge through e is opposite `kept`.
        const std::int32_t* hv = vertices(h);
        const int next = static_cast<int>(std::find(hv, hv + d, kept) - hv);
        if (next == d) throw InternalError("convex hull: neighbouring facets do not share a ridge");
        // The next crossed ridge is h less `kept`; its vertex outside e is the one of h that
        // is in neither g's ridge nor e: the vertex of h not in g.
        std::int32_t y = -1;
        for (int i = 0; i < d; ++i)
          if (std::find(vertices(g), vertices(g) + d, hv[i]) == vertices(g) + d) y = hv[i];
        g = h;
        through = next;
        kept = y;
      }
      const std::int32_t m = horizon_[static_cast<std::size_t>(walk_index_[static_cast<std::size_t>(g)]) * static_cast<std::size_t>(d) +
                                      static_cast<std::size_t>(through)];
      const std::int32_t* gv = vertices(g);
      const int other = static_cast<int>(std::find(gv, gv + d, kept) - gv);
      if (m < 0 || other == d || m == n) throw InternalError("convex hull: a ridge of the new facets has no partner");
      neighbors(n)[j] = m;
      neighbors(m)[other] = n;
    }
  }
}

}  // namespace drange::hull
