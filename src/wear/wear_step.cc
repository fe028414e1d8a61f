// SPDX-License-Identifier: LGPL-2.1-or-later
#include "wear/wear_step.h"

#include "base/exceptions.h"
#include "wear/wear_loop.h"

#include <algorithm>

namespace wearlink::wear
{
  namespace
  {
    /** max(0, now + low_pass(b (now − before))) per area. */
    std::vector<double>
    combined(const std::vector<double> &now,
             const std::vector<double> &before,
             const double               b,
             const double               width,
             const double               radius)
    {
      std::vector<double> change(now.size());
      for (std::size_t k = 0; k < now.size(); ++k)
        change[k] = b * (now[k] - before[k]);
      change = low_pass(change, width, radius);
      std::vector<double> out(now.size());
      for (std::size_t k = 0; k < now.size(); ++k)
        out[k] = std::max(0.0, now[k] + change[k]);
      return out;
    }
  } // namespace

  WearRate
  step_rate(const WearRate        &now,
            const WearRate        &before,
            const double           f_now,
            const double           f_before,
            const WearStep         scheme,
            const RateChangeScale &scale)
  {
    if (scheme == WearStep::euler || before.empty() || !(f_before > 0) || !(f_now > 0))
      return now;
    if (now.depth_pin.size() != before.depth_pin.size() || now.depth_bore.size() != before.depth_bore.size())
      throw NumericalError("The wear rates of two iterations have different numbers of discrete areas.");
    const double omega = std::min(f_now / f_before, max_step_ratio);
    const double a = 1 + omega / 2, b = omega / 2;
    WearRate     r;
    r.depth_pin      = combined(now.depth_pin, before.depth_pin, b, scale.contact_width, scale.pin_radius);
    r.depth_bore     = combined(now.depth_bore, before.depth_bore, b, scale.contact_width, scale.bore_radius);
    const auto total = [&](const double now_total, const double before_total) {
      return std::max(0.0, a * now_total - b * before_total);
    };
    r.volume_pin           = total(now.volume_pin, before.volume_pin);
    r.volume_bore          = total(now.volume_bore, before.volume_bore);
    r.archard_pin          = total(now.archard_pin, before.archard_pin);
    r.archard_bore         = total(now.archard_bore, before.archard_bore);
    r.sliding_distance     = total(now.sliding_distance, before.sliding_distance);
    r.relative_revolutions = total(now.relative_revolutions, before.relative_revolutions);
    return r;
  }
} // namespace wearlink::wear
