// SPDX-License-Identifier: LGPL-2.1-or-later
// Where the integrator's steps go: every accepted step of params/nine_bar_clearance.prm
// is classified by the contact regime of each clearance joint at its end — free, light
// contact (δ < 1 µm) or deep, and whether the sliding speed is below the friction
// ramp (stick0: |v_t| < 1e-4 m/s), inside it (ramp: < 2e-4 m/s) or the penetration rate
// inside the hysteresis guard (guard: |δ̇| < 1e-4 m/s) — and the table prints, per
// regime, the share of steps, the rejections charged to it, the median step and the
// simulated time it covers; then the regime transitions that carry the most rejections.
// This is how the stiff phases (0.1 µs steps while a pin sticks in the friction ramp
// during an impact) were found. Asserts nothing.
//   usage: step_regimes [seconds of motion, default 10] [Section/Entry=value ...]
#include "base/parameters.h"
#include "contact/clearance_joint.h"
#include "io/scene.h"
#include "register_all.h"
#include "support/test_support.h"
#include "workflows/run/run.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

using namespace wearlink;

namespace
{
  /** The regime of one joint at a state. */
  std::string
  regime(const contact::JointDiagnostics &d)
  {
    if (!(d.penetration > 0))
      return "free";
    const double slide = std::abs(d.sliding_velocity), rate = std::abs(d.penetration_rate);
    std::string  k = d.penetration < 1e-6 ? "light" : "deep";
    if (slide < 1e-4)
      k += "+stick0";
    else if (slide < 2e-4)
      k += "+ramp";
    if (rate < 1e-4)
      k += "+guard";
    return k;
  }

  class RegimeCounter : public mbs::StepObserver
  {
  public:
    explicit RegimeCounter(io::Scene &scene)
      : scene(scene)
    {
    }

    void
    on_step(const mbs::StepContext &c) override
    {
      const unsigned int   n = c.simulation.get_mechanism().n_coordinates();
      const mbs::StateView s(c.y.data(), c.y.data() + n);
      std::string          key;
      for (const auto &j : scene.clearance_joints)
        key += j->name() + ":" + regime(j->diagnostics(s)) + " ";
      const long rejected = c.simulation.get_integrator().n_rejected;
      steps[key].push_back(c.t - c.t_previous);
      rejections[key] += rejected - last_rejected;
      const std::string transition = previous + "-> " + key;
      transition_rejections[transition] += rejected - last_rejected;
      ++transition_steps[transition];
      last_rejected = rejected;
      previous      = key;
    }

    void
    print() const
    {
      long total = 0;
      for (const auto &[k, v] : steps)
        total += static_cast<long>(v.size());
      std::vector<std::pair<long, std::string>> order;
      for (const auto &[k, v] : steps)
        order.emplace_back(static_cast<long>(v.size()), k);
      std::sort(order.rbegin(), order.rend());
      std::printf("%7s %8s %8s %12s %12s  regime\n", "share", "steps", "rejected", "median [s]", "covers [s]");
      for (const auto &[count, k] : order)
        {
          auto v = steps.at(k);
          std::sort(v.begin(), v.end());
          double covered = 0;
          for (const double h : v)
            covered += h;
          std::printf("%6.2f%% %8ld %8ld %12.3e %12.4f  %s\n",
                      100.0 * count / total,
                      count,
                      rejections.at(k),
                      v[v.size() / 2],
                      covered,
                      k.c_str());
        }
      std::vector<std::pair<long, std::string>> worst;
      for (const auto &[k, r] : transition_rejections)
        worst.emplace_back(r, k);
      std::sort(worst.rbegin(), worst.rend());
      std::printf("\nrejections by transition (regime at the start of the step -> at its end):\n");
      for (std::size_t i = 0; i < worst.size() && i < 15; ++i)
        std::printf("%8ld of %8ld steps  %s\n",
                    worst[i].first,
                    transition_steps.at(worst[i].second),
                    worst[i].second.c_str());
    }

  private:
    io::Scene                                 &scene;
    std::map<std::string, std::vector<double>> steps;
    std::map<std::string, long>                rejections, transition_rejections, transition_steps;
    long                                       last_rejected = 0;
    std::string                                previous;
  };
} // namespace

int
main(int argc, char **argv)
{
  register_all();
  const double             end = argc > 1 ? std::stod(argv[1]) : 10;
  std::vector<std::string> overrides{"Simulation/End time=" + format_number(end), "Output/Time series=false"};
  for (int i = 2; i < argc; ++i)
    overrides.emplace_back(argv[i]);
  io::Scene             scene = io::read_scene(testing::source_path("params/nine_bar_clearance.prm"), overrides);
  RegimeCounter         counter(scene);
  workflows::RunOptions options;
  options.observers.push_back(&counter);
  const Json s = workflows::run_scene(scene, options);
  std::printf("%s, %.1f s of motion: %.0f steps, %.0f rejected, %.0f right-hand sides, wall %.2f s, energy "
              "balance %.2e\n\n",
              std::string(s.at("integrator")).c_str(),
              end,
              json_number(s.at("steps")),
              json_number(s.at("rejected_steps")),
              json_number(s.at("rhs_evaluations")),
              json_number(s.at("wall_time_s")),
              json_number(s.at("energy_balance_relative_error")));
  counter.print();
  return 0;
}
