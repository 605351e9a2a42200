// Tests of geometry/wide_determinant.hpp and wide_integer.hpp: every sign against GMP's.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "geometry/exact_matrix.hpp"
#include "geometry/wide_determinant.hpp"
#include "geometry/wide_integer.hpp"

namespace {

using drange::geometry::Frame;
using drange::geometry::Int128;
using drange::geometry::Wide;

mpz_class to_mpz(Int128 x) {
  const bool negative = x < 0;
  __extension__ unsigned __int128 m = negative ? -static_cast<unsigned __int128>(x) : static_cast<unsigned __int128>(x);
  mpz_class z = static_cast<unsigned long>(m >> 64);
  z <<= 64;
  z += static_cast<unsigned long>(m & ~0ul);
  return negative ? mpz_class(-z) : z;
}

template <int N>
mpz_class to_mpz(const Wide<N>& w) {
  mpz_class z = 0;
  for (int i = N - 1; i >= 0; --i) {
    z <<= 64;
    z += static_cast<unsigned long>(w.limb[i]);
  }
  if (w.negative()) z -= mpz_class(1) << (64 * N);
  return z;
}

Int128 random_int128(std::mt19937_64& rng, int bits) {
  __extension__ unsigned __int128 m = (static_cast<unsigned __int128>(rng()) << 64) | rng();
  if (bits < 128) m &= (static_cast<unsigned __int128>(1) << bits) - 1;
  const Int128 x = static_cast<Int128>(m);
  return (rng() & 1) ? -x : x;
}

TEST(WideInteger, SumsDifferencesAndProductsMatchGmp) {
  std::mt19937_64 rng(3);
  for (int trial = 0; trial < 20000; ++trial) {
    const int bits_a = 1 + static_cast<int>(rng() % 62), bits_b = 1 + static_cast<int>(rng() % 125);
    const Int128 a = random_int128(rng, bits_a), b = random_int128(rng, bits_b), c = random_int128(rng, 125);
    const Wide<1> wa = Wide<1>::from(a);
    const Wide<2> wb = Wide<2>::from(b), wc = Wide<2>::from(c);
    ASSERT_EQ(to_mpz(wa * wb), to_mpz(a) * to_mpz(b));
    ASSERT_EQ(to_mpz(wb + wc), to_mpz(b) + to_mpz(c));
    ASSERT_EQ(to_mpz(wb - wc), to_mpz(b) - to_mpz(c));
    const Wide<3> product = wa * wc;
    ASSERT_EQ(to_mpz(wb * product), to_mpz(b) * to_mpz(a) * to_mpz(c));
    ASSERT_EQ((wb * product).sign(), sgn(to_mpz(b) * to_mpz(a) * to_mpz(c)));
  }
}

// GMP's sign of the same determinants (exact_matrix.hpp): the reference.
int gmp_sign(const Frame& f, const double* const* points, bool lifted) {
  const int n = lifted ? f.k + 1 : f.k;
  drange::geometry::IntegerScale scale;
  for (int c = 0; c < f.dim; ++c) scale.include(f.base[c]);
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < f.dim; ++c) scale.include(points[r][c]);
  std::vector<mpz_class> a(static_cast<std::size_t>(n * n));
  for (int r = 0; r < n; ++r) {
    mpz_class lift = 0;
    for (int c = 0; c < f.dim; ++c) {
      const mpz_class delta = scale.integer(points[r][c]) - scale.integer(f.base[c]);
      lift += delta * delta;
    }
    for (int c = 0; c < f.k; ++c)
      a[static_cast<std::size_t>(r * n + c)] = scale.integer(points[r][f.axis(c)]) - scale.integer(f.base[f.axis(c)]);
    if (lifted) a[static_cast<std::size_t>(r * n + f.k)] = lift;
  }
  return sgn(drange::geometry::bareiss_determinant(a, n));
}

