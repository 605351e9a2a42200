// delaunay/incremental/bowyer_watson.cpp: locate, find the conflicts, fill the cavity.
#include "delaunay/incremental/bowyer_watson.hpp"

#include <algorithm>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "delaunay/incremental/cell_complex.hpp"
#include "delaunay/incremental/cell_predicates.hpp"
#include "drange/errors.hpp"

namespace drange::engine {
namespace {

constexpr std::int32_t kUnlinked = -3;

class Insertion {
 public:
  Insertion(const PointStore& points, IncrementalCounters& counters)
      : cells_(points.dim), test_(points, cells_), width_(points.dim + 1), counters_(counters) {
    cells_.reserve(static_cast<std::size_t>(points.size) * 8);
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

  void insert(std::int32_t q) {
    if (stamp_ > kLastStamp) {
      cells_.clear_marks();
      stamp_ = 0;
    }
    stamp_ += 4;
    find_conflicts(q, locate(q));
    fill_cavity(q);
  }

  CellComplex& cells() { return cells_; }
  std::uint64_t unfiltered_tests() const { return test_.unfiltered(); }
  // Finite cells in the triangulation now.
  std::size_t finite_cells() const { return finite_cells_; }

 private:
  // Each insertion's marks are new values, so that no mark needs clearing between insertions.
  static constexpr std::int32_t kLastStamp = std::numeric_limits<std::int32_t>::max() - 8;
  std::int32_t conflict_mark() const { return stamp_ + 1; }
  std::int32_t outside_mark() const { return stamp_ + 2; }
  std::int32_t new_mark() const { return stamp_ + 3; }

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
  std::int32_t stamp_ = 0;
  std::int32_t last_ = 0;
  std::size_t finite_cells_ = 1;
  std::vector<std::int32_t> conflicts_;
  std::vector<std::pair<std::int32_t, int>> boundary_;
  std::vector<Created> created_;
};

// d points of the hull facet and the first point off its hyperplane, positively oriented.
std::vector<std::int32_t> first_simplex(const PointStore& points, const FirstFacet& first,
                                        const std::vector<std::int32_t>& order) {
  const int d = points.dim;
  std::vector<std::int32_t> ids(first.ids);
  ids.push_back(-1);
  std::vector<const double*> rows(static_cast<std::size_t>(d + 1));
  for (int i = 0; i < d; ++i) rows[static_cast<std::size_t>(i)] = points.point(ids[static_cast<std::size_t>(i)]);
  for (const std::int32_t x : order) {
    rows[static_cast<std::size_t>(d)] = points.point(x);
    const int s = geometry::simplex_orientation(d, rows.data());
    if (s == 0) continue;
    ids[static_cast<std::size_t>(d)] = x;
    if (s < 0) std::swap(ids[0], ids[1]);
    return ids;
  }
  throw InternalError("incremental: the first facet's hyperplane holds every point");
}

}  // namespace

IncrementalCounters triangulate_incrementally(const PointStore& points, const FirstFacet& first,
                                              const std::vector<std::int32_t>& order, Triangulation& result,
                                              bool record_neighbors, const std::function<void(std::size_t)>& progress) {
  IncrementalCounters counters;
  const std::vector<std::int32_t> start = first_simplex(points, first, order);
  Insertion insertion(points, counters);
  insertion.start(start.data());
  // Options::progress's contract: multiples of kProgressInterval, increasing (the finite cells
  // can decrease by an insertion; a report waits until their count passes the next multiple).
  std::size_t next_report = kProgressInterval;
  for (const std::int32_t q : order) {
    if (std::find(start.begin(), start.end(), q) != start.end()) continue;
    insertion.insert(q);
    if (insertion.finite_cells() >= next_report) {
      if (progress) progress(next_report);
      next_report += kProgressInterval;
    }
  }
  counters.unfiltered_tests = insertion.unfiltered_tests();
  // The finite cells, numbered in the order of their rows.
  CellComplex& cells = insertion.cells();
  const int width = cells.width();
  std::vector<std::int32_t> number(cells.capacity(), -1);
  std::int32_t finite = 0, hull = 0;
  for (std::size_t c = 0; c < cells.capacity(); ++c) {
    const auto cell = static_cast<std::int32_t>(c);
    if (cells.removed(cell)) continue;
    if (cells.infinite_position(cell) >= 0) ++hull;
    else number[c] = finite++;
  }
  result.simplices.resize(static_cast<std::size_t>(finite) * static_cast<std::size_t>(width));
  if (record_neighbors) result.neighbors.resize(result.simplices.size());
  for (std::size_t c = 0; c < cells.capacity(); ++c) {
    if (number[c] < 0) continue;
    const auto cell = static_cast<std::int32_t>(c);
    const std::size_t row = static_cast<std::size_t>(number[c]) * static_cast<std::size_t>(width);
    std::copy(cells.vertices(cell), cells.vertices(cell) + width, result.simplices.begin() + static_cast<std::ptrdiff_t>(row));
    if (record_neighbors)
      for (int k = 0; k < width; ++k) result.neighbors[row + static_cast<std::size_t>(k)] = number[static_cast<std::size_t>(cells.neighbors(cell)[k])];
  }
  result.stats.hull_facets = static_cast<std::size_t>(hull);
  return counters;
}

}  // namespace drange::engine
