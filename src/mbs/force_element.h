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
  };
} // namespace wearlink::mbs