// Points of four kinds: decimal grids (0.1 k, 0.01 k), a cylindrical grid (r cos t, r sin t,
// z: ties that are not dyadic), random doubles near one point, and a few far apart or tiny
// (which the wide stage must decline).
std::vector<double> random_point(std::mt19937_64& rng, int dim, int kind) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> p(static_cast<std::size_t>(dim));
  for (int c = 0; c < dim; ++c) {
    double& x = p[static_cast<std::size_t>(c)];
    switch (kind) {
      case 0: x = 0.1 * static_cast<double>(rng() % 8); break;
      case 1: x = 0.01 * static_cast<double>(400 + rng() % 6); break;
      case 2: {
        const double r = 1.0 + 0.1 * static_cast<double>(rng() % 3), t = 2 * M_PI * static_cast<double>(rng() % 40) / 40;
        x = c == 0 ? r * std::cos(t) : c == 1 ? r * std::sin(t) : static_cast<double>(rng() % 4) / 49;
        break;
      }
      case 3: x = 0.5 + 1e-3 * u(rng); break;
      default: x = (rng() & 1) ? 1e-30 * u(rng) : 1e10 * u(rng);
    }
  }
  return p;
}

TEST(WideDeterminant, SignsMatchGmpOnTiesAndNearTies) {
  std::mt19937_64 rng(7);
  int decided[2] = {0, 0}, decided_4d = 0, zeros = 0, declined = 0;
  for (int trial = 0; trial < 40000; ++trial) {
    const int dim = 2 + static_cast<int>(rng() % 3), kind = static_cast<int>(rng() % 5);
    const bool lifted = (rng() & 1) != 0;
    const int k = lifted ? 2 + static_cast<int>(rng() % (dim - 1)) : 1 + static_cast<int>(rng() % dim);
    const int n = lifted ? k + 1 : k;
    std::vector<std::vector<double>> coords;
    for (int i = 0; i <= n; ++i) coords.push_back(random_point(rng, dim, kind));
    std::vector<const double*> rows;
    for (int i = 1; i <= n; ++i) rows.push_back(coords[static_cast<std::size_t>(i)].data());
    const int axes[4] = {dim - 1, 0, 1, 2};  // projected frames take the axes out of order
    const Frame f{dim, k, (k < dim && (rng() & 1)) ? axes : nullptr, coords[0].data()};
    const std::optional<int> s = lifted ? drange::geometry::wide_lifted_sign(f, rows.data())
                                        : drange::geometry::wide_orientation(f, rows.data());
    if (!s) {
      ++declined;
      continue;
    }
    ASSERT_EQ(*s, gmp_sign(f, rows.data(), lifted)) << "trial " << trial << " kind " << kind << " lifted " << lifted << " k " << k << " dim " << dim << " axes " << (f.axes != nullptr) << " base " << coords[0][0] << "," << coords[0][1] << " p1 " << coords[1][0] << "," << coords[1][1];
    ++decided[lifted];
    if (dim == 4) ++decided_4d;
    if (*s == 0) ++zeros;
  }
  // Every kind but the last is decided, ties among them (the grids): with this seed 15 924
  // orientations and 14 812 lifted determinants decided (9 916 of them in 4D), 1 346 zeros,
  // 9 264 declined.
  EXPECT_GT(decided[0], 13000);
  EXPECT_GT(decided[1], 12000);
  EXPECT_GT(decided_4d, 8000);
  EXPECT_GT(zeros, 1000);
  EXPECT_GT(declined, 7000);
}

// Coordinates within 2^61 of 0 on the multiples of 2^9 that doubles there have, one of them 1:
// in the unit 1, differences up to nearly 2^62, the largest the wide stage accepts, so every
// bound of its formulas is nearly reached.
std::vector<double> extreme_point(std::mt19937_64& rng, int dim) {
  std::vector<double> p(static_cast<std::size_t>(dim));
  for (double& x : p) x = ((rng() & 1) ? 1.0 : -1.0) * (std::ldexp(1.0, 61) - std::ldexp(static_cast<double>(rng() % (1u << 20)) + 1, 9));
  return p;
}

