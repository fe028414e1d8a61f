// SPDX-License-Identifier: LGPL-2.1-or-later
// Kinematic constraints Φ(q, t) = 0 between two bodies (or a body and the ground),
// each with its Jacobian blocks Φq, its time derivative Φt and the acceleration
// right-hand side γ = −(Φq q̇)_q q̇ − 2Φqt q̇ − Φtt, so that Φq q̈ = γ (doc/models.md §2,
// seed eqs 24–26). The library is generic: mechanisms are assembled from these pieces
// by the scene, never written out as equations in C++.
//
//   revolute       P_j − P_i − e0 = 0         (2 eqs; e0 = 0 for an ideal hinge; a
//                                              non-zero e0 pins a clearance joint at a
//                                              given eccentricity during assembly)
//   translational  n_i · (P_j − P_i) = 0,     (2 eqs; n_i ⟂ the axis fixed in body i)
//                  θ_j − θ_i − θ0 = 0
//   fixed-angle    θ_j − θ_i − θ0 = 0         (1 eq)
//   angle-driver   θ_j − θ_i − θ0 − ω t = 0   (1 eq, rheonomic)
// P_k = r_k + A(θ_k) s_k is the global position of the attachment point s_k of body k.
#pragma once

#include "mbs/types.h"

#include <array>
#include <memory>
#include <string>

namespace wearlink::mbs
{
  /** Values of at most two constraint equations and their derivatives. */
  struct ConstraintRows
  {
    unsigned int n           = 0;
    double       phi[2]      = {0, 0};
    double       phi_t[2]    = {0, 0};
    double       gamma[2]    = {0, 0};
    double       jac_i[2][3] = {{0, 0, 0}, {0, 0, 0}}; ///< ∂Φ/∂(x_i, y_i, θ_i)
    double       jac_j[2][3] = {{0, 0, 0}, {0, 0, 0}}; ///< ∂Φ/∂(x_j, y_j, θ_j)
  };

  class Constraint
  {
  public:
    Constraint(std::string name, int body_i, int body_j)
      : name(std::move(name))
      , body_i(body_i)
      , body_j(body_j)
    {
    }
    virtual ~Constraint() = default;

    virtual unsigned int
    n_equations() const = 0;

    /** Evaluate Φ, Φq, Φt and γ at time @p t for the state @p s. */
    virtual void
    evaluate(double t, const StateView &s, ConstraintRows &out) const = 0;

    /**
     * Which of the three Jacobian entries per body (x, y, θ) of equation @p row are
     * constants, the same at every state and time (e.g. the ±1 of a revolute's position
     * rows). The Schur complement folds products of constant entries once at set-up;
     * declaring an entry constant that is not gives wrong accelerations, so the unit
     * tests check every declaration at random states. The default declares none.
     */
    virtual std::array<bool, 3>
    constant_jacobian(unsigned int /*row*/) const
    {
      return {{false, false, false}};
    }

    /** Type name as written in the scene ("revolute", …). */
    virtual std::string
    type() const = 0;

    /**
     * The constant rate a rheonomic constraint prescribes (ω of an angle driver)
     * [rad/s]; 0 for a constraint that does not depend on time.
     */
    virtual double
    rate() const
    {
      return 0.0;
    }

    const std::string name;
    const int         body_i;
    const int         body_j;
  };

  std::unique_ptr<Constraint>
  make_revolute(const std::string &name,
                int                body_i,
                const Vec2        &s_i,
                int                body_j,
                const Vec2        &s_j,
                const Vec2        &offset = Vec2(0, 0));

  /** @p axis_i: axis direction in body i's frame (normalized here). */
  std::unique_ptr<Constraint>
  make_translational(const std::string &name,
                     int                body_i,
                     const Vec2        &s_i,
                     const Vec2        &axis_i,
                     int                body_j,
                     const Vec2        &s_j,
                     double             angle_offset);

  std::unique_ptr<Constraint>
  make_fixed_angle(const std::string &name, int body_i, int body_j, double angle_offset);

  /** θ_j − θ_i = θ0 + ω t. @p angular_velocity ω [rad/s]. */
  std::unique_ptr<Constraint>
  make_angle_driver(const std::string &name, int body_i, int body_j, double angle_offset, double angular_velocity);
} // namespace wearlink::mbs
