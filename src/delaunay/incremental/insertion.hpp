// delaunay/incremental/insertion.hpp: one Bowyer-Watson insertion at a time into a closed cell
// complex: locate the point by a visibility walk, find the cells in conflict with it, replace
// them by the point joined to the cavity's boundary facets. The one-shot kernel
// (bowyer_watson.hpp) and drange::IncrementalDelaunay both drive it.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "delaunay/incremental/cell_complex.hpp"
#include "delaunay/incremental/cell_predicates.hpp"
#include "delaunay/incremental/kernel_points.hpp"
#include "drange/delaunay.hpp"

namespace drange::engine {

struct IncrementalCounters {
  std::uint64_t walk_steps = 0;      // cells the walks entered
  std::uint64_t conflict_tests = 0;  // cells tested for conflict
  std::uint64_t unfiltered_tests = 0;  // orientations and conflict tests the fast filters left undecided
};

class Insertion {
 public:
  // `points` must outlive the insertion; its arrays may be replaced (grown) between insertions,
  // the view updated in place. `expected_points` reserves room for their cells.
  // `furthest_site`: the furthest-site triangulation (CellPredicates), of the extreme points
  // alone; a point inside the hull of those inserted before conflicts with no cell.
  Insertion(const KernelPoints& points, std::size_t expected_points, IncrementalCounters& counters,
            bool furthest_site = false)
      : cells_(points.dim), test_(points, cells_, furthest_site), width_(points.dim + 1), counters_(counters),
        furthest_site_(furthest_site) {
    cells_.reserve(expected_points * 8);
  }

  // The first simplex, `ids` (d + 1 points, positively oriented), and its hull's infinite cells.
  void start(const std::int32_t* ids) {
    const std::int32_t first = cells_.create();
    std::copy(ids, ids + width_, cells_.vertices(first));
    std::vector<std::int32_t> infinite(static_cast<std::size_t>(width_));
    for (int k = 0; k < width_; ++k) {
      const std::int32_t c = cells_.create();
      infinite[static_cast<std::size_t>(k)] = c;
      std::int32_t* v = cells_.vertices(c);
      std::copy(ids, ids + width_, v);
      v[k] = CellComplex::kInfinite;
      // A point beyond facet k lies where vertex k does not: one swap of two other vertices
      // makes that side the positive one.
      std::swap(v[(k + 1) % width_], v[(k + 2) % width_]);
      cells_.neighbors(first)[k] = c;
      cells_.neighbors(c)[k] = first;
    }
    // Two infinite cells share the facet of kInfinite and d - 1 of the simplex's vertices:
    // across cell a's vertex that b lacks.
    for (const std::int32_t a : infinite)
      for (const std::int32_t b : infinite)
        if (a != b) {
          const std::int32_t* v = cells_.vertices(a);
          for (int k = 0; k < width_; ++k)
            if (!cells_.has_vertex(b, v[k])) cells_.neighbors(a)[k] = b;
        }
    last_ = first;
  }

  // Inserts q; false when q conflicts with no cell (the furthest site: q is in the closed hull
  // of the points before, where the walk ends in a finite cell that holds it, and its lift is
  // beneath every cell's).
  bool insert(std::int32_t q) {
    next_stamp();
    const std::int32_t start = locate(q);
    if (furthest_site_ && cells_.infinite_position(start) < 0) return false;
    find_conflicts(q, start);
    fill_cavity(q);
    return true;
  }

  // Finds the cells in conflict with q and the facets between them and the others, and
  // changes nothing: conflicts() and boundary() then hold them until the next call. q must be
  // no vertex (a copy of none). Not for the furthest site.
  void probe(std::int32_t q) {
    next_stamp();
    find_conflicts(q, locate(q));
  }
  const std::vector<std::int32_t>& conflicts() const { return conflicts_; }
  // (cell, k): the facet of `cell` (in conflict) opposite its vertex k.
  const std::vector<std::pair<std::int32_t, int>>& boundary() const { return boundary_; }

  const CellComplex& cells() const { return cells_; }
  std::uint64_t unfiltered_tests() const { return test_.unfiltered(); }
  // Finite cells in the triangulation now.
  std::size_t finite_cells() const { return finite_cells_; }

 private:
  static constexpr std::int32_t kUnlinked = -3;  // a new cell's neighbour not yet found
  // Each insertion's marks are new values, so that no mark needs clearing between insertions.
  static constexpr std::int32_t kLastStamp = std::numeric_limits<std::int32_t>::max() - 8;
  std::int32_t conflict_mark() const { return stamp_ + 1; }
  std::int32_t outside_mark() const { return stamp_ + 2; }
  std::int32_t new_mark() const { return stamp_ + 3; }
  void next_stamp() {
    if (stamp_ > kLastStamp) {
      cells_.clear_marks();
      stamp_ = 0;
    }
    stamp_ += 4;
  }

