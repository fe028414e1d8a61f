// SPDX-License-Identifier: LGPL-2.1-or-later
#include "mbs/body_trig.h"

#include <cmath>

#if defined(__x86_64__) && defined(__GLIBC__) && defined(__GNUC__) && !defined(__clang__)
#  define WEARLINK_LIBMVEC 1
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
    /** The angles of bodies b0 … b0 + count − 1 into a[0 … lanes − 1], padded with zeros. */
    void
    gather_angles(const double *q, const unsigned int b0, const unsigned int count, const unsigned int lanes, double *a)
    {
      for (unsigned int l = 0; l < lanes; ++l)
        a[l] = l < count ? q[3 * (b0 + l) + 2] : 0.0;
    }

    /** cos c[l] and sin s[l] of bodies b0 + l, l < count, into trig. */
    void
    scatter(const double *c, const double *s, const unsigned int b0, const unsigned int count, double *trig)
    {
      for (unsigned int l = 0; l < count; ++l)
        {
          trig[2 * (b0 + l)]     = c[l];
          trig[2 * (b0 + l) + 1] = s[l];
        }
    }

#ifdef WEARLINK_LIBMVEC
    __attribute__((target("avx2,fma"))) void
    body_trig_avx2(const double *q, const unsigned int n_bodies, double *trig)
    {
      for (unsigned int b0 = 0; b0 < n_bodies; b0 += 4)
        {
          const unsigned int count = n_bodies - b0 < 4 ? n_bodies - b0 : 4;
          double             a[4], c[4], s[4];
          gather_angles(q, b0, count, 4, a);
          const __m256d x = _mm256_loadu_pd(a);
          _mm256_storeu_pd(c, _ZGVdN4v_cos(x));
          _mm256_storeu_pd(s, _ZGVdN4v_sin(x));
          scatter(c, s, b0, count, trig);
        }
    }

    void
    body_trig_sse2(const double *q, const unsigned int n_bodies, double *trig)
    {
      for (unsigned int b0 = 0; b0 < n_bodies; b0 += 2)
        {
          const unsigned int count = n_bodies - b0 < 2 ? n_bodies - b0 : 2;
          double             a[2], c[2], s[2];
          gather_angles(q, b0, count, 2, a);
          const __m128d x = _mm_loadu_pd(a);
          _mm_storeu_pd(c, _ZGVbN2v_cos(x));
          _mm_storeu_pd(s, _ZGVbN2v_sin(x));
          scatter(c, s, b0, count, trig);
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
      return body_trig_avx2(q, n_bodies, trig);
    return body_trig_sse2(q, n_bodies, trig);
#else
    for (unsigned int b = 0; b < n_bodies; ++b)
      {
        trig[2 * b]     = std::cos(q[3 * b + 2]);
        trig[2 * b + 1] = std::sin(q[3 * b + 2]);
      }
#endif
  }
} // namespace wearlink::mbs
