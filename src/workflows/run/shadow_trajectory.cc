// SPDX-License-Identifier: LGPL-2.1-or-later
#include "workflows/run/shadow_trajectory.h"

#include "base/exceptions.h"
#include "io/scene.h"

#include <cmath>

namespace wearlink::workflows
{
  ShadowTrajectory::ShadowTrajectory(const io::Scene &reference, const ShadowTrajectorySettings &s)
    : settings(s)
    , shadow_scene(std::make_unique<io::Scene>(io::read_scene(reference.file, reference.overrides)))
    , shadow(std::make_unique<mbs::Simulation>(*shadow_scene->mechanism, shadow_scene->simulation))
    , n_coordinates(reference.mechanism->n_coordinates())
    , next_time(s.begin_time)
  {
    AssertThrow(s.separation > 0.0 && s.interval > 0.0 && s.velocity_scale >= 0.0,
                dealii::ExcMessage("The two-trajectory settings must be positive."));
  }

  ShadowTrajectory::~ShadowTrajectory() = default;

  double
  ShadowTrajectory::distance(const Eigen::VectorXd &a, const Eigen::VectorXd &b) const
  {
    const unsigned int n  = n_coordinates;
    const double       dq = (a.head(n) - b.head(n)).squaredNorm();
    const double       dv = (a.segment(n, n) - b.segment(n, n)).squaredNorm();
    return std::sqrt(dq + settings.velocity_scale * settings.velocity_scale * dv);
  }

  // At each renormalization time t_r inside the reference's accepted step: the
  // reference state from its dense output, the shadow integrated up to t_r by its own
  // simulation, the logarithm of the distance ratio added, and the shadow restarted
  // at t_r at distance d0 along the current separation.
  void
  ShadowTrajectory::on_step(const mbs::StepContext &c)
  {
    while (next_time <= c.t)
      {
        c.simulation.state_at(next_time, y_ref);
        if (!started)
          {
            // First displacement: d0 along the same direction in every velocity
            // coordinate (deterministic; its constraint-violating part decays).
            Eigen::VectorXd y0    = y_ref;
            const double    scale = settings.velocity_scale > 0.0 ? settings.velocity_scale : 1.0;
            y0.segment(n_coordinates, n_coordinates).array() +=
              settings.separation / (scale * std::sqrt(static_cast<double>(n_coordinates)));
            shadow->initialize_state(next_time, y0);
            started = true;
          }
        else
          {
            shadow->run(next_time, {});
            Eigen::VectorXd y_shadow = shadow->state();
            const double    d        = distance(y_shadow, y_ref);
            if (!(d > 0.0) || !std::isfinite(d))
              throw NumericalError("The two-trajectory Lyapunov estimate lost its separation at t = " +
                                   std::to_string(next_time) + " s (distance " + std::to_string(d) + ").");
            sum_log += std::log(d / settings.separation);
            ++n;
            times.push_back(next_time);
            running.push_back(exponent());
            const unsigned int m = 2 * n_coordinates;
            y_shadow.head(m)     = y_ref.head(m) + settings.separation / d * (y_shadow.head(m) - y_ref.head(m));
            shadow->initialize_state(next_time, y_shadow);
          }
        next_time = settings.begin_time + settings.interval * static_cast<double>(n + 1);
      }
  }

  double
  ShadowTrajectory::exponent() const
  {
    return n > 0 ? sum_log / (n * settings.interval) : 0.0;
  }
} // namespace wearlink::workflows
