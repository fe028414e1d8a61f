// SPDX-License-Identifier: LGPL-2.1-or-later
// Force elements: everything that applies forces between bodies without being a
// kinematic constraint (here: the clearance revolute joint of src/contact). A force
// element adds its generalized forces to the right-hand side of the equations of motion
// and reports the power it dissipates, so that the energy balance of a run can be
// checked (ΔT + ΔV = W_constraints − D_damping − D_friction).
//
// Elements with a discrete mode (contact / no contact) expose an event function that
// the integrator locates in time; the element's mode (e.g. the impact velocity captured
// at contact onset, seed eq. 11) changes only in on_event(), between steps, so the
// right-hand side is a pure function of (t, q, v) within a step.
#pragma once

#include "mbs/integrator.h"
#include "mbs/types.h"

#include <string>
#include <vector>

namespace wearlink::mbs
{
  /** Where force elements add their contributions. */
  struct ForceAccumulator
  {
    double *g              = nullptr; ///< generalized forces, 3 per body [N, N, N m]
    double  damping_power  = 0;       ///< power dissipated by contact damping [W]
    double  friction_power = 0;       ///< power dissipated by friction [W]

    /** Apply force @p f [N] at global point @p at [m] to body @p b (not ground). */
    void
    add_force(int b, const StateView &s, const Vec2 &f, const Vec2 &at)
    {
      if (b == ground)
        return;
      g[3 * b] += f.x();
      g[3 * b + 1] += f.y();
      g[3 * b + 2] += cross(at - s.position(b), f);
    }
    /** Apply the couple @p torque [N m] to body @p b (not ground). */
    void
    add_torque(int b, double torque)
    {
      if (b != ground)
        g[3 * b + 2] += torque;
    }
  };

  /**
   * A contact that a force element holds as a constraint while it persists (the journal
   * sliding on the bore, doc/models.md §1.6): the normal force F is the constraint's
   * multiplier, the penetration δ(q) is kept at the quasi-static value of that force,
   * δ_s(F) = (F/K)^(1/e), through Baumgarte's terms at the rate b,
   *   w·q̈ + c = −2b δ̇ − b² (δ − δ_s(F)),
   * and the contact applies the generalized force F g. Mechanism::accelerations solves
   * for F (held_contacts.cc).
   */
  struct HeldContact
  {
    std::vector<double> w;                        ///< ∂δ/∂q over the n coordinates
    std::vector<double> g;                        ///< generalized force per newton of F (normal and friction)
    double              convective         = 0;   ///< c = δ̈ − w·q̈ at this state [m/s²]
    double              penetration        = 0;   ///< δ [m]
    double              rate               = 0;   ///< δ̇ [m/s]
    double              stiffness          = 0;   ///< K [N/mᵉ]
    double              exponent           = 1.5; ///< e [-]
    double              sliding_velocity   = 0;   ///< v_t [m/s]
    double              friction_per_force = 0;   ///< F_t / F at v_t [-]
  };

  class ForceElement
  {
  public:
    virtual ~ForceElement() = default;

    virtual const std::string &
    name() const = 0;

    /** Add generalized forces at time @p t for state @p s. Must not change the mode. */
    virtual void
    add_forces(double t, const StateView &s, ForceAccumulator &out) const = 0;

    /** Stored (elastic) energy [J], for the energy balance. */
    virtual double
    potential_energy(const StateView &s) const = 0;

    /**
     * Append the directions in which the element's forces change steeply at state @p s,
     * as gradients over the mechanism's @p n_coordinates coordinates (StiffDirection,
     * mbs/integrator.h): what a linearly implicit integrator builds its Jacobian from.
     * Default: none.
     */
    virtual void
    stiff_directions(const StateView & /*s*/,
                     unsigned int /*n_coordinates*/,
                     std::vector<StiffDirection> & /*out*/) const
    {
    }

    /** True if the element has a mode switched at located events. */
    virtual bool
    has_event() const
    {
      return false;
    }
    /** Event function; its sign gives the mode the state calls for (> 0: contact). */
    virtual double
    event_value(const StateView &) const
    {
      return 0;
    }
    /** The mode the element is in (true: contact episode). */
    virtual bool
    mode() const
    {
      return false;
    }
    /**
     * Switch the mode at a located event (time @p t, state @p s): @p onset true when the
     * event function became positive. Called between steps only.
     */
    virtual void
    on_event(double /*t*/, const StateView & /*s*/, bool /*onset*/)
    {
    }

    /** True if the element may hold its contact (update_hold() is called after each step). */
    virtual bool
    can_hold() const
    {
      return false;
    }
    /** True while the element holds its contact as a constraint (HeldContact). */
    virtual bool
    holds_contact() const
    {
      return false;
    }
    /** The held contact's rows at state @p s (w and g sized n already). */
    virtual void
    held_contact(const StateView & /*s*/, HeldContact & /*out*/) const
    {
    }
    /** The normal force [N] the mechanism solved for at its last evaluation. */
    virtual void
    set_held_force(double /*force*/) const
    {
    }
    /** That force [N] (0 when the contact is not held). */
    virtual double
    held_force() const
    {
      return 0;
    }
    /**
     * After an accepted step, between steps: take up or give up holding the contact at
     * state @p s with accelerations @p a (q̈). True if the mode changed (the right-hand
     * side changes with it).
     */
    virtual bool
    update_hold(double /*t*/, const StateView & /*s*/, const double * /*a*/)
    {
      return false;
    }
  };
} // namespace wearlink::mbs
