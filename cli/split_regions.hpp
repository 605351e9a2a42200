// cli/split_regions.hpp: the regions of space that decide whether a simplex found among a
// process's points is a simplex of the whole input (cli/split_rounds.cpp).
//
// A simplex of the process's points is one of the whole input when the process holds every
// input point in the closed circumball's part of the input's bounding box: the perturbation
// orders the points as the whole input does (docs/algorithm.md, "Exactness"), so the empty-ball
// test has the same answer. A facet on the hull of the process's points is on the whole input's
// hull when the process holds every point in the closed half-space beyond it (within the
// bounding box). These functions give boxes that contain those regions: computed in doubles,
// then enlarged by a bound on their rounding, so that a box may be larger than its region but
// not smaller. Where that bound is not small (a nearly flat simplex or facet), they are
// computed again in long double, and then in rational arithmetic; only for a simplex or facet
// that is flat in exact terms is the box the whole bounding box.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "drange/points.hpp"

namespace drange::cli {

// A closed box, lo[k] <= x[k] <= hi[k] for k < dim (fixed size: millions are made, one per
// simplex).
struct Box {
  std::size_t dim = 0;
  std::array<double, kMaxDimension> lo{}, hi{};
  static Box filled(std::size_t dim, double lo, double hi);
  bool contains(const Box& inner) const;
  bool meets(const Box& other) const;
  bool contains_point(const double* p) const;
};

// A box holding the closed circumball of the simplex `vertices` (d + 1 points) within `bounds`.
Box ball_region(const std::vector<const double*>& vertices, const Box& bounds);

// A box holding the closed half-space beyond the facet `facet` (d points), on the side away
// from `inside` (the simplex's other vertex), within `bounds`.
Box beyond_region(const std::vector<const double*>& facet, const double* inside, const Box& bounds);

}  // namespace drange::cli
