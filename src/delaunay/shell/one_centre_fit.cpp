// delaunay/shell/one_centre_fit.cpp: one sphere, or concentric spheres, that most of the
// points lie near (sphere_fit.hpp, one_centre).
//
// Why concentric spheres too: the layers of a spherical grid, or a sphere with a smaller one
// inside, are not near one sphere, but a node whose points lie near any sphere about the
// centre has as thin a range of offsets about it, and its cones hold as well; the index only
// needs the centre and, for its clusters, where the smallest sphere ends. A sample decides
// first, so that the inputs near no sphere (most of them) pay for a few thousand points.
#include "delaunay/shell/sphere_fit.hpp"

#include <algorithm>
#include <numeric>

namespace drange::engine::sphere_fit {

namespace {

constexpr std::int32_t kSample = 4096;

// How many of `ids` lie near the sphere or near one of the other spheres about its centre
// (squared radii `others`).
std::size_t near_any(const double* coords, int dim, const std::vector<std::int32_t>& ids, const Sphere& sphere,
                     const std::vector<double>& others) {
  std::size_t count = 0;
  for (std::int32_t id : ids) {
    const double t = distance2(coords + static_cast<std::size_t>(id) * static_cast<std::size_t>(dim), sphere.centre);
    bool near_one = is_near(t, sphere.radius2);
    for (std::size_t i = 0; i < others.size() && !near_one; ++i) near_one = is_near(t, others[i]);
    count += near_one ? 1 : 0;
  }
  return count;
}

// Concentric spheres: the shell's offsets are taken around one of them, and a centre is also
// accepted when most of the points lie near at most kMaxSpheres spheres about it, each with at
// least kSphereShare of them (and kSpherePoints), none wider than kMaxRadiusOverExtent times
// the sample's bounding box.
constexpr std::size_t kMaxSpheres = 32;
constexpr double kSphereShare = 0.01;
// The most points inside the smallest of the spheres, relative to the points on it (see
// spheres_in). Concentric spheres have none there, or a point at the centre; the 4D grid of
// 6^4 points has 16 inside its smallest sphere of 64, that of 10^4 points 88 in 64 of its
// sample, the 5D grid of 5^5 points 51 in 80.
constexpr double kMostlyEmpty = 0.125;
// The largest step between the squared distances of two points that centre_from_pairs takes
// to lie on one sphere, relative to the median step.
constexpr double kPairGap = 8.0;

using Distances = std::vector<std::pair<double, std::size_t>>;  // (squared distance, position in ids), sorted

Distances by_distance(const double* coords, int dim, const std::vector<std::int32_t>& ids, const std::vector<double>& centre) {
  Distances t(ids.size());
  for (std::size_t i = 0; i < ids.size(); ++i)
    t[i] = {distance2(coords + static_cast<std::size_t>(ids[i]) * static_cast<std::size_t>(dim), centre), i};
  std::sort(t.begin(), t.end());
  return t;
}

// The squared radii of the spheres that most of the points of `t` lie near, smallest first, or
// none. Each sphere takes the run from its least value t up to (1 + 2 kNear) t, and its squared
// radius is the run's middle value, which every member is within kNear of; runs with fewer
// than kSphereShare of the points (and `fewest`) are not spheres (a small grid's squared
// distances from its centre take few values, each held by a few dozen points: 8^3 points, 15
// values held by 8 to 72 points, 72 of the 512 in values held by 64 or more). The shell takes
// its offsets around the smallest: the ball inside it is one Delaunay cell with all its points
// on its sphere, the case the shell is for, where the other spheres' cells join points of two
// spheres (taking the most populous sphere instead made the search several times slower).
std::vector<double> spheres_in(const Distances& t, std::size_t fewest = kSpherePoints) {
  const auto least = std::max<std::size_t>(fewest, static_cast<std::size_t>(kSphereShare * static_cast<double>(t.size())));
  std::vector<double> radii2;
  std::size_t covered = 0;
  for (std::size_t i = 0; i < t.size();) {
    const double limit = t[i].first + 2 * kNear * t[i].first;
    std::size_t j = i + 1;
    while (j < t.size() && t[j].first <= limit) ++j;
    if (j - i >= least) {
      // The smallest sphere's ball must be nearly empty (kMostlyEmpty): a grid's squared
      // distances from its centre take few values too, in 4D and 5D each held by enough points,
      // but the smallest such sphere holds the grid's middle, where the shell only costs.
      if (radii2.empty() && static_cast<double>(i) > kMostlyEmpty * static_cast<double>(j - i)) return {};
      radii2.push_back(0.5 * (t[i].first + t[j - 1].first));
      covered += j - i;
    }
    i = j;
  }
  if (!mostly(covered, t.size()) || radii2.size() > kMaxSpheres) return {};
  return radii2;
}

// The squared radii of the spheres about `centre` that most of `ids` lie near (spheres_in).
std::vector<double> spheres_about(const double* coords, int dim, const std::vector<std::int32_t>& ids, const std::vector<double>& centre) {
  return spheres_in(by_distance(coords, dim, ids, centre));
}

// A better centre of concentric spheres than `centre`, from the points `ids` in the order of
// their squared distances from it (`t`). A least-squares fit to points of several spheres
// misses their centre by the imbalance of their sample (random points: by about a percent of
// the largest radius), too far for their squared distances to fall within kNear of a few
// values. But as long as the spheres' ranges
// of squared distances do not overlap, two points next in that order lie on one sphere, and
// |x - g|^2 = |x' - g|^2 is linear in g: 2 (x' - x) . g = |x'|^2 - |x|^2 (about the points'
// mean, for scale). The least-squares solution over those pairs, leaving out the pairs whose
// relative step is over kPairGap times the median step: where the order passes from one
// sphere to the next (the steps within a sphere are its spread over its points).
bool centre_from_pairs(const double* coords, int dim, const std::vector<std::int32_t>& ids, const Distances& t,
                       std::vector<double>& centre) {
  if (t.size() < 3) return false;
  const auto d = static_cast<std::size_t>(dim);
  const auto point = [&](std::size_t i) { return coords + static_cast<std::size_t>(ids[t[i].second]) * d; };
  std::vector<double> mean(d, 0.0);
  for (std::size_t i = 0; i < t.size(); ++i)
    for (std::size_t k = 0; k < d; ++k) mean[k] += point(i)[k];
  for (double& v : mean) v /= static_cast<double>(t.size());
  std::vector<double> steps(t.size() - 1);
  for (std::size_t i = 0; i + 1 < t.size(); ++i) steps[i] = (t[i + 1].first - t[i].first) / t[i].first;
  std::vector<double> sorted_steps = steps;
  std::nth_element(sorted_steps.begin(), sorted_steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2), sorted_steps.end());
  const double largest_step = kPairGap * sorted_steps[steps.size() / 2];
  std::vector<double> normal(d * d, 0.0), rhs(d, 0.0), a(d);
  std::size_t pairs = 0;
  for (std::size_t i = 0; i + 1 < t.size(); ++i) {
    if (!(steps[i] <= largest_step)) continue;
    double value = 0.0;
    for (std::size_t k = 0; k < d; ++k) {
      const double y = point(i)[k] - mean[k], y_next = point(i + 1)[k] - mean[k];
      a[k] = 2 * (y_next - y);
      value += y_next * y_next - y * y;
    }
    for (std::size_t r = 0; r < d; ++r) {
      rhs[r] += a[r] * value;
      for (std::size_t c = 0; c < d; ++c) normal[r * d + c] += a[r] * a[c];
    }
    ++pairs;
  }
  if (pairs < 2 * d || !solve(normal.data(), rhs.data(), dim)) return false;
  for (std::size_t k = 0; k < d; ++k) centre[k] = mean[k] + rhs[k];
  return true;
}

// The sample, and the tests a sphere's centre must pass.
struct Sample {
  const double* coords;
  int dim;
  std::vector<std::int32_t> ids;
  std::vector<std::int32_t> sparse;  // every 8th of ids
  double extent2;                    // the squared diagonal of its bounding box

