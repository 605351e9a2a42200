// delaunay/shell/shell_index.cpp: builds the sphere shell's index (shell_index.hpp) about the
// spheres that sphere_fit finds: the points' offsets in double-double arithmetic with their
// error bound, then per kd-tree node (children before parents) its sphere, its range of
// offsets, its cone and clusters, and per leaf its blocks by offset.
//
// Every bound here must hold the exact values, not the computed ones: the search prunes nodes
// and stops leaf scans on them. So each offset's error is bounded (sphere_offset), and every
// range, cluster and cone is widened by the roundings of the values it is made of.
#include "delaunay/shell/shell_index.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "delaunay/shell/sphere_fit.hpp"
#include "geometry/double_double.hpp"
#include "geometry/error_bound.hpp"
#include "spatial/kdtree.hpp"

namespace drange::engine {

using sphere_fit::Sphere;

namespace {

// |x - g|^2 - rho in double-double arithmetic, rounded to a double; `bound` receives the
// largest of rho and the computed |x - g|^2, on which the absolute error term depends:
// | result - exact | <= u |result| + offset_error(dim) * bound.
double sphere_offset(const double* x, const double* g, int dim, double rho, double& bound) {
  // Double-double: x_k - g_k = h + l exactly (two-sum); h^2 = p + q exactly (fma); the p are
  // added to -rho with two-sum (exact: hi plus the errors), the rest (errors, q, 2 h l) to lo.
  // With M = max(rho, sum of p), each partial sum of hi is at most 2M, so each two-sum error is
  // at most 2uM, each q at most uM, each 2 h l at most 2.01uM, and |lo| <= 2.02 (d + 3) uM.
  // Dropped or rounded: the l^2 and the roundings of 2 h l (3 u^2 M in all), and the 3d
  // additions to lo (each <= u |lo|): less than (6.1 d (d + 3) + 3) u^2 M, which
  // offset_error(dim) * M exceeds. The final hi + lo rounds by u |result|.
  double hi = -rho, lo = 0.0, total = 0.0;
  for (int k = 0; k < dim; ++k) {
    const geometry::DoubleDouble y = geometry::two_sum(x[k], -g[k]);
    const double h = y.hi, l = y.lo;
    const double p = h * h;
    const double q = std::fma(h, h, -p);
    const geometry::DoubleDouble sum = geometry::two_sum(hi, p);
    lo += sum.lo;
    hi = sum.hi;
    lo += q;
    lo += 2 * h * l;
    total += p;
  }
  bound = std::max(rho, total);
  return hi + lo;
}

double offset_error(int dim) { return 4.0 * (3 * dim * (dim + 4) + 3) * geometry::kUnitRoundoff * geometry::kUnitRoundoff; }

// A cone (SphereShell::cone) that holds the points [begin, end), around the axis `sum` (their
// directions' sum). Each point's direction e = fl(y / |y|) is within (d + 4) u of the exact
// one per unit of length and m . e rounds by d u more, so cos_lo, the least computed m . e
// less (4 d + 16) u, bounds the exact directions; the axis m is within (d + 2) u of unit
// length, which the (4 d + 16) u added under sin_hi's root covers. |y| rounds by (d + 2) u:
// r_lo and r_hi take (d + 4) u off and on.
void fit_cone(const std::vector<double>& unit, const std::vector<double>& radius, int dim, std::int32_t begin, std::int32_t end,
              const double* sum, double* cone) {
  const auto d = static_cast<std::size_t>(dim);
  const double u = geometry::kUnitRoundoff;
  double r_lo = std::numeric_limits<double>::infinity(), r_hi = 0.0;
  for (auto id = static_cast<std::size_t>(begin); id < static_cast<std::size_t>(end); ++id) {
    r_lo = std::min(r_lo, radius[id]);
    r_hi = std::max(r_hi, radius[id]);
  }
  cone[d + 2] = r_lo * (1 - (dim + 4) * u);
  cone[d + 3] = r_hi * (1 + (dim + 4) * u);
  double norm2 = 0.0;
  for (std::size_t k = 0; k < d; ++k) norm2 += sum[k] * sum[k];
  const double norm = std::sqrt(norm2);
  double cos_lo = -2.0;
  if (norm > 0.0 && r_lo > 0.0) {
    for (std::size_t k = 0; k < d; ++k) cone[k] = sum[k] / norm;
    cos_lo = 1.0;
    for (auto id = static_cast<std::size_t>(begin); id < static_cast<std::size_t>(end); ++id) {
      double dot = 0.0;
      for (std::size_t k = 0; k < d; ++k) dot += cone[k] * unit[id * d + k];
      cos_lo = std::min(cos_lo, dot);
    }
    cos_lo -= (4 * dim + 16) * u;
    if (!(cos_lo > 0.0)) cos_lo = -2.0;  // wider than a half-space: the box does as well
  }
  cone[d] = cos_lo;
  cone[d + 1] = cos_lo > 0.0 ? std::sqrt(1.0 - cos_lo * cos_lo + (4 * dim + 16) * u) * (1 + 4 * u) : 1.0;
}

// Cuts [begin, end) the way the build orders a leaf (halving, down to `size` points): appends
// the blocks' first positions.
void cut_blocks(std::int32_t begin, std::int32_t end, std::int32_t size, std::vector<std::int32_t>& starts) {
  if (end - begin <= size) {
    starts.push_back(begin);
    return;
  }
  const std::int32_t middle = begin + (end - begin) / 2;
  cut_blocks(begin, middle, size, starts);
  cut_blocks(middle, end, size, starts);
}

// The blocks' size, the fastest measured: on a circle a leaf's cone bounds its points well
// enough (smaller blocks only cost); on a sphere in 3D, blocks of the build's smallest order
// (8 points) test about a fifth of the points; from 4D, with leaves of 256 points, a
// cone per 8 points costs more than it saves, and one per 32 saves the most.
std::int32_t block_size(int dim) { return dim == 2 ? std::numeric_limits<std::int32_t>::max() : dim == 3 ? spatial::KdTree::kOrderLeafSize : 32; }

// Widens [lo, hi] to hold the exact offset of a point whose computed offset is s (error
// bound u |s| + eta): twice the bound, since the subtraction and addition here round by at
// most u of their results, which the second u |s| and eta cover.
void widen_offset(double s, double eta, double& lo, double& hi) {
  const double margin = 2 * geometry::kUnitRoundoff * std::fabs(s) + 2 * eta;
  lo = std::min(lo, s - margin);
  hi = std::max(hi, s + margin);
}

// The clusters of concentric spheres (SphereShell::clusters), leaves first, with the margins
// of the nodes' ranges (widen_offset) and of fit_cone's radii; `radius` is each point's |y|.
void fit_clusters(const std::vector<spatial::KdTree::Node>& nodes, const std::vector<double>& radius, int dim, SphereShell& shell) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const double u = geometry::kUnitRoundoff;
  shell.clusters.assign(nodes.size() * 8, 0.0);
  for (std::size_t i = nodes.size(); i-- > 0;) {
    double* c = &shell.clusters[i * 8];
    for (int part = 0; part < 2; ++part) {
      c[4 * part] = c[4 * part + 2] = kInf;
      c[4 * part + 1] = c[4 * part + 3] = -kInf;
    }
    const std::int32_t k = shell.node_sphere[i];
    if (k < 0) continue;
    const spatial::KdTree::Node& node = nodes[i];
    if (node.right < 0) {
      const double eta = shell.eta[static_cast<std::size_t>(k)];
      for (auto id = static_cast<std::size_t>(node.begin); id < static_cast<std::size_t>(node.end); ++id) {
        const double s = shell.offset[id];
        double* part = c + (s < shell.cluster_split ? 0 : 4);
        widen_offset(s, eta, part[0], part[1]);
        part[2] = std::min(part[2], radius[id] * (1 - (dim + 4) * u));
        part[3] = std::max(part[3], radius[id] * (1 + (dim + 4) * u));
      }
    } else {
      const double* left = &shell.clusters[(i + 1) * 8];
      const double* right = &shell.clusters[static_cast<std::size_t>(node.right) * 8];
      for (int j = 0; j < 8; j += 2) {
        c[j] = std::min(left[j], right[j]);
        c[j + 1] = std::max(left[j + 1], right[j + 1]);
      }
    }
  }
}

// The nodes' cones, the blocks and their cones, and the blocks' points by offset: each about
// its sphere's centre, for the nodes and leaves in a sphere (SphereShell::node_sphere); with one
// sphere, every node's cone about its centre (the points off it too).
void fit_cones_and_blocks(const double* coords, int dim, const std::vector<spatial::KdTree::Node>& nodes, SphereShell& shell) {
  const auto d = static_cast<std::size_t>(dim);
  const std::size_t n = shell.offset.size(), stride = d + 4;
  const bool one_sphere = shell.spheres() == 1;
  std::vector<double> unit(n * d, 0.0), radius(n, 0.0);
  for (std::size_t id = 0; id < n; ++id) {
    const std::int32_t k = shell.point_sphere[id] < 0 && one_sphere ? 0 : shell.point_sphere[id];
    if (k < 0) continue;
    const double* g = shell.sphere(k).centre;
    double r2 = 0.0;
    for (std::size_t c = 0; c < d; ++c) {
      const double y = coords[id * d + c] - g[c];
      unit[id * d + c] = y;
      r2 += y * y;
    }
    radius[id] = std::sqrt(r2);
    for (std::size_t c = 0; c < d; ++c) unit[id * d + c] = radius[id] > 0.0 ? unit[id * d + c] / radius[id] : 0.0;
  }
  // The nodes' axes: the sums of their points' directions (children before parents: preorder
  // backwards).
  std::vector<double> sum(nodes.size() * d, 0.0);
  shell.cone.assign(nodes.size() * stride, 0.0);
  shell.first_block.assign(nodes.size(), -1);
  for (std::size_t i = nodes.size(); i-- > 0;) {
    const spatial::KdTree::Node& node = nodes[i];
    double* cone = &shell.cone[i * stride];
    if (shell.node_sphere[i] < 0 && !one_sphere) {
      cone[d] = -2.0;
      continue;
    }
    double* s = &sum[i * d];
    if (node.right < 0) {
      for (auto id = static_cast<std::size_t>(node.begin); id < static_cast<std::size_t>(node.end); ++id)
        for (std::size_t k = 0; k < d; ++k) s[k] += unit[id * d + k];
    } else {
      const std::size_t left = i + 1, right = static_cast<std::size_t>(node.right);
      for (std::size_t k = 0; k < d; ++k) s[k] = sum[left * d + k] + sum[right * d + k];
    }
    fit_cone(unit, radius, dim, node.begin, node.end, s, cone);
  }
  if (shell.cluster_split > 0.0) fit_clusters(nodes, radius, dim, shell);
  // The blocks, leaf by leaf and run by run: preorder lists the leaves by position (a left
  // child's points come first), so block_start increases. A run in no sphere is one block,
  // without a cone.
  shell.block_start.clear();
  shell.block_sphere.clear();
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (nodes[i].right >= 0) continue;
    if (shell.node_sphere[i] != -1) shell.first_block[i] = static_cast<std::int32_t>(shell.block_start.size());
    for (std::int32_t begin = nodes[i].begin, end; begin < nodes[i].end; begin = end) {
      const std::int32_t k = shell.point_sphere[static_cast<std::size_t>(begin)];
      for (end = begin + 1; end < nodes[i].end && shell.point_sphere[static_cast<std::size_t>(end)] == k;) ++end;
      cut_blocks(begin, end, k >= 0 ? block_size(dim) : end - begin, shell.block_start);
      shell.block_sphere.resize(shell.block_start.size(), k);
    }
  }
  shell.block_start.push_back(static_cast<std::int32_t>(n));
  const std::size_t blocks = shell.block_start.size() - 1;
  shell.block_cone.assign(blocks * stride, 0.0);
  shell.block_ids.resize(n);
  shell.block_offsets.resize(n);
  std::vector<double> block_sum(d);
  for (std::size_t b = 0; b < blocks; ++b) {
    const std::int32_t begin = shell.block_start[b], end = shell.block_start[b + 1];
    const auto first = shell.block_ids.begin() + begin, last = shell.block_ids.begin() + end;
    std::iota(first, last, begin);
    if (shell.block_sphere[b] < 0) {
      shell.block_cone[b * stride + d] = -2.0;
      for (std::int32_t i = begin; i < end; ++i) shell.block_offsets[static_cast<std::size_t>(i)] = 0.0;
      continue;
    }
    std::fill(block_sum.begin(), block_sum.end(), 0.0);
    for (auto id = static_cast<std::size_t>(begin); id < static_cast<std::size_t>(end); ++id)
      for (std::size_t k = 0; k < d; ++k) block_sum[k] += unit[id * d + k];
    fit_cone(unit, radius, dim, begin, end, block_sum.data(), &shell.block_cone[b * stride]);
    std::sort(first, last, [&](std::int32_t a, std::int32_t c) {
      const double sa = shell.offset[static_cast<std::size_t>(a)], sc = shell.offset[static_cast<std::size_t>(c)];
      return sa < sc || (sa == sc && a < c);
    });
    for (std::int32_t i = begin; i < end; ++i)
      shell.block_offsets[static_cast<std::size_t>(i)] = shell.offset[static_cast<std::size_t>(shell.block_ids[static_cast<std::size_t>(i)])];
  }
}

