// SPDX-License-Identifier: LGPL-2.1-or-later
#include "analysis/nonlinear_dynamics.h"

#include "base/exceptions.h"
#include "base/numbers.h"

#include <algorithm>
#include <cmath>

namespace wearlink::analysis
{
  namespace
  {
    using numbers::two_pi;
  }

  std::vector<ChannelSpread>
  section_spread(const PoincareSection &section)
  {
    std::vector<ChannelSpread> out;
    const auto                &p = section.points;
    if (p.n_samples() == 0)
      return out;
    for (std::size_t c = 0; c < p.names.size(); ++c)
      {
        const auto &v = p.values[c];
        if (p.units[c] == "rad")
          {
            // An angle is a point on the circle: measure every point from the first one
            // along the shorter arc, so that -pi and +pi are no spread at all.
            double lo = 0.0, hi = 0.0;
            for (const double x : v)
              {
                const double d = std::remainder(x - v.front(), two_pi);
                lo             = std::min(lo, d);
                hi             = std::max(hi, d);
              }
            out.push_back({p.names[c], p.units[c], v.front() + lo, v.front() + hi, hi - lo});
          }
        else
          {
            const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
            out.push_back({p.names[c], p.units[c], *lo, *hi, *hi - *lo});
          }
      }
    return out;
  }

  ChannelLyapunov
  lyapunov_of_channel(const RecordedRun &run, const std::string &channel, LyapunovSettings settings)
  {
    if (!(run.sample_interval > 0.0))
      throw InputError("The run has no uniformly sampled series; the Lyapunov exponent of '" + channel +
                       "' needs one (list phase-portrait or lyapunov in "
                       "'Analyses/List of analyses').");
    const std::size_t c      = run.series.index(channel);
    settings.sample_interval = run.sample_interval;
    ChannelLyapunov out;
    out.channel         = channel;
    out.n_samples       = run.series.n_samples();
    out.sample_interval = run.sample_interval;
    try
      {
        out.estimate = estimate_largest_lyapunov_exponent(run.series.values[c], settings);
      }
    catch (const Error &e) // InputError (settings) or EstimationError (the scene's run is too short)
      {
        throw InputError("Lyapunov exponent of channel '" + channel + "' (" + std::to_string(out.n_samples) +
                         " samples every " + std::to_string(run.sample_interval) + " s): " + e.message());
      }
    out.per_driving_period = out.estimate.exponent() * run.driving_period;
    return out;
  }
} // namespace wearlink::analysis
