// SPDX-License-Identifier: LGPL-2.1-or-later
// Two 50,000-revolution wear predictions of the nine-bar with the FE model.
// 1. params/nine_bar_wear.prm, joints A and B on the fe pressure model (the dynamics on
// L-N) and a re-mesh of both worn pairs after every iteration (Remesh depth 0): 10 iterations of 1 simulated cycle, each extrapolated × 5000; the FE model
// is evaluated at 24 load samples per cycle (each window of 1/24 cycle reuses its shape,
// wear/archard.h); FE surface element 0.2 mm. Prints the total wall time and its
// breakdown (dynamics, meshing, FE set-up, FE compliance columns, FE solves, wear
// bookkeeping, outputs). Target: under 5 minutes on the 2-core development
// machine. Asserts only that the run did what it says (10 iterations, 50,000
// revolutions, 21 meshes), never a time.
// 2. The shipped FE scene params/nine_bar_wear_fe.prm as it is (fe pressure and fe
// contact law on both joints, 25 µm, meshes kept over 2 elements of wear): the same breakdown plus the contact
// law's tables. Target: < 300 s, goal < 60 s.
#include "base/effect_ledger.h"
#include "base/json.h"
#include "contact/clearance_joint.h"
#include "scene_support.h"
#include "workflows/wear/wear_run.h"

#include <gtest/gtest.h>

#include <iomanip>
#include <iostream>

using namespace wearlink;

TEST(WearBenchmark, NineBarFiftyThousandRevolutionsWithFe)
{
  auto                      scene = wearlink::testing::scene("params/nine_bar_wear.prm",
                                        {"Joint A/Clearance/Pressure model=fe",
                                                              "Joint B/Clearance/Pressure model=fe",
                                                              "Joint A/Clearance/fe/Surface element size=2e-4",
                                                              "Joint B/Clearance/fe/Surface element size=2e-4",
                                                              "Wear/Cycles per iteration=1",
                                                              "Wear/Number of iterations=10",
                                                              "Wear/Extrapolation factor=5000",
                                                              "Wear/Pressure evaluation=samples per cycle",
                                                              "Wear/Load samples per cycle=24",
                                                              "Wear/Response cycles=1"});
  workflows::WearRunOptions o;
  o.output_directory = wearlink::testing::fresh_directory("wear_benchmark");
  o.progress         = true;
  const auto r       = workflows::run_wear(scene, o);
  ASSERT_TRUE(r.finished);
  EXPECT_EQ(r.state.iterations_done, 10u);
  EXPECT_DOUBLE_EQ(r.state.revolutions, 50000.0);
  // The fresh joints A and B are equal and share one mesh (fe/model_pool.h); Remesh
  // depth 0 then renews each joint's mesh after every iteration.
  EXPECT_EQ(EffectLedger::instance().resources("gmsh sessions"), 21); // 1 initial + 2 × 10

  const auto  &t      = r.timings;
  const double solves = t.pressure_evaluation - t.fe_compliance;
  std::cout << std::fixed << std::setprecision(1)
            << "\nnine-bar, 50,000 revolutions, fe pressure, re-mesh every iteration:\n"
            << "  total            " << t.total << " s\n"
            << "  dynamics         " << t.dynamics << " s (10 cycles + 1 after-wear cycle)\n"
            << "  meshing (gmsh)   " << t.meshing << " s (21 meshes)\n"
            << "  FE set-up        " << t.fe_setup << " s (assembly + factorization)\n"
            << "  FE compliance    " << t.fe_compliance << " s (condensed columns, on demand)\n"
            << "  FE solves        " << solves << " s (contact QPs, " << 24 * 10 << " load samples per joint)\n"
            << "  wear bookkeeping " << t.wear_bookkeeping << " s\n"
            << "  outputs          " << t.outputs << " s\n";
  for (const auto &j : r.state.joints)
    std::cout << std::scientific << std::setprecision(3) << "  joint " << j.name << ": V_pin "
              << j.history.back().volume_pin * 1e9 << " mm³, V_bushing " << j.history.back().volume_bore * 1e9
              << " mm³, h_pin " << j.history.back().max_depth_pin * 1e6 << " µm, h_bushing "
              << j.history.back().max_depth_bore * 1e6 << " µm\n";
}

namespace
{
  double
  json_number(const Json &j, const char *key)
  {
    return j.contains(key) ? j.at(key).get<double>() : 0.0;
  }
} // namespace

TEST(WearBenchmark, ShippedFeSceneWithTheFeContactLaw)
{
  auto                      scene = wearlink::testing::scene("params/nine_bar_wear_fe.prm", {});
  workflows::WearRunOptions o;
  o.output_directory = wearlink::testing::fresh_directory("wear_benchmark_fe");
  o.progress         = true;
  const auto r       = workflows::run_wear(scene, o);
  ASSERT_TRUE(r.finished);
  EXPECT_DOUBLE_EQ(r.state.revolutions, 50000.0);

  const auto &t            = r.timings;
  double      table_solves = 0;
  unsigned    builds = 0, repaired = 0, failed = 0;
  for (const auto *j : scene.clearance_joints)
    {
      const Json law = j->normal_force_law().report(); // stored: its items are read below
      table_solves += json_number(law, "table_fe_solves");
      builds += static_cast<unsigned>(json_number(law, "table_builds"));
      repaired += static_cast<unsigned>(json_number(law, "table_repaired_points"));
      failed += static_cast<unsigned>(json_number(law, "table_failed_solves"));
    }
  std::cout << std::fixed << std::setprecision(1) << "\nparams/nine_bar_wear_fe.prm (fe pressure + fe law, 25 µm):\n"
            << "  total               " << t.total << " s (the loop; the tables built at set-up are outside)\n"
            << "  dynamics            " << t.dynamics << " s (10 × 10 cycles, fe law)\n"
            << "  pressure evaluation " << t.pressure_evaluation << " s (FE solves and the columns they computed)\n"
            << "  contact-law tables  " << t.contact_law_tables << " s (" << builds
            << " builds over both joints, set-up included; FE meshing, set-up and columns of the models they made; "
            << table_solves << " FE solves in the last; " << repaired << " points repaired, " << failed
            << " failed in the last)\n"
            << "  meshing (gmsh)      " << t.meshing << " s (models the pressure models made; "
            << EffectLedger::instance().resources("gmsh sessions") << " gmsh sessions in all)\n"
            << "  FE set-up           " << t.fe_setup << " s (likewise)\n"
            << "  FE compliance       " << t.fe_compliance << " s (likewise)\n"
            << "  wear bookkeeping    " << t.wear_bookkeeping << " s\n"
            << "  outputs             " << t.outputs << " s\n";
}
