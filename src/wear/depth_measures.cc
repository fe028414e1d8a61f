// SPDX-License-Identifier: LGPL-2.1-or-later
#include "wear/depth_measures.h"

#include "contact/hertz.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace wearlink::wear
{
  unsigned int
  window_areas(const double width, const double radius, const unsigned int n_areas)
  {
    const double area  = 2 * numbers::pi * radius / std::max(n_areas, 1u);
    double       count = std::isfinite(width / area) ? std::round(width / area) : 3.0;
    count              = std::clamp(count, 3.0, static_cast<double>(std::max(n_areas, 3u)));
    auto w             = static_cast<unsigned int>(count);
    if (w % 2 == 0)
      w = w + 1 <= n_areas ? w + 1 : w - 1;
    return std::max(1u, std::min(w, n_areas));
  }

  double
  largest_depth(const std::vector<double> &depth)
  {
    return depth.empty() ? 0.0 : *std::max_element(depth.begin(), depth.end());
  }

  double
  envelope_depth(const std::vector<double> &depth, const unsigned int window)
  {
    const long n = static_cast<long>(depth.size());
    if (n == 0)
      return 0;
    const long          half = std::min<long>(window / 2, (n - 1) / 2);
    std::vector<double> buffer(2 * half + 1);
    double              best = -std::numeric_limits<double>::infinity();
    for (long k = 0; k < n; ++k)
      {
        for (long d = -half; d <= half; ++d)
          buffer[d + half] = depth[((k + d) % n + n) % n];
        std::nth_element(buffer.begin(), buffer.begin() + half, buffer.end());
        best = std::max(best, buffer[half]);
      }
    return best;
  }

  // The local parabola of a window of 2m + 1 equally spaced samples, evaluated at its
  // centre, is a fixed linear combination of them (Savitzky–Golay, degree 2):
  //   c_d = 3 (3m² + 3m − 1 − 5d²) / ((2m − 1)(2m + 1)(2m + 3)),  d = −m … m.
  double
  roughness(const std::vector<double> &depth, const unsigned int window)
  {
    const long   n     = static_cast<long>(depth.size());
    const double scale = largest_depth(depth);
    if (n < 3 || !(scale > 0))
      return 0;
    const long          m = std::max<long>(1, std::min<long>(window / 2, (n - 1) / 2));
    std::vector<double> c(2 * m + 1);
    const double        denominator = static_cast<double>((2 * m - 1) * (2 * m + 1) * (2 * m + 3));
    for (long d = -m; d <= m; ++d)
      c[d + m] = 3.0 * static_cast<double>(3 * m * m + 3 * m - 1 - 5 * d * d) / denominator;
    double worst = 0;
    for (long k = 0; k < n; ++k)
      {
        double fit = 0;
        for (long d = -m; d <= m; ++d)
          fit += c[d + m] * depth[((k + d) % n + n) % n];
        worst = std::max(worst, std::abs(depth[k] - fit));
      }
    return worst / scale;
  }

  double
  hertz_contact_width(const double force,
                      const double bore_radius,
                      const double pin_radius,
                      const double effective_modulus,
                      const double length)
  {
    if (!(force > 0) || !(bore_radius > pin_radius) || !(length > 0))
      return 0;
    const double r_star = bore_radius * pin_radius / (bore_radius - pin_radius);
    return 2 * contact::hertz_line_contact(force / length, r_star, effective_modulus).half_width;
  }
} // namespace wearlink::wear
