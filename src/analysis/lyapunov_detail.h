// SPDX-License-Identifier: LGPL-2.1-or-later
// What the two largest-Lyapunov-exponent estimators of analysis/lyapunov.h share: delay
// vectors and their distances, the series' extent, and the length check. Internal to
// lyapunov.cc (Wolf) and lyapunov_rosenstein.cc (Rosenstein).
#pragma once

#include "analysis/lyapunov.h"
#include "base/exceptions.h"
#include "base/numbers.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace wearlink::analysis::lyapunov_detail
{
  /**
   * Points closer than this fraction of the attractor extent coincide: an exact
   * recurrence, the same state, not a neighbour [-]. Periodic motion computed to
   * ~1e-10 relative repeats within it; one integrated much more loosely (relative
   * drift per period above 1e-9) would need a larger value.
   */
  inline constexpr double exact_recurrence = 1e-9;

  /** Fewest neighbour candidates a method needs beyond the Theiler window [-]. */
  inline constexpr std::size_t min_vectors_beyond_window = 32;

  /** Delay vector y_i of @p series into @p y (m coordinates). */
  inline void
  delay_vector(const std::vector<double> &series, const Embedding &emb, const std::size_t i, std::vector<double> &y)
  {
    y.resize(emb.dimension);
    for (unsigned int d = 0; d < emb.dimension; ++d)
      y[d] = series[i + d * emb.delay];
  }

  /** |y_i - y_j| without forming the vectors [units of the series]. */
  inline double
  distance(const std::vector<double> &series, const Embedding &emb, const std::size_t i, const std::size_t j)
  {
    double s = 0.0;
    for (unsigned int d = 0; d < emb.dimension; ++d)
      {
        const double diff = series[i + d * emb.delay] - series[j + d * emb.delay];
        s += diff * diff;
      }
    return std::sqrt(s);
  }

  inline void
  check_length(const std::string &method,
               const std::size_t  n_samples,
               const Embedding   &emb,
               const std::size_t  reserved,
               const std::size_t  theiler_window)
  {
    const std::size_t needed = emb.window() + reserved + 2 * theiler_window + min_vectors_beyond_window;
    if (n_samples < needed)
      throw EstimationError("The " + method + " method with embedding dimension " + std::to_string(emb.dimension) +
                            ", delay " + std::to_string(emb.delay) + " and Theiler window " +
                            std::to_string(theiler_window) + " samples needs at least " + std::to_string(needed) +
                            " samples; the series has " + std::to_string(n_samples) +
                            ". Give a longer series, or a smaller embedding dimension or delay.");
  }

  inline double
  series_extent(const std::vector<double> &series)
  {
    const auto [lo, hi] = std::minmax_element(series.begin(), series.end());
    return *hi - *lo;
  }
} // namespace wearlink::analysis::lyapunov_detail
