// SPDX-License-Identifier: LGPL-2.1-or-later
// The mathematical constants of the project, defined once (C++17 has no std::numbers).
#pragma once

namespace wearlink::numbers
{
  /** π to double precision. */
  inline constexpr double pi = 3.14159265358979323846;
  /** 2π (exactly 2 × pi in binary floating point). */
  inline constexpr double two_pi = 2.0 * pi;
} // namespace wearlink::numbers
