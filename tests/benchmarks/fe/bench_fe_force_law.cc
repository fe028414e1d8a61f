// SPDX-License-Identifier: LGPL-2.1-or-later
// Benchmark (label benchmark): the `fe` normal force law against the sphere-formula
// Lankarani–Nikravesh law on 100 driving cycles of params/nine_bar_clearance.prm, in one
// process, same integrator settings. Prints wall time, steps and the time per step of
// both runs and their ratios, and the fe tables' set-up apart (built into a fresh cache
// directory, then read back by a second run). Asserts only that the runs complete and
// that the second run took its tables from the cache.
// Next to them, the two closed-form cylindrical laws (johnson, esdu-78035), tabulated
// like fe but from formulas: they too include the axial length and are 1.5–4× stiffer
// than the sphere formula at these loads, so they show what a stiffer contact costs in
// steps whatever evaluates it — the step ratio of fe against L-N is the physics of the
// stiffer contact (a higher contact frequency at the same tolerances), not its table.
#include "base/effect_ledger.h"
#include "base/timings.h"
#include "scene_support.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>

using namespace wearlink;

namespace
{
  struct Timed
  {
    double wall = 0, steps = 0, tables = 0;
    bool   cached = true;
  };

  Timed
  run(const std::vector<std::string> &overrides)
  {
    const Stopwatch clock;
    io::Scene       scene = wearlink::testing::scene("params/nine_bar_clearance.prm", overrides);
    const double    read  = clock.seconds();
    const Json      s     = wearlink::testing::run(scene);
    Timed           t;
    t.wall  = clock.seconds() - read;
    t.steps = json_number(s.at("steps"));
    for (const auto &[name, j] : s.at("clearance_joints").items())
      if (j.contains("table_build_time_s"))
        {
          t.tables += json_number(j.at("table_build_time_s"));
          t.cached = t.cached && j.at("table_from_cache").get<bool>();
        }
    return t;
  }
} // namespace

TEST(FeForceLawBenchmark, HundredCyclesAgainstLankaraniNikravesh)
{
  ::setenv("WEARLINK_CACHE_DIR", wearlink::testing::fresh_directory("bench_fe_force_law_cache").c_str(), 1);
  const std::vector<std::string> common = {"Simulation/End time=50", "Output/Time series=false"};
  auto                           fe     = common;
  for (const char *j : {"A", "B"})
    {
      fe.push_back(std::string("Joint ") + j + "/Clearance/Normal force law=fe");
      fe.push_back(std::string("Joint ") + j + "/Clearance/fe/Restitution coefficient=0.9");
    }
  const auto law = [&](const char *name) {
    auto o = common;
    for (const char *j : {"A", "B"})
      {
        o.push_back(std::string("Joint ") + j + "/Clearance/Normal force law=" + name);
        o.push_back(std::string("Joint ") + j + "/Clearance/" + name + "/Restitution coefficient=0.9");
      }
    return o;
  };
  const Timed ln      = run(common);
  const Timed cold    = run(fe);
  const Timed warm    = run(fe);
  const Timed johnson = run(law("johnson"));
  const Timed esdu    = run(law("esdu-78035"));
  std::cout << "100 cycles, lankarani-nikravesh: " << ln.wall << " s, " << ln.steps << " steps, "
            << 1e6 * ln.wall / ln.steps << " us/step\n"
            << "100 cycles, fe (tables cached):   " << warm.wall - warm.tables << " s, " << warm.steps << " steps, "
            << 1e6 * (warm.wall - warm.tables) / warm.steps << " us/step\n"
            << "ratio fe / L-N: wall " << (warm.wall - warm.tables) / ln.wall << ", steps " << warm.steps / ln.steps
            << ", per step " << ((warm.wall - warm.tables) / warm.steps) / (ln.wall / ln.steps) << '\n'
            << "fe table set-up: " << cold.tables << " s cold (both joints), " << warm.tables << " s from the cache\n";
  for (const auto &[name, t] : {std::pair<const char *, const Timed &>{"johnson", johnson}, {"esdu-78035", esdu}})
    std::cout << "100 cycles, " << name << ": " << t.wall << " s, " << t.steps << " steps; ratio to L-N: wall "
              << t.wall / ln.wall << ", steps " << t.steps / ln.steps << "; fe / " << name << ": steps "
              << warm.steps / t.steps << ", per step " << ((warm.wall - warm.tables) / warm.steps) / (t.wall / t.steps)
              << '\n';
  EXPECT_FALSE(cold.cached);
  EXPECT_TRUE(warm.cached);
  ::unsetenv("WEARLINK_CACHE_DIR");
}