  // Whether most of the sample lies near a few spheres about the centre of `sphere`, or about
  // the centre that centre_from_pairs finds from it, twice; if so, `sphere` becomes the
  // smallest of those spheres (see spheres_in). A new centre is tried on the sparse sample
  // first, where three points make a sphere: most inputs are not concentric spheres, and this
  // spares them two sorts of the sample.
  bool concentric(Sphere& sphere) const {
    std::vector<double> centre = sphere.centre;
    for (int round = 0; round < 3; ++round) {
      if (round > 0 && spheres_in(by_distance(coords, dim, sparse, centre), 3).empty()) return false;
      const Distances t = by_distance(coords, dim, ids, centre);
      const std::vector<double> radii2 = spheres_in(t);
      if (!radii2.empty()) {
        for (double r2 : radii2)
          if (!(r2 <= kMaxRadiusOverExtent * kMaxRadiusOverExtent * extent2)) return false;
        sphere.centre = centre;
        sphere.radius2 = radii2.front();
        return true;
      }
      if (round == 2 || !centre_from_pairs(coords, dim, ids, t, centre)) return false;
    }
    return false;
  }
};

// A sphere that most of the sample lies near, or whose centre most of it lies around, on a few
// spheres. First the least-squares fit of the whole sample (which is near the centre of
// concentric spheres too, by their symmetry); but a few points far from the sphere pull that
// fit off by about their residuals over n, more than kNear (the corners of a box added around
// points on a sphere, say), and then no point is near it. So then
// spheres fitted to dim + 2 sample points drawn at random are tried: with 9 in 10 of the points
// near one sphere, each draw is all near it with odds of at least 0.9^10 = 0.35 up to d = 8,
// and kDraws draws all fail with odds below 10^-11. The draws are the same for every run (a
// fixed seed): the shell changes the work, never the result.
constexpr int kDraws = 64;
bool sphere_of_most(const Sample& sample, Sphere& sphere) {
  const std::vector<std::int32_t>& ids = sample.ids;
  const int dim = sample.dim;
  if (fit(sample.coords, dim, ids, sphere) && (mostly_near(sample.coords, dim, ids, sphere) || sample.concentric(sphere)))
    return true;
  if (ids.size() < static_cast<std::size_t>(dim + 2)) return false;
  std::uint64_t state = 0x9e3779b97f4a7c15ull;
  std::vector<std::int32_t> drawn(static_cast<std::size_t>(dim + 2));
  for (int draw = 0; draw < kDraws; ++draw) {
    for (std::int32_t& id : drawn) {
      state = state * 6364136223846793005ull + 1442695040888963407ull;  // Knuth's MMIX LCG
      id = ids[static_cast<std::size_t>((state >> 33) % ids.size())];
    }
    if (fit(sample.coords, dim, drawn, sphere) && mostly_near(sample.coords, dim, ids, sphere)) return true;
  }
  return false;
}

}  // namespace

