// SPDX-License-Identifier: LGPL-2.1-or-later
// Benchmark: the cost of params/nine_bar_clearance.prm as a statistic. The clearance
// dynamics are chaotic, so one run's step count is one draw: equivalent runs (relative
// tolerance × 1, 1.01, 0.99, 1.02, 0.98, …, everything else equal) differ by ±5 % in
// right-hand sides, as much as many a speed-up. This runs N such members of the scene
// and, with --vs, N members of a variant (the given entries set), alternating member by
// member so that both see the same machine, and prints per member the steps, rejections,
// right-hand sides, CPU time and energy balance, then per setting the mean, standard
// deviation, smallest and largest, and the ratio of the variant's means to the scene's
// with the standard error of that ratio. Asserts nothing.
//   usage: bench_scatter [seconds of motion, default 10] [members, default 8]
//                        [Section/Entry=value ... (both settings)] [--vs Section/Entry=value ...]
#include "base/effect_ledger.h"
#include "base/parameters.h"
#include "io/scene.h"
#include "register_all.h"
#include "support/test_support.h"
#include "workflows/run/run.h"

#include <cmath>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

using namespace wearlink;

namespace
{
  /** One member: the figures of its summary.json and its CPU time. */
  struct Member
  {
    double steps, rejected, rhs, cpu, energy;
  };

  Member
  run_member(const std::vector<std::string> &overrides)
  {
    EffectLedger::instance().reset();
    io::Scene    scene = io::read_scene(testing::source_path("params/nine_bar_clearance.prm"), overrides);
    const auto   start = std::clock();
    const Json   s     = workflows::run_scene(scene, workflows::RunOptions());
    const double cpu   = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
    return {json_number(s.at("steps")),
            json_number(s.at("rejected_steps")),
            json_number(s.at("rhs_evaluations")),
            cpu,
            json_number(s.at("energy_balance_relative_error"))};
  }

  /** The k-th member's tolerance factor: 1, 1.01, 0.99, 1.02, 0.98, … */
  double
  factor(const int k)
  {
    const int step = (k + 1) / 2;
    return 1 + 0.01 * (k % 2 == 1 ? step : -step);
  }

  struct Moments
  {
    double mean = 0, sd = 0, lo = 0, hi = 0;
  };

  Moments
  moments(const std::vector<Member> &members, double Member::*of)
  {
    Moments m;
    m.lo = m.hi = members.front().*of;
    for (const auto &x : members)
      {
        m.mean += x.*of;
        m.lo = std::min(m.lo, x.*of);
        m.hi = std::max(m.hi, x.*of);
      }
    m.mean /= static_cast<double>(members.size());
    for (const auto &x : members)
      m.sd += (x.*of - m.mean) * (x.*of - m.mean);
    m.sd = members.size() > 1 ? std::sqrt(m.sd / static_cast<double>(members.size() - 1)) : 0.0;
    return m;
  }

  void
  print_setting(const char *name, const std::vector<Member> &members)
  {
    const Moments rhs = moments(members, &Member::rhs), cpu = moments(members, &Member::cpu),
                  energy = moments(members, &Member::energy);
    std::printf("%-10s rhs %10.0f ± %8.0f (%.0f … %.0f)   cpu %6.3f ± %.3f s   energy %.2e (%.2e … %.2e)\n",
                name,
                rhs.mean,
                rhs.sd,
                rhs.lo,
                rhs.hi,
                cpu.mean,
                cpu.sd,
                energy.mean,
                energy.lo,
                energy.hi);
  }

  /** mean(b)/mean(a) and its standard error (first-order propagation of both means' errors). */
  void
  print_ratio(const char *what, const std::vector<Member> &a, const std::vector<Member> &b, double Member::*of)
  {
    const Moments ma = moments(a, of), mb = moments(b, of);
    const double  n = static_cast<double>(a.size()), r = mb.mean / ma.mean;
    const double  se = r * std::sqrt(std::pow(ma.sd / ma.mean, 2) / n + std::pow(mb.sd / mb.mean, 2) / n);
    std::printf("variant / scene, %s: %.3f ± %.3f\n", what, r, se);
  }
} // namespace

int
main(int argc, char **argv)
{
  register_all();
  const double             seconds = argc > 1 ? std::stod(argv[1]) : 10;
  const int                n       = argc > 2 ? std::stoi(argv[2]) : 8;
  std::vector<std::string> common{"Simulation/End time=" + format_number(seconds), "Output/Time series=false"};
  std::vector<std::string> variant;
  bool                     vs = false;
  for (int a = 3; a < argc; ++a)
    if (std::string(argv[a]) == "--vs")
      vs = true;
    else
      (vs ? variant : common).push_back(argv[a]);

  std::printf("nine_bar_clearance.prm, %g s of motion, %d equivalent members (relative tolerance × 1, 1.01, 0.99, "
              "…)%s\n\n",
              seconds,
              n,
              vs ? ", scene and variant alternating" : "");
  std::printf("%-10s %6s %10s %9s %11s %8s %10s\n",
              "setting",
              "factor",
              "steps",
              "rejected",
              "rhs",
              "cpu [s]",
              "energy");
  std::vector<Member> scene_members, variant_members;
  for (int k = 0; k < n; ++k)
    {
      auto o = common;
      o.push_back("Integrator/Relative tolerance=" + format_number(1e-6 * factor(k)));
      for (int which = 0; which < (vs ? 2 : 1); ++which)
        {
          auto with = o;
          if (which == 1)
            with.insert(with.end(), variant.begin(), variant.end());
          const Member m = run_member(with);
          (which == 0 ? scene_members : variant_members).push_back(m);
          std::printf("%-10s %6.2f %10.0f %9.0f %11.0f %8.3f %10.2e\n",
                      which == 0 ? "scene" : "variant",
                      factor(k),
                      m.steps,
                      m.rejected,
                      m.rhs,
                      m.cpu,
                      m.energy);
        }
    }
  std::printf("\n");
  print_setting("scene", scene_members);
  if (vs)
    {
      print_setting("variant", variant_members);
      print_ratio("right-hand sides", scene_members, variant_members, &Member::rhs);
      print_ratio("CPU time", scene_members, variant_members, &Member::cpu);
    }
  return 0;
}
