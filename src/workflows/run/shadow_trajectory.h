// SPDX-License-Identifier: LGPL-2.1-or-later
// Largest Lyapunov exponent from the simulation itself (no delay embedding): the
// two-trajectory method of Benettin, Galgani & Strelcyn (1976) / Benettin et al. (1980),
// the finite-difference form of integrating the variational equations. A second copy
// of the scene (the shadow) starts at t_b from the reference state displaced by d0 and
// is integrated by the same integrator; every renormalization interval τ the distance
// d = |y_shadow − y_ref| is measured on the reference's dense output, ln(d/d0) is
// added, and the shadow is put back at distance d0 along the same direction. Then
// λ = Σ ln(d/d0) / (N τ) [1/s, natural log].
//
// "Where the dynamics allows": it needs no smoothness of the right-hand side (contact
// onsets are located in each trajectory separately), but d0 must stay far above the
// integration error (else the error's growth is measured) and far below the clearance
// (else saturation). The distance mixes positions [m, rad] and velocities scaled by the
// driving period over 2π [s], so that both count; the asymptotic exponent does not
// depend on that choice. Components that violate the constraints decay (Baumgarte), so
// a 0-DOF mechanism gives a negative exponent (the ideal nine-bar: −4.5 1/s, the
// Baumgarte double root at −5 1/s).
//
// Status: the integration error of the two independently stepped trajectories,
// amplified at every located impact, acts as noise of the size of the tolerance, so d0
// must stay far above it. At the nine-bar's scene tolerance (1e-6) it does not: 285 …
// 1378 1/s for d0 = 1e-6 … 1e-9 m. At 1e-11 (10 periods, τ = 5 ms): 100–145 1/s before
// and 346–362 1/s after 50,000 rev of wear for d0 = 1e-8 … 1e-6 m, i.e. known to about
// ±20 % before wear (doc/tutorials/nonlinear_dynamics.md). The wear scenes' before/after comparison runs it at its
// own tolerance (workflows/wear/wear_run.cc).
#pragma once

#include "io/scene.h"
#include "mbs/simulation.h"

#include <memory>
#include <string>
#include <vector>

namespace wearlink::workflows
{

  /** Settings of ShadowTrajectory. */
  struct ShadowTrajectorySettings
  {
    /** Start t_b [s]. */
    double begin_time = 0.0;
    /** Separation d0 [m]. */
    double separation = 1e-6;
    /** Renormalization interval τ [s]. */
    double interval = 0.02;
    /** Scale of velocity differences in the distance [s]. */
    double velocity_scale = 0.0;
  };

  /**
   * An observer of the reference run that drives the shadow copy of the same scene (read
   * again from its file with the same overrides) and accumulates the exponent.
   */
  class ShadowTrajectory : public mbs::StepObserver
  {
  public:
    ShadowTrajectory(const io::Scene &reference, const ShadowTrajectorySettings &settings);
    ~ShadowTrajectory();

    void
    on_step(const mbs::StepContext &context) override;

    /** λ [1/s, natural log]; 0 before the first renormalization. */
    double
    exponent() const;
    std::size_t
    n_renormalizations() const
    {
      return n;
    }
    /** Running estimate after each renormalization [1/s] at these times [s]. */
    const std::vector<double> &
    running_exponent() const
    {
      return running;
    }
    const std::vector<double> &
    running_time() const
    {
      return times;
    }

  private:
    double
    distance(const Eigen::VectorXd &a, const Eigen::VectorXd &b) const;

    ShadowTrajectorySettings         settings;
    std::unique_ptr<io::Scene>       shadow_scene;
    std::unique_ptr<mbs::Simulation> shadow;
    unsigned int                     n_coordinates = 0;
    double                           next_time     = 0.0;
    bool                             started       = false;
    double                           sum_log       = 0.0;
    std::size_t                      n             = 0;
    std::vector<double>              running, times;
    Eigen::VectorXd                  y_ref;
  };
} // namespace wearlink::workflows
