// delaunay/incremental/incremental_state.hpp: what drange::IncrementalDelaunay keeps between
// calls (incremental_delaunay.cpp builds and grows it; natural_neighbours.cpp probes it).
//
// Point ids are input indices. Each id has a rank in the lexicographic order of the distinct
// points (the perturbation's order; -1 for a duplicate), renumbered when points are added:
// only the ranks' relative order enters a predicate, and adding points does not change the
// relative order of those already there, so the cells built before stay valid. The kernel
// reads the coordinates scaled by a power of two (exact), rescaled from the caller's copy when
// a new point is larger than every point before.
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "delaunay/incremental/insertion.hpp"
#include "drange/incremental.hpp"

namespace drange {

struct IncrementalDelaunay::State {
  int dim = 0;
  std::vector<double> input;        // every point added, in input order, as given
  std::vector<double> coords;       // the same, times 2^-exponent when view.scaled
  int exponent = 0;
  double largest = 0.0;             // the largest and smallest nonzero magnitude in `input`
  double smallest = std::numeric_limits<double>::infinity();
  std::vector<std::int32_t> ranks;  // per id; -1 for a duplicate
  std::vector<std::int32_t> lex;    // the distinct ids in lexicographic order
  std::vector<Duplicate> duplicates;
  engine::KernelPoints view;                // what the insertion reads; updated in place
  engine::IncrementalCounters counters;
  std::unique_ptr<engine::Insertion> insertion;
  bool furthest_site = false;
  double seconds = 0.0;

  const double* point(std::int32_t id) const { return input.data() + static_cast<std::size_t>(id) * static_cast<std::size_t>(dim); }
  bool less(std::int32_t a, std::int32_t b) const {
    return std::lexicographical_compare(point(a), point(a) + dim, point(b), point(b) + dim);
  }
  bool same(std::int32_t a, std::int32_t b) const { return std::equal(point(a), point(a) + dim, point(b)); }

  // Appends the points; returns the ids of the new distinct ones, in lexicographic order.
  std::vector<std::int32_t> append(PointsView points);
  // Keeps `coords` the scaled copy of `input` (PointStore::scaled's rule) and `view` current.
  void rescale(std::size_t first_new);
  // The first simplex from the first points' distinct ids, positively oriented.
  std::vector<std::int32_t> first_simplex(const std::vector<std::int32_t>& distinct) const;
  void insert(const std::vector<std::int32_t>& distinct, const std::vector<std::int32_t>& skip);
};

}  // namespace drange
