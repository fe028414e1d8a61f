// SPDX-License-Identifier: LGPL-2.1-or-later
// A mesh kept across small wear updates (PinBushingModel::update_profiles, 'Remesh
// depth'): the worn profiles enter the gaps, the compliance stays the meshed bodies'.
// Against a fresh mesh of the worn profiles (the exact path) at the loads of the
// nine-bar joints, and the sharing of one model by the pool.
#include "fe/model_pool.h"
#include "fe_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

using namespace wearlink;
using namespace wearlink::fe;
using namespace wearlink::fe::testing;

// 4 µm of bore wear and 2 µm of pin wear on 50 µm elements (drift 0.08 elements): the
// kept mesh reproduces the re-meshed pair's peak pressure and pin displacement at 1 kN
// and 10 kN to within 10 % of what the wear itself changed (the dent makes the
// contact conformal: the peak drops by ~10 %), and to 1 % absolutely. Measured: peak
// 104.54 kept / 104.05 re-meshed / 115.31 round MPa at 1 kN, 336.98 / 336.26 / 371.21
// at 10 kN; the pin positions agree to 2e-9 m.
TEST(FeKeptMesh, WornProfilesThroughTheGapsMatchARemesh)
{
  const auto      worn = dented_pair(4e-6, 2e-6);
  const auto      s    = settings_about_minus_y(50e-6, 40);
  PinBushingModel kept(steel_pair(), s, mesh_file("kept_round"));
  PinBushingModel remeshed(worn, s, mesh_file("kept_worn"));
  EXPECT_NEAR(kept.profile_drift(worn.bore, worn.pin), 4e-6, 1e-12);
  for (const double F : {1e3, 1e4})
    {
      const auto round = kept.solve(load_minus_y(F), SolverKind::condensed);
      kept.update_profiles(worn.bore, worn.pin);
      const auto a = kept.solve(load_minus_y(F), SolverKind::condensed);
      const auto b = remeshed.solve(load_minus_y(F), SolverKind::condensed);
      kept.update_profiles(steel_pair().bore, steel_pair().pin);
      const double wear_effect = std::abs(b.peak_pressure - round.peak_pressure);
      const double kept_error  = std::abs(a.peak_pressure - b.peak_pressure);
      const double y_effect    = std::abs(b.pin_displacement[1] - round.pin_displacement[1]);
      const double y_error     = std::abs(a.pin_displacement[1] - b.pin_displacement[1]);
      std::cout << F << " N: peak round " << round.peak_pressure / 1e6 << ", kept " << a.peak_pressure / 1e6
                << ", re-meshed " << b.peak_pressure / 1e6 << " MPa; pin y round " << round.pin_displacement[1]
                << ", kept " << a.pin_displacement[1] << ", re-meshed " << b.pin_displacement[1] << " m\n";
      EXPECT_LT(a.equilibrium_relative_residual, 1e-9);
      if (F == 1e3)
        {
          EXPECT_GT(wear_effect, 0.05 * round.peak_pressure) << "the dent must matter for the test to mean anything";
        }
      EXPECT_LT(kept_error, 0.1 * wear_effect);
      EXPECT_LT(kept_error, 0.01 * b.peak_pressure);
      EXPECT_LT(y_error, 0.1 * y_effect);
    }
}

// The pool hands one model to every holder of the same set-up within 'Remesh depth', sets
// its profiles to each holder's, and meshes anew beyond that depth or for another set-up.
TEST(FeKeptMesh, PoolSharesWithinTheRemeshDepth)
{
  auto s            = settings_about_minus_y(100e-6, 30);
  s.remesh_depth    = 0.5; // 50 µm
  bool       reused = true;
  const auto first  = shared_model(steel_pair(), s, &reused);
  EXPECT_FALSE(reused);
  const auto worn   = dented_pair(20e-6, 10e-6);
  const auto second = shared_model(worn, s, &reused);
  EXPECT_TRUE(reused);
  EXPECT_EQ(first, second);
  EXPECT_EQ(second->current_geometry().bore.samples(), worn.bore.samples());
  EXPECT_EQ(second->meshed_geometry().bore.samples(), steel_pair().bore.samples());
  const auto deep = shared_model(dented_pair(80e-6, 0), s, &reused);
  EXPECT_FALSE(reused) << "80 µm > 0.5 × 100 µm";
  auto other     = s;
  other.degree   = 2;
  const auto deg = shared_model(steel_pair(), other, &reused);
  EXPECT_FALSE(reused) << "another set-up";
  s.remesh_depth = 0;
  EXPECT_FALSE(within_reach(*first, worn, s)) << "depth 0: only the meshed profiles themselves";
  EXPECT_TRUE(within_reach(*first, steel_pair(), s));
}
