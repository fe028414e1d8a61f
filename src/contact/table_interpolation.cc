// SPDX-License-Identifier: LGPL-2.1-or-later
#include "contact/table_interpolation.h"

#include "base/numbers.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace wearlink::contact
{
  namespace
  {
    /**
     * Three-point end slope, kept within [d0/2, 3 d0] of the end secant d0 > 0 (see
     * HermiteEnds::increasing).
     */
    double
    increasing_end_slope(const double h0, const double h1, const double d0, const double d1)
    {
      const double m = ((2 * h0 + h1) * d0 - h0 * d1) / (h0 + h1);
      return std::clamp(m, 0.5 * d0, 3 * d0);
    }
  } // namespace

  void
  periodic_grid_position(const double angle, const unsigned int n, unsigned int &i0, unsigned int &i1, double &f)
  {
    if (n == 1)
      {
        i0 = i1 = 0;
        f       = 0;
        return;
      }
    double s = angle / numbers::two_pi;
    s -= std::floor(s);
    const double x = s * n;
    i0             = std::min(static_cast<unsigned int>(x), n - 1);
    f              = x - i0;
    i1             = i0 + 1 == n ? 0 : i0 + 1;
  }

  void
  hermite_slopes(const double *x, const double *y, const std::size_t K, const HermiteEnds ends, double *m)
  {
    std::vector<double> h(K - 1), d(K - 1);
    for (std::size_t k = 0; k + 1 < K; ++k)
      {
        h[k] = x[k + 1] - x[k];
        d[k] = (y[k + 1] - y[k]) / h[k];
      }
    if (K == 2)
      {
        m[0] = m[1] = ends == HermiteEnds::flat ? 0.0 : d[0];
        return;
      }
    for (std::size_t k = 1; k + 1 < K; ++k)
      {
        if (!(d[k - 1] * d[k] > 0)) // an extremum or a flat secant: no overshoot
          {
            m[k] = 0;
            continue;
          }
        const double w1 = 2 * h[k] + h[k - 1], w2 = h[k] + 2 * h[k - 1];
        m[k] = (w1 + w2) / (w1 / d[k - 1] + w2 / d[k]);
      }
    if (ends == HermiteEnds::flat)
      {
        m[0] = m[K - 1] = 0;
        return;
      }
    m[0]     = increasing_end_slope(h[0], h[1], d[0], d[1]);
    m[K - 1] = increasing_end_slope(h[K - 2], h[K - 3], d[K - 2], d[K - 3]);
  }

  void
  hermite(const double *x, const double *y, const double *m, const double t, double &yt, double &dy)
  {
    const double h  = x[1] - x[0];
    const double t2 = t * t, t3 = t2 * t;
    yt = (2 * t3 - 3 * t2 + 1) * y[0] + (t3 - 2 * t2 + t) * h * m[0] + (-2 * t3 + 3 * t2) * y[1] + (t3 - t2) * h * m[1];
    dy = ((6 * t2 - 6 * t) * (y[0] - y[1])) / h + (3 * t2 - 4 * t + 1) * m[0] + (3 * t2 - 2 * t) * m[1];
  }

  int
  hermite_interpolate(const double     *x,
                      const double     *y,
                      const double     *m,
                      const std::size_t K,
                      const double      xq,
                      double           &yq,
                      double           &dy)
  {
    if (xq < x[0] || xq > x[K - 1])
      {
        const std::size_t e = xq < x[0] ? 0 : K - 1;
        dy                  = m[e];
        yq                  = y[e] + dy * (xq - x[e]);
        return e == 0 ? -1 : 1;
      }
    const std::size_t k = std::min<std::size_t>(K - 2, std::upper_bound(x, x + K, xq) - x - 1);
    hermite(x + k, y + k, m + k, (xq - x[k]) / (x[k + 1] - x[k]), yq, dy);
    return 0;
  }
} // namespace wearlink::contact
