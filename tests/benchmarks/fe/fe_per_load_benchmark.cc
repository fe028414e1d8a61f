// SPDX-License-Identifier: LGPL-2.1-or-later
// Wall time of the condensed contact solver per load state along a load path like a
// mechanism cycle's, at the default FE mesh (both surfaces refined all around at 25 µm,
// as a wear loop with a rotating load needs) of the steel pair of params/pin_bushing.prm,
// at 100 N, 1 kN, 10 kN and 100 kN. Per load level, a sequence of 72 states: the load
// direction turns by 5° per state (a full turn) and the pin by 2.5° against the bushing,
// the magnitude varies by ±10 % about the level. The first pass over the path computes
// the compliance columns it needs (reported as set-up); the figure is the mean (and the
// largest) time per state of the second pass. The target: < 1 ms at every level.
// Next to the wall time, the CPU time of this thread per state: on a machine that others
// share, the wall time includes the waits for a core, the CPU time far less.
// Next to them, where the second pass's time goes (CondensedTimings, per state): the
// gathering of the window's compliance columns, the factorization of the active block,
// the gaps (products of the columns with the multipliers), the triangular
// substitutions, and the rest (kinematics, active-set bookkeeping).
// Asserted: equilibrium of every state (the physics); never a time.
#include "fe/contact_solver.h"
#include "fe_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <ctime>
#include <iomanip>
#include <iostream>
#include <sstream>

using namespace wearlink;
using namespace wearlink::fe;
using namespace wearlink::fe::testing;

namespace
{
  /** The load levels [N]: 100 N … 100 kN, or those of $WEARLINK_BENCH_LEVELS (e.g. "1e5"). */
  std::vector<double>
  levels()
  {
    std::vector<double> out;
    if (const char *env = std::getenv("WEARLINK_BENCH_LEVELS"); env != nullptr)
      {
        std::istringstream in(env);
        for (double v; in >> v;)
          out.push_back(v);
      }
    return out.empty() ? std::vector<double>{1e2, 1e3, 1e4, 1e5} : out;
  }

  LoadCase
  path_state(const double level, const unsigned int k)
  {
    const double direction = -pi / 2 + k * 5 * pi / 180;
    const double magnitude = level * (1 + 0.1 * std::sin(3 * direction));
    LoadCase     lc;
    lc.control       = Control::force;
    lc.bushing_angle = 0.1;
    lc.pin_angle     = 0.1 + k * 2.5 * pi / 180;
    lc.load          = {{magnitude * std::cos(direction), magnitude * std::sin(direction)}};
    return lc;
  }

  /** CPU time of the calling thread [s]. */
  double
  thread_seconds()
  {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
  }
} // namespace

TEST(FePerLoadState, FourLevelsAlongACycle)
{
  const auto geometry = steel_pair();
  FeSettings settings; // defaults: 25 µm all around
  settings.outer_radius = 0.024;
  PinBushingModel model(geometry, settings, mesh_file("per_load"));
  model.prepare_condensed();
  const unsigned int n_states = 72;
  std::cout << "default mesh: " << model.statistics().n_dofs << " DoFs, " << model.statistics().n_pin_candidates
            << " pin + " << model.statistics().n_bore_candidates << " bore candidates\n"
            << "  load [N]  active  columns [s]  first pass [ms/state]  mean [ms/state]  max [ms]  iterations  "
               "cpu [ms/state]\n";
  for (const double level : levels())
    {
      const double columns_before = model.compliance_time();
      double       first          = 0;
      for (unsigned int k = 0; k < n_states; ++k)
        first += model.solve(path_state(level, k), SolverKind::condensed).solve_time;
      const double           columns = model.compliance_time() - columns_before;
      double                 mean = 0, worst = 0, iterations = 0, active = 0, cpu = 0;
      const CondensedTimings before = model.condensed_timings();
      if (std::getenv("WEARLINK_BENCH_REPEAT"))
        for (int rep = 0; rep < 30; ++rep)
          for (unsigned int k = 0; k < n_states; ++k)
            model.solve(path_state(level, k), SolverKind::condensed);
      for (unsigned int k = 0; k < n_states; ++k)
        {
          const double cpu_before = thread_seconds();
          const auto   r          = model.solve(path_state(level, k), SolverKind::condensed);
          cpu += (thread_seconds() - cpu_before) / n_states;
          mean += r.solve_time / n_states;
          worst = std::max(worst, r.solve_time);
          iterations += double(r.iterations) / n_states;
          active += double(r.n_active) / n_states;
          EXPECT_LT(r.equilibrium_relative_residual, 1e-8) << level << " N, state " << k;
        }
      std::cout << std::setw(10) << level << std::setw(8) << std::fixed << std::setprecision(0) << active
                << std::setprecision(2) << std::setw(13) << columns << std::setw(23) << 1e3 * first / n_states
                << std::setprecision(3) << std::setw(17) << 1e3 * mean << std::setw(10) << 1e3 * worst
                << std::setprecision(1) << std::setw(12) << iterations << std::setprecision(3) << std::setw(16)
                << 1e3 * cpu << "\n"
                << std::defaultfloat;
      const CondensedTimings &after = model.condensed_timings();
      const double            n     = after.solves - before.solves;
      const auto              ms    = [&](const double a, const double b) {
        return 1e3 * (a - b) / n;
      };
      const double gather = ms(after.gather, before.gather), factor = ms(after.factorization, before.factorization),
                   gaps = ms(after.gaps, before.gaps), subs = ms(after.substitutions, before.substitutions),
                   total = ms(after.total, before.total);
      std::cout << std::setprecision(3) << std::fixed << "            of which [ms/state]: gather " << gather
                << ", factorization " << factor << ", gaps " << gaps << ", substitutions " << subs << ", rest "
                << total - gather - factor - gaps - subs << " (condensed solve " << total << ")\n"
                << std::defaultfloat;
    }
}
