// SPDX-License-Identifier: LGPL-2.1-or-later
// A depth (or radius) profile given as N samples equally spaced over one turn, read at
// other angles: linear between neighbouring samples, periodic. The studies compare
// profiles of different sample counts on one grid with it.
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

namespace wearlink::wear
{
  /** @p h (N samples over 2π, the first at angle 0) at the angle fraction @p s ∈ [0, 1). */
  inline double
  periodic_at(const std::vector<double> &h, const double s)
  {
    const double x = s * h.size();
    const auto   i = static_cast<std::size_t>(std::floor(x)) % h.size();
    const double w = x - std::floor(x);
    return (1 - w) * h[i] + w * h[(i + 1) % h.size()];
  }

  /** @p h on the angles of @p n equally spaced samples (itself if it has @p n). */
  inline std::vector<double>
  periodic_resampled(const std::vector<double> &h, const std::size_t n)
  {
    if (h.size() == n)
      return h;
    std::vector<double> out(n);
    for (std::size_t k = 0; k < n; ++k)
      out[k] = periodic_at(h, static_cast<double>(k) / n);
    return out;
  }
} // namespace wearlink::wear
