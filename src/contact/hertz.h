// SPDX-License-Identifier: LGPL-2.1-or-later
// Hertz line contact of two parallel cylinders (doc/models.md §5.1), the one definition
// used by the `hertz-strip` pressure model and the FE contact case's comparison: for a
// load per unit length P on a pair of relative radius R* (internal contact: R* = R1 R2 /
// (R1 − R2)) and effective modulus E*, the contact half-width is b = √(4 P R* / (π E*))
// and the peak pressure p0 = 2 P / (π b), with the elliptical distribution
// p(s) = p0 √(1 − s²/b²) across the strip.
#pragma once

#include "base/numbers.h"

#include <cmath>

namespace wearlink::contact
{
  struct HertzLineContact
  {
    double half_width    = 0; ///< b [m]
    double peak_pressure = 0; ///< p0 [Pa]
  };

  /** @p line_load P [N/m], @p relative_radius R* [m], @p effective_modulus E* [Pa]. */
  inline HertzLineContact
  hertz_line_contact(const double line_load, const double relative_radius, const double effective_modulus)
  {
    HertzLineContact h;
    h.half_width    = std::sqrt(4 * line_load * relative_radius / (numbers::pi * effective_modulus));
    h.peak_pressure = 2 * line_load / (numbers::pi * h.half_width);
    return h;
  }
} // namespace wearlink::contact
