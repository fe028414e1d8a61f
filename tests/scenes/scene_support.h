// SPDX-License-Identifier: LGPL-2.1-or-later
// Running a scene from params/ inside a test, with overrides and extra observers.
#pragma once

#include "base/effect_ledger.h"
#include "io/scene.h"
#include "support/test_support.h"
#include "workflows/run/run.h"

#include <functional>

namespace wearlink::testing
{
  /** Samples a quantity on the dense output at a fixed interval. */
  class Sampler : public mbs::StepObserver
  {
  public:
    using Function = std::function<std::vector<double>(double t, const Eigen::VectorXd &y, mbs::Simulation &)>;
    Sampler(double interval, Function f)
      : interval(interval)
      , f(std::move(f))
    {
    }
    void
    on_start(const mbs::StepContext &c) override
    {
      next = c.t;
    }
    void
    on_step(const mbs::StepContext &c) override
    {
      while (next <= c.t)
        {
          Eigen::VectorXd y;
          c.simulation.state_at(next, y);
          times.push_back(next);
          values.push_back(f(next, y, c.simulation));
          next = times.front() + interval * times.size();
        }
    }
    double                           interval, next = 0;
    Function                         f;
    std::vector<double>              times;
    std::vector<std::vector<double>> values;
  };

  /**
   * Read a scene from params/ (path relative to the source tree) with overrides. The
   * effect ledger starts afresh here, since reading constructs the chosen plugins.
   */
  inline io::Scene
  scene(const std::string &relative, const std::vector<std::string> &overrides = {})
  {
    EffectLedger::instance().reset();
    return io::read_scene(source_path(relative), overrides);
  }

  /** Run @p scene with extra @p observers; returns the summary. */
  inline Json
  run(io::Scene &scene, const std::vector<mbs::StepObserver *> &observers = {})
  {
    workflows::RunOptions o;
    o.observers = observers;
    return workflows::run_scene(scene, o);
  }
} // namespace wearlink::testing
