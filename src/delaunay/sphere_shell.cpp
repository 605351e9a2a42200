// delaunay/sphere_shell.cpp: the sphere fit, the points' offsets and the nodes' ranges.
#include "delaunay/sphere_shell.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

#include "drange/points.hpp"
#include "geometry/double_double.hpp"
#include "geometry/error_bound.hpp"
#include "spatial/kdtree.hpp"
#include "util/union_find.hpp"

namespace drange::engine {

namespace {

// A point is near the sphere when | |x - g|^2 - R^2 | <= kNear R^2: far looser than rounding,
// so that points a little off a sphere (measured, then normalised in single precision) count.
constexpr double kNear = 0x1p-10;
constexpr double kInlierShare = 0.9;
constexpr std::int32_t kSample = 4096;

struct Sphere {
  std::vector<double> centre;
  double radius2 = 0.0;
};

// The fit's unknowns: the centre and one more.
constexpr int kMaxUnknowns = kMaxDimension + 1;

// Solves the m x m system a z = b (row-major, both overwritten) by Gaussian elimination with
// partial pivoting; the solution is left in b. False when a pivot is zero or not finite.
bool solve(double* a, double* b, int m) {
  for (int col = 0; col < m; ++col) {
    int pivot = col;
    for (int r = col + 1; r < m; ++r)
      if (std::fabs(a[static_cast<std::size_t>(r * m + col)]) > std::fabs(a[static_cast<std::size_t>(pivot * m + col)])) pivot = r;
    const double p = a[static_cast<std::size_t>(pivot * m + col)];
    if (!(std::fabs(p) > 0.0) || !std::isfinite(p)) return false;
    if (pivot != col) {
      for (int c = 0; c < m; ++c) std::swap(a[static_cast<std::size_t>(pivot * m + c)], a[static_cast<std::size_t>(col * m + c)]);
      std::swap(b[static_cast<std::size_t>(pivot)], b[static_cast<std::size_t>(col)]);
    }
    for (int r = col + 1; r < m; ++r) {
      const double f = a[static_cast<std::size_t>(r * m + col)] / p;
      for (int c = col; c < m; ++c) a[static_cast<std::size_t>(r * m + c)] -= f * a[static_cast<std::size_t>(col * m + c)];
      b[static_cast<std::size_t>(r)] -= f * b[static_cast<std::size_t>(col)];
    }
  }
  for (int r = m - 1; r >= 0; --r) {
    double s = b[static_cast<std::size_t>(r)];
    for (int c = r + 1; c < m; ++c) s -= a[static_cast<std::size_t>(r * m + c)] * b[static_cast<std::size_t>(c)];
    b[static_cast<std::size_t>(r)] = s / a[static_cast<std::size_t>(r * m + r)];
  }
  for (int r = 0; r < m; ++r)
    if (!std::isfinite(b[static_cast<std::size_t>(r)])) return false;
  return true;
}

// The algebraic least-squares sphere of the points `ids`: |y|^2 = 2 c . y + k with y = x - m
// (m their mean, which keeps the normal equations well scaled), then one step of refinement
// on the residuals (with `passes` 2). False when the system is singular (points in a
// hyperplane).
bool fit(const double* coords, int dim, const std::vector<std::int32_t>& ids, Sphere& sphere, int passes = 2) {
  if (ids.size() < static_cast<std::size_t>(dim + 2) || dim + 1 > kMaxUnknowns) return false;
  const auto point = [&](std::int32_t id) { return coords + static_cast<std::size_t>(id) * static_cast<std::size_t>(dim); };
  // Arrays on the stack: the patches' search fits thousands of spheres of a few points.
  std::array<double, kMaxUnknowns> mean{}, z{}, solution{}, rhs{};
  std::array<double, kMaxUnknowns * kMaxUnknowns> normal{};
  for (std::int32_t id : ids)
    for (int k = 0; k < dim; ++k) mean[static_cast<std::size_t>(k)] += point(id)[k];
  for (int k = 0; k < dim; ++k) mean[static_cast<std::size_t>(k)] /= static_cast<double>(ids.size());

  const int m = dim + 1;
  // The normal equations' right-hand side for the residual of (c, k): the first pass with
  // c = 0, k = 0, the refinement with the first solution.
  for (int pass = 0; pass < passes; ++pass) {
    std::fill(normal.begin(), normal.end(), 0.0);
    std::fill(rhs.begin(), rhs.end(), 0.0);
    for (std::int32_t id : ids) {
      double norm2 = 0.0, predicted = solution[static_cast<std::size_t>(dim)];
      for (int k = 0; k < dim; ++k) {
        const double y = point(id)[k] - mean[static_cast<std::size_t>(k)];
        z[static_cast<std::size_t>(k)] = 2 * y;
        norm2 += y * y;
        predicted += 2 * y * solution[static_cast<std::size_t>(k)];
      }
      z[static_cast<std::size_t>(dim)] = 1.0;
      const double residual = norm2 - predicted;
      for (int r = 0; r < m; ++r) {
        rhs[static_cast<std::size_t>(r)] += z[static_cast<std::size_t>(r)] * residual;
        for (int c = 0; c < m; ++c) normal[static_cast<std::size_t>(r * m + c)] += z[static_cast<std::size_t>(r)] * z[static_cast<std::size_t>(c)];
      }
    }
    if (!solve(normal.data(), rhs.data(), m)) return false;
    for (int r = 0; r < m; ++r) solution[static_cast<std::size_t>(r)] += rhs[static_cast<std::size_t>(r)];
  }
  sphere.centre.assign(static_cast<std::size_t>(dim), 0.0);
  double c2 = 0.0;
  for (int k = 0; k < dim; ++k) {
    sphere.centre[static_cast<std::size_t>(k)] = mean[static_cast<std::size_t>(k)] + solution[static_cast<std::size_t>(k)];
    c2 += solution[static_cast<std::size_t>(k)] * solution[static_cast<std::size_t>(k)];
  }
  sphere.radius2 = solution[static_cast<std::size_t>(dim)] + c2;
  return std::isfinite(sphere.radius2) && sphere.radius2 > 0.0;
}

double distance2(const double* x, const std::vector<double>& g) {
  double t = 0.0;
  for (std::size_t k = 0; k < g.size(); ++k) t += (x[k] - g[k]) * (x[k] - g[k]);
  return t;
}

// Whether a squared distance t from the centre is near the sphere of squared radius r2.
bool is_near(double t, double r2) { return std::fabs(t - r2) <= kNear * r2; }

bool is_near(const double* coords, int dim, std::int32_t id, const Sphere& sphere) {
  return is_near(distance2(coords + static_cast<std::size_t>(id) * static_cast<std::size_t>(dim), sphere.centre), sphere.radius2);
}

// The ids among `ids` near the sphere.
std::vector<std::int32_t> near(const double* coords, int dim, const std::vector<std::int32_t>& ids, const Sphere& sphere) {
  std::vector<std::int32_t> kept;
  kept.reserve(ids.size());
  for (std::int32_t id : ids)
    if (is_near(coords, dim, id, sphere)) kept.push_back(id);
  return kept;
}

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

bool mostly(std::size_t part, std::size_t whole) { return static_cast<double>(part) >= kInlierShare * static_cast<double>(whole); }

// Whether most of `ids` lie near the sphere; stops counting once too many are off it, so that
// a sphere far from the points costs a few hundred of them, not all.
bool mostly_near(const double* coords, int dim, const std::vector<std::int32_t>& ids, const Sphere& sphere) {
  const auto allowed = static_cast<std::size_t>((1.0 - kInlierShare) * static_cast<double>(ids.size()));
  std::size_t off = 0;
  for (std::int32_t id : ids)
    if (!is_near(coords, dim, id, sphere) && ++off > allowed) return false;
  return true;
}

// Concentric spheres (the layers of a spherical grid, a sphere with a smaller one inside): the
// shell's offsets are taken around one of them, but a node whose points lie near another sphere
// about the same centre has as thin a range of offsets, and its cones hold as well. So a centre
// is also accepted when most of the points lie near at most kMaxSpheres spheres about it, each
// with at least kSphereShare of them, none wider than kMaxRadiusOverExtent times the sample's
// bounding box: a sphere much larger than the points is near a hyperplane, and the points of
// any input lie near a few of those.
constexpr std::size_t kMaxSpheres = 32;
constexpr double kSphereShare = 0.01;
constexpr std::size_t kSpherePoints = 64;
constexpr double kMaxRadiusOverExtent = 16.0;
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
// spheres (time_search with the smallest, and with the most populous sphere of the sample
// instead: two concentric circles of 10 000 points 0.093 s and 0.288 s; five spheres of 4 000
// points in 3D 0.56 s and 3.84 s; one run each).
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
// misses their centre by the imbalance of their sample (five spheres of 4 000 random points:
// by 1.2% of the largest radius; eight layers of a Fibonacci grid: 0.2%), too far for their
// squared distances to fall within kNear of a few values. But as long as the spheres' ranges
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

// The squared diagonal of the points' bounding box.
double bounding_diagonal2(const double* coords, int dim, const std::vector<std::int32_t>& ids) {
  double total = 0.0;
  for (int k = 0; k < dim; ++k) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::int32_t id : ids) {
      const double x = coords[static_cast<std::size_t>(id) * static_cast<std::size_t>(dim) + static_cast<std::size_t>(k)];
      lo = std::min(lo, x);
      hi = std::max(hi, x);
    }
    total += (hi - lo) * (hi - lo);
  }
  return total;
}

