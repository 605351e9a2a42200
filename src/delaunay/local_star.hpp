// delaunay/local_star.hpp: the star of one point (every Delaunay simplex incident to it),
// found without the rest of the triangulation (drange::delaunay_stars).
//
// The direct algorithm needs no global structure: FacetSearch::find_apex closes any Delaunay
// facet, wherever it lies, into the Delaunay simplex on its open side. So:
//   1. a first Delaunay simplex: the first facet (first_facet.hpp) closed by the search;
//   2. a walk toward the point p: from a simplex that does not have p as a vertex, cross a
//      facet whose hyperplane strictly separates the simplex from p (exact orientation), by
//      searching that facet's other side. Every distinct input point is a vertex of the
//      triangulation, and no input point lies in a closed simplex other than as its vertex,
//      so such a facet exists until p is reached; the walk cannot cycle, because the
//      triangulation under the perturbation is a regular one (Edelsbrunner's acyclicity
//      theorem for the in-front relation seen from any point);
//   3. the paper's wrapping (step 3), restricted to the stars: each simplex found opens its
//      facets through a wanted point (a facet through none leads out of the stars and is
//      ignored), closes those already open, and each open facet is searched once. The stars of
//      wanted points joined by Delaunay edges are wrapped in one go; a wanted point that no
//      simplex found so far has is walked to, and wrapping starts again from there.
// Every simplex is one that the full construction finds: find_apex is exact and decides by the
// same perturbation, so the star is exactly the full triangulation's, vertex set for vertex set.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "delaunay/facet_search.hpp"
#include "delaunay/first_facet.hpp"
#include "delaunay/point_store.hpp"
#include "drange/points.hpp"

namespace drange::engine {

// A simplex as the search finds it: its facet's sorted ids (the first d of `facet`), that facet's open side (where the
// apex lies) and the apex. Its vertices, positively oriented, are the facet's ids with the
// first two exchanged when sigma < 0, then the apex (as the full construction records it).
struct FoundSimplex {
  std::array<std::int32_t, kMaxDimension> facet;
  int sigma = 1;
  std::int32_t apex = -1;
};

class StarWrapper {
 public:
  // Closes `first` into the first simplex; throws InternalError when it is on the hull on
  // both sides (cannot be: the points span E^d).
  StarWrapper(const PointStore& points, FacetSearch& search, const FirstFacet& first);

  // Appends to `rows` (d+1 engine ids per simplex, positively oriented) every simplex of the
  // stars of the points `wanted` (engine ids; a repeat is ignored), each once, in the order
  // the wrapping finds them, the points taken in increasing id order (the kd-tree's, so that
  // the walks between them are short). Counts into `counters` the search's work and into `hull_facets`
  // the stars' facets on the hull. The cost is that of the simplices found and the walks.
  // With `links`, links[r * (d+1) + f] is what lies across facet f (opposite vertex f) of row r:
  // the row on the other side, kHullSide when f is on the hull, or kNotOpened when f holds no
  // wanted point (the wrapping left it alone: it leads out of the stars).
  void stars(const std::vector<std::int32_t>& wanted, std::vector<std::int32_t>& rows, SearchCounters& counters,
             std::vector<std::int32_t>& hull_facets, std::vector<std::int32_t>* links = nullptr);
  static constexpr std::int32_t kNotOpened = -1;
  static constexpr std::int32_t kHullSide = -2;
  // Calls `report(rows, count)` with each `every` simplices that stars() appends, as they are
  // appended, and with the rest when it returns; an exception from it ends stars().
  void report_rows(std::size_t every, std::function<void(const std::int32_t*, std::size_t)> report) {
    report_every_ = every;
    report_ = std::move(report);
  }
  // The most facets open at once in the wrappings so far (Statistics::Debug::max_open_facets).
  std::size_t max_open_facets() const { return max_open_facets_; }

 private:
  void walk_to(std::int32_t p, SearchCounters& counters);
  // The d+1 facets of `s` (facet f omits vertex f of the positively oriented simplex), sorted
  // ids into facets_ (d per facet), each one's outward side into sides_.
  void facets_of(const FoundSimplex& s);
  void vertices_of(const FoundSimplex& s, std::int32_t* out) const;
  FoundSimplex found_simplex(const std::int32_t* facet, int sigma, std::int32_t apex) const;

  const PointStore& points_;
  FacetSearch& search_;
  int d_;
  FoundSimplex current_;  // the walk's simplex: the last star's first simplex
  std::vector<std::int32_t> facets_;
  std::vector<std::int32_t> sides_;
  std::size_t max_open_facets_ = 0;
  std::size_t report_every_ = 0;
  std::function<void(const std::int32_t*, std::size_t)> report_;
};

}  // namespace drange::engine
