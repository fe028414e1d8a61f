// SPDX-License-Identifier: LGPL-2.1-or-later
// The round steel pair of the contact tests: the nine-bar joints (R1 = 12 mm,
// c = 0.5 mm, L = 10 mm, E = 207 GPa, ν = 0.3 for both bodies), and the same with a
// worn bore.
#pragma once

#include "contact/pressure_model.h"

#include <cmath>

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

  /** The steel pair with its bore worn into a pocket of 20 µm at −90°, ±40° wide (cos² shape). */
  inline JointGeometry
  worn_steel_pair()
  {
    auto g = steel_pair();
    for (unsigned int k = 0; k < g.bore.n_points(); ++k)
      {
        const double d = std::remainder(g.bore.angle(k) + M_PI / 2, 2 * M_PI);
        if (std::abs(d) < 40 * M_PI / 180)
          g.bore.samples()[k] += 20e-6 * std::pow(std::cos(d * 90 / 40), 2);
      }
    return g;
  }
} // namespace wearlink::contact::testing