// The shell of the spheres, given each point's (-1: none). A node is in a sphere when all its
// points are; a leaf with some, but not all, of its points in spheres is kParts.
SphereShell shell_of(const double* coords, std::int32_t n, int dim, const spatial::KdTree& tree, const std::vector<Sphere>& spheres,
                     std::vector<std::int32_t> point_sphere, double cluster_split) {
  SphereShell shell;
  shell.dim = dim;
  shell.cluster_split = cluster_split;
  const auto& nodes = tree.nodes();
  shell.point_sphere = std::move(point_sphere);
  shell.node_sphere.assign(nodes.size(), -1);
  for (std::size_t i = nodes.size(); i-- > 0;) {  // children first: preorder backwards
    const spatial::KdTree::Node& node = nodes[i];
    std::int32_t& k = shell.node_sphere[i];
    if (node.right < 0) {
      const auto first = shell.point_sphere.begin() + node.begin, last = shell.point_sphere.begin() + node.end;
      if (std::all_of(first, last, [&](std::int32_t j) { return j == *first; })) k = *first;
      else if (std::any_of(first, last, [](std::int32_t j) { return j >= 0; })) k = SphereShell::kParts;
    } else {
      const std::int32_t left = shell.node_sphere[i + 1], right = shell.node_sphere[static_cast<std::size_t>(node.right)];
      if (left >= 0 && left == right) k = left;
    }
  }

  // The points' offsets, each about its sphere, and each sphere's error bound: an exact offset
  // is within u |s| + eta of the computed s.
  const auto d = static_cast<std::size_t>(dim);
  for (const Sphere& sphere : spheres) {
    shell.centres.insert(shell.centres.end(), sphere.centre.begin(), sphere.centre.end());
    shell.rho.push_back(sphere.radius2);
  }
  std::vector<double> largest = shell.rho;
  shell.offset.assign(static_cast<std::size_t>(n), 0.0);
  for (std::int32_t id = 0; id < n; ++id) {
    const std::int32_t k = shell.point_sphere[static_cast<std::size_t>(id)];
    if (k < 0) continue;
    const auto at = static_cast<std::size_t>(k);
    double bound = 0.0;
    shell.offset[static_cast<std::size_t>(id)] =
        sphere_offset(coords + static_cast<std::size_t>(id) * d, &shell.centres[at * d], dim, shell.rho[at], bound);
    largest[at] = std::max(largest[at], bound);
  }
  for (double l : largest) {
    shell.eta.push_back(offset_error(dim) * l);
    if (!std::isfinite(shell.eta.back())) return SphereShell{};
  }
  // The nodes' ranges, leaves first (children follow their parent in preorder).
  shell.range.assign(2 * nodes.size(), 0.0);
  for (std::size_t i = nodes.size(); i-- > 0;) {
    const spatial::KdTree::Node& node = nodes[i];
    const std::int32_t k = shell.node_sphere[i];
    if (k < 0) continue;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    if (node.right < 0) {
      const double eta = shell.eta[static_cast<std::size_t>(k)];
      for (std::int32_t id = node.begin; id < node.end; ++id) widen_offset(shell.offset[static_cast<std::size_t>(id)], eta, lo, hi);
    } else {
      const std::size_t left = i + 1, right = static_cast<std::size_t>(node.right);
      lo = std::min(shell.range[2 * left], shell.range[2 * right]);
      hi = std::max(shell.range[2 * left + 1], shell.range[2 * right + 1]);
    }
    shell.range[2 * i] = lo;
    shell.range[2 * i + 1] = hi;
  }
  fit_cones_and_blocks(coords, dim, nodes, shell);
  return shell;
}

}  // namespace

SphereShell fit_sphere_shell(const double* coords, std::int32_t n, int dim, const spatial::KdTree& tree) {
  if (tree.nodes().empty()) return {};
  std::vector<Sphere> spheres(1);
  std::vector<std::int32_t> point_sphere;
  std::vector<double> radii2;  // of the concentric spheres, smallest first
  double cluster_split = 0.0;
  if (sphere_fit::one_centre(coords, n, dim, spheres.front(), radii2)) {
    point_sphere.assign(static_cast<std::size_t>(n), 0);  // every point, near one of the spheres or not
    // Offsets from the smallest sphere: about 0 on it, about radii2[1] - radii2[0] on the next.
    if (radii2.size() > 1) cluster_split = 0.5 * (radii2[1] - radii2[0]);
  } else {
    spheres.clear();
    if (!sphere_fit::spheres_of_patches(coords, n, dim, tree, spheres, point_sphere)) return {};
  }
  return shell_of(coords, n, dim, tree, spheres, std::move(point_sphere), cluster_split);
}

}  // namespace drange::engine