// A sphere that most of the sample lies near, or whose centre most of it lies around, on a few
// spheres. First the least-squares fit of the whole sample (which is near the centre of
// concentric spheres too, by their symmetry); but a few points far from the sphere pull that
// fit off by more than kNear (the 8 corners of the bounding box of 32 000 points on a sphere in
// 3D, by about their residuals over n: 0.14% of rho), and then no point is near it. So then
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

// The blocks' size: on a circle a leaf's cone bounds its points well enough (with blocks of
// 8, the circle of 80 000 points took 0.213 s in the search instead of 0.201), on a sphere
// blocks of 8 test a fifth of the points (3D, 32 000 points: 0.604 -> 0.536 s; 16: 0.236 ->
// 0.232, within the noise). From 4D, with leaves of 256 points, a cone per 8 points costs more
// than it saves: 4D sphere, 5 000 points, min of 5, 8 / 16 / 32 / 64 / whole leaf: 0.335 /
// 0.300 / 0.288 / 0.342 / 0.564 s; 5D, 1 500 points, 8 / 32: 3.02 / 2.95 s.
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

// The determinant of the K x K submatrix of `a` on `rows` and `columns` by Laplace expansion
// along its first row, and the same expansion on absolute values (its error bound's tree:
// within gamma(laplace_roundings(K, 1)) of it when each entry carries one rounding).
template <int N, int K>
void minor_of(const double (&a)[N][N], const int* rows, const int* columns, double& value, double& tree) {
  if constexpr (K == 1) {
    value = a[rows[0]][columns[0]];
    tree = std::fabs(value);
  } else {
    value = tree = 0.0;
    for (int j = 0; j < K; ++j) {
      int rest[K - 1];
      for (int t = 0, o = 0; t < K; ++t)
        if (t != j) rest[o++] = columns[t];
      double v = 0.0, t = 0.0;
      minor_of<N, K - 1>(a, rows + 1, rest, v, t);
      const double entry = a[rows[0]][columns[j]];
      value += (j % 2 ? -entry : entry) * v;
      tree += std::fabs(entry) * t;
    }
  }
}

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

