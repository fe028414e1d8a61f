// SPDX-License-Identifier: LGPL-2.1-or-later
#include "fe/window_kernels.h"

// One version per vector width where GCC's function multi-versioning is there (the
// loader's ifunc picks one on the first call); elsewhere the plain build.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
#  define WEARLINK_VECTOR_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#  define WEARLINK_VECTOR_CLONES
#endif

namespace wearlink::fe::kernels
{
  WEARLINK_VECTOR_CLONES void
  field(double *__restrict fx,
        double *__restrict fy,
        const BlockRows   &k,
        const double       a,
        const double       b,
        const unsigned int n,
        const bool         accumulate)
  {
    const double *__restrict xx = k.xx, *__restrict yx = k.yx, *__restrict xy = k.xy, *__restrict yy = k.yy;
    if (accumulate)
      for (unsigned int t = 0; t < n; ++t)
        {
          fx[t] += a * xx[t] + b * xy[t];
          fy[t] += a * yx[t] + b * yy[t];
        }
    else
      for (unsigned int t = 0; t < n; ++t)
        {
          fx[t] = a * xx[t] + b * xy[t];
          fy[t] = a * yx[t] + b * yy[t];
        }
  }


  WEARLINK_VECTOR_CLONES void
  field_two(double *__restrict fx,
            double *__restrict fy,
            const BlockRows   &k0,
            const double       a0,
            const double       b0,
            const BlockRows   &k1,
            const double       a1,
            const double       b1,
            const unsigned int n)
  {
    const double *__restrict xx0 = k0.xx, *__restrict yx0 = k0.yx, *__restrict xy0 = k0.xy, *__restrict yy0 = k0.yy;
    const double *__restrict xx1 = k1.xx, *__restrict yx1 = k1.yx, *__restrict xy1 = k1.xy, *__restrict yy1 = k1.yy;
    for (unsigned int t = 0; t < n; ++t)
      {
        fx[t] = a0 * xx0[t] + b0 * xy0[t] + a1 * xx1[t] + b1 * xy1[t];
        fy[t] = a0 * yx0[t] + b0 * yy0[t] + a1 * yx1[t] + b1 * yy1[t];
      }
  }


  WEARLINK_VECTOR_CLONES void
  read_two(double *__restrict out,
           const double *__restrict pin,
           const double *__restrict vx0,
           const double *__restrict vy0,
           const double *__restrict fx0,
           const double *__restrict fy0,
           const double *__restrict vx1,
           const double *__restrict vy1,
           const double *__restrict fx1,
           const double *__restrict fy1,
           const unsigned int n)
  {
    for (unsigned int t = 0; t < n; ++t)
      out[t] = pin[t] + vx0[t] * fx0[t] + vy0[t] * fy0[t] + vx1[t] * fx1[t] + vy1[t] * fy1[t];
  }


  WEARLINK_VECTOR_CLONES void
  read_add(double *__restrict out,
           const double *__restrict vx,
           const double *__restrict vy,
           const double *__restrict fx,
           const double *__restrict fy,
           const unsigned int n)
  {
    for (unsigned int t = 0; t < n; ++t)
      out[t] += vx[t] * fx[t] + vy[t] * fy[t];
  }
} // namespace wearlink::fe::kernels
