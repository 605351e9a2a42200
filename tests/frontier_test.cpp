// Tests of the driver's guard against a runaway search (delaunay/frontier.hpp,
// delaunay/simplex_estimate.hpp): simplex_upper_bound is the upper bound theorem's count, valid
// on the inputs with the most simplices, and a frontier fed wrong apexes stops with an
// InternalError instead of searching while memory lasts.
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "delaunay/derived_facets.hpp"
#include "delaunay/facet_queue.hpp"
#include "delaunay/first_facet.hpp"
#include "delaunay/frontier.hpp"
#include "delaunay/simplex_estimate.hpp"
#include "drange/delaunay.hpp"
#include "drange/errors.hpp"

namespace {

using drange::engine::simplex_upper_bound;

// C(a, b) in integers (small arguments).
std::size_t choose(std::size_t a, std::size_t b) {
  if (b > a) return 0;
  std::size_t c = 1;
  for (std::size_t i = 1; i <= b; ++i) c = c * (a - b + i) / i;
  return c;
}

// The facets of the cyclic polytope C(n, d + 1), by the integer form of Gale's evenness count:
// D = 2m: C(n - m, m) + C(n - m - 1, m - 1); D = 2m + 1: 2 C(n - m - 1, m).
std::size_t cyclic_facets(int d, std::size_t n) {
  const int big_d = d + 1;
  const auto m = static_cast<std::size_t>(big_d / 2);
  if (big_d % 2 == 0) return choose(n - m, m) + choose(n - m - 1, m - 1);
  return 2 * choose(n - m - 1, m);
}

TEST(SimplexUpperBound, IsTheCyclicPolytopesFacetCountRoundedUpSlightly) {
  for (int d = 2; d <= 8; ++d)
    for (std::size_t n = static_cast<std::size_t>(d) + 2; n <= 60; ++n) {
      const std::size_t exact = cyclic_facets(d, n), bound = simplex_upper_bound(d, n);
      EXPECT_GE(bound, exact) << "d=" << d << " n=" << n;
      EXPECT_LE(bound, exact + 2) << "d=" << d << " n=" << n;
    }
  EXPECT_EQ(cyclic_facets(2, 100), 196u);  // 2n - 4
  EXPECT_EQ(cyclic_facets(3, 100), 4850u);  // n (n - 3) / 2
  EXPECT_EQ(simplex_upper_bound(3, 4), 1u);
  EXPECT_EQ(simplex_upper_bound(5, 6), 1u);
  // Large counts saturate rather than wrap.
  EXPECT_EQ(simplex_upper_bound(11, std::size_t{1} << 30), std::numeric_limits<std::size_t>::max());
  EXPECT_GT(simplex_upper_bound(3, 1000000), std::size_t{499998500000} - 1);
}

// Points on the moment curve (t, t^2, t^3) in 3D have nearly the most tetrahedra that n points
// can have: (n - 2)(n - 3) / 2 against the bound's n (n - 3) / 2. The guard must not trip there,
// and a bound smaller by n would.
TEST(SimplexUpperBound, HoldsOnTheMomentCurveWhereItIsNearlyReached) {
  for (int n : {8, 13, 21}) {
    std::vector<double> coords;
    for (int i = 0; i < n; ++i) {
      const double t = 1.0 + i / 4.0;
      coords.insert(coords.end(), {t, t * t, t * t * t});
    }
    drange::Options options;
    options.threads = 1;
    const drange::Triangulation result = drange::delaunay(drange::PointsView{coords.data(), static_cast<std::size_t>(n), 3}, options);
    const std::size_t simplices = result.simplices.size() / 4;
    EXPECT_LE(simplices, simplex_upper_bound(3, static_cast<std::size_t>(n))) << "n=" << n;
    EXPECT_GE(simplices + static_cast<std::size_t>(n), simplex_upper_bound(3, static_cast<std::size_t>(n))) << "n=" << n;
  }
}

// A frontier whose "search" always returns the smallest id outside the facet: the simplices
// overlap, facets closed long ago are opened again, and the queue never drains. The guard must
// stop it once there are more simplices than 2D points can have.
TEST(FrontierGuard, WrongApexesStopWithAnInternalError) {
  using drange::engine::FacetInfo;
  using drange::engine::FacetQueue;
  using drange::engine::Frontier;
  constexpr int d = 2;
  constexpr std::int32_t n = 7;
  drange::Triangulation result;
  const std::function<void(std::size_t)> no_progress;
  Frontier<FacetQueue> frontier(d, n, result, no_progress, FacetQueue(d));
  frontier.open_first(drange::engine::FirstFacet{{0, 1}, 1});
  std::vector<std::int32_t> ids(d), derived(drange::engine::derived_block_size(d));
  FacetInfo info{};
  bool stopped = false;
  std::string message;
  // Far more turns than a valid run takes (at most 2n - 4 simplices, 3 facets each): without
  // the guard the loop ends here, not in the frontier.
  for (int turn = 0; turn < 1000 && !frontier.queue_empty(); ++turn) {
    const bool closed = frontier.pop(ids.data(), info);
    if (!frontier.take(ids.data(), info, closed)) continue;
    std::int32_t apex = 0;
    while (apex == ids[0] || apex == ids[1]) ++apex;
    drange::engine::derive_other_facets(ids.data(), info.sigma, apex, d, derived.data());
    try {
      frontier.close(ids.data(), info, apex, derived.data());
    } catch (const drange::InternalError& e) {
      stopped = true;
      message = e.what();
      break;
    }
  }
  ASSERT_TRUE(stopped) << "the frontier kept going with " << result.simplices.size() / 3 << " simplices";
  EXPECT_EQ(result.simplices.size() / 3, simplex_upper_bound(d, n));
  EXPECT_NE(message.find("wrong apex"), std::string::npos) << message;
  EXPECT_NE(message.find("7 points in 2 dimensions"), std::string::npos) << message;
}

}  // namespace
