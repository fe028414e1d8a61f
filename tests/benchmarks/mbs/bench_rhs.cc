// SPDX-License-Identifier: LGPL-2.1-or-later
// Benchmark: the cost of one right-hand side of the nine-bar with clearance joints A and
// B (params/nine_bar_clearance.prm), isolated from the integrator: the states of every
// 50th accepted step over the first T seconds of motion (default 5 s = 10 cycles) are
// recorded, then Mechanism::accelerations() is evaluated on all of them, round after
// round; the best round gives ns per right-hand side. The states are the ones the
// integrator meets (free flight, impacts, continuous contact in the proportions of the
// run), so the figure is a run's mean cost without the integrator, and the best of many
// rounds carries less of the machine's noise than a whole run. Each build records its
// own run's states: a build whose round-off differs follows another (equally typical)
// trajectory, with a different number of states and checksum; the checksum of the
// accelerations is equal only across builds that compute the same numbers.
//   usage: bench_rhs [T] [rounds]
#include "base/parameters.h"
#include "io/scene.h"
#include "mbs/mechanism.h"
#include "mbs/simulation.h"
#include "register_all.h"
#include "support/test_support.h"
#include "workflows/run/run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace wearlink;

namespace
{
  /** Every 50th accepted step's (t, q, v). */
  class StateRecorder : public mbs::StepObserver
  {
  public:
    void
    on_step(const mbs::StepContext &c) override
    {
      if (count++ % 50 != 0)
        return;
      times.push_back(c.t);
      states.emplace_back(c.y.data(), c.y.data() + c.y.size());
    }

    std::vector<double>              times;
    std::vector<std::vector<double>> states;

  private:
    long count = 0;
  };
} // namespace

int
main(int argc, char **argv)
{
  register_all();
  const double          end    = argc > 1 ? std::stod(argv[1]) : 5;
  const int             rounds = argc > 2 ? std::stoi(argv[2]) : 20;
  io::Scene             scene  = io::read_scene(testing::source_path("params/nine_bar_clearance.prm"),
                                   {"Simulation/End time=" + format_number(end), "Output/Time series=false"});
  StateRecorder         recorder;
  workflows::RunOptions options;
  options.observers.push_back(&recorder);
  workflows::run_scene(scene, options);

  mbs::Mechanism     &mech = *scene.mechanism;
  const unsigned int  n    = mech.n_coordinates();
  std::vector<double> a(n);
  mbs::PowerTerms     power;
  double              best = 1e300, checksum = 0;
  for (int r = 0; r < rounds; ++r)
    {
      const auto start = std::chrono::steady_clock::now();
      for (std::size_t i = 0; i < recorder.states.size(); ++i)
        {
          const double *y = recorder.states[i].data();
          mech.accelerations(recorder.times[i], y, y + n, a.data(), power);
          if (r == 0)
            for (const double x : a)
              checksum += std::abs(x);
        }
      const std::chrono::duration<double> d = std::chrono::steady_clock::now() - start;
      best                                  = std::min(best, d.count());
    }
  std::printf("%zu states, best of %d rounds: %.1f ns per right-hand side; checksum %.17g\n",
              recorder.states.size(),
              rounds,
              1e9 * best / static_cast<double>(recorder.states.size()),
              checksum);
  return 0;
}
