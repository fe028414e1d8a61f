// SPDX-License-Identifier: LGPL-2.1-or-later
// Tangential (friction) laws of the clearance joint (doc/models.md §1.4, seed eqs 12–13):
//   coulomb           F_t = −μ F_n sign(v_t)
//   modified-coulomb  F_t = −μ c_d F_n v_t/|v_t|, Ambrósio's dynamic correction c_d:
//                     0 below v0, linear from v0 to v1, 1 above v1.
// v_t is the sliding velocity of the pin's material point relative to the bushing's at
// the contact point [m/s]; F_t is the tangential force on the pin along t = n rotated
// by +90°. `none` is not a plugin object: a joint with Friction law = none computes no
// tangential force at all.
#pragma once

#include "base/registry.h"

namespace wearlink::contact
{
  class FrictionLaw
  {
  public:
    virtual ~FrictionLaw() = default;
    /** Tangential force on the pin [N] for normal force @p normal_force [N] ≥ 0. */
    virtual double
    force(double normal_force, double sliding_velocity) const = 0;
    /** μ, the bound |F_t| ≤ μ F_n. */
    virtual double
    coefficient() const = 0;
  };

  Registry<FrictionLaw> &
  friction_laws();

  /** The Selection pattern of friction laws including "none". */
  std::string
  friction_law_pattern();
} // namespace wearlink::contact
