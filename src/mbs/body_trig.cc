// SPDX-License-Identifier: LGPL-2.1-or-later
#include "mbs/body_trig.h"

#include <cmath>

#ifdef WEARLINK_LIBMVEC // set by src/mbs/CMakeLists.txt when libmvec is linked
#  include <immintrin.h>

// libmvec's entry points, named by the x86-64 vector function ABI (b: SSE2, 2 lanes;
// d: AVX2, 4 lanes; N: unmasked; v: one vector argument).
extern "C" __m128d _ZGVbN2v_sin(__m128d);
extern "C" __m128d _ZGVbN2v_cos(__m128d);
extern "C" __m256d _ZGVdN4v_sin(__m256d);
extern "C" __m256d _ZGVdN4v_cos(__m256d);
#endif

namespace wearlink::mbs
{
  namespace
  {
#ifdef WEARLINK_LIBMVEC
    /** c = cos a, s = sin a for 4 angles (AVX2). */
    __attribute__((target("avx2,fma"))) void
    cos_sin_4(const double *a, double *c, double *s)
    {
      const __m256d x = _mm256_loadu_pd(a);
      _mm256_storeu_pd(c, _ZGVdN4v_cos(x));
      _mm256_storeu_pd(s, _ZGVdN4v_sin(x));
    }

    /** c = cos a, s = sin a for 2 angles (SSE2). */
    void
    cos_sin_2(const double *a, double *c, double *s)
    {
      const __m128d x = _mm_loadu_pd(a);
      _mm_storeu_pd(c, _ZGVbN2v_cos(x));
      _mm_storeu_pd(s, _ZGVbN2v_sin(x));
    }

    /**
     * The bodies in groups of @p lanes through @p cos_sin (the last group padded with
     * zero angles, whose results are not written).
     */
    template <unsigned int lanes>
    void
    in_groups(const double      *q,
              const unsigned int n_bodies,
              double            *trig,
              void (*cos_sin)(const double *, double *, double *))
    {
      for (unsigned int b0 = 0; b0 < n_bodies; b0 += lanes)
        {
          const unsigned int count = n_bodies - b0 < lanes ? n_bodies - b0 : lanes;
          double             a[lanes], c[lanes], s[lanes];
          for (unsigned int l = 0; l < lanes; ++l)
            a[l] = l < count ? q[3 * (b0 + l) + 2] : 0.0;
          cos_sin(a, c, s);
          for (unsigned int l = 0; l < count; ++l)
            {
              trig[2 * (b0 + l)]     = c[l];
              trig[2 * (b0 + l) + 1] = s[l];
            }
        }
    }
#endif
  } // namespace

  void
  body_trig(const double *q, const unsigned int n_bodies, double *trig)
  {
#ifdef WEARLINK_LIBMVEC
    static const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    if (avx2)
      return in_groups<4>(q, n_bodies, trig, cos_sin_4);
    return in_groups<2>(q, n_bodies, trig, cos_sin_2);
#else
    for (unsigned int b = 0; b < n_bodies; ++b)
      {
        trig[2 * b]     = std::cos(q[3 * b + 2]);
        trig[2 * b + 1] = std::sin(q[3 * b + 2]);
      }
#endif
  }
} // namespace wearlink::mbs
