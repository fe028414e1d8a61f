// SPDX-License-Identifier: LGPL-2.1-or-later
// Contract tests instantiated over every registered law (doc/contributing.md §8), and the
// restitution each dissipative normal law actually produces.
//
// Normal laws: zero force at zero penetration, never tensile, continuous in δ, and
// non-decreasing in δ at zero rate; the elastic part derives from the potential
// (F_el = dV/dδ, checked by central differences).
// Friction laws: the force opposes sliding and stays within μ F_n.
// Restitution: a mass hitting a wall with speed v0 through the contact law leaves with
// v1; for Lankarani–Nikravesh the hysteresis factor was derived for c_e near 1 and the
// literature reports effective restitution within a few per cent of c_e for c_e = 0.9
// (Flores et al., Mech. Mach. Theory 46 (2011)); Flores' law matches c_e more closely.
#include "base/parameters.h"
#include "contact/friction_law.h"
#include "contact/normal_force_law.h"
#include "plugin_support.h"
#include "steel_pair.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace wearlink;
using namespace wearlink::contact;

namespace
{
  /** Construct plugin @p name of @p registry with its required entries set. */
  template <class Interface>
  std::unique_ptr<Interface>
  make(const Registry<Interface> &registry, const std::string &name, double restitution = 0.9)
  {
    return contact::testing::make_plugin(registry,
                                         name,
                                         {{"Restitution coefficient", std::to_string(restitution)},
                                          {"Friction coefficient", "0.2"},
                                          // laws built from an FE model: a coarse one, no disk cache
                                          {"Surface element size", "2e-4"},
                                          {"Table cache", "false"}});
  }

  class NormalLawContract : public ::testing::TestWithParam<std::string>
  {
  };
  class FrictionLawContract : public ::testing::TestWithParam<std::string>
  {
  };
} // namespace

TEST_P(NormalLawContract, ZeroNonNegativeContinuousMonotoneAndConservative)
{
  const auto law = make(normal_force_laws(), GetParam());
  law->update_geometry(contact::testing::steel_pair()); // for laws built from the geometry
  const double K    = 7.97e10;                          // nine-bar joint, N/m^1.5
  auto         eval = [&](double d, double rate, double impact) {
    NormalContactInput in;
    in.penetration      = d;
    in.penetration_rate = rate;
    in.impact_velocity  = impact;
    in.stiffness        = K;
    NormalContactOutput out;
    law->evaluate(in, out);
    out.potential = law->potential(in);
    return out;
  };
  EXPECT_EQ(eval(0, 0.1, 0.1).force, 0.0);
  EXPECT_EQ(eval(0, -0.1, 0.1).force, 0.0);
  double previous = 0;
  for (double d = 1e-9; d < 1e-4; d *= 1.3)
    {
      for (double rate : {-1.0, -0.01, 0.0, 0.01, 1.0})
        EXPECT_GE(eval(d, rate, 0.05).force, 0.0) << "tensile at δ = " << d << ", δ̇ = " << rate;
      const double f = eval(d, 0, 0.05).force;
      EXPECT_GE(f, previous) << "decreasing at δ = " << d;
      // Continuity: a relative step of 1e-8 in δ changes F by O(1e-8) relatively.
      EXPECT_NEAR(eval(d * (1 + 1e-8), 0, 0.05).force, f, 1e-7 * f + 1e-12);
      // F_el = dV/dδ.
      const double h  = 1e-6 * d;
      const double dv = (eval(d + h, 0, 0.05).potential - eval(d - h, 0, 0.05).potential) / (2 * h);
      EXPECT_NEAR(dv, eval(d, 0, 0.05).elastic_force, 1e-6 * f);
      previous = f;
    }
  // The impact-velocity guard: a vanishing impact velocity must not blow the force up.
  const double guarded = eval(1e-6, 1e-3, 1e-15).force;
  EXPECT_TRUE(std::isfinite(guarded));
  EXPECT_LT(guarded, 10 * eval(1e-6, 0, 1).force);
}

TEST_P(FrictionLawContract, OpposesSlidingWithinCoulombBound)
{
  const auto   law = make(friction_laws(), GetParam());
  const double fn  = 100.0;
  for (double v : {-1.0, -1e-3, -1e-4, -1e-5, 0.0, 1e-5, 1e-4, 1.5e-4, 1e-3, 1.0})
    {
      const double ft = law->force(fn, v);
      EXPECT_LE(ft * v, 0.0) << "friction drives sliding at v = " << v;
      EXPECT_LE(std::abs(ft), law->coefficient() * fn * (1 + 1e-15));
    }
  EXPECT_NEAR(std::abs(law->force(fn, 1.0)), 0.2 * fn, 1e-12) << "full Coulomb at high speed";
}

INSTANTIATE_TEST_SUITE_P(AllRegistered,
                         NormalLawContract,
                         ::testing::ValuesIn(normal_force_laws().names()),
                         contact::testing::plugin_test_name);
INSTANTIATE_TEST_SUITE_P(AllRegistered,
                         FrictionLawContract,
                         ::testing::ValuesIn(friction_laws().names()),
                         contact::testing::plugin_test_name);

namespace
{
  /** Effective restitution of a mass hitting a wall through @p law at speed @p v0. */
  double
  effective_restitution(const NormalForceLaw &law, double v0)
  {
    const double m = 0.2, K = 7.97e10;
    double       d = 0, v = v0;
    // Contact duration ~ 2.9 (m²/(K² v0))^(1/5) ≈ 1e-4 s here: 1e-8 s steps resolve it.
    const double h   = 1e-8;
    auto         acc = [&](double dd, double vv) {
      if (dd <= 0)
        return 0.0;
      NormalContactInput  in{dd, vv, v0, K};
      NormalContactOutput out;
      law.evaluate(in, out);
      return -out.force / m;
    };
    for (int i = 0; i < 10000000; ++i)
      {
        const double k1v = acc(d, v), k1d = v;
        const double k2v = acc(d + 0.5 * h * k1d, v + 0.5 * h * k1v), k2d = v + 0.5 * h * k1v;
        const double k3v = acc(d + 0.5 * h * k2d, v + 0.5 * h * k2v), k3d = v + 0.5 * h * k2v;
        const double k4v = acc(d + h * k3d, v + h * k3v), k4d = v + h * k3v;
        d += h / 6 * (k1d + 2 * k2d + 2 * k3d + k4d);
        v += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
        if (d < 0 && v < 0)
          return -v / v0;
      }
    return std::nan("");
  }
} // namespace

TEST(NormalLaws, EffectiveRestitution)
{
  for (double ce : {0.9, 0.7})
    {
      const double ln = effective_restitution(*make(normal_force_laws(), "lankarani-nikravesh", ce), 0.5);
      const double fl = effective_restitution(*make(normal_force_laws(), "flores", ce), 0.5);
      const double hz = effective_restitution(*make(normal_force_laws(), "hertz", ce), 0.5);
      std::cout << "c_e = " << ce << ": effective restitution L-N " << ln << ", Flores " << fl << ", Hertz " << hz
                << "\n";
      EXPECT_NEAR(hz, 1.0, 1e-6) << "Hertz is elastic";
      EXPECT_NEAR(fl, ce, 0.03 * ce) << "Flores' law is built to reproduce c_e";
      if (ce == 0.9)
        EXPECT_NEAR(ln, ce, 0.03 * ce) << "L-N is accurate for c_e near 1";
      else
        EXPECT_GT(ln, ce) << "L-N under-dissipates for lower c_e (known limitation)";
    }
}
