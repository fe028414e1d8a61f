// SPDX-License-Identifier: LGPL-2.1-or-later
// The mathematical constants of the project, defined once (C++17 has no std::numbers).
#pragma once

#include <limits>

namespace wearlink::numbers
{
  /** π to double precision. */
  inline constexpr double pi = 3.14159265358979323846;
  /** 2π (exactly 2 × pi in binary floating point). */
  inline constexpr double two_pi = 2.0 * pi;
  /** The quiet NaN that marks a figure as not available. */
  inline constexpr double nan = std::numeric_limits<double>::quiet_NaN();
} // namespace wearlink::numbers
