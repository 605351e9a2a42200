// tests/shell/shell_arithmetic_test.cpp: the lifted form about a sphere's centre against the
// lifted determinant, exactly: geometry::exact_lifted_form equal to it within the truncation
// of its coefficients, and float_form (delaunay/shell/shell_arithmetic.hpp) within its stated
// bounds of the exact form, with the facet's minors kept or not, from 2D to 8D.
#include <gtest/gtest.h>

#include <gmpxx.h>

#include <cmath>
#include <vector>

#include "geometry/predicates.hpp"
#include "shell/shell_inputs.hpp"

namespace {

using drange::Distribution;
using drange::PointCloud;
using namespace drange::test::shell;

TEST(SphereShell, LiftedFormEqualsTheLiftedDeterminant) {
  // det[r_1; ...; r_d; r_x] against b . (x - g) + lift (|x - g|^2 - rho) + constant, exactly,
  // with the coefficients' truncation (a relative 2^-52 each) as the only allowed difference.
  drange::test::TestRandom random(12);
  for (int d : {2, 3, 4, 6}) {
    for (int trial = 0; trial < 20; ++trial) {
      const PointCloud points = sphere(static_cast<std::size_t>(d + 2), d, 100 + static_cast<std::uint64_t>(trial), 1.5, 0.125,
                                       trial % 2 ? 1e-6 : 0.0);
      std::vector<double> g(static_cast<std::size_t>(d));
      for (double& c : g) c = 0.125 + (random.uniform() - 0.5) * 1e-9;
      const double rho = 2.25 * (1 + (random.uniform() - 0.5) * 1e-9);
      std::vector<const double*> rows;
      for (int i = 1; i <= d; ++i) rows.push_back(points.point(static_cast<std::size_t>(i)));
      const drange::geometry::Frame frame{d, d, nullptr, points.point(0)};
      std::vector<double> b(static_cast<std::size_t>(d));
      double lift = 0.0, constant = 0.0;
      ASSERT_TRUE(drange::geometry::exact_lifted_form(frame, rows.data(), g.data(), rho, b.data(), &lift, &constant));
      const double* x = points.point(static_cast<std::size_t>(d + 1));
      // The determinant, exactly.
      std::vector<mpq_class> m;
      for (int r = 0; r <= d; ++r) {
        const double* p = r < d ? rows[static_cast<std::size_t>(r)] : x;
        mpq_class lifted = 0;
        for (int k = 0; k < d; ++k) {
          const mpq_class delta = mpq_class(p[k]) - mpq_class(points.point(0)[k]);
          m.push_back(delta);
          lifted += delta * delta;
        }
        m.push_back(lifted);
      }
      const mpq_class det = drange::test::reference_determinant(m, d + 1);
      mpq_class form = mpq_class(constant), magnitude = abs(mpq_class(constant));
      for (int k = 0; k < d; ++k) {
        const mpq_class term = mpq_class(b[static_cast<std::size_t>(k)]) * (mpq_class(x[k]) - mpq_class(g[static_cast<std::size_t>(k)]));
        form += term;
        magnitude += abs(term);
      }
      const mpq_class offset_term = mpq_class(lift) * exact_offset(x, g.data(), d, rho);
      form += offset_term;
      magnitude += abs(offset_term);
      EXPECT_LE(abs(form - det), magnitude * mpq_class(0x1p-51)) << "d=" << d << " trial " << trial;
      EXPECT_EQ(sgn(form), sgn(det)) << "d=" << d << " trial " << trial;
    }
  }
}

TEST(SphereShell, FloatFormIsWithinItsBoundsOfTheExactForm) {
  // The exact coefficients from the lifted determinant's cofactors along x's row (C_c for the
  // spatial columns, C_L for the lift), rewritten around g: B_c = C_c - 2 C_L y0_c, W = C_L,
  // K = C_L (rho + |y0|^2) - C . y0 with y0 = f0 - g. Each float coefficient must be within
  // its bound of them; and most simplices must get a float form at all (2D to 8D).
  drange::test::TestRandom random(41);
  for (int d : {2, 3, 4, 5, 6, 7, 8}) {
    for (double noise : {0.0, 1e-12, 1e-9}) {
      const auto store = store_of(sphere(3000, d, 42 + static_cast<std::uint64_t>(d), 1.5, 0.25, noise));
      const drange::engine::SphereShell& shell = store.shell;
      ASSERT_TRUE(shell.active());
      int accepted = 0;
      const int trials = 200;
      for (int trial = 0; trial < trials; ++trial) {
        // d + 1 points near each other (a random point and the next ids, 1 to 13 apart:
        // neighbours in the tree), all within the store.
        const auto first = static_cast<std::int32_t>(random.uniform() * (store.size - 13 * d - 1));
        std::vector<std::int32_t> ids;
        for (int i = 0; i <= d; ++i) ids.push_back(first + i * (1 + trial % 13));
        const double* f0 = store.point(ids[0]);
        std::vector<const double*> rows;
        std::vector<double> row_offsets;
        for (int i = 1; i <= d; ++i) {
          rows.push_back(store.point(ids[static_cast<std::size_t>(i)]));
          row_offsets.push_back(shell.offset[static_cast<std::size_t>(ids[static_cast<std::size_t>(i)])]);
        }
        drange::engine::FloatForm form{};
        if (!drange::engine::float_form(shell.sphere(0), d, f0, shell.offset[static_cast<std::size_t>(ids[0])], rows.data(), row_offsets.data(),
                                        form))
          continue;
        ++accepted;
        {
          // The facet's minors kept from another candidate's form give this form bit for bit.
          drange::engine::FacetMinors minors;
          std::vector<const double*> other_rows = rows;
          std::vector<double> other_offsets = row_offsets;
          const std::int32_t other = ids[0] > 0 ? ids[0] - 1 : ids[static_cast<std::size_t>(d)] + 1;
          other_rows.back() = store.point(other);
          other_offsets.back() = shell.offset[static_cast<std::size_t>(other)];
          drange::engine::FloatForm first{}, again{};
          drange::engine::float_form(shell.sphere(0), d, f0, shell.offset[static_cast<std::size_t>(ids[0])], other_rows.data(), other_offsets.data(),
                                     first, &minors);
          ASSERT_TRUE(drange::engine::float_form(shell.sphere(0), d, f0, shell.offset[static_cast<std::size_t>(ids[0])], rows.data(),
                                                 row_offsets.data(), again, &minors));
          for (int c = 0; c < d; ++c) {
            EXPECT_EQ(again.b[c], form.b[c]) << "d=" << d << " trial " << trial;
            EXPECT_EQ(again.b_err[c], form.b_err[c]) << "d=" << d << " trial " << trial;
          }
          EXPECT_EQ(again.lift, form.lift);
          EXPECT_EQ(again.lift_err, form.lift_err);
          EXPECT_EQ(again.constant, form.constant);
          EXPECT_EQ(again.constant_err, form.constant_err);
        }
        // Cofactors of the last row of the (d + 1) x (d + 1) lifted matrix, exactly.
        std::vector<std::vector<mpq_class>> r(static_cast<std::size_t>(d));
        for (int i = 0; i < d; ++i) {
          mpq_class lift = 0;
          for (int k = 0; k < d; ++k) {
            const mpq_class delta = mpq_class(rows[static_cast<std::size_t>(i)][k]) - mpq_class(f0[k]);
            r[static_cast<std::size_t>(i)].push_back(delta);
            lift += delta * delta;
          }
          r[static_cast<std::size_t>(i)].push_back(lift);
        }
        std::vector<mpq_class> cofactor(static_cast<std::size_t>(d + 1));
        for (int j = 0; j <= d; ++j) {
          std::vector<mpq_class> minor;
          for (int i = 0; i < d; ++i)
            for (int c = 0; c <= d; ++c)
              if (c != j) minor.push_back(r[static_cast<std::size_t>(i)][static_cast<std::size_t>(c)]);
          const mpq_class m = drange::test::reference_determinant(minor, d);
          cofactor[static_cast<std::size_t>(j)] = ((d + j) % 2 == 0) ? m : mpq_class(-m);
        }
        const mpq_class& cl = cofactor[static_cast<std::size_t>(d)];
        mpq_class y0_2 = 0, k_exact = 0;
        for (int c = 0; c < d; ++c) {
          const mpq_class y0 = mpq_class(f0[c]) - mpq_class(shell.sphere(0).centre[c]);
          y0_2 += y0 * y0;
          k_exact -= cofactor[static_cast<std::size_t>(c)] * y0;
          const mpq_class b_exact = cofactor[static_cast<std::size_t>(c)] - 2 * cl * y0;
          ASSERT_LE(abs(mpq_class(form.b[c]) - b_exact), mpq_class(form.b_err[c])) << "d=" << d << " noise " << noise << " trial " << trial;
        }
        k_exact += cl * (mpq_class(shell.rho[0]) + y0_2);
        ASSERT_LE(abs(mpq_class(form.lift) - cl), mpq_class(form.lift_err)) << "d=" << d << " trial " << trial;
        ASSERT_LE(abs(mpq_class(form.constant) - k_exact), mpq_class(form.constant_err)) << "d=" << d << " trial " << trial;
      }
      EXPECT_GT(accepted, trials * 9 / 10) << "d=" << d << " noise " << noise;
    }
  }
}

}  // namespace
