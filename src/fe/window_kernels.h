// SPDX-License-Identifier: LGPL-2.1-or-later
// The two inner loops of gathering a column of the contact window's compliance
// (condensed_contact_solver.cc, WindowCompliance): plain loops over contiguous arrays,
// compiled with -O3 and, on x86-64 with GCC, in one version per vector width (AVX-512,
// AVX2 + FMA, SSE2), of which the loader picks the widest the processor has. The
// versions differ in round-off only (a fused multiply–add rounds once).
#pragma once

namespace wearlink::fe::kernels
{
  /** Rows of the four blocks of a bore column (BoundaryCompliance::BoreColumn), from one row on. */
  struct BlockRows
  {
    const double *xx, *yx, *xy, *yy;
  };

  /**
   * The bore field of one face node over n rows: fx = a·xx + b·xy, fy = a·yx + b·yy,
   * or (@p accumulate) added to fx, fy.
   */
  void
  field(double *fx, double *fy, const BlockRows &k, double a, double b, unsigned int n, bool accumulate);

  /**
   * The bore field of two face nodes over n rows in one pass: the sum of field() for
   * (@p k0, a0, b0) and (@p k1, a1, b1), without storing and reading back the first
   * node's field.
   */
  void
  field_two(double          *fx,
            double          *fy,
            const BlockRows &k0,
            double           a0,
            double           b0,
            const BlockRows &k1,
            double           a1,
            double           b1,
            unsigned int     n);

  /**
   * out = pin + vx0·fx0 + vy0·fy0 + vx1·fx1 + vy1·fy1 over n positions (a face of two
   * nodes: its readers and the field at their rows).
   */
  void
  read_two(double       *out,
           const double *pin,
           const double *vx0,
           const double *vy0,
           const double *fx0,
           const double *fy0,
           const double *vx1,
           const double *vy1,
           const double *fx1,
           const double *fy1,
           unsigned int  n);

  /** out += vx·fx + vy·fy over n positions (one more face node). */
  void
  read_add(double *out, const double *vx, const double *vy, const double *fx, const double *fy, unsigned int n);
} // namespace wearlink::fe::kernels
