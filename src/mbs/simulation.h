// SPDX-License-Identifier: LGPL-2.1-or-later
// Time integration of a Mechanism: the ODE y = [q | v | z] with z the energy
// accumulators (reaction work, its absolute value, damping and friction dissipation),
// integrated by the chosen integrator, with events of the force elements (contact
// onset and separation) located on the dense output:
//   - an event is a change of the sign of a force element's event function against its
//     mode (free → penetration > 0, contact → penetration ≤ 0);
//   - its time t* is found by Illinois regula falsi on the dense output;
//   - with `locate` (the adaptive methods) the step is ended at t* (Integrator::
//     end_step_at: taken again up to t*, or with `Event point = interpolated` cut on
//     dopri5's continuous extension), the mode is switched there, and
//     integration restarts; without it (rk4, fixed grid as in the seed) the mode
//     switches at the end of the step, but the impact velocity is still read from the
//     interpolated state at t* (seed eq. 11's δ̇⁽⁻⁾).
// Observers see every accepted step (never a step that was discarded for an event).
#pragma once

#include "mbs/integrator.h"
#include "mbs/mechanism.h"

#include <Eigen/Core>

#include <memory>
#include <vector>

namespace wearlink::mbs
{
  /** y' = f(t, y) for a mechanism, with the energy accumulators. */
  class MechanismOde : public OdeSystem
  {
  public:
    /** Offsets of the accumulators after q and v. */
    enum Quadrature : unsigned int
    {
      reaction_work = 0,    ///< ∫ −q̇ᵀΦqᵀλ dt [J]
      reaction_work_abs,    ///< ∫ |q̇ᵀΦqᵀλ| dt [J]
      damping_dissipation,  ///< ∫ P_damping dt [J]
      friction_dissipation, ///< ∫ P_friction dt [J]
      n_quadratures
    };

    explicit MechanismOde(Mechanism &mechanism)
      : mechanism(mechanism)
    {
    }

    unsigned int
    size() const override
    {
      return 2 * mechanism.n_coordinates() + n_quadratures;
    }

    void
    rhs(double t, const double *y, double *dydt) override;

    unsigned int
    n_second_order() const override
    {
      return mechanism.n_coordinates();
    }

    /** The force elements' stiff directions (contacts) at (t, y). */
    void
    stiff_directions(double t, const double *y, std::vector<StiffDirection> &out) override;

    unsigned int
    q_offset() const
    {
      return 0;
    }
    unsigned int
    v_offset() const
    {
      return mechanism.n_coordinates();
    }
    unsigned int
    z_offset() const
    {
      return 2 * mechanism.n_coordinates();
    }

    Mechanism &mechanism;
  };

  struct SimulationSettings
  {
    IntegratorSettings integrator;
    /** Time resolution of located events [s]. */
    double event_time_tolerance = 1e-12;
    /**
     * Step budget [1/s]: more than step_budget_grace + this × the simulated time steps
     * (rejected ones included) since initialize() is a NumericalError; 0: no budget.
     */
    double max_steps_per_second = 1e7;
    double step_budget_grace    = 5e4;
    /**
     * Shorten a step that the ballistic prediction q(τ) = q + τ q̇ + ½ τ² q̈ from its
     * start puts across a contact onset, so that it ends just past the onset instead of
     * being rejected after its late stages met the contact stiffness (needs event
     * location).
     */
    bool predict_onsets = true;
  };

  class Simulation;

  /** What an observer sees after each accepted step. */
  struct StepContext
  {
    Simulation &simulation;
    double      t_previous; ///< start of the step [s]
    double      t;          ///< end of the step [s]
    /** State at t: [q | v | z]. */
    const Eigen::VectorXd &y;
    /** f(t, y): [q̇ | q̈ | ż]. */
    const Eigen::VectorXd &dydt;
  };

  class StepObserver
  {
  public:
    virtual ~StepObserver() = default;
    /** Called once before the first step with the initial state. */
    virtual void
    on_start(const StepContext &)
    {
    }
    virtual void
    on_step(const StepContext &context) = 0;
  };

  class Simulation
  {
  public:
    Simulation(Mechanism &mechanism, const SimulationSettings &settings);

    /** Start at time @p t0 from assembled (q0, v0); the accumulators start at 0. */
    void
    initialize(double t0, const Eigen::VectorXd &q0, const Eigen::VectorXd &v0);

