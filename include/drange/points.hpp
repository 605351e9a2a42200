// drange/points.hpp: a point cloud in E^d as one contiguous, row-major n*d buffer.
#pragma once

#include <cstddef>
#include <vector>

namespace drange {

// The largest dimension drange triangulates (from 2): the exact predicates' tables of minors
// reach d + 1 = 12 columns.
inline constexpr int kMaxDimension = 11;

// Points stored row-major: coordinate k of point i is coords[i * dim + k].
struct PointCloud {
  int dim = 0;
  std::vector<double> coords;

  std::size_t size() const { return dim > 0 ? coords.size() / static_cast<std::size_t>(dim) : 0; }
  const double* point(std::size_t i) const { return coords.data() + i * static_cast<std::size_t>(dim); }
};

// A non-owning view of the same layout; the engine never copies the caller's coordinates
// except to reorder them for its own kd-tree.
struct PointsView {
  const double* coords = nullptr;
  std::size_t n = 0;
  int dim = 0;

  PointsView() = default;
  PointsView(const double* c, std::size_t count, int d) : coords(c), n(count), dim(d) {}
  PointsView(const PointCloud& cloud) : coords(cloud.coords.data()), n(cloud.size()), dim(cloud.dim) {}  // NOLINT
  const double* point(std::size_t i) const { return coords + i * static_cast<std::size_t>(dim); }
};

}  // namespace drange
