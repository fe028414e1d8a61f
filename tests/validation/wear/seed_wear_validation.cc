// SPDX-License-Identifier: LGPL-2.1-or-later
// The seed's wear results, as far as they can be checked (doc/models.md §4, §6.2):
//  1. Experiment (§4.3, params/nine_bar_experiment.prm): the Al pin of joint A lost
//     6.3 mg over 50,000 revolutions at ±90 rpm. The seed gives no wear coefficient.
//     The literature range for dry sliding of aluminium alloys against steel is
//     k_D ≈ 1e-4 … 7e-2 mm³/(N m) (doc/models.md §4 [lit]: mild to severe regimes);
//     nothing in this test is taken from the 6.3 mg. Two runs at the literature's
//     lower end k_lo = 1e-4 and at 2 k_lo give the mass loss per unit k_D, s, and
//     check Archard's proportionality through the coupled dynamics (the worn geometry
//     feeds back into the loads, so within 25 %, not exactly). The measured loss is
//     consistent with the literature if the coefficient it implies, 6.3 mg / s, lies in
//     [1e-4, 7e-2] mm³/(N m): the model must not predict more than 6.3 mg at the
//     least-wearing literature coefficient. (Upper-range coefficients wear the 0.2 mm
//     clearance pin through long before 50,000 revolutions, so the upper end is
//     reached by proportionality, not simulated.)
//  2. Simulation (§4.2.1, params/nine_bar_wear.prm): the seed reports that joint B
//     wears more than joint A. Asserted: B's worn volume (pin + bushing) exceeds A's.
#include "scene_support.h"
#include "workflows/wear/wear_run.h"

#include <gtest/gtest.h>

#include <iomanip>
#include <iostream>
#include <sstream>
#include <vector>

using namespace wearlink;

TEST(SeedWear, ExperimentPinMassLossImpliesALiteratureWearCoefficient)
{
  const double measured_mg = 6.3;
  const double k_lo = 1e-4, k_hi = 7e-2; // mm³/(N m), dry Al alloys on steel [lit]
  std::cout << "\nseed experiment (§4.3): Al pin, joint A, 0.2 mm, ±90 rpm, 50,000 revolutions; measured "
            << measured_mg
            << " mg\n  k_D [mm³/(N m)]   pin mass loss [mg]   per k_D [mg/(mm³/(N m))]   max depth [µm]   "
               "mean F_n [N]   sliding [m]\n";
  const std::vector<double> k_values = {k_lo, 2 * k_lo};
  std::vector<double>       per_k;
  for (const double k_mm : k_values)
    {
      const double       k = k_mm * 1e-9; // mm³/(N m) → m³/(N m)
      std::ostringstream set;
      set << std::setprecision(17) << "Joint A/Clearance/archard/Pin wear coefficient=" << k;
      auto                      scene = wearlink::testing::scene("params/nine_bar_experiment.prm", {set.str()});
      workflows::WearRunOptions o;
      o.progress      = false;
      o.final_outputs = false;
      const auto r    = workflows::run_wear(scene, o);
      ASSERT_EQ(r.state.revolutions, 50000.0);
      const auto  &h  = r.state.joints[0].history.back();
      const double mg = h.volume_pin * scene.wear[0]->archard.pin_density * 1e6;
      per_k.push_back(mg / k_mm);
      std::cout << std::setw(17) << k_mm << std::setw(21) << std::setprecision(4) << mg << std::setw(27) << mg / k_mm
                << std::setw(17) << h.max_depth_pin * 1e6 << std::setw(15) << h.mean_normal_force << std::setw(14)
                << h.sliding_distance << '\n';
    }
  EXPECT_NEAR(per_k[1], per_k[0], 0.25 * per_k[0]) << "Archard's proportionality through the coupled dynamics";
  const double implied = measured_mg / per_k[0];
  std::cout << "  implied k_D = " << implied << " mm³/(N m); literature " << k_lo << " … " << k_hi << '\n';
  EXPECT_GE(implied, k_lo) << "the model wears more at the least-wearing literature coefficient than measured";
  EXPECT_LE(implied, k_hi);
}

TEST(SeedWear, JointBOutWearsJointA)
{
  auto                      scene = wearlink::testing::scene("params/nine_bar_wear.prm");
  workflows::WearRunOptions o;
  o.output_directory = wearlink::testing::fresh_directory("seed_nine_bar_wear");
  o.progress         = true;
  const auto r       = workflows::run_wear(scene, o);
  ASSERT_EQ(r.state.joints.size(), 2u);
  const auto &a = r.state.joints[0].history.back();
  const auto &b = r.state.joints[1].history.back();
  std::cout << std::setprecision(4) << "\nseed §4.2.1, 100 cycles × 500 = " << r.state.revolutions << " revolutions:\n"
            << "  joint A: V_pin " << a.volume_pin * 1e9 << " mm³, V_bushing " << a.volume_bore * 1e9 << " mm³, h_pin "
            << a.max_depth_pin * 1e6 << " µm, h_bushing " << a.max_depth_bore * 1e6 << " µm, mean F_n "
            << a.mean_normal_force << " N\n"
            << "  joint B: V_pin " << b.volume_pin * 1e9 << " mm³, V_bushing " << b.volume_bore * 1e9 << " mm³, h_pin "
            << b.max_depth_pin * 1e6 << " µm, h_bushing " << b.max_depth_bore * 1e6 << " µm, mean F_n "
            << b.mean_normal_force << " N\n"
            << "  outputs in " << o.output_directory << "\n";
  EXPECT_GT(b.volume_pin + b.volume_bore, a.volume_pin + a.volume_bore) << "the seed: joint B wears more than A";
}
