// SPDX-License-Identifier: LGPL-2.1-or-later
#include "contact/gap.h"

#include "base/numbers.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace wearlink::contact
{
  namespace
  {
    using numbers::two_pi;
  }

  Gap::Gap(const Profile &bore_profile, const Profile &pin_profile)
    : bore(bore_profile)
    , pin(pin_profile)
    , is_round(bore_profile.is_round() && pin_profile.is_round())
    , r1(bore_profile.mean_radius())
    , r2(pin_profile.mean_radius())
    , min_clearance(bore_profile.min_radius() - pin_profile.max_radius())
  {
  }

  GapResult
  Gap::evaluate(const mbs::Vec2 &e, double tb, double tp) const
  {
    GapResult    r;
    const double ne = e.norm();
    if (is_round)
      {
        r.penetration = ne - (r1 - r2);
        r.normal      = ne > 0 ? mbs::Vec2(e / ne) : mbs::Vec2(1, 0);
        r.bore_radius = r1;
        r.pin_radius  = r2;
        return r;
      }
    const double phi_e = ne > 0 ? std::atan2(e.y(), e.x()) : 0.0;
    if (!(ne > min_clearance))
      {
        // No direction can touch: a continuous lower bound of −δ, exact in sign.
        r.penetration = ne - min_clearance;
        r.normal      = mbs::Vec2(std::cos(phi_e), std::sin(phi_e));
        r.bore_radius = bore.radius(phi_e - tb);
        r.pin_radius  = pin.radius(phi_e - tp);
        return r;
      }
    // Directions with e·u(φ) ≥ min_clearance: |φ − φ_e| ≤ acos(min_clearance/|e|).
    const double half = min_clearance > 0 ? std::acos(std::min(1.0, min_clearance / ne)) : 0.5 * two_pi;
    const double lo = phi_e - half, hi = phi_e + half;

    // Kinks of both profiles inside [lo, hi], merged in increasing order.
    const unsigned int nb = bore.n_points(), np = pin.n_points();
    const double       db = two_pi / nb, dp = two_pi / np;
    double             next_b = tb + std::ceil((lo - tb) / db) * db;
    double             next_p = tp + std::ceil((lo - tp) / dp) * dp;
    // h(φ) = R1*(φ − θ_b) − R2*(φ − θ_p), the part of g that is linear between kinks.
    auto h = [&](double phi) {
      return bore.radius(phi - tb) - pin.radius(phi - tp);
    };
    double best = std::numeric_limits<double>::infinity(), phi = phi_e;
    auto   consider = [&](double x, double hx) {
      const double g = hx - ne * std::cos(x - phi_e);
      if (g < best)
        {
          best = g;
          phi  = x;
        }
    };
    double a = lo, ha = h(lo);
    consider(a, ha);
    while (a < hi)
      {
        double bnext = std::min({next_b, next_p, hi});
        if (bnext <= a) // a kink at a itself: step to the following one
          {
            if (next_b <= a)
              next_b += db;
            if (next_p <= a)
              next_p += dp;
            continue;
          }
        const double hb    = h(bnext);
        const double slope = (hb - ha) / (bnext - a);
        if (std::abs(slope) < ne)
          {
            const double x = phi_e - std::asin(slope / ne);
            if (x > a && x < bnext)
              consider(x, ha + slope * (x - a));
          }
        consider(bnext, hb);
        a  = bnext;
        ha = hb;
      }
    const double g = best;
    r.penetration  = -g;
    r.normal       = mbs::Vec2(std::cos(phi), std::sin(phi));
    r.bore_radius  = bore.radius(phi - tb);
    r.pin_radius   = pin.radius(phi - tp);
    return r;
  }

  GapResult
  Gap::evaluate_per_area(const mbs::Vec2 &e, double tb, double tp) const
  {
    if (is_round)
      return evaluate(e, tb, tp);
    GapResult    r;
    const double ne  = e.norm();
    const double phi = ne > 0 ? std::atan2(e.y(), e.x()) : 0.0;
    r.normal         = mbs::Vec2(std::cos(phi), std::sin(phi));
    r.bore_radius    = bore.radius(phi - tb);
    r.pin_radius     = pin.radius(phi - tp);
    r.penetration    = ne - (r.bore_radius - r.pin_radius);
    return r;
  }
} // namespace wearlink::contact
