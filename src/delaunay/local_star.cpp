// delaunay/local_star.cpp: the star of one point by a walk and a wrapping restricted to it
// (local_star.hpp says why each step is exact).
#include "delaunay/local_star.hpp"

#include <algorithm>
#include <deque>
#include <string>
#include <unordered_map>
#include <utility>

#include "delaunay/facet_table.hpp"
#include "delaunay/simplex_estimate.hpp"
#include "delaunay/simplex_facets.hpp"
#include "drange/errors.hpp"
#include "geometry/predicates.hpp"

namespace drange::engine {
namespace {

struct KeyHash {
  std::size_t operator()(const std::vector<std::int32_t>& ids) const {
    return facet_hash(ids.data(), static_cast<int>(ids.size()));
  }
};

}  // namespace

StarWrapper::StarWrapper(const PointStore& points, FacetSearch& search, const FirstFacet& first)
    : points_(points),
      search_(search),
      d_(points.dim),
      facets_(static_cast<std::size_t>((points.dim + 1) * points.dim)),
      sides_(static_cast<std::size_t>(points.dim + 1)) {
  SearchCounters ignored;
  current_ = FoundSimplex{first.ids, first.sigma, search_.find_apex(first.ids.data(), first.sigma, ignored)};
  if (current_.apex < 0) throw InternalError("delaunay stars: the first facet has no simplex on its inner side");
}

void StarWrapper::vertices_of(const FoundSimplex& s, std::int32_t* out) const {
  std::copy(s.facet.begin(), s.facet.end(), out);
  if (s.sigma < 0) std::swap(out[0], out[1]);
  out[d_] = s.apex;
}

void StarWrapper::facets_of(const FoundSimplex& s) {
  const auto d = static_cast<std::size_t>(d_);
  std::vector<std::int32_t> open_side(d);
  simplex_other_facets(s.facet.data(), d_, s.apex, s.sigma < 0, facets_.data(), open_side.data());
  std::copy(open_side.begin(), open_side.end(), sides_.begin());
  // Facet d omits the apex: the facet the simplex was found from, whose open side held the apex.
  std::copy(s.facet.begin(), s.facet.end(), facets_.begin() + static_cast<std::ptrdiff_t>(d * d));
  sides_[d] = -s.sigma;
}

void StarWrapper::walk_to(std::int32_t p, SearchCounters& counters) {
  const auto d = static_cast<std::size_t>(d_);
  std::vector<std::int32_t> vertices(d + 1);
  std::vector<const double*> rows(d);
  // More steps than there are simplices: the walk cycled, which the acyclicity theorem rules out.
  const std::size_t limit = simplex_upper_bound(d_, static_cast<std::size_t>(points_.size));
  for (std::size_t step = 0; step <= limit; ++step) {
    vertices_of(current_, vertices.data());
    if (std::find(vertices.begin(), vertices.end(), p) != vertices.end()) return;
    facets_of(current_);
    bool crossed = false;
    for (std::size_t f = 0; f <= d && !crossed; ++f) {
      const std::int32_t* facet = &facets_[f * d];
      const geometry::Frame frame{d_, d_, nullptr, points_.point(facet[0])};
      for (std::size_t i = 1; i < d; ++i) rows[i - 1] = points_.point(facet[i]);
      rows[d - 1] = points_.point(p);
      if (sides_[f] * geometry::orientation(frame, rows.data()) <= 0) continue;  // p not strictly beyond
      const std::int32_t apex = search_.find_apex(facet, sides_[f], counters);
      // p lies in the hull, never strictly beyond a hull facet.
      if (apex < 0) throw InternalError("delaunay stars: the walk to point " + std::to_string(p) + " left the hull");
      current_ = FoundSimplex{std::vector<std::int32_t>(facet, facet + d), sides_[f], apex};
      crossed = true;
    }
    if (!crossed)
      throw InternalError("delaunay stars: point " + std::to_string(p) + " lies in a simplex without being its vertex");
  }
  throw InternalError("delaunay stars: the walk to point " + std::to_string(p) + " does not end");
}

void StarWrapper::star(std::int32_t p, std::vector<std::int32_t>& rows, SearchCounters& counters,
                       std::vector<std::int32_t>& hull_facets) {
  walk_to(p, counters);
  const auto d = static_cast<std::size_t>(d_);
  // The star's facets through p: true while open (one side's simplex found, the other's not).
  std::unordered_map<std::vector<std::int32_t>, bool, KeyHash> open;
  std::deque<std::pair<std::vector<std::int32_t>, int>> queue;
  std::vector<std::int32_t> vertices(d + 1);
  // Records a simplex of the star; `searched`: the facet it was found from, closed already.
  const auto record = [&](const FoundSimplex& s, bool searched) {
    vertices_of(s, vertices.data());
    rows.insert(rows.end(), vertices.begin(), vertices.end());
    facets_of(s);
    for (std::size_t f = 0; f <= d; ++f) {
      if (vertices[f] == p || (searched && f == d)) continue;  // the facet opposite p leaves the star
      std::vector<std::int32_t> key(facets_.begin() + static_cast<std::ptrdiff_t>(f * d),
                                    facets_.begin() + static_cast<std::ptrdiff_t>((f + 1) * d));
      const auto [it, inserted] = open.emplace(key, true);
      if (inserted) {
        queue.emplace_back(std::move(key), sides_[f]);
      } else if (it->second) {
        it->second = false;  // the simplex on its other side is found: no search needed
      } else {
        throw InternalError("delaunay stars: a facet of the star of point " + std::to_string(p) + " has three simplices");
      }
    }
  };
  record(current_, false);
  while (!queue.empty()) {
    auto [facet, side] = std::move(queue.front());
    queue.pop_front();
    bool& is_open = open[facet];
    if (!is_open) continue;
    is_open = false;
    const std::int32_t apex = search_.find_apex(facet.data(), side, counters);
    if (apex < 0) {
      hull_facets.insert(hull_facets.end(), facet.begin(), facet.end());
      continue;
    }
    record(FoundSimplex{std::move(facet), side, apex}, true);
  }
}

}  // namespace drange::engine
