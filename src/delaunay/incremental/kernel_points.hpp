// delaunay/incremental/kernel_points.hpp: what the incremental kernel reads of the points.
//
// The kernel needs each point's coordinates and its lexicographic rank (the symbolic
// perturbation's order: only the ranks' relative order matters, so any numbering consistent
// with the lexicographic order of the coordinates gives the same triangulation). It reads
// them through this view so that both the one-shot construction (PointStore, ids in kd-tree
// order) and drange::IncrementalDelaunay (ids = input indices, points added over time) can
// drive it.
#pragma once

#include <cstddef>
#include <cstdint>

#include "delaunay/point_store.hpp"

namespace drange::engine {

struct KernelPoints {
  int dim = 0;
  const double* coords = nullptr;       // id-major, dim per id
  const std::int32_t* ranks = nullptr;  // lexicographic rank of each id, distinct
  // Every coordinate is below 1 in magnitude, scaled exactly (PointStore::scaled): the fast
  // filters' error bounds hold.
  bool scaled = false;

  const double* point(std::int32_t id) const { return coords + static_cast<std::size_t>(id) * static_cast<std::size_t>(dim); }
  std::int64_t rank(std::int32_t id) const { return ranks[static_cast<std::size_t>(id)]; }
};

inline KernelPoints kernel_points(const PointStore& store) {
  return KernelPoints{store.dim, store.coords.data(), store.tree.order().data(), store.scaled};
}

}  // namespace drange::engine
