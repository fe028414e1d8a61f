// SPDX-License-Identifier: LGPL-2.1-or-later
// The pin of a sliced joint as an elastic beam (doc/models.md §1.8). Without it the pin
// is rigid: each slice sees the pin centre the mechanism places. With it, the pin is an
// Euler–Bernoulli beam of bending stiffness EI held by its supports, loaded by the
// slices' elastic forces f_j at their heights z_j; it deflects by
//     v_i = Σ_j C_ij f_j      (each in-plane direction alike: a round section),
// C the beam's flexibility at the slices for the supports chosen:
//   - pinned:     simply supported at z = ±(L/2 + d) (d: Support distance);
//   - clamped:    built in at z = ±(L/2 + d);
//   - cantilever: built in at z = −(L/2 + d), free at the pin's other end z = L/2.
// Slice i then sees the pin centre moved by v_i, and its force f_i depends on it: the
// deflections are the solution of v = C f(e + v), found by Newton's method at every
// state the mechanism evaluates (the last solution is kept: the slices of one joint ask
// for it in turn at the same state). The beam carries the elastic forces only (the
// contact's hysteresis damping is left out of its load) and stores ½ Σ v_i·f_i.
#pragma once

#include "mbs/types.h"

#include <Eigen/Dense>

#include <vector>

namespace wearlink::contact
{
  class ClearanceJoint;

  enum class PinSupport
  {
    rigid,
    pinned,
    cantilever,
    clamped
  };

  /** How a sliced joint's pin bends (SliceLayout::bending). */
  struct PinBending
  {
    PinSupport support           = PinSupport::rigid;
    double     bending_stiffness = 0; ///< EI [N m²] (> 0 when the pin bends)
    double     support_distance  = 0; ///< d, the supports beyond the bushing's ends [m]
  };

  /**
   * C_ij: the beam's deflection at @p positions[i] per unit force at @p positions[j]
   * [m/N], the heights measured from the bushing's mid-plane, the bushing @p length long.
   * An exact Euler–Bernoulli solution (cubic Hermite elements between the supports and
   * the load points). Empty for a rigid pin.
   */
  Eigen::MatrixXd
  pin_flexibility(const PinBending &bending, double length, const std::vector<double> &positions);

  class ElasticPin
  {
  public:
    /** The beam over @p positions (z_i, bushing @p length long). */
    ElasticPin(const PinBending &bending, double length, const std::vector<double> &positions);

    /**
     * The slices it carries, in the order of their positions: their bodies, attachment
     * points and offsets tell where the rigid pin is.
     */
    void
    attach(std::vector<const ClearanceJoint *> slices);

    /** The deflection of the pin at slice @p i at state @p s, global axes [m]. */
    mbs::Vec2
    deflection(unsigned int i, const mbs::StateView &s) const;

    /** The strain energy of the bent pin at state @p s [J]. */
    double
    bending_energy(const mbs::StateView &s) const;

    /**
     * With the rigid pin centre at @p e from the joint's nominal bore centre (bushing
     * frame) and the relative angle @p relative_angle: the slices' elastic forces on the
     * bent pin (bushing frame) [N].
     */
    const std::vector<mbs::Vec2> &
    forces(const mbs::Vec2 &e, double relative_angle) const;

    /** The same, the pin's deflections (bushing frame) [m]. */
    const std::vector<mbs::Vec2> &
    deflections(const mbs::Vec2 &e, double relative_angle) const;

    /** States at which Newton's method did not reach its tolerance (the best point was used). */
    long
    n_failures() const
    {
      return failures;
    }

    const Eigen::MatrixXd &
    flexibility() const
    {
      return c;
    }

  private:
    /** Solve for the state (e, relative angle) unless it is the last one. */
    void
    solve(const mbs::Vec2 &e, double relative_angle) const;
    /** The slices' forces with the pin bent by @p v (bushing frame). */
    void
    slice_forces(const Eigen::VectorXd &v, std::vector<mbs::Vec2> &f) const;
    /** r = v − C f(v). */
    Eigen::VectorXd
    residual(const Eigen::VectorXd &v, std::vector<mbs::Vec2> &f) const;
    /** Factorize the Jacobian of the residual at @p x. */
    void
    update_jacobian(const Eigen::VectorXd &x) const;
    /** The rigid pin centre from the nominal bore centre (bushing frame) at state @p s. */
    mbs::Vec2
    rigid_eccentricity(const mbs::StateView &s) const;

    Eigen::MatrixXd                     c;
    std::vector<const ClearanceJoint *> slices;
    std::vector<mbs::Vec2>              offsets; ///< the slices' bore offsets (bushing frame)
    int                                 bushing_body = mbs::ground, pin_body = mbs::ground;
    mbs::Vec2                           nominal_bushing_point{0, 0}, pin_point{0, 0};

    mutable bool                                 solved = false;
    mutable mbs::Vec2                            last_e{0, 0};
    mutable double                               last_angle = 0;
    mutable std::vector<mbs::Vec2>               v, f;
    mutable Eigen::VectorXd                      warm; ///< the last solution, Newton's start
    mutable long                                 failures = 0;
    mutable Eigen::PartialPivLU<Eigen::MatrixXd> lu;
    mutable bool                                 have_jacobian = false, fresh = false;
  };
} // namespace wearlink::contact
