// SPDX-License-Identifier: LGPL-2.1-or-later
// The closed-form cylindrical contact relations (contact/cylindrical_contact.h) and the
// tables the `johnson` and `esdu-78035` laws evaluate. Pair: the nine-bar joints (steel,
// R1 = 12 mm, c = 0.5 mm, L = 10 mm).
#include "base/numbers.h"
#include "contact/cylindrical_contact.h"
#include "steel_pair.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace wearlink;
using namespace wearlink::contact;

using contact::testing::steel_pair;

// The two laws differ only in the bracket's constant (−1 Johnson, +1 ESDU-78035): at any
// load ESDU's approach exceeds Johnson's by exactly 2P/(π E*). The force at an approach
// inverts the approach at a force.
TEST(CylindricalContact, JohnsonAndEsduDifferByTheBracketConstantAndInvert)
{
  const auto pair = CylinderPair::of(steel_pair());
  for (const double F : {10.0, 1e3, 1e5})
    {
      const double P  = F / pair.axial_length;
      const double dj = cylindrical_approach(CylindricalLaw::johnson, pair, F);
      const double de = cylindrical_approach(CylindricalLaw::esdu_78035, pair, F);
      EXPECT_NEAR(de - dj, 2 * P / (numbers::pi * pair.effective_modulus), 1e-12 * de);
      EXPECT_NEAR(cylindrical_force(CylindricalLaw::johnson, pair, dj) / F, 1.0, 1e-9);
      EXPECT_NEAR(cylindrical_force(CylindricalLaw::esdu_78035, pair, de) / F, 1.0, 1e-9);
    }
  // Beyond the valid range the law has no force to give.
  const double top = cylindrical_valid_max_force(CylindricalLaw::johnson, pair);
  EXPECT_TRUE(std::isnan(
    cylindrical_force(CylindricalLaw::johnson, pair, 2 * cylindrical_approach(CylindricalLaw::johnson, pair, top))));
}

// The tables the laws evaluate reproduce the closed forms between their nodes (60 levels
// from 1 N to the valid maximum) to 0.1 %.
TEST(CylindricalContact, TableReproducesTheClosedForm)
{
  const auto pair = CylinderPair::of(steel_pair());
  for (const auto law : {CylindricalLaw::johnson, CylindricalLaw::esdu_78035})
    {
      const ForceApproachTable t = tabulate_cylindrical_law(law, pair, 1.0, 60);
      const auto              &F = t.forces();
      for (std::size_t k = 0; k + 1 < F.size(); ++k)
        {
          const double Fm = std::sqrt(F[k] * F[k + 1]);
          EXPECT_NEAR(t.evaluate(cylindrical_approach(law, pair, Fm), 0, 0).force / Fm, 1.0, 1e-3) << Fm << " N";
        }
    }
}

// The linear Winkler layer on round profiles against a direct quadrature of
// ∫ E_c/h (e cos φ − c) cos φ L R1 dφ over the overlapping arc.
TEST(CylindricalContact, WinklerRoundForceIsTheFoundationIntegral)
{
  const auto   g  = steel_pair();
  const double h  = 1e-3;
  const double nu = 0.3, Ef = 207e9 * (1 - nu) / ((1 + nu) * (1 - 2 * nu)), Ec = Ef / 2;
  for (const double delta : {1e-7, 1e-6, 1e-5})
    {
      const double c = 0.5e-3, e = c + delta, phi0 = std::acos(c / e);
      const int    n = 200000;
      double       F = 0;
      for (int i = 0; i < n; ++i)
        {
          const double phi = -phi0 + (i + 0.5) * 2 * phi0 / n;
          F += Ec / h * (e * std::cos(phi) - c) * std::cos(phi) * g.axial_length * 0.012 * (2 * phi0 / n);
        }
      EXPECT_NEAR(winkler_round_force(g, h, delta) / F, 1.0, 1e-6) << delta;
    }
}
