// delaunay/point_store.hpp: the engine's own numbering of the distinct input points.
//
// Point ids are positions in kd-tree order (so that a leaf's points are contiguous); each id
// knows its input index and its rank in the lexicographic order of coordinates, which is what
// the symbolic perturbation uses, so that the result does not depend on the input order.
#pragma once

#include <cstdint>
#include <vector>

#include "delaunay/known_hull.hpp"
#include "delaunay/leaf_blocks.hpp"
#include "delaunay/sphere_shell.hpp"
#include "spatial/kdtree.hpp"
#include "util/uninitialized_vector.hpp"

namespace drange::engine {

struct PointStore {
  int dim = 0;
  std::int32_t size = 0;
  // The arrays are filled in full by prepare_points, on its threads: left uninitialised until
  // then, their pages are first touched there (not zeroed by one thread first).
  util::UninitializedVector<double> coords;             // size * dim, in id order
  util::UninitializedVector<std::int32_t> input_index;  // input index of each id (n < 2^31)
  spatial::KdTree tree;                    // over the ids
  LeafBlocks blocks;                       // the leaves' points in blocks, for the search's leaf scan
  KnownHull hull;                          // the hull's clean facets, when it has many (2D, 3D)
  // True when the coordinates were scaled below 1 in magnitude (prepare_points.cpp): then every
  // entry of the search's determinants is below 2^6 and no underflow can escape the error bounds
  // of its fast filter. False only for inputs spanning more than 2^1022 in magnitude, which
  // are then decided by the generic predicates alone.
  bool scaled = false;
  // When every coordinate is an integer multiple of 2^unit_exponent and the extent is small in
  // those units (a dyadic grid, e.g. integer coordinates), differences of coordinates are
  // exact, and the search can prove some evaluations exact (geometry/static_exactness.hpp).
  bool dyadic = false;
  int unit_exponent = 0;
  // For points near spheres: their centres g, each point's offset |x - g|^2 - rho from its
  // sphere and each kd-tree node's range of them (sphere_shell.hpp).
  SphereShell shell;

  const double* point(std::int32_t id) const { return coords.data() + static_cast<std::size_t>(id) * static_cast<std::size_t>(dim); }
  // The lexicographic rank of id: the tree was built over the distinct points in that order,
  // so its order() is the rank of each id, and no array of its own is kept (n ints less, and a
  // pass of page faults and gathers less in prepare_points).
  std::int64_t rank(std::int32_t id) const { return tree.order()[static_cast<std::size_t>(id)]; }
};

}  // namespace drange::engine
