// delaunay/algorithm_choice.cpp: the direct search's work on a sample.
#include "delaunay/algorithm_choice.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "delaunay/search_options.hpp"
#include "delaunay/search_pipeline.hpp"
#include "delaunay/simplex_estimate.hpp"
#include "delaunay/triangulate.hpp"
#include "drange/errors.hpp"

namespace drange::engine {
namespace {

// The sample: one point in kSampleShare, from kSmallestSample to kLargestSample points. Below
// kSmallestSample the kd-tree has too few leaves (64 points each in 2D, 128 in 3D) for the
// search's work to show the input's shape; above kLargestSample the probe would only cost more.
constexpr std::size_t kSmallestSample = 2048;
constexpr std::size_t kLargestSample = 4096;
constexpr std::size_t kSampleShare = 8;
// Below this many points (the sample would be more than a quarter of them) the direct search
// runs without a probe.
constexpr std::size_t kSmallestProbed = 4 * kSmallestSample;

// Twice the work per simplex (kd-tree nodes entered plus points tested) of the direct search
// on 4096 uniform points in 2D and 3D (4.5 and 6.7).
double work_limit(int d) { return d == 2 ? 9.0 : 13.0; }
// The probe's direct search stops at this many times the limit (on points near a cube's faces
// it would otherwise cost as much as the incremental kernel's whole run).
constexpr double kBudgetOverLimit = 4.0;

// In 3D, a model of each construction's time per simplex from its counts on the sample, fitted by
// least squares to both constructions' one-thread times on 4096-point samples of uniform
// points, a sphere, an ellipsoid, a cylinder, a torus mesh and points near a cube's faces. The
// units are arbitrary; only the comparison counts. The direct search: a node entered costs
// three points tested. The incremental kernel: a conflict test costs about twice a step of the
// walk, and a sign the fast filters leave to the exact stages (near-ties: cospherical points)
// four conflict tests.
// `growth`: how much more search work per simplex the whole input takes than the sample.
double direct_cost(const Statistics& s, double growth) {
  return (0.46 * double(s.simplices) + growth * (0.031 * double(s.search_calls) + 0.010 * double(s.debug.points_tested))) /
         double(s.simplices);
}

double work_per_simplex(const Statistics& s) { return double(s.search_calls + s.debug.points_tested) / double(s.simplices); }

// The search work per simplex of n points over that of m, extrapolated from the sample's (m
// points) and a quarter of it's: constant on points spread through space, growing as a power of
// n on surfaces (up to sqrt(n): a ball's band of kd-tree nodes). The exponent is kept within
// [0, 1/2].
double work_growth(double at_m, double at_quarter, std::size_t n, std::size_t m) {
  const double exponent = std::clamp(std::log(at_m / at_quarter) / std::log(4.0), 0.0, 0.5);
  return std::pow(double(n) / double(m), exponent);
}
double incremental_cost(const Statistics& s) {
  return (0.05 * double(s.simplices) + 0.040 * double(s.search_calls) + 0.073 * double(s.debug.points_tested) +
          0.31 * double(s.debug.unfiltered_tests)) /
         double(s.simplices);
}

}  // namespace

bool worth_probing(const PointStore& points) {
  return points.dim <= 3 && static_cast<std::size_t>(points.size) >= kSmallestProbed;
}

bool prefer_incremental(const PointStore& points, const std::vector<std::int32_t>& order) {
  const int d = points.dim;
  const auto n = static_cast<std::size_t>(points.size);
  const std::size_t m = std::clamp(n / kSampleShare, kSmallestSample, kLargestSample);
  // The coarsest rounds of the insertion order: a random sample drawn from the ranks.
  std::vector<double> coords;
  coords.reserve(m * static_cast<std::size_t>(d));
  for (std::size_t i = 0; i < m; ++i) {
    const double* p = points.point(order[i]);
    coords.insert(coords.end(), p, p + d);
  }
  Options options;
  options.threads = 1;
  options.compute_neighbors = false;
  try {
    const PointsView sample{coords.data(), m, d};
    // Far beyond the limit the model would choose the kernel too: the run stops there.
    const auto budget = static_cast<std::uint64_t>(kBudgetOverLimit * work_limit(d) * double(expected_simplices(d, m)));
    Statistics direct;
    try {
      direct = triangulate(sample, options, SearchOptions{}, Algorithm::direct, budget).stats;
    } catch (const WorkBudgetExceeded&) {
      return true;
    }
    if (direct.simplices == 0) return false;
    const double work = work_per_simplex(direct);
    if (work <= work_limit(d)) return false;
    // The direct search is slow here; in 3D the incremental kernel too, where the points are so
    // near one sphere that its signs need the exact stages (the direct search's sphere shell
    // decides those in floating point). Both on the sample, by the model, the direct search's
    // work extrapolated to n from the sample and its first quarter. (In 2D those signs are
    // 3 x 3 determinants, and the kernel stays the faster on a circle.)
    if (d == 2) return true;
    const Statistics quarter = triangulate(PointsView{coords.data(), m / 4, d}, options, SearchOptions{}).stats;
    const double growth = quarter.simplices == 0 ? 1.0 : work_growth(work, work_per_simplex(quarter), n, m);
    const Statistics incremental = triangulate(sample, options, SearchOptions{}, Algorithm::incremental).stats;
    return direct_cost(direct, growth) > incremental_cost(incremental);
  } catch (const DegenerateInputError&) {
    // A sample in one hyperplane: most points are (a plateau, a circle and its poles).
    return true;
  }
}

}  // namespace drange::engine
