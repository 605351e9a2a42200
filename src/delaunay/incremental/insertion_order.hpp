// delaunay/incremental/insertion_order.hpp: the order in which the incremental kernel inserts
// the points, a biased randomized insertion order (Amenta, Choi and Rote, "Incremental
// constructions con BRIO").
//
// Each point draws a round from a hash of its lexicographic rank: the last round with
// probability 1/2, the one before with 1/4, and so on, so that every round is a random sample
// about half the size of the next. The expected work of a randomized insertion (Clarkson and
// Shor) then holds whatever the points' shape: each new point conflicts with O(1) simplices of
// the triangulation of the rounds before it, in expectation. Within a round the points follow
// the kd-tree's leaves along a continuous path, so that consecutive points are near each other
// and the walk that locates each one is short. The order depends on the coordinates only (ranks and the
// kd-tree), not on the input order.
#pragma once

#include <cstdint>
#include <vector>

#include "delaunay/point_store.hpp"

namespace drange::engine {

// Every id of `points` once, coarsest round first.
std::vector<std::int32_t> insertion_order(const PointStore& points);

// The same order for `n` rows of `coords` (row-major, `dim` columns) that no kd-tree holds
// yet: the rounds drawn from `keys` (one distinct value per row), the path along a kd-tree
// built here. Every row once, as row numbers.
std::vector<std::int32_t> insertion_order(const double* coords, const std::int64_t* keys, std::int32_t n, int dim);

}  // namespace drange::engine