    /** Start from a full state vector (checkpoint / continuation). */
    void
    initialize_state(double t0, const Eigen::VectorXd &y0);

    /** Integrate up to @p t_end, notifying @p observers after every accepted step. */
    void
    run(double t_end, const std::vector<StepObserver *> &observers);

    /** Dense output at @p t within the last accepted step. */
    void
    state_at(double t, Eigen::VectorXd &y) const;

    /** Recompute f at @p t for state @p y (clobbers the mechanism's workspace). */
    void
    derivative_at(double t, const Eigen::VectorXd &y, Eigen::VectorXd &dydt);

    double
    time() const
    {
      return integrator->time();
    }
    const Eigen::VectorXd &
    state() const
    {
      return integrator->state();
    }
    const MechanismOde &
    ode() const
    {
      return system;
    }
    Mechanism &
    get_mechanism() const
    {
      return mechanism;
    }
    const Integrator &
    get_integrator() const
    {
      return *integrator;
    }

    long
    n_events() const
    {
      return events;
    }
    /** Steps shortened because the ballistic prediction put a contact onset inside them. */
    long
    n_predicted_onsets() const
    {
      return predicted_onsets;
    }
    /** Steps after which a force element took up or gave up holding its contact. */
    long
    n_hold_switches() const
    {
      return hold_switches;
    }
    /** Steps ended early at an event or at a held contact's release. */
    long
    n_event_restarts() const
    {
      return restarts;
    }

  private:
    /** NumericalError when the steps since initialize() exceed the budget. */
    void
    check_step_budget() const;

    /**
     * The end of the next step: @p t_end, or just past the earliest contact onset among
     * the free elements of @p elements that the ballistic prediction puts inside the
     * integrator's proposed step.
     */
    double
    step_limit(double t_end, const std::vector<ForceElement *> &elements) const;
    /**
     * After a step from (@p t_start, @p y_start): the elements of @p event_elements whose
     * mode no longer matches the state, into @p triggered with their located times in
     * @p roots; with event location the step is ended at the first of them
     * (Integrator::end_step_at), and only the events at that time are kept (later ones
     * are found again).
     */
    void
    find_events(double                             t_start,
                const Eigen::VectorXd             &y_start,
                const std::vector<ForceElement *> &event_elements,
                std::vector<ForceElement *>       &triggered,
                std::vector<double>               &roots);
    /** Switch the modes of @p triggered at their @p roots; true if any switched. */
    bool
    switch_modes(const std::vector<ForceElement *> &triggered, const std::vector<double> &roots);
    /** The held forces at (@p t, @p y) in the elements (one evaluation unless they are from there). */
    void
    held_forces_here(double t, const Eigen::VectorXd &y);
    /**
     * If a held force is no longer compressive at the end of the step from (@p t_start,
     * @p y_start), take the step again so that it ends where it fell to zero.
     */
    void
    locate_hold_release(double t_start, const Eigen::VectorXd &y_start, const std::vector<ForceElement *> &elements);
    /** After an accepted step: let @p elements take up or give up holding; true if any did. */
    bool
    update_holds(const std::vector<ForceElement *> &elements);

    /**
     * How deep a predicted onset may be crossed by the step that meets it: the
     * integrator's absolute position tolerance [m] (the event functions of contact
     * elements are penetrations). Small enough that the contact's stiffness barely acts
     * within the step, which then ends just past the onset, where it is located as usual.
     */
    double
    onset_penetration() const
    {
      return position_tolerance;
    }

    /** Locate the root of element @p e's event function in the last step. */
    double
    locate(const ForceElement &e, bool onset) const;

    Mechanism                  &mechanism;
    SimulationSettings          settings;
    MechanismOde                system;
    std::unique_ptr<Integrator> integrator;
    bool                        locate_events;
    long                        events           = 0;
    long                        restarts         = 0;
    mutable long                predicted_onsets = 0;
    long                        hold_switches    = 0;
    Eigen::VectorXd             hold_accelerations, hold_state, event_state;
    double                      position_tolerance = 1e-9; ///< absolute, of the coordinates q [m]
    double                      budget_start_time  = 0;    ///< time of initialize() [s]
    long                        budget_start_steps = 0;    ///< steps taken before it
    mutable Eigen::VectorXd     scratch;
    std::vector<double>         end_trig; ///< the bodies' (cos θ, sin θ) at the end of a step
  };
} // namespace wearlink::mbs