// One sphere (or concentric spheres) that most of the points lie near: sphere_of_most on a
// sample first (most inputs are not near a sphere, and this costs them a few thousand points),
// then the least-squares fit of all the points near that sphere, twice: the points far from it
// are left out (a centre point, say, would pull the fit off by its distance over n: far more
// than rounding), and the second fit sees the points the first one brings near. Most points
// must then lie near it, or near one of the spheres about its centre that most of the sample
// lies near.
bool one_centre(const double* coords, std::int32_t n, int dim, Sphere& sphere, std::vector<double>& radii2) {
  Sample sample{coords, dim, {}, {}, 0.0};
  const std::int32_t stride = std::max<std::int32_t>(1, n / kSample);
  for (std::int32_t id = 0; id < n; id += stride) sample.ids.push_back(id);
  for (std::size_t i = 0; i < sample.ids.size(); i += 8) sample.sparse.push_back(sample.ids[i]);
  sample.extent2 = bounding_diagonal2(coords, dim, sample.ids);
  if (!sphere_of_most(sample, sphere)) return false;
  std::vector<std::int32_t> all(static_cast<std::size_t>(n));
  std::iota(all.begin(), all.end(), 0);
  for (int pass = 0; pass < 2; ++pass) {
    const std::vector<std::int32_t> ids = near(coords, dim, all, sphere);
    if (ids.size() < static_cast<std::size_t>(dim + 2) || !fit(coords, dim, ids, sphere)) return false;
  }
  radii2 = spheres_about(coords, dim, sample.ids, sphere.centre);
  return mostly(near_any(coords, dim, all, sphere, radii2), static_cast<std::size_t>(n));
}

}  // namespace drange::engine::sphere_fit