TEST(WideDeterminant, CofactorsGiveTheWholeDeterminantsSign) {
  // In 3D and 4D, a candidate's rows once, then many last points: the same sign as GMP's for
  // every point they accept, and they accept most (they decline a point with a lower set bit).
  std::mt19937_64 rng(9);
  int accepted[5] = {}, tested[5] = {}, zeros = 0;
  for (int trial = 0; trial < 6000; ++trial) {
    const int dim = 3 + trial % 2, kind = static_cast<int>(rng() % 5);  // kind 4: extreme_point
    const auto draw = [&] { return kind == 4 ? extreme_point(rng, dim) : random_point(rng, dim, kind); };
    std::vector<std::vector<double>> coords;
    for (int i = 0; i <= dim; ++i) coords.push_back(draw());
    if (kind == 4) coords[0][0] = 1.0;  // the unit 1
    std::vector<const double*> rows;
    for (int i = 1; i <= dim; ++i) rows.push_back(coords[static_cast<std::size_t>(i)].data());
    rows.push_back(nullptr);  // the last row: each point in turn
    const Frame f{dim, dim, nullptr, coords[0].data()};
    drange::geometry::WideLiftedCofactors cofactors;
    if (!cofactors.prepare(f, rows.data())) continue;
    for (int j = 0; j < 10; ++j) {
      const std::vector<double> x = draw();
      rows.back() = x.data();
      ++tested[kind];
      const std::optional<int> s = cofactors.sign_with(x.data());
      if (!s) continue;
      ++accepted[kind];
      if (*s == 0) ++zeros;
      ASSERT_EQ(*s, gmp_sign(f, rows.data(), true)) << "trial " << trial << " kind " << kind << " dim " << dim;
    }
  }
  // With this seed, accepted of tested by kind: 11 410 of 12 020, 12 010 of 12 010, 7 096 of
  // 8 210, 11 830 of 11 830, 12 150 of 12 150 (the extremes); 642 ties.
  for (int kind : {0, 1, 2, 4}) EXPECT_GT(accepted[kind], tested[kind] * 3 / 4) << "kind " << kind;
  EXPECT_GT(zeros, 500);
}
TEST(WideDeterminant, FiveToSevenDimensionalSignsMatchGmp) {
  // 5 x 5 to 7 x 7 orientations, 6 x 6 to 8 x 8 lifted determinants, whole (wide_orientation,
  // wide_lifted_sign) and by a candidate's cofactors, and orientations by a facet's cofactors
  // (6D, 7D), on the kinds above and on extremes.
  for (const int dim : {5, 6, 7}) {
    std::mt19937_64 rng(11);
    int decided[2] = {0, 0}, accepted = 0, tested = 0, zeros = 0, plane_accepted = 0, plane_tested = 0, plane_zeros = 0;
    int reused_accepted = 0;
    drange::geometry::WideLiftedCofactors reused;  // kept across the trials too
    for (int trial = 0; trial < 3000; ++trial) {
      const int kind = static_cast<int>(rng() % 6);
      // Kind 5: corners of a box of decimal sides, all on one sphere (every lifted determinant
      // a tie) and many on one hyperplane.
      const auto corner = [&] {
        std::vector<double> p(static_cast<std::size_t>(dim));
        for (double& x : p) x = (rng() & 1) ? 0.3 : 0.7;
        return p;
      };
      const auto draw = [&] { return kind == 5 ? corner() : kind == 4 ? extreme_point(rng, dim) : random_point(rng, dim, kind); };
      std::vector<std::vector<double>> coords;
      for (int i = 0; i <= dim + 1; ++i) coords.push_back(draw());
      if (kind == 4) coords[0][0] = 1.0;  // the unit 1
      std::vector<const double*> rows;
      for (int i = 1; i <= dim + 1; ++i) rows.push_back(coords[static_cast<std::size_t>(i)].data());
      const Frame f{dim, dim, nullptr, coords[0].data()};
      for (const bool lifted : {false, true}) {
        const std::optional<int> s = lifted ? drange::geometry::wide_lifted_sign(f, rows.data())
                                            : drange::geometry::wide_orientation(f, rows.data());
        if (!s) continue;
        ASSERT_EQ(*s, gmp_sign(f, rows.data(), lifted)) << "dim " << dim << " trial " << trial << " kind " << kind << " lifted " << lifted;
        ++decided[lifted];
        if (*s == 0) ++zeros;
      }
      // A facet's orientation cofactors (6D, 7D): rows 0 .. dim - 2, then x as row dim - 1.
      drange::geometry::WideOrientationCofactors plane;
      if (dim >= drange::geometry::WideOrientationCofactors::kMinDim && plane.prepare(f, rows.data())) {
        std::vector<const double*> plane_rows(rows.begin(), rows.begin() + dim);
        for (int j = 0; j < 5; ++j) {
          const std::vector<double> x = draw();
          plane_rows.back() = x.data();
          ++plane_tested;
          const std::optional<int> s = plane.sign_with(x.data());
          if (!s) continue;
          ++plane_accepted;
          if (*s == 0) ++plane_zeros;
          ASSERT_EQ(*s, gmp_sign(f, plane_rows.data(), false)) << "dim " << dim << " trial " << trial << " kind " << kind;
        }
      }
      // One object for the trial's candidates: from 5D the facet's part of the table is kept
      // between them (prepare_from_facet), so later candidates take that path.
      {
        std::vector<const double*> lifted_rows = rows;
        for (int j = 0; j < 3; ++j) {
          const std::vector<double> candidate = draw(), x = draw();
          lifted_rows[static_cast<std::size_t>(dim - 1)] = candidate.data();
          lifted_rows.back() = x.data();
          if (!reused.prepare(f, lifted_rows.data())) continue;
          const std::optional<int> s = reused.sign_with(x.data());
          if (!s) continue;
          ++reused_accepted;
          ASSERT_EQ(*s, gmp_sign(f, lifted_rows.data(), true)) << "dim " << dim << " trial " << trial << " kind " << kind << " candidate " << j;
        }
      }
      drange::geometry::WideLiftedCofactors cofactors;
      if (!cofactors.prepare(f, rows.data())) continue;
      for (int j = 0; j < 5; ++j) {
        const std::vector<double> x = draw();
        rows.back() = x.data();
        ++tested;
        const std::optional<int> s = cofactors.sign_with(x.data());
        if (!s) continue;
        ++accepted;
        if (*s == 0) ++zeros;
        ASSERT_EQ(*s, gmp_sign(f, rows.data(), true)) << "dim " << dim << " trial " << trial << " kind " << kind;
      }
    }
    // With this seed, in 5D: 2 819 orientations and 2 793 lifted determinants decided whole,
    // 13 950 of 14 095 tests by cofactors, 3 207 zeros; in 6D 2 770, 2 741, 13 740 of 13 850
    // and 3 077; in 7D 2 755, 2 740, 13 643 of 13 775 and 3 324. By a facet's cofactors: in 6D
    // 13 981 of 14 105, 1 431 zeros; in 7D 13 844 of 13 965, 1 273.
    EXPECT_GT(decided[0], 2000) << "dim " << dim;
    EXPECT_GT(decided[1], 2000) << "dim " << dim;
    EXPECT_GT(accepted, tested * 9 / 10) << "dim " << dim;
    EXPECT_GT(zeros, 2000) << "dim " << dim;
    if (dim >= drange::geometry::WideOrientationCofactors::kMinDim) {
      EXPECT_GT(plane_accepted, plane_tested * 9 / 10) << "dim " << dim;
      EXPECT_GT(plane_zeros, 1000) << "dim " << dim;
    }
    EXPECT_GT(reused_accepted, 7000) << "dim " << dim;
  }
}
}  // namespace