// Spheres about several centres (bubbles; the cells of a foam), found patch by patch: a patch
// is a kd-tree node of kLeastPatch to kPatchPoints points (contiguous ids, near each other), or
// a part of a leaf down to kLeastPart points (the build orders a leaf's points by the same
// halving splits), that most of its points lie near a sphere no wider than
// kMaxRadiusOverExtent times its bounding box. The patches of one sphere are then grouped, and
// each group's sphere refitted on all their points near it. The parts of leaves give a sphere
// the points of the leaves that straddle two bubbles (bubbles3: 6% of the points were left in
// no sphere, and the searches of their facets took 67% of the time in double-double tests).
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
    // most patches tried are not near a sphere, and this is what they cost (uniform 2D,
    // 1 000 000 points with 200 bubbles: the patches' search took 3.0 G instructions with a
    // least-squares fit of dim + 2 points per draw and vectors for the eight).
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

void join_near_spheres(const double* coords, int dim, const std::vector<Sphere>& spheres, std::vector<std::int32_t>& point_sphere);

// Which spheres only fit a small cap of a smooth surface (an ellipsoid, a scanned object):
// near every point of such a surface, a patch lies within kNear of its osculating sphere, but
// the points of that sphere span a small part of it (extent under kWideCap times its radius)
// and some lie farther from it than rounding (kTightCap relative). The shell gains nothing
// there (ellipsoid of 80 000 points, 228 such spheres: time_search level with and without the
// shell), and the points left out of them cost join_near_spheres a test against every sphere
// (320 000 points, 1 632 spheres: 0.45 s). Bubbles, the cells of a foam and
// spheres with points off them span at least 2.69 radii in bench/degenerate_families.py, their
// points within 6e-15; the caps of the ellipsoid of 80 000 points spanned at most 0.34 radii,
// some of their points 1.5e-4 to 9.8e-4 off.
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
  // meet it (2D, 12 bubbles of 300 points: one, which the bubbles' own spheres left 4 points).
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

