// check/facet_pass.cpp: facet pairing, side test and the local Delaunay test.
//
// The local test is enough. Delaunay's lemma (B. Delaunay, "Sur la sphère vide", 1934; see
// also Edelsbrunner, "Geometry and Topology for Mesh Generation", ch. 1, for d = 2, and the
// same lifting argument in any d): a triangulation of a point set in which every interior
// facet is locally Delaunay (the vertex of one simplex opposite the facet is not strictly
// inside the circumsphere of the other) is the lifted lower convex hull, hence no point lies
// strictly inside any circumsphere. One test per facet suffices: for two simplices s, t on
// opposite sides of their common facet, "the apex of t is strictly inside the sphere of s" and
// "the apex of s is strictly inside the sphere of t" are the same sign of the same lifted
// determinant of the d+2 points.
#include "check/facet_pass.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>

#include "util/key_groups.hpp"
#include "geometry/predicates.hpp"

namespace drange::check {
namespace {

std::string facet_text(const SimplexTable& t, FacetRef f) {
  const std::vector<std::int32_t> ids = facet_ids(t, f);
  return "facet " + format_ids(ids.data(), t.dim);
}

std::string simplex_with_vertices(const SimplexTable& t, std::int32_t s) {
  return "simplex " + std::to_string(s) + " " + format_ids(t.row(static_cast<std::size_t>(s)), t.dim + 1);
}

class FacetChecker {
 public:
  FacetChecker(PointsView points, const SimplexTable& table, ProblemLog& log)
      : points_(points), table_(table), log_(log), corners_(static_cast<std::size_t>(table.dim) + 1) {}

  template <class Item>
  void visit(const Item* group, std::size_t size) {
    const int width = table_.dim + 1;
    auto ref = [&](Item item) {
      return FacetRef{static_cast<std::int32_t>(item / static_cast<Item>(width)),
                      static_cast<std::int32_t>(item % static_cast<Item>(width))};
    };
    if (size == 1) {
      ++summary_.boundary;
      const FacetRef f = ref(group[0]);
      if (table_.usable(static_cast<std::size_t>(f.simplex))) summary_.boundary_facets.push_back(f);
    } else if (size == 2) {
      ++summary_.interior;
      check_pair(ref(group[0]), ref(group[1]));
    } else {
      ++summary_.bad_pairings;
      std::vector<std::int32_t> owners;
      for (std::size_t i = 0; i < size; ++i) owners.push_back(ref(group[i]).simplex);
      std::sort(owners.begin(), owners.end());
      log_.report([&] {
        return facet_text(table_, ref(group[0])) + " is shared by " + std::to_string(size) + " simplices " +
               format_ids(owners.data(), static_cast<int>(owners.size()));
      });
    }
  }

  FacetSummary take_summary() { return std::move(summary_); }

 private:
  void check_pair(FacetRef a, FacetRef b) {
    if (a.simplex > b.simplex) std::swap(a, b);
    if (!table_.usable(static_cast<std::size_t>(a.simplex)) || !table_.usable(static_cast<std::size_t>(b.simplex)))
      return;  // a flat simplex has no sides; it is reported already
    if (inner_side(table_, a) == inner_side(table_, b)) {
      ++summary_.bad_pairings;
      log_.report([&] {
        return facet_text(table_, a) + " of simplices " + std::to_string(a.simplex) + " and " +
               std::to_string(b.simplex) + ": both lie on the same side of it (they overlap)";
      });
      return;
    }
    const std::int32_t apex = opposite_vertex(table_, b);
    if (strictly_inside_sphere(a.simplex, points_.point(static_cast<std::size_t>(apex)))) {
      log_.report([&] {
        return "not Delaunay: point " + std::to_string(apex) + " (of simplex " + std::to_string(b.simplex) +
               ") is strictly inside the circumsphere of " + simplex_with_vertices(table_, a.simplex) + ", across " +
               facet_text(table_, a);
      });
    }
  }

  // geometry::in_sphere, without recomputing the orientation the table already holds: with
  // the rows relative to v_0, q is strictly inside exactly when sigma * lifted_sign < 0.
  bool strictly_inside_sphere(std::int32_t s, const double* q) {
    const std::int32_t* row = table_.row(static_cast<std::size_t>(s));
    for (int k = 1; k <= table_.dim; ++k) corners_[static_cast<std::size_t>(k - 1)] = points_.point(static_cast<std::size_t>(row[k]));
    corners_[static_cast<std::size_t>(table_.dim)] = q;
    const geometry::Frame frame{table_.dim, table_.dim, nullptr, points_.point(static_cast<std::size_t>(row[0]))};
    return table_.sign[static_cast<std::size_t>(s)] * geometry::lifted_sign(frame, corners_.data()) < 0;
  }

  PointsView points_;
  const SimplexTable& table_;
  ProblemLog& log_;
  std::vector<const double*> corners_;
  FacetSummary summary_;
};

template <class Item>
FacetSummary run(PointsView points, const SimplexTable& table, ProblemLog& log) {
  const int width = table.dim + 1;
  auto for_each_item = [&](auto&& f) {
    for (std::size_t s = 0; s < table.count; ++s) {
      if (!table.combinatorial(s)) continue;
      for (int j = 0; j < width; ++j) f(static_cast<Item>(s * static_cast<std::size_t>(width) + static_cast<std::size_t>(j)));
    }
  };
  // Key id k of incidence (s, j): the sorted row of s without position j.
  auto key = [&](Item item, int k) {
    const std::size_t s = static_cast<std::size_t>(item / static_cast<Item>(width));
    const int j = static_cast<int>(item % static_cast<Item>(width));
    return table.row(s)[k + (k >= j ? 1 : 0)];
  };
  FacetChecker checker(points, table, log);
  util::for_each_key_group<Item>(points.n, table.dim, for_each_item, key,
                           [&](const Item* group, std::size_t size) { checker.visit(group, size); });
  return checker.take_summary();
}

}  // namespace

FacetSummary check_facets(PointsView points, const SimplexTable& table, ProblemLog& log) {
  // Incidences (simplex, omitted position) are numbered s * (d+1) + j; 32 bits halve the
  // memory of the largest array whenever they suffice.
  const std::size_t incidences = table.count * static_cast<std::size_t>(table.dim + 1);
  if (incidences <= std::numeric_limits<std::uint32_t>::max()) return run<std::uint32_t>(points, table, log);
  return run<std::uint64_t>(points, table, log);
}

}  // namespace drange::check