  // A cell in conflict with q: the finite cell whose closed simplex holds q (every point of a
  // closed simplex but its vertices is strictly inside its circumsphere), or the infinite cell
  // beyond whose hull facet the walk left. The visibility walk crosses any facet that q is
  // strictly beyond; on a Delaunay triangulation (a regular one, as the perturbed one is) it
  // cannot cycle (Edelsbrunner). The facet it came through is not tested again.
  std::int32_t locate(std::int32_t q) {
    std::int32_t c = last_;
    std::int32_t came_from = -1;
    for (;;) {
      ++counters_.walk_steps;
      if (cells_.infinite_position(c) >= 0) return c;
      const std::int32_t* n = cells_.neighbors(c);
      int k = 0;
      for (; k < width_; ++k)
        if (n[k] != came_from && test_.side(c, k, q) < 0) break;
      if (k == width_) return c;
      came_from = c;
      c = n[k];
    }
  }

  // Marks every cell in conflict with q (they form a connected set containing `start`) and
  // lists the facets between them and the cells that are not.
  void find_conflicts(std::int32_t q, std::int32_t start) {
    conflicts_.clear();
    boundary_.clear();
    cells_.mark(start) = conflict_mark();
    conflicts_.push_back(start);
    for (std::size_t i = 0; i < conflicts_.size(); ++i) {
      const std::int32_t c = conflicts_[i];
      for (int k = 0; k < width_; ++k) {
        const std::int32_t n = cells_.neighbors(c)[k];
        std::int32_t& m = cells_.mark(n);
        if (m == conflict_mark()) continue;
        if (m != outside_mark()) {
          ++counters_.conflict_tests;
          m = test_.in_conflict(n, q) ? conflict_mark() : outside_mark();
          if (m == conflict_mark()) {
            conflicts_.push_back(n);
            continue;
          }
        }
        boundary_.push_back({c, k});
      }
    }
  }

  // Joins q to each boundary facet, links the new cells to the outside and to each other, and
  // removes the conflicting cells.
  void fill_cavity(std::int32_t q) {
    created_.clear();
    for (const auto& [c, k] : boundary_) {
      const std::int32_t n = cells_.create();
      std::int32_t* v = cells_.vertices(n);
      std::copy(cells_.vertices(c), cells_.vertices(c) + width_, v);
      v[k] = q;
      std::int32_t* nn = cells_.neighbors(n);
      std::fill(nn, nn + width_, kUnlinked);
      const std::int32_t outside = cells_.neighbors(c)[k];
      nn[k] = outside;
      cells_.neighbors(outside)[cells_.index_of_neighbor(outside, c)] = n;
      cells_.mark(n) = new_mark();
      if (cells_.infinite_position(n) < 0) ++finite_cells_;
      // The removed cell's row now leads from its boundary facet to the cell that replaced it.
      cells_.neighbors(c)[k] = n;
      created_.push_back({n, c, k});
    }
    for (const Created& created : created_)
      for (int j = 0; j < width_; ++j)
        if (cells_.neighbors(created.cell)[j] == kUnlinked) link(created, j);
    for (const std::int32_t c : conflicts_) {
      if (cells_.infinite_position(c) < 0) --finite_cells_;
      cells_.remove(c);
    }
    last_ = created_.front().cell;
    if (cells_.infinite_position(last_) >= 0) last_ = cells_.neighbors(last_)[cells_.infinite_position(last_)];
  }

  struct Created {
    std::int32_t cell;     // the new cell
    std::int32_t removed;  // the conflicting cell whose boundary facet it stands on
    int q_position;        // q's place in it: the boundary facet's opposite vertex
  };

  // Links a new cell across the facet opposite its vertex j (j != q's place): the facet holds q
  // and the ridge R of the boundary facet without vertex j. The cells around R that were in
  // conflict are crossed one by one, each through its other facet on R, until a boundary
  // facet on R: the new cell standing on it is the neighbour.
  void link(const Created& created, int j) {
    std::int32_t cur = created.removed;
    std::int32_t drop = cells_.vertices(cur)[j];                   // cur's vertex whose facet comes next
    std::int32_t keep = cells_.vertices(cur)[created.q_position];  // cur's other vertex off R
    for (;;) {
      const std::int32_t next = cells_.neighbors(cur)[cells_.index_of_vertex(cur, drop)];
      if (cells_.mark(next) == new_mark()) {
        cells_.neighbors(created.cell)[j] = next;
        // next holds q and R; the vertex it has beyond them is keep.
        cells_.neighbors(next)[cells_.index_of_vertex(next, keep)] = created.cell;
        return;
      }
      const std::int32_t beyond = cells_.vertices(next)[cells_.index_of_neighbor(next, cur)];
      cur = next;
      drop = keep;
      keep = beyond;
    }
  }

  CellComplex cells_;
  CellPredicates test_;
  int width_;
  IncrementalCounters& counters_;
  bool furthest_site_;
  std::int32_t stamp_ = 0;
  std::int32_t last_ = 0;
  std::size_t finite_cells_ = 1;
  std::vector<std::int32_t> conflicts_;
  std::vector<std::pair<std::int32_t, int>> boundary_;
  std::vector<Created> created_;
};

// The finite cells of `cells` as result.simplices (numbered in the order of their rows),
// result.neighbors (when `record_neighbors`; -1 on the hull) and result.stats.hull_facets.
void export_cells(const CellComplex& cells, Triangulation& result, bool record_neighbors);

}  // namespace drange::engine