// Points in no patch (in a block of a leaf that straddles two bubbles, say) join a sphere they
// lie near, the first in the spheres' order. Even a few points left out cost much: the search
// of a facet with one of them as a vertex has no form, and every point of the sphere in reach
// is then a near-tie for the double-double test (bubbles3: 158 points in no sphere, 0.40 M
// such tests). The spheres tried for a point are those whose centre's first coordinate is
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
  if (one_centre(coords, n, dim, spheres.front(), radii2)) {
    point_sphere.assign(static_cast<std::size_t>(n), 0);  // every point, near one of the spheres or not
    // Offsets from the smallest sphere: about 0 on it, about radii2[1] - radii2[0] on the next.
    if (radii2.size() > 1) cluster_split = 0.5 * (radii2[1] - radii2[0]);
  } else {
    spheres.clear();
    if (!spheres_of_patches(coords, n, dim, tree, spheres, point_sphere)) return {};
  }
  return shell_of(coords, n, dim, tree, spheres, std::move(point_sphere), cluster_split);
}

namespace {
// The index of the column pair {c, j}, c < j, among the d (d - 1) / 2 pairs.
constexpr int pair_index(int d, int c, int j) { return c * (2 * d - c - 1) / 2 + (j - c - 1); }

// The Laplace expansion along `row` (d entries) of a minor without column c, over `sub`, its
// minors without columns c and t (by pair_index): minor_of's value and tree for the minor's
// rows taken `row` first. Inlined, for d = N (called out of line, with d at run time: 5D
// sphere of 1 500 points, +3% instructions over the whole run).
template <int N>
[[gnu::always_inline]] inline void expand_along(const double* row, const double (*sub)[2], int c, double& value, double& tree) {
  constexpr int d = N;
  value = tree = 0.0;
  for (int t = 0, position = 0; t < d; ++t) {
    if (t == c) continue;
    const double* m = sub[c < t ? pair_index(d, c, t) : pair_index(d, t, c)];
    value += (position % 2 ? -row[t] : row[t]) * m[0];
    tree += std::fabs(row[t]) * m[1];
    ++position;
  }
}

// FacetMinors for the facet rows a[0..d-2]: the (d - 2)-minors without row i and columns c < j,
// then the (d - 1)-minors without column c, expanded along row 0 over the former (so each is
// minor_of's value for rows 0..d-2, bit for bit).
template <int N>
void fill_facet_minors(const double (&a)[N][N], FacetMinors& minors) {
  constexpr int d = N;
  for (int i = 0; i < d - 1; ++i) {
    int rows_left[N - 2];
    for (int t = 0, r = 0; t < d - 1; ++t)
      if (t != i) rows_left[r++] = t;
    for (int c = 0; c < d; ++c)
      for (int j = c + 1; j < d; ++j) {
        int columns_left[N - 2];
        for (int t = 0, k = 0; t < d; ++t)
          if (t != c && t != j) columns_left[k++] = t;
        double* m = minors.sub[i][pair_index(d, c, j)];
        minor_of<N, N - 2>(a, rows_left, columns_left, m[0], m[1]);
      }
  }
  for (int c = 0; c < d; ++c) expand_along<N>(a[0], minors.sub[0], c, minors.top[c][0], minors.top[c][1]);
  minors.ready = true;
}

// float_form for d = N: loops of fixed length (a run-time d made the 4D form a quarter slower
// once 5D was added: 4D sphere, 5 000 points, time_search 0.284 -> 0.352 s). Up to 8D: the
// Laplace expansions grow as (d - 1)!, and while they were made per candidate, 8D's cost more
// than GMP's Bareiss (sphere, 80 points: time_total 17.4 s with GMP, 28.0 s in floating
// point); 6D and 7D won (500 points in 6D: 8.23 -> 1.45 s; 200 in 7D: 17.4 -> 6.46 s). With
// the facet's minors made once per facet (FacetMinors), 8D wins too (time_search 38.4 s with
// GMP, 12.8 s in floating point, same run of a slower machine).
template <int N>
bool float_form_fixed(const ShellSphere& sphere, const double* f0, double s0, const double* const* rows, const double* row_offsets,
                      FloatForm& form, FacetMinors* minors) {
  constexpr int d = N;
  // With S_x = |x - g|^2 - rho, |x - f0|^2 = (S_x - S_0) - 2 (f0 - g) . (x - f0): the lift
  // column less a combination of the spatial ones, so the lifted determinant is
  //   det[p_i - f0, S_i - S_0 (i = 1..d); x - f0, S_x - S_0].
  // Along its last row, with A the d x d matrix of the p_i - f0 and s_i = S_i - S_0:
  //   b = -adj(A) s,  lift = det A,  constant = -b . (f0 - g) - lift S_0.
  // On points near the sphere the s_i are tiny and b is computed to a few units of its own
  // terms, where the exact form's cofactors cancel. (The stored offsets' errors, u |s| + eta,
  // are a few hundred units of an offset: far below what the shell's tests resolve.)
  // Error bounds, each against the exact coefficients (exact points and offsets):
  //   the entries a = fl(p - f0) are within u |a| (1 + u); an adjugate entry alpha (a
  //   (d - 1)-minor by Laplace expansion) within gamma(m) of its absolute tree tau, m =
  //   laplace_roundings(d - 1, 1);
  //   e_i >= |fl(s_i - s_0) - (S_i - S_0)| = 1.01 u |s^_i| + u (|s_i| + |s_0|) + 2 eta;
  //   |B_c - b_c| <= gamma(d + m + 2) sum tau |s^| + (1 + gamma(m + 2)) sum tau e;
  //   |W - lift| <= gamma(laplace_roundings(d, 1)) sum |a| tau over the candidate's row (W is
  //   A's Laplace expansion along that row);
  //   K: the sum's roundings, the b and y0 errors, W's error and the offset S_0's error.
  // Each bound is evaluated with a margin for its own roundings.
  constexpr double u = geometry::kUnitRoundoff;
  const double eta = sphere.eta;
  double a[N][N], sh[N], e[N];
  for (int i = 0; i < d; ++i) {
    const double* p = rows[i];
    for (int c = 0; c < d; ++c) a[i][c] = p[c] - f0[c];
    const double si = row_offsets[i];
    sh[i] = si - s0;
    e[i] = (1.01 * u * std::fabs(sh[i]) + u * (std::fabs(si) + std::fabs(s0)) + 2 * eta) * (1 + 8 * u);
  }
  double alpha[N][N], tau[N][N];  // adj(A)[c][i] = cofactor (i, c)
  if constexpr (N == 2) {
    alpha[0][0] = a[1][1], alpha[0][1] = -a[0][1], alpha[1][0] = -a[1][0], alpha[1][1] = a[0][0];
    for (int c = 0; c < 2; ++c)
      for (int i = 0; i < 2; ++i) tau[c][i] = std::fabs(alpha[c][i]);
  } else if constexpr (N == 3) {  // the cofactors by cyclic indices (the sign comes with them)
    for (int c = 0; c < 3; ++c)
      for (int i = 0; i < 3; ++i) {
        const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, c1 = (c + 1) % 3, c2 = (c + 2) % 3;
        alpha[c][i] = a[i1][c1] * a[i2][c2] - a[i1][c2] * a[i2][c1];
        tau[c][i] = std::fabs(a[i1][c1]) * std::fabs(a[i2][c2]) + std::fabs(a[i1][c2]) * std::fabs(a[i2][c1]);
      }
  } else {  // d = 4 to 8: the cofactors as (d - 1) x (d - 1) minors
    // Without the candidate's row (i = d - 1): a minor of the facet's rows. With it, the
    // minor's rows are taken candidate first (d - 2 swaps: the sign (-1)^d), and its Laplace
    // expansion along that row runs over (d - 2)-minors of the facet's rows. Either way the
    // value is minor_of's for those rows (the bound below holds for any row order: the tree
    // is the same), and the facet's minors are computed once per facet (FacetMinors).
    FacetMinors local;
    if (minors == nullptr) minors = &local;
    if (!minors->ready) fill_facet_minors<N>(a, *minors);
    for (int c = 0; c < d; ++c) {
      for (int i = 0; i < d - 1; ++i) {
        double value = 0.0, tree = 0.0;
        expand_along<N>(a[d - 1], minors->sub[i], c, value, tree);
        if (d % 2) value = -value;
        alpha[c][i] = (i + c) % 2 ? -value : value;
        tau[c][i] = tree;
      }
      const double value = minors->top[c][0];
      alpha[c][d - 1] = (d - 1 + c) % 2 ? -value : value;
      tau[c][d - 1] = minors->top[c][1];
    }
  }
  const int m = geometry::laplace_roundings(d - 1, 1);
  const double margin = 1 + geometry::gamma_bound(4 * d + 4);
  double b_sum = 0.0, b_err_sum = 0.0;
  for (int c = 0; c < d; ++c) {
    double v = 0.0, t = 0.0, r = 0.0;
    for (int i = 0; i < d; ++i) {
      v += alpha[c][i] * sh[i];
      t += tau[c][i] * std::fabs(sh[i]);
      r += tau[c][i] * e[i];
    }
    form.b[c] = -v;
    const double err = (geometry::gamma_bound(d + m + 2) * t + (1 + geometry::gamma_bound(m + 2)) * r) * margin;
    form.b_err[c] = err;
    b_sum += std::fabs(v);
    b_err_sum += err;
  }
  double w = 0.0, w_tree = 0.0;
  for (int c = 0; c < d; ++c) {
    w += a[d - 1][c] * alpha[c][d - 1];
    w_tree += std::fabs(a[d - 1][c]) * tau[c][d - 1];
  }
  const double w_err = geometry::gamma_bound(geometry::laplace_roundings(d, 1)) * w_tree * margin;
  const double* g = sphere.centre;
  double k = -w * s0, k_tree = std::fabs(w) * std::fabs(s0), k_err = 0.0;
  for (int c = 0; c < d; ++c) {
    const double y0 = f0[c] - g[c];
    const double b = form.b[c];
    k -= b * y0;
    k_tree += std::fabs(b) * std::fabs(y0);
    k_err += (form.b_err[c] + 1.01 * u * (std::fabs(b) + form.b_err[c])) *
             std::fabs(y0) * (1 + 2 * u);
  }
  k_err = (k_err + geometry::gamma_bound(d + 3) * k_tree + w_err * std::fabs(s0) + (std::fabs(w) + w_err) * (u * std::fabs(s0) + eta)) * margin;
  if (!(k_tree + k_err < geometry::kFilterOverflow && std::fabs(w) + b_sum < geometry::kFilterOverflow)) return false;
  constexpr double kSmall = 0x1p-30;  // the bounds' share of their terms that keeps the shell's tests sharp
  if (!(w_err <= kSmall * std::fabs(w) && b_err_sum <= kSmall * b_sum && k_err <= kSmall * (k_tree + std::fabs(k)))) return false;
  form.lift = w;
  form.constant = k;
  form.lift_err = w_err;
  form.constant_err = k_err;
  form.b_err_sum = b_err_sum;
  return true;
}
}  // namespace

bool float_form(const ShellSphere& sphere, int d, const double* f0, double s0, const double* const* rows, const double* row_offsets,
                FloatForm& form, FacetMinors* minors) {
  switch (d) {
    case 2: return float_form_fixed<2>(sphere, f0, s0, rows, row_offsets, form, minors);
    case 3: return float_form_fixed<3>(sphere, f0, s0, rows, row_offsets, form, minors);
    case 4: return float_form_fixed<4>(sphere, f0, s0, rows, row_offsets, form, minors);
    case 5: return float_form_fixed<5>(sphere, f0, s0, rows, row_offsets, form, minors);
    case 6: return float_form_fixed<6>(sphere, f0, s0, rows, row_offsets, form, minors);
    case 7: return float_form_fixed<7>(sphere, f0, s0, rows, row_offsets, form, minors);
    case 8: return float_form_fixed<8>(sphere, f0, s0, rows, row_offsets, form, minors);
    default: return false;
  }
}

}  // namespace drange::engine
