// SPDX-License-Identifier: LGPL-2.1-or-later
// What the embedded Runge–Kutta pairs (dopri5, dop853) share: the weighted error norm,
// the step-size controller (Hairer, Nørsett & Wanner, Solving ODE I, §II.4), the
// starting-step heuristic and the checks of the proposed step. Each pair supplies its
// stages, its error estimate and its dense output.
#pragma once

#include "mbs/integrator.h"

#include <Eigen/Core>

#include <algorithm>
#include <memory>
#include <vector>

namespace wearlink::mbs
{
  class AdaptiveRungeKutta : public Integrator
  {
  public:
    /** Trial steps until one meets the tolerance; that one becomes the current point. */
    void
    step(double t_limit) override;

    double
    proposed_step() const override
    {
      return h > 0 ? std::min(h, settings.max_step) : 0.0;
    }

    /**
     * h·ρ of the last accepted step: the step times an estimate of the largest
     * eigenvalue magnitude of the Jacobian that matters for stability (0: the method
     * has no estimate). Against the method's stability boundary it tells whether the
     * step was limited by stability rather than accuracy.
     */
    virtual double
    stiffness_indicator() const
    {
      return 0;
    }

    /**
     * The fastest rate ρ [1/s] of the method's own model of the stiffness, built at its
     * current point (a Rosenbrock-W method builds W there and keeps it for its next
     * step); 0 for methods without one.
     */
    virtual double
    probe_stiff_rate()
    {
      return 0;
    }

    /**
     * Continue from another method's current point (t, y, f) with the step proposal
     * @p h_proposal, without evaluating f (stiff switching).
     */
    void
    take_over(double t, const Eigen::VectorXd &y, const Eigen::VectorXd &f, double h_proposal);

    /** The pair's continuous extension of the last step; its start point before any step. */
    void
    dense_output(double time, double *out) const final;

  protected:
    /** The pair's stages for a trial step to @p t_new; returns the normalized error. */
    virtual double
    attempt(double hs, double t_new) = 0;
    /** Make the accepted trial step the current point (dense output, advance()). */
    virtual void
    accept(double hs, double t_new) = 0;
    /** The continuous extension of the last step at s = (time − t_prev)/(step_end − t_prev). */
    virtual void
    interpolate(double s, double *out) const = 0;
    /** The name in messages ("dopri5"). */
    virtual const char *
    method_name() const = 0;

    /** Constants of the controller h_new = h / clamp(err^expo / err_old^beta / safe). */
    struct Controller
    {
      double expo;    ///< 1/(q+1) − (share of) beta for an error estimate of order q
      double beta;    ///< the PI memory (0: a plain I controller)
      double fac_min; ///< largest shrink per step, as the reciprocal
      double fac_max; ///< largest growth per step
      double safe = 0.9;
    };

    AdaptiveRungeKutta(OdeSystem &system, const IntegratorSettings &settings, const Controller &controller, int order);

    /**
     * The step to try from t towards @p t_limit (the current proposal, capped by the
     * maximum step and the limit); NumericalError below the minimum step.
     */
    double
    trial_step(double t_limit, const char *method) const;

    /** √(mean over controlled components of (e_i / (atol_i + rtol·max|y_i|,|ŷ_i|))²). */
    double
    error_norm(const Eigen::VectorXd &e, const Eigen::VectorXd &y_new) const;
    /** The sum of squares inside error_norm, and how many components it counts. */
    double
    error_sum(const Eigen::VectorXd &e, const Eigen::VectorXd &y_new, unsigned int &n_controlled) const;

    /**
     * Accept or reject a trial step @p hs with error @p err (≤ 1 accepts); updates the
     * proposal h for the next try. @p truncated: the step was shortened to land on a
     * limit, so a larger earlier proposal is kept.
     */
    bool
    control(double err, double hs, bool &last_rejected);

    /** The point was replaced from outside (take_over()): drop what depends on the old one. */
    virtual void
    restarted()
    {
    }

    /** Hairer's starting step (Solving ODE I, §II.4) for a method of order @p order. */
    double
    initial_step_size();

    /** Make the accepted step's end the current point. */
    void
    advance(double t_new, const Eigen::VectorXd &y_new, const Eigen::VectorXd &f_new);

    std::vector<double> tolerance;
    double              h        = 0;
    double              step_end = 0; ///< the end of the step the continuous extension belongs to [s]
    Controller          controller;
    int                 order;

  private:
    double fac_old = 1e-4;
  };

  /** The Dormand–Prince 5(4) pair (Hairer's dopri5) with its 4th-order dense output. */
  std::unique_ptr<AdaptiveRungeKutta>
  make_dopri5(OdeSystem &system, const IntegratorSettings &settings);

  /** The Dormand–Prince 8(5,3) pair (Hairer's DOP853) with its 7th-order dense output. */
  std::unique_ptr<Integrator>
  make_dop853(OdeSystem &system, const IntegratorSettings &settings);

  /** The Rosenbrock-W method ROS34PW2 (rosenbrock_w.cc); needs a second-order system. */
  std::unique_ptr<AdaptiveRungeKutta>
  make_ros34pw2(OdeSystem &system, const IntegratorSettings &settings);

  /** dopri5 switching to ROS34PW2 in stiff phases (stiff_switching.cc). */
  std::unique_ptr<Integrator>
  make_dopri5_stiff(OdeSystem &system, const IntegratorSettings &settings);
} // namespace wearlink::mbs
