// voronoi/vertex_classes.cpp: see vertex_classes.hpp.
#include "voronoi/vertex_classes.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>

#include "geometry/predicates.hpp"
#include "util/for_ranges.hpp"
#include "util/key_groups.hpp"
#include "util/union_find.hpp"
#include "voronoi/circumcentre.hpp"

namespace drange::diagram {
namespace {

// The prefilter that spares the exact in-sphere test. Centres are solved in long double
// (circumcentre.hpp): their error is below about Hadamard ratio * d * 2^-63 * R, so for a
// ratio under 1e8 two centres of one exact sphere differ by less than 1e-9 R. Centres
// further apart than 1e-6 R cannot belong to one sphere; anything closer, or any simplex
// flatter than the bound, goes to the exact predicate, which alone decides a merge.
constexpr double kTrustedRatio = 1e8;
constexpr double kSeparation = 1e-6;
// Simplices per range of a thread (a circumcentre or a few exact tests each).
constexpr std::size_t kCentresPerRange = std::size_t{1} << 12;

struct Context {
  PointsView points;
  const Triangulation& t;
  int d;
  int width;  // d + 1

  std::int32_t vertex(std::size_t s, int k) const { return t.simplices[s * static_cast<std::size_t>(width) + static_cast<std::size_t>(k)]; }
  std::int32_t neighbor(std::size_t s, int k) const { return t.neighbors[s * static_cast<std::size_t>(width) + static_cast<std::size_t>(k)]; }
  const double* point(std::int32_t v) const { return points.point(static_cast<std::size_t>(v)); }
};

double squared_distance(int d, const double* a, const double* b) {
  double sum = 0;
  for (int k = 0; k < d; ++k) sum += (a[k] - b[k]) * (a[k] - b[k]);
  return sum;
}

// Unites neighbouring simplices with the same circumsphere. `centres` and `ratios` are the
// per-simplex results of simplex_circumcentre.
// Whether simplex s has the same circumsphere as its neighbour across facet k, for the
// neighbours of higher index (each facet once): bit k of the result.
std::uint32_t cospherical_neighbours(const Context& c, const std::vector<double>& centres, const std::vector<float>& ratios,
                                     std::size_t s, std::vector<const double*>& corners) {
  const double* centre = centres.data() + s * static_cast<std::size_t>(c.d);
  const double radius2 = squared_distance(c.d, centre, c.point(c.vertex(s, 0)));
  std::uint32_t same = 0;
  bool corners_set = false;
  for (int k = 0; k < c.width; ++k) {
    const std::int32_t other = c.neighbor(s, k);
    if (other < 0 || static_cast<std::size_t>(other) < s) continue;
    const auto o = static_cast<std::size_t>(other);
    if (ratios[s] < kTrustedRatio && ratios[o] < kTrustedRatio &&
        squared_distance(c.d, centre, centres.data() + o * static_cast<std::size_t>(c.d)) > kSeparation * kSeparation * radius2)
      continue;
    int far = 0;
    while (c.neighbor(o, far) != static_cast<std::int32_t>(s)) ++far;
    if (!corners_set) {
      for (int i = 0; i < c.width; ++i) corners[static_cast<std::size_t>(i)] = c.point(c.vertex(s, i));
      corners_set = true;
    }
    if (geometry::in_sphere(c.d, corners.data(), c.point(c.vertex(o, far))) == 0) same |= std::uint32_t{1} << k;
  }
  return same;
}

// The exact tests run on the team's threads (an integer grid has one per facet of every cell);
// the unions, in simplex order, on the calling thread.
void unite_cospherical(const Context& c, const std::vector<double>& centres, const std::vector<float>& ratios,
                       util::UnionFind& classes, engine::Team& team) {
  const std::size_t m = c.t.size();
  std::vector<std::uint32_t> same(m);
  util::for_ranges(m, team, [&](std::size_t, std::size_t begin, std::size_t end) {
    std::vector<const double*> corners(static_cast<std::size_t>(c.width));
    for (std::size_t s = begin; s < end; ++s) same[s] = cospherical_neighbours(c, centres, ratios, s, corners);
  }, kCentresPerRange);
  for (std::size_t s = 0; s < m; ++s)
    for (int k = 0; same[s] != 0 && k < c.width; ++k)
      if (same[s] & (std::uint32_t{1} << k)) classes.unite(s, static_cast<std::size_t>(c.neighbor(s, k)));
}

struct HullFacet {
  std::int32_t simplex;
  int face;  // the simplex's vertex opposite the facet
};

// Unites neighbouring hull facets that lie in one hyperplane. Hull facets meet in pairs along
// (d-2)-faces ("hull ridges"), found by sorting keys, not by hashing.
void unite_coplanar(const Context& c, const std::vector<HullFacet>& hull, util::UnionFind& classes,
                    std::size_t first) {
  const int d = c.d;
  // Each hull facet's vertex ids, sorted, so that a ridge key (one id dropped) is sorted too.
  std::vector<std::int32_t> ids(hull.size() * static_cast<std::size_t>(d));
  for (std::size_t h = 0; h < hull.size(); ++h) {
    std::int32_t* row = ids.data() + h * static_cast<std::size_t>(d);
    int n = 0;
    for (int k = 0; k < c.width; ++k)
      if (k != hull[h].face) row[n++] = c.vertex(static_cast<std::size_t>(hull[h].simplex), k);
    std::sort(row, row + d);
  }
  // Item: facet h with its id at position `drop` left out, packed as h * d + drop.
  auto for_each_item = [&](auto&& f) {
    for (std::size_t h = 0; h < hull.size(); ++h)
      for (int drop = 0; drop < d; ++drop) f(static_cast<std::uint64_t>(h) * static_cast<std::uint64_t>(d) + static_cast<std::uint64_t>(drop));
  };
  auto key = [&](std::uint64_t item, int k) {
    const std::size_t h = item / static_cast<std::uint64_t>(d);
    const int drop = static_cast<int>(item % static_cast<std::uint64_t>(d));
    return ids[h * static_cast<std::size_t>(d) + static_cast<std::size_t>(k < drop ? k : k + 1)];
  };
  std::vector<const double*> corners(static_cast<std::size_t>(c.width));
  util::for_each_key_group<std::uint64_t>(c.points.n, d - 1, for_each_item, key, [&](const std::uint64_t* group, std::size_t size) {
    if (size != 2) return;  // a valid triangulation's hull is closed: every hull ridge has two sides
    const std::size_t f = group[0] / static_cast<std::uint64_t>(d);
    const std::size_t g = group[1] / static_cast<std::uint64_t>(d);
    const int g_drop = static_cast<int>(group[1] % static_cast<std::uint64_t>(d));
    for (int i = 0; i < d; ++i) corners[static_cast<std::size_t>(i)] = c.point(ids[f * static_cast<std::size_t>(d) + static_cast<std::size_t>(i)]);
    corners[static_cast<std::size_t>(d)] = c.point(ids[g * static_cast<std::size_t>(d) + static_cast<std::size_t>(g_drop)]);
    if (geometry::simplex_orientation(d, corners.data()) == 0) classes.unite(first + f, first + g);
  });
}

}  // namespace

VertexClasses classify_vertices(PointsView points, const Triangulation& t, engine::Team& team) {
  const Context c{points, t, t.dim, t.dim + 1};
  const std::size_t m = t.size();
  const auto d = static_cast<std::size_t>(c.d);
  const auto width = static_cast<std::size_t>(c.width);

  // Every simplex's circumcentre, and how flat the simplex is.
  std::vector<double> centres(m * d);
  std::vector<float> ratios(m);
  util::for_ranges(m, team, [&](std::size_t, std::size_t begin, std::size_t end) {
    std::vector<const double*> corners(width);
    for (std::size_t s = begin; s < end; ++s) {
      for (std::size_t i = 0; i < width; ++i) corners[i] = c.point(c.vertex(s, static_cast<int>(i)));
      const double ratio = simplex_circumcentre(c.d, corners.data(), centres.data() + s * d);
      ratios[s] = static_cast<float>(std::min(ratio, 1e30));
    }
  }, kCentresPerRange);

  std::vector<HullFacet> hull;
  for (std::size_t s = 0; s < m; ++s)
    for (int k = 0; k < c.width; ++k)
      if (c.neighbor(s, k) < 0) hull.push_back({static_cast<std::int32_t>(s), k});

  // Union-find over simplices 0..m-1, then hull facets m..m+h-1.
  util::UnionFind classes(m + hull.size());
  unite_cospherical(c, centres, ratios, classes, team);
  unite_coplanar(c, hull, classes, m);

  // Number the classes in the order of their first member: simplices first, so that the
  // finite classes (the Voronoi vertices) get the ids 0..finite-1.
  VertexClasses out;
  out.dim = c.d;
  std::vector<std::int32_t> id(m + hull.size(), -1);
  std::vector<std::int32_t> size;
  for (std::size_t x = 0; x < m + hull.size(); ++x) {
    const std::size_t root = classes.find(x);
    if (id[root] < 0) {
      id[root] = static_cast<std::int32_t>(size.size());
      size.push_back(0);
    }
    id[x] = id[root];
    ++size[static_cast<std::size_t>(id[x])];
    if (x + 1 == m) out.finite = static_cast<std::int32_t>(size.size());
  }
  if (m == 0) out.finite = 0;
  out.total = static_cast<std::int32_t>(size.size());
  out.of_simplex.assign(id.begin(), id.begin() + static_cast<std::ptrdiff_t>(m));
  // `hull` was collected in increasing (simplex, face) order, so its keys come sorted.
  for (std::size_t h = 0; h < hull.size(); ++h) {
    out.hull_facet_keys.push_back(static_cast<std::int64_t>(static_cast<std::size_t>(hull[h].simplex) * width + static_cast<std::size_t>(hull[h].face)));
    out.hull_facet_class.push_back(id[m + h]);
  }

  // Each Voronoi vertex is the centre of its class's best-conditioned simplex. The copy is in
  // place: class c's members all have indices >= c, and slots below c are the only ones
  // already overwritten.
  const auto finite = static_cast<std::size_t>(out.finite);
  std::vector<std::int32_t> best(finite, -1);
  out.simplex_of.assign(finite, -1);
  for (std::size_t s = 0; s < m; ++s) {
    const auto k = static_cast<std::size_t>(out.of_simplex[s]);
    if (best[k] < 0 || ratios[s] < ratios[static_cast<std::size_t>(best[k])]) best[k] = static_cast<std::int32_t>(s);
    if (out.simplex_of[k] < 0) out.simplex_of[k] = static_cast<std::int32_t>(s);
  }
  for (std::size_t k = 0; k < finite; ++k)
    std::copy_n(centres.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(best[k]) * d), d,
                centres.begin() + static_cast<std::ptrdiff_t>(k * d));
  centres.resize(finite * d);
  centres.shrink_to_fit();
  out.vertices = std::move(centres);

  // Vertex sets of the merged and the infinite classes: (class, point) pairs, sorted, unique.
  std::vector<std::pair<std::int32_t, std::int32_t>> pairs;
  for (std::size_t s = 0; s < m; ++s)
    if (size[static_cast<std::size_t>(out.of_simplex[s])] > 1)
      for (int k = 0; k < c.width; ++k) pairs.emplace_back(out.of_simplex[s], c.vertex(s, k));
  for (std::size_t h = 0; h < hull.size(); ++h)
    for (int k = 0; k < c.width; ++k)
      if (k != hull[h].face) pairs.emplace_back(id[m + h], c.vertex(static_cast<std::size_t>(hull[h].simplex), k));
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  out.set_of.assign(static_cast<std::size_t>(out.total), -1);
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    if (i > 0 && pairs[i].first != pairs[i - 1].first) out.sets.end_row();
    if (i == 0 || pairs[i].first != pairs[i - 1].first) out.set_of[static_cast<std::size_t>(pairs[i].first)] = static_cast<std::int32_t>(out.sets.size());
    out.sets.values.push_back(pairs[i].second);
  }
  if (!pairs.empty()) out.sets.end_row();
  return out;
}

}  // namespace drange::diagram
