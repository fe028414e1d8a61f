// SPDX-License-Identifier: LGPL-2.1-or-later
// Benchmark: the nine-bar press mechanism over N crank cycles (default 100 = 50 s of
// motion at 120 rpm), with clearance joints A and B (params/nine_bar_clearance.prm) and
// with ideal joints (params/nine_bar_ideal.prm at the clearance scene's tolerances), in
// one process. Prints wall time, process CPU time (the one-core figure, insensitive to
// other load on the machine), accepted/rejected steps, right-hand-side evaluations,
// contact events, and the clearance/ideal ratios; the clearance scene also with dop853.
// No time is asserted. Instructions per step: instructions_per_step.sh (callgrind).
//   usage: bench_mbs [cycles]
#include "base/effect_ledger.h"
#include "base/parameters.h"
#include "io/scene.h"
#include "register_all.h"
#include "support/test_support.h"
#include "workflows/run.h"

#include <cstdio>
#include <ctime>
#include <iostream>
#include <string>

using namespace wearlink;

namespace
{
  Json
  run(const std::string &file, const std::vector<std::string> &overrides)
  {
    EffectLedger::instance().reset();
    io::Scene  scene = io::read_scene(testing::source_path(file), overrides);
    const auto start = std::clock();
    Json       s     = workflows::run_scene(scene, workflows::RunOptions());
    s["cpu_time_s"]  = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
    return s;
  }
} // namespace

int
main(int argc, char **argv)
{
  register_all();
  const int                      cycles = argc > 1 ? std::stoi(argv[1]) : 100;
  const double                   end    = 0.5 * cycles;
  const std::vector<std::string> common = {"Simulation/End time=" + format_number(end), "Output/Time series=false"};
  // The ideal run uses the clearance scene's integrator settings, so the ratio measures
  // the cost of the clearance joints, not of a tighter tolerance.
  auto ideal_overrides = common;
  for (const auto &o : {"Integrator/Relative tolerance=1e-6",
                        "Integrator/Position tolerance=1e-9",
                        "Integrator/Velocity tolerance=1e-6"})
    ideal_overrides.push_back(o);

  const Json c                = run("params/nine_bar_clearance.prm", common);
  auto       dop853_overrides = common;
  dop853_overrides.push_back("Integrator/Method=dop853");
  const Json d = run("params/nine_bar_clearance.prm", dop853_overrides);
  const Json i = run("params/nine_bar_ideal.prm", ideal_overrides);

  auto row = [](const char *name, const Json &s) {
    long events = static_cast<long>(json_number(s.at("contact_events")));
    std::printf("%-22s %10.3f %10.3f %10.0f %10.0f %12.0f %8ld %14.3e\n",
                name,
                json_number(s.at("wall_time_s")),
                json_number(s.at("cpu_time_s")),
                json_number(s.at("steps")),
                json_number(s.at("rejected_steps")),
                json_number(s.at("rhs_evaluations")),
                events,
                json_number(s.at("cpu_time_s")) / json_number(s.at("rhs_evaluations")));
  };
  std::printf("nine-bar press mechanism, %d crank cycles (%.1f s simulated)\n", cycles, end);
  std::printf("%-22s %10s %10s %10s %10s %12s %8s %14s\n",
              "run",
              "wall [s]",
              "cpu [s]",
              "steps",
              "rejected",
              "rhs evals",
              "events",
              "cpu/rhs [s]");
  row("clearance A and B", c);
  row("  the same, dop853", d);
  row("ideal joints", i);
  std::printf("ratio clearance/ideal: wall time %.1f, cpu time %.1f, rhs evaluations %.1f\n",
              json_number(c.at("wall_time_s")) / json_number(i.at("wall_time_s")),
              json_number(c.at("cpu_time_s")) / json_number(i.at("cpu_time_s")),
              json_number(c.at("rhs_evaluations")) / json_number(i.at("rhs_evaluations")));
  std::printf("joint A: %.0f impacts, in contact %.1f%%; joint B: %.0f impacts, in contact %.1f%%\n",
              json_number(c.at("clearance_joints").at("A").at("impacts")),
              100 * json_number(c.at("clearance_joints").at("A").at("fraction_in_contact")),
              json_number(c.at("clearance_joints").at("B").at("impacts")),
              100 * json_number(c.at("clearance_joints").at("B").at("fraction_in_contact")));
  std::printf("energy balance relative error: clearance %.2e (dop853 %.2e), ideal %.2e\n",
              json_number(c.at("energy_balance_relative_error")),
              json_number(d.at("energy_balance_relative_error")),
              json_number(i.at("energy_balance_relative_error")));
  std::printf("dop853/dopri5: cpu time %.2f, steps %.2f, rhs evaluations %.2f\n",
              json_number(d.at("cpu_time_s")) / json_number(c.at("cpu_time_s")),
              json_number(d.at("steps")) / json_number(c.at("steps")),
              json_number(d.at("rhs_evaluations")) / json_number(c.at("rhs_evaluations")));
  return 0;
}
