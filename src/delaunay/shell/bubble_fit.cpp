// delaunay/shell/bubble_fit.cpp: spheres about several centres (bubbles, the cells of a
// foam), found patch by patch in the kd-tree (sphere_fit.hpp, spheres_of_patches).
//
// Why patches: when the points lie near many spheres, no fit to all of them finds one, but a
// small kd-tree node or a part of a leaf (points near each other) lies on one bubble, and a
// sphere through a few of its points shows it. A few probes decide first, so that inputs with
// no patch (most of them) pay for a few thousand points' tests.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

#include "delaunay/shell/sphere_fit.hpp"
#include "spatial/kdtree.hpp"
#include "util/union_find.hpp"

namespace drange::engine::sphere_fit {

namespace {

// Spheres about several centres (bubbles; the cells of a foam), found patch by patch: a patch
// is a kd-tree node of kLeastPatch to kPatchPoints points (contiguous ids, near each other), or
// a part of a leaf down to kLeastPart points (the build orders a leaf's points by the same
// halving splits), that most of its points lie near a sphere no wider than
// kMaxRadiusOverExtent times its bounding box. The patches of one sphere are then grouped, and
// each group's sphere refitted on all their points near it. The parts of leaves give a sphere
// the points of the leaves that straddle two bubbles: left in no sphere, the searches of their
// facets would fall to the double-double tests.
constexpr std::int32_t kPatchPoints = 512;
constexpr std::int32_t kLeastPatch = 64;
constexpr std::int32_t kLeastPart = spatial::KdTree::kOrderLeafSize;
// Spheres tried per patch, each through dim + 2 of its points spread over its order: with 9 in
// 10 of them near a sphere, one draw of up to 7 points (5D) misses it with odds below 1/2.
constexpr int kPatchDraws = 4;
// How many nodes of kPatchPoints points are tried (down to kLeastPatch) before all of them:
// one must have a patch. Most inputs have none, and this caps their cost at a few thousand
// points' tests.
constexpr std::size_t kProbes = 32;

struct Patch {
  std::int32_t begin, end;  // a node's points, or a part of a leaf
  Sphere sphere;
  std::int32_t group = -1;
};

// The sphere through dim + 1 points (`ids`): its centre c = p_0 + z with 2 (p_i - p_0) . z =
// |p_i - p_0|^2, a dim x dim system on the stack. False when they lie in a hyperplane.
bool sphere_through(const double* coords, int dim, const std::int32_t* ids, Sphere& sphere) {
  if (dim + 1 > kMaxUnknowns) return false;
  const auto point = [&](std::int32_t id) { return coords + static_cast<std::size_t>(id) * static_cast<std::size_t>(dim); };
  std::array<double, kMaxUnknowns * kMaxUnknowns> a;  // its dim x dim corner filled below
  std::array<double, kMaxUnknowns> z;
  const double* p0 = point(ids[0]);
  for (int i = 0; i < dim; ++i) {
    const double* p = point(ids[i + 1]);
    double q2 = 0.0;
    for (int k = 0; k < dim; ++k) {
      const double q = p[k] - p0[k];
      a[static_cast<std::size_t>(i * dim + k)] = 2 * q;
      q2 += q * q;
    }
    z[static_cast<std::size_t>(i)] = q2;
  }
  if (!solve(a.data(), z.data(), dim)) return false;
  sphere.centre.resize(static_cast<std::size_t>(dim));
  double r2 = 0.0;
  for (int k = 0; k < dim; ++k) {
    sphere.centre[static_cast<std::size_t>(k)] = p0[k] + z[static_cast<std::size_t>(k)];
    r2 += z[static_cast<std::size_t>(k)] * z[static_cast<std::size_t>(k)];
  }
  sphere.radius2 = r2;
  return std::isfinite(r2) && r2 > 0.0;
}

// A sphere that most of the points [begin, end) lie near, refitted on those points.
bool patch_sphere(const double* coords, int dim, std::int32_t begin, std::int32_t end, Sphere& sphere) {
  const std::int32_t count = end - begin;
  if (count < dim + 2 || dim + 1 > kMaxUnknowns) return false;
  std::array<std::int32_t, kMaxUnknowns> drawn{};
  std::array<std::int32_t, 8> spread{};
  for (int i = 0; i < 8; ++i) spread[static_cast<std::size_t>(i)] = begin + (2 * i + 1) * count / 16;
  std::vector<std::int32_t> ids;
  double widest2 = -1.0;
  for (int draw = 0; draw < kPatchDraws; ++draw) {
    const std::int32_t shift = draw * count / ((dim + 1) * kPatchDraws);
    for (int j = 0; j <= dim; ++j) drawn[static_cast<std::size_t>(j)] = begin + (j * count / (dim + 1) + shift) % count;
    // The sphere through dim + 1 points, and eight points tested first, without allocating:
    // most patches tried are not near a sphere, and this is what they cost.
    if (!sphere_through(coords, dim, drawn.data(), sphere)) continue;
    int off = 0;
    for (std::int32_t id : spread) off += is_near(coords, dim, id, sphere) ? 0 : 1;
    if (off > 1) continue;
    if (ids.empty()) {
      ids.resize(static_cast<std::size_t>(count));
      std::iota(ids.begin(), ids.end(), begin);
      widest2 = kMaxRadiusOverExtent * kMaxRadiusOverExtent * bounding_diagonal2(coords, dim, ids);
    }
    if (!(sphere.radius2 <= widest2) || !mostly_near(coords, dim, ids, sphere)) continue;
    if (fit(coords, dim, near(coords, dim, ids, sphere), sphere) && sphere.radius2 <= widest2 && mostly_near(coords, dim, ids, sphere))
      return true;
  }
  return false;
}

// The patches among the points [begin, end) of a leaf: all of them, else those of each half,
// down to `least` points.
void find_parts(const double* coords, int dim, std::int32_t begin, std::int32_t end, std::int32_t least, std::vector<Patch>& patches) {
  if (end - begin < least) return;
  Sphere sphere;
  if (patch_sphere(coords, dim, begin, end, sphere)) {
    patches.push_back({begin, end, std::move(sphere)});
    return;
  }
  const std::int32_t middle = begin + (end - begin) / 2;
  find_parts(coords, dim, begin, middle, least, patches);
  find_parts(coords, dim, middle, end, least, patches);
}

// The patches under `node`: the node itself when it is one, else those of its children, and
// then the parts of its leaves, down to `least` points.
void find_patches(const double* coords, int dim, const spatial::KdTree& tree, std::int32_t node, std::int32_t least,
                  std::vector<Patch>& patches) {
  const spatial::KdTree::Node& at = tree.nodes()[static_cast<std::size_t>(node)];
  const std::int32_t count = at.end - at.begin;
  if (count < least) return;
  Sphere sphere;
  if (count <= kPatchPoints && patch_sphere(coords, dim, at.begin, at.end, sphere)) {
    patches.push_back({at.begin, at.end, std::move(sphere)});
    return;
  }
  if (at.right >= 0) {
    find_patches(coords, dim, tree, node + 1, least, patches);
    find_patches(coords, dim, tree, at.right, least, patches);
  } else {
    const std::int32_t middle = at.begin + count / 2;
    find_parts(coords, dim, at.begin, middle, least, patches);
    find_parts(coords, dim, middle, at.end, least, patches);
  }
}

// The nodes of at most kPatchPoints points whose parent has more (or leaves), in preorder.
void patch_roots(const spatial::KdTree& tree, std::int32_t node, std::vector<std::int32_t>& roots) {
  const spatial::KdTree::Node& at = tree.nodes()[static_cast<std::size_t>(node)];
  if (at.end - at.begin <= kPatchPoints || at.right < 0) {
    roots.push_back(node);
    return;
  }
  patch_roots(tree, node + 1, roots);
  patch_roots(tree, at.right, roots);
}

// Whether two patches' spheres are one: centres within 4 kNear of the larger radius, squared
// radii within 4 kNear (far looser than two caps of one sphere fit, far tighter than two
// bubbles differ).
bool same_sphere(const Sphere& a, const Sphere& b) {
  const double r2 = std::max(a.radius2, b.radius2);
  double apart2 = 0.0;
  for (std::size_t k = 0; k < a.centre.size(); ++k) apart2 += (a.centre[k] - b.centre[k]) * (a.centre[k] - b.centre[k]);
  return apart2 <= 16 * kNear * kNear * r2 && std::fabs(a.radius2 - b.radius2) <= 4 * kNear * r2;
}

// Which spheres only fit a small cap of a smooth surface (an ellipsoid, a scanned object):
// near every point of such a surface, a patch lies within kNear of its osculating sphere, but
// the points of that sphere span a small part of it (extent under kWideCap times its radius)
// and some lie farther from it than rounding (kTightCap relative). The shell gains nothing
// there, and the points left out of them cost join_near_spheres a test against every sphere.
// The thresholds are far from both sides: bubbles, the cells of a foam and spheres with points
// off them span at least 2.69 radii in bench/degenerate_families.py, their points within
// 6e-15 of their sphere; the caps of an ellipsoid of 80 000 points spanned at most 0.34
// radii, some of their points 1.5e-4 to 9.8e-4 off.
constexpr double kWideCap = 1.0;
constexpr double kTightCap = 0x1p-30;
std::vector<bool> caps_of_surfaces(const double* coords, int dim, const std::vector<Sphere>& spheres,
                                   const std::vector<std::int32_t>& point_sphere) {
  const auto d = static_cast<std::size_t>(dim);
  std::vector<double> lo(spheres.size() * d, std::numeric_limits<double>::infinity()), hi(lo.size(), -lo.front());
  std::vector<double> farthest(spheres.size(), 0.0);
  for (std::size_t id = 0; id < point_sphere.size(); ++id) {
    if (point_sphere[id] < 0) continue;
    const auto k = static_cast<std::size_t>(point_sphere[id]);
    const double* x = coords + id * d;
    for (std::size_t j = 0; j < d; ++j) {
      lo[k * d + j] = std::min(lo[k * d + j], x[j]);
      hi[k * d + j] = std::max(hi[k * d + j], x[j]);
    }
    farthest[k] = std::max(farthest[k], std::fabs(distance2(x, spheres[k].centre) - spheres[k].radius2));
  }
  std::vector<bool> caps(spheres.size(), false);
  for (std::size_t k = 0; k < spheres.size(); ++k) {
    double extent2 = 0.0;
    for (std::size_t j = 0; j < d; ++j) extent2 += (hi[k * d + j] - lo[k * d + j]) * (hi[k * d + j] - lo[k * d + j]);
    caps[k] = extent2 < kWideCap * kWideCap * spheres[k].radius2 && farthest[k] > kTightCap * spheres[k].radius2;
  }
  return caps;
}

// Points in no patch (in a block of a leaf that straddles two bubbles, say) join a sphere they
// lie near, the first in the spheres' order. Even a few points left out cost much: the search
// of a facet with one of them as a vertex has no form, and every point of the sphere in reach
// is then a near-tie for the double-double test. The spheres tried for a point are those whose centre's first coordinate is
// within the largest radius of the point's (a binary search in that order).
void join_near_spheres(const double* coords, int dim, const std::vector<Sphere>& spheres, std::vector<std::int32_t>& point_sphere) {
  std::vector<std::int32_t> by_first(spheres.size());
  std::iota(by_first.begin(), by_first.end(), 0);
  const auto first = [&](std::int32_t k) { return spheres[static_cast<std::size_t>(k)].centre[0]; };
  std::sort(by_first.begin(), by_first.end(), [&](std::int32_t a, std::int32_t b) { return first(a) < first(b) || (first(a) == first(b) && a < b); });
  double widest = 0.0;
  for (const Sphere& sphere : spheres) widest = std::max(widest, std::sqrt(sphere.radius2) * (1 + kNear));
  for (std::size_t id = 0; id < point_sphere.size(); ++id) {
    if (point_sphere[id] >= 0) continue;
    const double x = coords[id * static_cast<std::size_t>(dim)];
    auto it = std::lower_bound(by_first.begin(), by_first.end(), x - widest, [&](std::int32_t k, double v) { return first(k) < v; });
    std::int32_t joined = -1;
    for (; it != by_first.end() && first(*it) <= x + widest; ++it)
      if (is_near(coords, dim, static_cast<std::int32_t>(id), spheres[static_cast<std::size_t>(*it)]) && (joined < 0 || *it < joined)) joined = *it;
    point_sphere[id] = joined;
  }
}

}  // namespace

// The spheres of the patches, each group of patches of one sphere refitted (twice, as in
// one_centre) on all their points near it; a patch that is then not mostly near its group's
// sphere is dropped. Each point of a patch is in its group's sphere if it lies near it (a patch
// may hold a few points of another bubble), the groups with more points first; a sphere left
// with few points is dropped; then the points left join a sphere they lie near
// (join_near_spheres). False when no sphere is left.
bool spheres_of_patches(const double* coords, std::int32_t n, int dim, const spatial::KdTree& tree, std::vector<Sphere>& spheres,
                        std::vector<std::int32_t>& point_sphere) {
  std::vector<Patch> patches;
  std::vector<std::int32_t> roots;
  patch_roots(tree, 0, roots);
  const std::size_t step = std::max<std::size_t>(1, roots.size() / kProbes);
  for (std::size_t i = 0; i < roots.size() && patches.empty(); i += step) find_patches(coords, dim, tree, roots[i], kLeastPatch, patches);
  if (patches.empty()) return false;
  patches.clear();
  for (std::int32_t root : roots) find_patches(coords, dim, tree, root, kLeastPart, patches);
  // Group the patches: compared in the order of their centres' first coordinate, each with
  // those whose first coordinate is near enough to be the same sphere.
  const std::size_t m = patches.size();
  std::vector<std::int32_t> order(m);
  std::iota(order.begin(), order.end(), 0);
  util::UnionFind sets(m);
  const auto first_coordinate = [&](std::int32_t i) { return patches[static_cast<std::size_t>(i)].sphere.centre[0]; };
  std::sort(order.begin(), order.end(), [&](std::int32_t a, std::int32_t b) { return first_coordinate(a) < first_coordinate(b); });
  for (std::size_t i = 0; i < m; ++i) {
    const Sphere& a = patches[static_cast<std::size_t>(order[i])].sphere;
    const double reach = 4 * kNear * std::sqrt(a.radius2) * (1 + 4 * kNear);
    for (std::size_t j = i + 1; j < m && first_coordinate(order[j]) - first_coordinate(order[i]) <= reach * 2; ++j)
      if (same_sphere(a, patches[static_cast<std::size_t>(order[j])].sphere))
        sets.unite(static_cast<std::size_t>(order[i]), static_cast<std::size_t>(order[j]));
  }
  std::vector<std::int32_t> group_of_root(m, -1);
  std::vector<std::vector<std::int32_t>> members;
  for (std::size_t i = 0; i < m; ++i) {
    std::int32_t& group = group_of_root[sets.find(i)];
    if (group < 0) {
      group = static_cast<std::int32_t>(members.size());
      members.emplace_back();
    }
    members[static_cast<std::size_t>(group)].push_back(static_cast<std::int32_t>(i));
  }
  for (const std::vector<std::int32_t>& group : members) {
    Sphere sphere = patches[static_cast<std::size_t>(group.front())].sphere;
    std::vector<std::int32_t> all;
    for (std::int32_t i : group)
      for (std::int32_t id = patches[static_cast<std::size_t>(i)].begin; id < patches[static_cast<std::size_t>(i)].end; ++id) all.push_back(id);
    bool fitted = true;
    for (int pass = 0; pass < 2 && fitted; ++pass) fitted = fit(coords, dim, near(coords, dim, all, sphere), sphere);
    if (!fitted) continue;
    const auto index = static_cast<std::int32_t>(spheres.size());
    for (std::int32_t i : group) {
      Patch& patch = patches[static_cast<std::size_t>(i)];
      std::vector<std::int32_t> ids(static_cast<std::size_t>(patch.end - patch.begin));
      std::iota(ids.begin(), ids.end(), patch.begin);
      if (mostly_near(coords, dim, ids, sphere)) patch.group = index;
    }
    spheres.push_back(std::move(sphere));
  }
  std::vector<std::int64_t> group_points(spheres.size(), 0);
  for (const Patch& patch : patches)
    if (patch.group >= 0) group_points[static_cast<std::size_t>(patch.group)] += patch.end - patch.begin;
  std::sort(patches.begin(), patches.end(), [&](const Patch& a, const Patch& b) {
    const std::int64_t size_a = a.group >= 0 ? group_points[static_cast<std::size_t>(a.group)] : -1;
    const std::int64_t size_b = b.group >= 0 ? group_points[static_cast<std::size_t>(b.group)] : -1;
    return size_a != size_b ? size_a > size_b : a.begin < b.begin;
  });
  point_sphere.assign(static_cast<std::size_t>(n), -1);
  for (const Patch& patch : patches) {
    if (patch.group < 0) break;  // the dropped patches come last
    const Sphere& sphere = spheres[static_cast<std::size_t>(patch.group)];
    for (std::int32_t id = patch.begin; id < patch.end; ++id)
      if (point_sphere[static_cast<std::size_t>(id)] < 0 && is_near(coords, dim, id, sphere)) point_sphere[static_cast<std::size_t>(id)] = patch.group;
  }
  // A sphere with fewer than kSpherePoints points is left out, its points free again, and the
  // others renumbered: a patch may lie near a sphere that touches two bubbles where their arcs
  // meet it; the bubbles' own spheres, taken first, leave it a few points.
  // So is a cap of a smooth surface that its osculating sphere fits (caps_of_surfaces).
  std::vector<std::int32_t> renumbered(spheres.size(), 0);
  for (std::int32_t k : point_sphere)
    if (k >= 0) ++renumbered[static_cast<std::size_t>(k)];
  const std::vector<bool> caps = caps_of_surfaces(coords, dim, spheres, point_sphere);
  std::vector<Sphere> kept;
  for (std::size_t k = 0; k < spheres.size(); ++k) {
    if (renumbered[k] < static_cast<std::int32_t>(kSpherePoints) || caps[k]) {
      renumbered[k] = -1;
      continue;
    }
    renumbered[k] = static_cast<std::int32_t>(kept.size());
    kept.push_back(std::move(spheres[k]));
  }
  for (std::int32_t& k : point_sphere)
    if (k >= 0) k = renumbered[static_cast<std::size_t>(k)];
  spheres = std::move(kept);
  join_near_spheres(coords, dim, spheres, point_sphere);
  return !spheres.empty();
}

}  // namespace drange::engine::sphere_fit
