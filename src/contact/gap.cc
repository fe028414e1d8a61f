// SPDX-License-Identifier: LGPL-2.1-or-later
#include "contact/gap.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace wearlink::contact
{
  namespace
  {
    constexpr double two_pi = 6.283185307179586476925286766559;
  }

  Gap::Gap(const Profile &bore_profile, const Profile &pin_profile)
    : bore(bore_profile)
    , pin(pin_profile)
    , is_round(bore_profile.is_round() && pin_profile.is_round())
    , r1(bore_profile.mean_radius())
    , r2(pin_profile.mean_radius())
    , min_clearance(bore_profile.min_radius() - pin_profile.max_radius())
    , search_step(two_pi / (2.0 * std::max(bore_profile.n_points(), pin_profile.n_points())))
  {}

  GapResult
  Gap::evaluate(const mbs::Vec2 &e, double tb, double tp) const
  {
    GapResult    r;
    const double ne = e.norm();
    if (is_round)
      {
        r.penetration = ne - (r1 - r2);
        r.normal      = ne > 0 ? mbs::Vec2(e / ne) : mbs::Vec2(1, 0);
        r.angle       = std::atan2(r.normal.y(), r.normal.x());
        r.bore_radius = r1;
        r.pin_radius  = r2;
        return r;
      }
    const double phi_e = ne > 0 ? std::atan2(e.y(), e.x()) : 0.0;
    if (!(ne > min_clearance))
      {
        // No direction can touch: a continuous lower bound of −δ, exact in sign.
        r.penetration = ne - min_clearance;
        r.angle       = phi_e;
        r.normal      = mbs::Vec2(std::cos(phi_e), std::sin(phi_e));
        r.bore_radius = bore.radius(phi_e - tb);
        r.pin_radius  = pin.radius(phi_e - tp);
        return r;
      }
    // Directions with e·u(φ) ≥ min_clearance: |φ − φ_e| ≤ acos(min_clearance/|e|).
    const double half = min_clearance > 0 ? std::acos(std::min(1.0, min_clearance / ne)) :
                                            0.5 * two_pi;
    const unsigned int n_grid =
      std::max(3u, static_cast<unsigned int>(std::ceil(2 * half / search_step)) + 1);
    const double dphi  = 2 * half / (n_grid - 1);
    double       best  = std::numeric_limits<double>::infinity();
    unsigned int k_min = 0;
    for (unsigned int k = 0; k < n_grid; ++k)
      {
        const double g = gap(phi_e - half + k * dphi, e, tb, tp);
        if (g < best)
          {
            best  = g;
            k_min = k;
          }
      }
    // Golden-section refinement on the bracket around the grid minimum.
    double a = phi_e - half + (k_min == 0 ? 0 : k_min - 1) * dphi;
    double b = phi_e - half + std::min(n_grid - 1, k_min + 1) * dphi;
    constexpr double invphi = 0.6180339887498948482;
    double c  = b - invphi * (b - a);
    double d  = a + invphi * (b - a);
    double gc = gap(c, e, tb, tp);
    double gd = gap(d, e, tb, tp);
    for (unsigned int it = 0; it < 40 && b - a > 1e-10; ++it)
      {
        if (gc < gd)
          {
            b  = d;
            d  = c;
            gd = gc;
            c  = b - invphi * (b - a);
            gc = gap(c, e, tb, tp);
          }
        else
          {
            a  = c;
            c  = d;
            gc = gd;
            d  = a + invphi * (b - a);
            gd = gap(d, e, tb, tp);
          }
      }
    double phi = 0.5 * (a + b);
    double g   = gap(phi, e, tb, tp);
    const double grid_phi = phi_e - half + k_min * dphi;
    if (best < g)
      {
        g   = best;
        phi = grid_phi;
      }
    r.penetration = -g;
    r.angle       = phi;
    r.normal      = mbs::Vec2(std::cos(phi), std::sin(phi));
    r.bore_radius = bore.radius(phi - tb);
    r.pin_radius  = pin.radius(phi - tp);
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
    r.angle          = phi;
    r.normal         = mbs::Vec2(std::cos(phi), std::sin(phi));
    r.bore_radius    = bore.radius(phi - tb);
    r.pin_radius     = pin.radius(phi - tp);
    r.penetration    = ne - (r.bore_radius - r.pin_radius);
    return r;
  }
} // namespace wearlink::contact
