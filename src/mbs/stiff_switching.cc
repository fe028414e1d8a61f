// SPDX-License-Identifier: LGPL-2.1-or-later
// dopri5-stiff: dopri5 while its steps are set by accuracy, ROS34PW2 while they are set by
// stability (the idea of LSODA's switching, Petzold 1983, with the stiffness tests of
// Hairer's dopri5 and of the Rosenbrock-W method's own stiff directions).
//
// A clearance joint is stiff in short phases only: while a pin sticks in its bushing
// during an impact, the friction law's ramp between the static and dynamic velocity
// limits acts as a damper of μF_n/(v1 − v0) ≈ 10⁶–10⁷ N s/m on a light relative motion,
// and dopri5 crawls at 0.1 µs steps whatever its tolerance. Elsewhere (free flight, the
// micro-vibrations of light continuous contact) the steps are accuracy-limited and the
// explicit fifth-order pair is the cheaper method. So:
//   - dopri5 → ROS34PW2: Hairer's estimate h·ρ (stages 6 and 7 of dopri5, both at t + h)
//     above `suspect_limit` for `patience` consecutive accepted steps makes the phase
//     suspect; ROS34PW2 then builds its W at the current point (one right-hand side per
//     stiff direction) and takes over if dopri5's step times the fastest rate of W's
//     stiff directions exceeds `stiff_limit` — dopri5 sits at its stability boundary
//     there (h·ρ ≈ 3.3 on the negative real axis), so its step is set by stability.
//     Hairer's estimate alone separates the phases poorly on a mechanism (measured on
//     the nine-bar: 1–3 in the sticking phases, up to 1.5 in light contact, where dopri5
//     is accurate and should stay), hence the second test; a suspicion that W does not
//     confirm doubles `patience` (up to `max_patience`), so light contact is not
//     probed at every step.
//   - ROS34PW2 → dopri5 after `switch_after` consecutive accepted steps whose h·ρ, with ρ
//     the fastest rate of W's stiff directions, is below `calm_limit`: dopri5 would be
//     stable, with room, at the step the implicit method takes.
// A hand-over copies the current point and the step proposal; nothing is evaluated.
// The thresholds were chosen on 100 cycles of params/nine_bar_clearance.prm (right-hand
// sides 4.76 M with dopri5, 4.08 M with this; the choices within ±4 % of each other,
// the chaotic scatter of equivalent runs).
#include "mbs/adaptive_runge_kutta.h"

#include <algorithm>

namespace wearlink::mbs
{
  namespace
  {
    constexpr double suspect_limit = 1.0;
    constexpr double stiff_limit   = 2.0;
    constexpr double calm_limit    = 1.5;
    constexpr int    switch_after  = 3;
    constexpr int    max_patience  = 8;

    class StiffSwitching : public Integrator
    {
    public:
      StiffSwitching(OdeSystem &system, const IntegratorSettings &settings)
        : Integrator(system, settings)
        , explicit_method(make_dopri5(system, settings))
        , implicit_method(make_ros34pw2(system, settings))
        , active(explicit_method.get())
      {
      }

      void
      reset(const double time, const Eigen::VectorXd &state) override
      {
        active->reset(time, state);
        synchronize();
      }

      void
      step(const double t_limit) override
      {
        active->step(t_limit);
        synchronize();
        choose_method();
      }

      /** Cut on dopri5's continuous extension (`interpolate_events`), else taken again. */
      void
      end_step_at(const double t_end, const double t_start, const Eigen::VectorXd &y_start) override
      {
        if (!settings.interpolate_events || active != explicit_method.get())
          return Integrator::end_step_at(t_end, t_start, y_start);
        active->end_step_at(t_end, t_start, y_start);
        synchronize();
      }

      double
      proposed_step() const override
      {
        return active->proposed_step();
      }

      void
      dense_output(const double time, double *out) const override
      {
        active->dense_output(time, out);
      }

    private:
      /** The active method's point and the counters of both. */
      void
      synchronize()
      {
        t             = active->time();
        t_prev        = active->previous_time();
        y             = active->state();
        y_prev        = active->previous_state();
        f             = active->derivative();
        n_accepted    = explicit_method->n_accepted + implicit_method->n_accepted;
        n_rejected    = explicit_method->n_rejected + implicit_method->n_rejected;
        n_evaluations = explicit_method->n_evaluations + implicit_method->n_evaluations;
      }

      /** Hand over after the last accepted step if the stiffness tests say so. */
      void
      choose_method()
      {
        const double indicator = active->stiffness_indicator();
        if (active == implicit_method.get())
          {
            run = indicator < calm_limit ? run + 1 : 0;
            if (run >= switch_after)
              hand_over(*explicit_method);
            return;
          }
        run = indicator > suspect_limit ? run + 1 : 0;
        if (run < patience)
          return;
        // Suspected: ask the implicit method's W (built at this point) whether the
        // step is at dopri5's stability limit of the stiff directions.
        run            = 0;
        const double h = explicit_method->proposed_step();
        implicit_method->take_over(t, y, f, h);
        if (h * implicit_method->probe_stiff_rate() > stiff_limit)
          {
            active   = implicit_method.get();
            patience = switch_after;
            ++switches;
          }
        else
          patience = std::min(2 * patience, max_patience); // light contact: ask less often
      }

      void
      hand_over(AdaptiveRungeKutta &next)
      {
        next.take_over(t, y, f, active->proposed_step());
        active = &next;
        run    = 0;
        ++switches;
      }

      std::unique_ptr<AdaptiveRungeKutta> explicit_method, implicit_method;
      AdaptiveRungeKutta                 *active;
      int                                 run      = 0;
      int                                 patience = switch_after;
      long                                switches = 0;
    };
  } // namespace

  std::unique_ptr<Integrator>
  make_dopri5_stiff(OdeSystem &system, const IntegratorSettings &settings)
  {
    return std::make_unique<StiffSwitching>(system, settings);
  }
} // namespace wearlink::mbs
