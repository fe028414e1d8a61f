// SPDX-License-Identifier: LGPL-2.1-or-later
// The round steel pair of the contact tests: the nine-bar joints (R1 = 12 mm,
// c = 0.5 mm, L = 10 mm, E = 207 GPa, ν = 0.3 for both bodies).
#pragma once

#include "contact/pressure_model.h"

namespace wearlink::contact::testing
{
  inline JointGeometry
  steel_pair()
  {
    JointGeometry g;
    g.bore         = Profile::round(0.012, 360);
    g.pin          = Profile::round(0.0115, 360);
    g.axial_length = 0.01;
    g.bushing      = {207e9, 0.3};
    g.pin_material = {207e9, 0.3};
    return g;
  }
} // namespace wearlink::contact::testing
