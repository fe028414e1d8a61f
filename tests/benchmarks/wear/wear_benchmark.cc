// SPDX-License-Identifier: LGPL-2.1-or-later
// A 50,000-revolution wear prediction of the nine-bar (params/nine_bar_wear.prm, joints
// A and B) with the fe pressure model and a re-mesh of both worn pairs after every
// iteration: 10 iterations of 1 simulated cycle, each extrapolated × 5000; the FE model
// is evaluated at 24 load samples per cycle (each window of 1/24 cycle reuses its shape,
// wear/archard.h); FE surface element 0.2 mm. Prints the total wall time and its
// breakdown (dynamics, meshing, FE set-up, FE compliance columns, FE solves, wear
// bookkeeping, outputs). Target (issue 4): under 5 minutes on the 2-core development
// machine. Asserts only that the run did what it says (10 iterations, 50,000
// revolutions, 20 meshes), never a time.
#include "scene_support.h"
#include "workflows/wear_run.h"

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
                                                              "Wear/Remesh interval=1",
                                                              "Wear/Response cycles=1"});
  workflows::WearRunOptions o;
  o.output_directory = wearlink::testing::fresh_directory("wear_benchmark");
  o.progress         = true;
  const auto r       = workflows::run_wear(scene, o);
  ASSERT_TRUE(r.finished);
  EXPECT_EQ(r.state.iterations_done, 10u);
  EXPECT_DOUBLE_EQ(r.state.revolutions, 50000.0);
  EXPECT_EQ(EffectLedger::instance().resources("gmsh sessions"), 22); // 2 initial + 2 × 10

  const auto  &t      = r.timings;
  const double solves = t.pressure_evaluation - t.fe_compliance;
  std::cout << std::fixed << std::setprecision(1)
            << "\nnine-bar, 50,000 revolutions, fe pressure, re-mesh every iteration:\n"
            << "  total            " << t.total << " s\n"
            << "  dynamics         " << t.dynamics << " s (10 cycles + 1 after-wear cycle)\n"
            << "  meshing (gmsh)   " << t.meshing << " s (22 meshes)\n"
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
