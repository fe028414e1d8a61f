// SPDX-License-Identifier: LGPL-2.1-or-later
// Every constraint's analytic Jacobian Φq, time derivative Φt and acceleration
// right-hand side γ against finite differences, at random states, with the body on
// side i both moving and ground.
//   Φq: central differences of Φ in each coordinate, error O(h²) ≈ 1e-10 at h = 1e-5;
//   γ:  Φq q̈ = γ must hold for the second time derivative of Φ along the motion
//       q(τ) = q + v τ + ½ a τ², i.e. γ = d²Φ/dτ² − Φq a at τ = 0 (with a = 0:
//       γ = d²Φ/dτ²), by central second differences, error O(h²) ≈ 1e-6 at h = 1e-4.
#include "mbs/constraint.h"

#include <gtest/gtest.h>

#include <functional>
#include <memory>
#include <random>

using namespace wearlink::mbs;

namespace
{
  struct Case
  {
    std::string                                  name;
    std::function<std::unique_ptr<Constraint>()> make;
  };

  std::vector<Case>
  cases()
  {
    return {
      {"revolute",
       [] {
         return make_revolute("r", 0, Vec2(0.1, -0.2), 1, Vec2(-0.3, 0.05));
       }},
      {"revolute_ground",
       [] {
         return make_revolute("r", ground, Vec2(0.4, 0.1), 1, Vec2(-0.3, 0.05));
       }},
      {"revolute_offset",
       [] {
         return make_revolute("r", 0, Vec2(0.1, 0), 1, Vec2(0, 0.02), Vec2(1e-4, -2e-4));
       }},
      {"translational",
       [] {
         return make_translational("t", 0, Vec2(0.1, 0.2), Vec2(1, 0.5), 1, Vec2(-0.1, 0.3), 0.4);
       }},
      {"translational_ground",
       [] {
         return make_translational("t", ground, Vec2(0.45, 0), Vec2(0, 1), 1, Vec2(0.01, 0), 1.5);
       }},
      {"fixed_angle",
       [] {
         return make_fixed_angle("f", 0, 1, 0.3);
       }},
      {"angle_driver",
       [] {
         return make_angle_driver("d", ground, 1, 5.7645, -12.566);
       }},
    };
  }

  /** Φ of constraint @p c at (t, q) with zero velocity. */
  std::vector<double>
  phi(const Constraint &c, double t, const std::vector<double> &q)
  {
    std::vector<double> v(q.size(), 0.0);
    ConstraintRows      r;
    c.evaluate(t, StateView(q.data(), v.data()), r);
    return std::vector<double>(r.phi, r.phi + r.n);
  }
} // namespace

TEST(Constraints, JacobianTimeDerivativeAndGammaMatchFiniteDifferences)
{
  std::mt19937                           rng(42);
  std::uniform_real_distribution<double> u(-1, 1);
  for (const auto &test : cases())
    for (int trial = 0; trial < 5; ++trial)
      {
        SCOPED_TRACE(test.name + " trial " + std::to_string(trial));
        const auto          c = test.make();
        std::vector<double> q(6), v(6);
        for (int i = 0; i < 6; ++i)
          {
            q[i] = u(rng);
            v[i] = 3 * u(rng);
          }
        const double   t = 0.7 * u(rng);
        ConstraintRows r;
        c->evaluate(t, StateView(q.data(), v.data()), r);

        // Φq by central differences.
        const double h = 1e-5;
        for (int i = 0; i < 6; ++i)
          {
            auto qp = q, qm = q;
            qp[i] += h;
            qm[i] -= h;
            const auto fp = phi(*c, t, qp), fm = phi(*c, t, qm);
            for (unsigned int k = 0; k < r.n; ++k)
              {
                const double fd   = (fp[k] - fm[k]) / (2 * h);
                const bool   on_i = i < 3;
                const double an   = on_i ? (c->body_i == ground ? 0.0 : r.jac_i[k][i]) : r.jac_j[k][i - 3];
                // Map: body 0 is coordinates 0..2, body 1 is 3..5.
                EXPECT_NEAR(an, fd, 1e-8) << "d phi_" << k << " / d q_" << i;
              }
          }

        // Φt and γ from the motion q(τ) = q + v τ at t + τ: dΦ/dτ = Φq v + Φt and
        // d²Φ/dτ² = (Φq v)_q v + 2 Φqt v + Φtt = −γ.
        const double hs = 1e-4;
        auto         at = [&](double tau) {
          std::vector<double> qq(6);
          for (int i = 0; i < 6; ++i)
            qq[i] = q[i] + v[i] * tau;
          return phi(*c, t + tau, qq);
        };
        const auto f0 = at(0), fp = at(hs), fm = at(-hs);
        for (unsigned int k = 0; k < r.n; ++k)
          {
            double jv = r.phi_t[k];
            for (int i = 0; i < 3; ++i)
              {
                jv += (c->body_i == ground ? 0.0 : r.jac_i[k][i]) * v[i];
                jv += r.jac_j[k][i] * v[3 + i];
              }
            EXPECT_NEAR(jv, (fp[k] - fm[k]) / (2 * hs), 1e-6) << "dPhi/dt row " << k;
            EXPECT_NEAR(-r.gamma[k], (fp[k] - 2 * f0[k] + fm[k]) / (hs * hs), 1e-4) << "gamma row " << k;
          }
      }
}

// The entries a constraint declares constant (Constraint::constant_jacobian) are folded
// into the Schur complement once: they must be the same, to the bit, at any state and
// time, and at the state the mechanism reads them from (q = 0, q̇ = 0, t = 0).
TEST(Constraints, DeclaredConstantJacobianEntriesDoNotChange)
{
  std::mt19937                           rng(7);
  std::uniform_real_distribution<double> u(-3, 3);
  int                                    n_declared = 0;
  for (const auto &test : cases())
    {
      SCOPED_TRACE(test.name);
      const auto          c = test.make();
      std::vector<double> zero(6, 0.0);
      ConstraintRows      rest;
      c->evaluate(0.0, StateView(zero.data(), zero.data()), rest);
      for (int trial = 0; trial < 20; ++trial)
        {
          std::vector<double> q(6), v(6);
          for (unsigned int k = 0; k < 6; ++k)
            {
              q[k] = u(rng);
              v[k] = u(rng);
            }
          ConstraintRows r;
          c->evaluate(u(rng), StateView(q.data(), v.data()), r);
          for (unsigned int row = 0; row < r.n; ++row)
            {
              const auto fixed = c->constant_jacobian(row);
              for (unsigned int d = 0; d < 3; ++d)
                if (fixed[d])
                  {
                    EXPECT_EQ(r.jac_i[row][d], rest.jac_i[row][d]) << "row " << row << " entry " << d;
                    EXPECT_EQ(r.jac_j[row][d], rest.jac_j[row][d]) << "row " << row << " entry " << d;
                    n_declared += trial == 0;
                  }
            }
        }
    }
  // revolute ×3: 2 rows × 2 entries; translational ×2: 3 entries of row 1; fixed-angle
  // and driver: 3 each. A library that declared nothing would pass the loop vacuously.
  EXPECT_EQ(n_declared, 3 * 4 + 2 * 3 + 3 + 3);
}
