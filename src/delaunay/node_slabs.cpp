// delaunay/node_slabs.cpp: the nodes' moments bottom-up, their normals, and their slabs.
#include "delaunay/node_slabs.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "delaunay/team.hpp"
#include "drange/points.hpp"
#include "geometry/error_bound.hpp"
#include "util/for_ranges.hpp"

namespace drange::engine {

namespace {
// A slab is kept only when it is this many times thinner than the node's box along its normal.
constexpr double kThinner = 4.0;

// The unit eigenvector of the symmetric d x d matrix `a` (row-major, destroyed) with the
// smallest eigenvalue, by cyclic Jacobi rotations; returns that eigenvalue.
double smallest_eigenvector(std::vector<double>& a, int d, double* vector) {
  std::vector<double> v(static_cast<std::size_t>(d * d), 0.0);
  const auto at = [d](int i, int j) { return static_cast<std::size_t>(i * d + j); };
  for (int i = 0; i < d; ++i) v[at(i, i)] = 1.0;
  for (int sweep = 0; sweep < 32; ++sweep) {
    double off = 0.0, diagonal = 0.0;
    for (int p = 0; p < d; ++p) {
      diagonal += a[at(p, p)] * a[at(p, p)];
      for (int q = p + 1; q < d; ++q) off += a[at(p, q)] * a[at(p, q)];
    }
    if (!(off > 1e-30 * diagonal)) break;
    for (int p = 0; p < d; ++p)
      for (int q = p + 1; q < d; ++q) {
        const double apq = a[at(p, q)];
        if (apq == 0.0) continue;
        const double theta = (a[at(q, q)] - a[at(p, p)]) / (2 * apq);
        const double t = (theta >= 0 ? 1.0 : -1.0) / (std::fabs(theta) + std::sqrt(theta * theta + 1));
        const double c = 1 / std::sqrt(t * t + 1), s = t * c;
        for (int k = 0; k < d; ++k) {  // columns p and q
          const double akp = a[at(k, p)], akq = a[at(k, q)];
          a[at(k, p)] = c * akp - s * akq;
          a[at(k, q)] = s * akp + c * akq;
        }
        for (int k = 0; k < d; ++k) {  // rows p and q
          const double apk = a[at(p, k)], aqk = a[at(q, k)];
          a[at(p, k)] = c * apk - s * aqk;
          a[at(q, k)] = s * apk + c * aqk;
        }
        for (int k = 0; k < d; ++k) {
          const double vkp = v[at(k, p)], vkq = v[at(k, q)];
          v[at(k, p)] = c * vkp - s * vkq;
          v[at(k, q)] = s * vkp + c * vkq;
        }
      }
  }
  int least = 0;
  for (int i = 1; i < d; ++i)
    if (a[at(i, i)] < a[at(least, least)]) least = i;
  double norm2 = 0.0;
  for (int k = 0; k < d; ++k) norm2 += v[at(k, least)] * v[at(k, least)];
  const double norm = std::sqrt(norm2);
  for (int k = 0; k < d; ++k) vector[k] = v[at(k, least)] / norm;
  return a[at(least, least)];
}

// The mean and M2 (upper triangle) of the points [begin, end), in local accumulators (the
// output could alias the coordinates, which kept every sum in memory).
template <int D>
void leaf_moments_fixed(const double* coords, std::int32_t begin, std::int32_t end, int dim, double* mean, double* m2) {
  const auto d = static_cast<std::size_t>(D > 0 ? D : dim);
  // One pass, about the first point (near the others: no cancellation to speak of).
  const double* origin = coords + static_cast<std::size_t>(begin) * d;
  double s1[kMaxDimension] = {}, s2[kMaxDimension * kMaxDimension] = {};
  for (std::int32_t p = begin; p < end; ++p) {
    double y[kMaxDimension];
    for (std::size_t k = 0; k < d; ++k) {
      y[k] = coords[static_cast<std::size_t>(p) * d + k] - origin[k];
      s1[k] += y[k];
    }
    for (std::size_t r = 0; r < d; ++r)
      for (std::size_t c = r; c < d; ++c) s2[r * d + c] += y[r] * y[c];
  }
  const double n = end - begin;
  for (std::size_t r = 0; r < d; ++r) {
    mean[r] = origin[r] + s1[r] / n;
    for (std::size_t c = r; c < d; ++c) m2[r * d + c] = s2[r * d + c] - s1[r] * s1[c] / n;
  }
}

void leaf_moments(const double* coords, std::int32_t begin, std::int32_t end, int dim, double* mean, double* m2) {
  switch (dim) {
    case 2: return leaf_moments_fixed<2>(coords, begin, end, dim, mean, m2);
    case 3: return leaf_moments_fixed<3>(coords, begin, end, dim, mean, m2);
    default: return leaf_moments_fixed<0>(coords, begin, end, dim, mean, m2);
  }
}

// Each node's mean and centred second moments M2 = sum (x - mean)(x - mean)^T (upper
// triangle): over a leaf's points (on the team's threads), and for an inner node from its
// children's (Chan, Golub and LeVeque's pairwise update), so that every point is read once.
void node_moments(const spatial::KdTree& tree, const double* coords, int dim, Team& team, std::vector<double>& mean,
                  std::vector<double>& m2) {
  const auto& nodes = tree.nodes();
  const auto d = static_cast<std::size_t>(dim);
  mean.resize(nodes.size() * d);
  m2.resize(nodes.size() * d * d);
  std::vector<std::size_t> leaves;
  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (nodes[i].right < 0) leaves.push_back(i);
  util::for_ranges(leaves.size(), team, [&](std::size_t, std::size_t begin, std::size_t end) {
    for (std::size_t j = begin; j < end; ++j) {
      const std::size_t i = leaves[j];
      leaf_moments(coords, nodes[i].begin, nodes[i].end, dim, &mean[i * d], &m2[i * d * d]);
    }
  }, 256);
  for (std::size_t i = nodes.size(); i-- > 0;) {  // backwards: a node's children follow it in preorder
    if (nodes[i].right < 0) continue;
    const std::size_t left = i + 1, right = static_cast<std::size_t>(nodes[i].right);
    const double na = nodes[left].end - nodes[left].begin, nb = nodes[right].end - nodes[right].begin;
    const double weight = na * nb / (na + nb);
    for (std::size_t k = 0; k < d; ++k) mean[i * d + k] = (na * mean[left * d + k] + nb * mean[right * d + k]) / (na + nb);
    for (std::size_t r = 0; r < d; ++r)
      for (std::size_t c = r; c < d; ++c) {
        const double dr = mean[right * d + r] - mean[left * d + r], dc = mean[right * d + c] - mean[left * d + c];
        m2[i * d * d + r * d + c] = m2[left * d * d + r * d + c] + m2[right * d * d + r * d + c] + weight * dr * dc;
      }
  }
}

// The slab of node i (n, lo, hi into `out`) when it is kThinner times thinner than the node's box
// along n; `covariance` is the node's (full, destroyed).
bool thin_slab(const spatial::KdTree& tree, std::int32_t i, const double* coords, int dim, std::vector<double>& covariance,
               double* out) {
  const auto d = static_cast<std::size_t>(dim);
  const double* lo = tree.lower(i);
  const double* hi = tree.upper(i);
  // Gershgorin: no eigenvalue is below the least C_kk - sum_j |C_kj|, and the box's extent along
  // a unit vector is at most its diagonal. Most nodes of uniform input stop here.
  double gershgorin = std::numeric_limits<double>::infinity(), diagonal2 = 0.0;
  for (std::size_t r = 0; r < d; ++r) {
    double disc = covariance[r * d + r];
    for (std::size_t c = 0; c < d; ++c)
      if (c != r) disc -= std::fabs(covariance[r * d + c]);
    gershgorin = std::min(gershgorin, disc);
    diagonal2 += (hi[r] - lo[r]) * (hi[r] - lo[r]);
  }
  // Points within a slab of width w have a variance of at most w^2 / 4 across it.
  const double factor = 4 * kThinner * kThinner;
  if (gershgorin * factor >= diagonal2) return false;
  double* normal = out;
  const double least = smallest_eigenvector(covariance, dim, normal);
  // The box's extent along the normal, and a bound of |n . x| over it.
  double extent = 0.0, magnitude = 0.0;
  for (std::size_t k = 0; k < d; ++k) {
    extent += std::fabs(normal[k]) * (hi[k] - lo[k]);
    magnitude += std::fabs(normal[k]) * std::max(std::fabs(lo[k]), std::fabs(hi[k]));
  }
  if (!(least * factor < extent * extent)) return false;
  const spatial::KdTree::Node& node = tree.nodes()[static_cast<std::size_t>(i)];
  double t_lo = std::numeric_limits<double>::infinity(), t_hi = -t_lo;
  for (std::int32_t p = node.begin; p < node.end; ++p) {
    const double* x = coords + static_cast<std::size_t>(p) * d;
    double t = 0.0;
    for (std::size_t k = 0; k < d; ++k) t += normal[k] * x[k];
    t_lo = std::min(t_lo, t);
    t_hi = std::max(t_hi, t);
  }
  if (!((t_hi - t_lo) * kThinner < extent)) return false;
  // Each computed n . x is within (d + 1) u |n| . |x| (+ underflow) of its exact value; the
  // margin also covers the rounding of lo and hi themselves.
  const double margin = 2 * static_cast<double>(d + 3) * geometry::kUnitRoundoff * magnitude + 0x1p-1000;
  out[d] = t_lo - margin;
  out[d + 1] = t_hi + margin;
  return true;
}
}  // namespace

NodeSlabs::NodeSlabs(const spatial::KdTree& tree, const double* coords, int dim, Team& team) : d_(dim) {
  const std::size_t count = tree.nodes().size();
  const auto d = static_cast<std::size_t>(dim);
  std::vector<double> mean, m2;
  node_moments(tree, coords, dim, team, mean, m2);
  // Each node's slab in a place of its own, on the team's threads.
  std::vector<double> fitted(count * stride());
  std::vector<char> kept(count, 0);
  util::for_ranges(count, team, [&](std::size_t, std::size_t begin, std::size_t end) {
    std::vector<double> covariance(d * d);
    for (std::size_t i = begin; i < end; ++i) {
      const double n = tree.nodes()[i].end - tree.nodes()[i].begin;
      for (std::size_t r = 0; r < d; ++r)
        for (std::size_t c = r; c < d; ++c) covariance[r * d + c] = covariance[c * d + r] = m2[i * d * d + r * d + c] / n;
      kept[i] = thin_slab(tree, static_cast<std::int32_t>(i), coords, dim, covariance, &fitted[i * stride()]);
    }
  }, 256);
  for (const char k : kept) kept_ += k != 0;
  if (kept_ == 0) return;
  for (std::size_t i = 0; i < count; ++i)
    if (!kept[i]) {
      fitted[i * stride() + d] = 1.0;  // lo > hi
      fitted[i * stride() + d + 1] = 0.0;
    }
  slabs_ = std::move(fitted);
}

}  // namespace drange::engine
