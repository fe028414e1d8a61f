// SPDX-License-Identifier: LGPL-2.1-or-later
// Time integrators for y' = f(t, y). A closed set (doc/contributing.md §5: numerical methods are
// an enum + switch whose default throws):
//   rk4     classical fixed-step Runge–Kutta, the seed's 1e-4 s; cubic Hermite dense
//           output from (y, f) at both ends.
//   dopri5  Dormand–Prince 5(4) with embedded error estimate, PI step-size control
//           (Hairer, Nørsett & Wanner, Solving ODE I, §II.4–5 and the dopri5 code) and
//           the 4th-order continuous extension for dense output.
//   dop853  Dormand–Prince 8(5,3) (Hairer's DOP853: 12 stages, an error estimate that
//           blends the 5th- and 3rd-order embedded solutions, I control) with the
//           7th-order dense output, whose three extra stages are evaluated only for the
//           steps in which dense output is asked for.
//   ros34pw2 the linearly implicit Rosenbrock-W method ROS34PW2 (Rang & Angermann 2005:
//           4 stages, order 3, embedded order 2, L-stable, order kept with any
//           approximate Jacobian), its Jacobian built from the system's stiff
//           directions only (rosenbrock_w.cc); cubic Hermite dense output.
//   dopri5-stiff dopri5 that hands over to ros34pw2 while the steps are limited by
//           stability rather than accuracy (stiff contact phases: a sticking
//           friction ramp, a heavily damped contact), and back when they are not
//           (stiff_switching.cc).
// All finish every step with f evaluated at the new point (FSAL for dopri5, the next
// step's first stage for rk4), so an observer reading the system after step() sees the
// accelerations and reactions of the accepted state.
#pragma once

#include <Eigen/Core>

#include <memory>
#include <string>
#include <vector>

namespace wearlink::mbs
{
  /**
   * A direction in which the right-hand side of a second-order system (below) changes
   * steeply: the gradient w of a scalar s = w·q (for positions) or ṡ = w·q̇ (for
   * velocities) on which a force depends stiffly, e.g. a contact's penetration and its
   * relative sliding velocity. A linearly implicit method builds its Jacobian from the
   * change of f along these directions only (rosenbrock_w.cc).
   */
  struct StiffDirection
  {
    Eigen::VectorXd w;                     ///< gradient over the n coordinates q
    bool            position      = false; ///< f depends steeply on w·q
    bool            velocity      = false; ///< f depends steeply on w·q̇
    double          position_step = 0;     ///< finite-difference step of w·q [its unit]
    double          velocity_step = 0;     ///< finite-difference step of w·q̇ [its unit / s]
  };

  class OdeSystem
  {
  public:
    virtual ~OdeSystem() = default;
    virtual unsigned int
    size() const = 0;
    virtual void
    rhs(double t, const double *y, double *dydt) = 0;
    /**
     * For systems y = [q | q̇ | rest] whose first n components satisfy q' = q̇ exactly:
     * n. 0 (default): not of this form (no linearly implicit method applies).
     */
    virtual unsigned int
    n_second_order() const
    {
      return 0;
    }
    /** The stiff directions at (t, y) (second-order systems; default none). */
    virtual void
    stiff_directions(double /*t*/, const double * /*y*/, std::vector<StiffDirection> &out)
    {
      out.clear();
    }
  };

  enum class IntegratorType
  {
    rk4,
    dopri5,
    dop853,
    ros34pw2,
    dopri5_stiff
  };

  /** A scene's method name ("rk4", "dopri5", …) → type; throws InputError on anything else. */
  IntegratorType
  parse_integrator_type(const std::string &name);
  std::string
  integrator_names();
  /** The scene's name of @p type. */
  std::string
  integrator_name(IntegratorType type);

  struct IntegratorSettings
  {
    IntegratorType type               = IntegratorType::dopri5;
    double         time_step          = 1e-4; ///< rk4 step [s]
    double         relative_tolerance = 1e-6;
    /** Absolute tolerance per component; components with a value ≤ 0 are not error-controlled. */
    std::vector<double> absolute_tolerance;
    double              max_step     = 1e-3;  ///< [s]
    double              min_step     = 1e-14; ///< below this a step is a NumericalError [s]
    double              initial_step = 0;     ///< 0: automatic [s]
    /** End a step at an event on dopri5's continuous extension instead of integrating to it. */
    bool interpolate_events = false;
  };

  class Integrator
  {
  public:
    virtual ~Integrator() = default;

    /** Start (or restart after an event) at (t, y): evaluates f(t, y). */
    virtual void
    reset(double t, const Eigen::VectorXd &y);

    /** Take one accepted step that does not pass @p t_limit. */
    virtual void
    step(double t_limit) = 0;

    /**
     * End the last accepted step, which began at (@p t_start, @p y_start), at @p t_end ∈
     * (previous_time(), time()) instead (an event inside it): the step is taken again
     * from its start with @p t_end as the limit (error-controlled, several steps if need
     * be), or, with `interpolate_events`, dopri5 takes the point from its continuous
     * extension. Evaluates f at the new point either way.
     */
    virtual void
    end_step_at(double t_end, double t_start, const Eigen::VectorXd &y_start);

    /**
     * The size the next step would try [s] (before the limit passed to step()); 0 if
     * the method has no proposal yet.
     */
    virtual double
    proposed_step() const
    {
      return settings.time_step;
    }

    /** Dense output of the last step at @p t ∈ [previous_time(), time()]. */
    virtual void
    dense_output(double t, double *y) const = 0;

    double
    time() const
    {
      return t;
    }
    double
    previous_time() const
    {
      return t_prev;
    }
    const Eigen::VectorXd &
    state() const
    {
      return y;
    }
    const Eigen::VectorXd &
    previous_state() const
    {
      return y_prev;
    }
    /** f(time(), state()). */
    const Eigen::VectorXd &
    derivative() const
    {
      return f;
    }

    long n_accepted    = 0;
    long n_rejected    = 0;
    long n_evaluations = 0;

  protected:
    Integrator(OdeSystem &system, const IntegratorSettings &settings);

    void
    evaluate(double time, const Eigen::VectorXd &state, Eigen::VectorXd &derivative);
    /** Make (time, state) with f = @p derivative the current point, with no step behind it. */
    void
    start_at(double time, const Eigen::VectorXd &state, const Eigen::VectorXd &derivative);

    OdeSystem         &system;
    IntegratorSettings settings;
    double             t = 0, t_prev = 0;
    Eigen::VectorXd    y, y_prev, f, f_prev;
  };

  std::unique_ptr<Integrator>
  make_integrator(OdeSystem &system, const IntegratorSettings &settings);

  /**
   * The cubic Hermite interpolant at s ∈ [0, 1] of a step of length @p h from (y0, f0)
   * to (y1, f1), into @p out (dense output of rk4 and of the Rosenbrock-W method).
   */
  void
  hermite_interpolate(double                 s,
                      double                 h,
                      const Eigen::VectorXd &y0,
                      const Eigen::VectorXd &f0,
                      const Eigen::VectorXd &y1,
                      const Eigen::VectorXd &f1,
                      double                *out);
} // namespace wearlink::mbs
