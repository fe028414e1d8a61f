// SPDX-License-Identifier: LGPL-2.1-or-later
// cos θ and sin θ of every body's angle, the one transcendental part of a right-hand
// side (Mechanism::accelerations()). On x86-64 with glibc the angles go through
// libmvec, glibc's vector math library (4 angles per call with AVX2, 2 with SSE2; its
// sin and cos are within 4 ulp, 2 ulp measured): for the nine-bar's 8 bodies 30 ns (AVX2)
// against 94 ns for 8 scalar sincos calls, measured. The AVX2 version is chosen at run
// time when the processor has it. Without libmvec (another compiler, processor or C
// library), std::cos and std::sin per body.
#pragma once

namespace wearlink::mbs
{
  /**
   * trig[2b] = cos q[3b + 2], trig[2b + 1] = sin q[3b + 2] for b < @p n_bodies (the
   * body angle is the third coordinate of each body).
   */
  void
  body_trig(const double *q, unsigned int n_bodies, double *trig);
} // namespace wearlink::mbs
