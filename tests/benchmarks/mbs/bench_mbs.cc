// SPDX-License-Identifier: LGPL-2.1-or-later
// Benchmark: the nine-bar press mechanism over N crank cycles (default 100 = 50 s of
// motion at 120 rpm) with clearance joints A and B (params/nine_bar_clearance.prm), in
// one process, with each integrator and against two yardsticks:
//   - the cost: wall time, process CPU time (the one-core figure), accepted and rejected
//     steps, right-hand-side evaluations (deterministic, whatever the machine's load);
//   - the accuracy that the cost buys, by the figures a user reads — contact fraction and
//     peak normal force of each joint, the slider's peak acceleration — and the energy
//     balance, each beside a tight reference (dopri5 at a tenth of the tolerances) and
//     beside the chaos floor: dopri5 at tolerances scaled by 1.01, a run that differs
//     from the scene's only by what must not matter. A method whose deviation from the
//     reference stays within the floor's is as accurate as the scene's dopri5.
// The ideal-joint nine-bar at the same tolerances gives the clearance/ideal ratio.
// No time is asserted. Instructions per step: instructions_per_step.sh (callgrind).
//   usage: bench_mbs [cycles]
#include "base/effect_ledger.h"
#include "base/parameters.h"
#include "io/scene.h"
#include "register_all.h"
#include "support/test_support.h"
#include "workflows/run/run.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

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

  /** The clearance scene with @p method at the scene's tolerances × @p factor. */
  std::vector<std::string>
  overrides(const std::vector<std::string> &common, const std::string &method, const double factor)
  {
    auto o = common;
    o.push_back("Integrator/Method=" + method);
    o.push_back("Integrator/Relative tolerance=" + format_number(1e-6 * factor));
    o.push_back("Integrator/Position tolerance=" + format_number(1e-9 * factor));
    o.push_back("Integrator/Velocity tolerance=" + format_number(1e-6 * factor));
    return o;
  }

  /** The figures compared: contact fraction and peak force per joint, the slider's larger peak |a_x|, |a_y|. */
  std::vector<double>
  figures(const Json &s)
  {
    std::vector<double> f;
    for (const char *j : {"A", "B"})
      {
        f.push_back(json_number(s.at("clearance_joints").at(j).at("fraction_in_contact")));
        f.push_back(json_number(s.at("clearance_joints").at(j).at("max_normal_force_N")));
      }
    const auto &slider = s.at("bodies").at("slider9");
    f.push_back(std::max(json_number(slider.at("max_abs_ax_m_s2")), json_number(slider.at("max_abs_ay_m_s2"))));
    return f;
  }

  void
  cost_row(const char *name, const Json &s)
  {
    std::printf("%-30s %9.2f %9.2f %9.0f %9.0f %11.0f %8.0f %10.2e\n",
                name,
                json_number(s.at("wall_time_s")),
                json_number(s.at("cpu_time_s")),
                json_number(s.at("steps")),
                json_number(s.at("rejected_steps")),
                json_number(s.at("rhs_evaluations")),
                json_number(s.at("contact_events")),
                json_number(s.at("energy_balance_relative_error")));
  }

  /** The figures of @p s and their relative deviations from @p reference. */
  void
  accuracy_row(const char *name, const Json &s, const Json &reference)
  {
    const auto f = figures(s), r = figures(reference);
    std::printf("%-30s", name);
    for (std::size_t k = 0; k < f.size(); ++k)
      std::printf(" %9.4g (%+6.1f%%)", f[k], 100 * (f[k] - r[k]) / r[k]);
    std::printf("\n");
  }
} // namespace

int
main(int argc, char **argv)
{
  register_all();
  const int                      cycles    = argc > 1 ? std::stoi(argv[1]) : 100;
  const double                   end       = 0.5 * cycles;
  const std::vector<std::string> common    = {"Simulation/End time=" + format_number(end), "Output/Time series=false"};
  const char                    *clearance = "params/nine_bar_clearance.prm";

  struct Run
  {
    const char *name;
    Json        summary;
  };
  std::vector<Run> runs;
  runs.push_back({"dopri5 (the scene's)", run(clearance, overrides(common, "dopri5", 1))});
  runs.push_back({"dopri5-stiff", run(clearance, overrides(common, "dopri5-stiff", 1))});
  runs.push_back({"dop853", run(clearance, overrides(common, "dop853", 1))});
  runs.push_back({"chaos floor: dopri5, tol x1.01", run(clearance, overrides(common, "dopri5", 1.01))});
  {
    auto held = overrides(common, "dopri5-stiff", 1);
    held.push_back("Joint A/Clearance/Persistent contact=held");
    held.push_back("Joint B/Clearance/Persistent contact=held");
    runs.push_back({"dopri5-stiff, contacts held", run(clearance, held)});
    auto interpolated = overrides(common, "dopri5-stiff", 1);
    interpolated.push_back("Integrator/Event point=interpolated");
    runs.push_back({"dopri5-stiff, events interp.", run(clearance, interpolated)});
    auto floor = overrides(common, "dopri5-stiff", 1.01);
    runs.push_back({"dopri5-stiff, tol x1.01", run(clearance, floor)});
  }
  runs.push_back({"reference: dopri5, tol x0.1", run(clearance, overrides(common, "dopri5", 0.1))});
  const Json ideal = run("params/nine_bar_ideal.prm", overrides(common, "dopri5", 1));

  std::printf("nine-bar press mechanism, %d crank cycles (%.1f s simulated)\n\n", cycles, end);
  std::printf("%-30s %9s %9s %9s %9s %11s %8s %10s\n",
              "run",
              "wall [s]",
              "cpu [s]",
              "steps",
              "rejected",
              "rhs evals",
              "events",
              "energy");
  for (const auto &r : runs)
    cost_row(r.name, r.summary);
  cost_row("ideal joints (dopri5)", ideal);

  const Json &reference = runs.back().summary;
  std::printf("\nagainst the reference (dopri5 at a tenth of the tolerances):\n%-30s", "run");
  for (const char *h : {"A in contact", "A peak F [N]", "B in contact", "B peak F [N]", "slider |a| [m/s2]"})
    std::printf(" %19s", h);
  std::printf("\n");
  for (const auto &r : runs)
    accuracy_row(r.name, r.summary, reference);

  const Json &scene = runs.front().summary;
  std::printf("\nratio clearance/ideal (dopri5): cpu time %.1f, rhs evaluations %.1f\n",
              json_number(scene.at("cpu_time_s")) / json_number(ideal.at("cpu_time_s")),
              json_number(scene.at("rhs_evaluations")) / json_number(ideal.at("rhs_evaluations")));
  for (std::size_t k = 1; k < 3; ++k)
    std::printf("%s / dopri5: cpu time %.2f, steps %.2f, rhs evaluations %.2f\n",
                runs[k].name,
                json_number(runs[k].summary.at("cpu_time_s")) / json_number(scene.at("cpu_time_s")),
                json_number(runs[k].summary.at("steps")) / json_number(scene.at("steps")),
                json_number(runs[k].summary.at("rhs_evaluations")) / json_number(scene.at("rhs_evaluations")));
  return 0;
}
