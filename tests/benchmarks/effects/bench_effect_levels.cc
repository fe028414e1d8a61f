// SPDX-License-Identifier: LGPL-2.1-or-later
// Benchmark: what each effect level costs on the nine-bar press over N crank cycles
// (default 10 = 5 s of motion at 120 rpm), all in one process and at the same
// integrator settings (those of params/nine_bar_clearance.prm), so that the ratios
// measure the effects, not a tolerance:
//   1. ideal joints                         params/nine_bar_ideal.prm
//   2. clearance A and B, no friction       nine_bar_clearance.prm, Friction law = none
//   3. + friction (modified Coulomb)        nine_bar_clearance.prm
//   4. + wear, hertz-strip pressure         nine_bar_wear.prm, 1 iteration of N cycles
//   5. + wear, fe pressure                  as 4 with Pressure model = fe at the
//      affordable settings of the wear benchmark (24 load samples per cycle, 0.2 mm
//      surface elements); the first mesh, factorization and compliance columns are
//      part of its cost.
// Prints wall time, process CPU time (insensitive to other load on the machine) and
// both as ratios to level 1. Asserts nothing about time; fails only if a level fails.
//   usage: bench_effect_levels [cycles]
#include "base/effect_ledger.h"
#include "base/parameters.h"
#include "io/scene.h"
#include "register_all.h"
#include "support/test_support.h"
#include "workflows/run/run.h"
#include "workflows/wear/wear_run.h"

#include <chrono>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

using namespace wearlink;

namespace
{
  struct Level
  {
    const char              *name;
    std::string              file;
    std::vector<std::string> overrides;
  };

  struct Cost
  {
    double wall = 0, cpu = 0;
  };

  /** Read, build and run one level; the wear levels run their loop without outputs. */
  Cost
  measure(const Level &level)
  {
    EffectLedger::instance().reset();
    const auto wall0 = std::chrono::steady_clock::now();
    const auto cpu0  = std::clock();
    io::Scene  scene = io::read_scene(testing::source_path(level.file), level.overrides);
    if (workflows::has_wear(scene))
      {
        workflows::WearRunOptions o;
        o.progress      = false;
        o.final_outputs = false;
        workflows::run_wear(scene, o);
      }
    else
      workflows::run_scene(scene, workflows::RunOptions());
    Cost c;
    c.cpu  = static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC;
    c.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    return c;
  }
} // namespace

int
main(int argc, char **argv)
{
  register_all();
  const int                      cycles     = argc > 1 ? std::stoi(argv[1]) : 10;
  const double                   end        = 0.5 * cycles; // 120 rpm: 0.5 s per crank cycle
  const std::vector<std::string> dynamics   = {"Simulation/End time=" + format_number(end), "Output/Time series=false"};
  const std::vector<std::string> tolerances = {"Integrator/Relative tolerance=1e-6",
                                               "Integrator/Position tolerance=1e-9",
                                               "Integrator/Velocity tolerance=1e-6"};
  auto                           with       = [](std::vector<std::string> a, const std::vector<std::string> &b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
  };
  const std::vector<std::string> one_iteration = {"Wear/Cycles per iteration=" + std::to_string(cycles),
                                                  "Wear/Number of iterations=1"};
  std::vector<std::string>       fe            = one_iteration;
  for (const char *j : {"A", "B"})
    for (const std::string e : {"Pressure model=fe", "fe/Surface element size=2e-4"})
      fe.push_back(std::string("Joint ") + j + "/Clearance/" + e);
  fe.push_back("Wear/Pressure evaluation=samples per cycle");
  fe.push_back("Wear/Load samples per cycle=24");

  const std::vector<Level> levels = {
    {"ideal joints", "params/nine_bar_ideal.prm", with(dynamics, tolerances)},
    {"clearance, no friction",
     "params/nine_bar_clearance.prm",
     with(dynamics, {"Joint A/Clearance/Friction law=none", "Joint B/Clearance/Friction law=none"})},
    {"+ friction", "params/nine_bar_clearance.prm", dynamics},
    {"+ wear, hertz-strip", "params/nine_bar_wear.prm", one_iteration},
    {"+ wear, fe", "params/nine_bar_wear.prm", fe},
  };

  std::printf("\nnine-bar, %d crank cycles per level (same integrator settings)\n", cycles);
  std::printf("%-24s %10s %10s %12s %12s\n", "level", "wall s", "CPU s", "wall/ideal", "CPU/ideal");
  Cost ideal;
  for (std::size_t i = 0; i < levels.size(); ++i)
    {
      const Cost c = measure(levels[i]);
      if (i == 0)
        ideal = c;
      std::printf("%-24s %10.3f %10.3f %12.1f %12.1f\n",
                  levels[i].name,
                  c.wall,
                  c.cpu,
                  c.wall / ideal.wall,
                  c.cpu / ideal.cpu);
      std::fflush(stdout);
    }
  return 0;
}
