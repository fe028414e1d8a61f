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

    /**
     * The kinks of one profile (its sample angles, turned by the body angle θ) from a
     * start angle on, in increasing order: the next kink's global angle, its radius, and
     * cos/sin of (kink − φ_e) advanced by a fixed rotation per kink instead of a cosine
     * each (~100 kinks per evaluation at most: a rounding drift of ~1e-14).
     */
    struct KinkWalker
    {
      KinkWalker(const std::vector<double> &samples, double theta, double start, double phi_e, const Gap::Step &step)
        : r(samples)
        , n(static_cast<long>(samples.size()))
        , d(two_pi / samples.size())
        , inverse_d(samples.size() / two_pi)
        , step(step)
      {
        // The start in the body frame, in sample spacings reduced to [0, n): indices
        // and angles stay small whatever the body angle (a trial stage of a diverging
        // step can hold 1e17 rad); base is the global angle of sample 0 nearest below.
        double psi = (start - theta) / d;
        psi -= static_cast<double>(n) * std::floor(psi / static_cast<double>(n));
        psi   = std::clamp(psi, 0.0, static_cast<double>(n));
        base  = start - psi * d;
        k     = static_cast<long>(std::ceil(psi));
        angle = base + k * d;
        if (angle < start) // rounding
          {
            ++k;
            angle = base + k * d;
          }
        cos_rel = std::cos(angle - phi_e);
        sin_rel = std::sin(angle - phi_e);
        i       = k % n;
        i_prev  = i == 0 ? n - 1 : i - 1;
      }
      double
      next_radius() const
      {
        return r[i];
      }
      /** Radius at a global angle @p x in [angle − d, angle] (the segment before the next kink). */
      double
      radius_at(double x) const
      {
        const double r0 = r[i_prev], r1 = r[i];
        return r0 + (r1 - r0) * ((x - (angle - d)) * inverse_d);
      }
      void
      advance()
      {
        ++k;
        i_prev         = i;
        i              = i + 1 == n ? 0 : i + 1; // k mod n, without a division per kink
        angle          = base + k * d;
        const double c = cos_rel * step.cos - sin_rel * step.sin;
        sin_rel        = sin_rel * step.cos + cos_rel * step.sin;
        cos_rel        = c;
      }
      const std::vector<double> &r;
      long                       n;
      double                     d, inverse_d, base;
      const Gap::Step           &step;
      long                       k;                 ///< the next kink's sample index, unwrapped (k ≥ 0)
      long                       i = 0, i_prev = 0; ///< k and k − 1 modulo n
      double                     angle, cos_rel, sin_rel;
    };
  } // namespace

  Gap::Gap(const Profile &bore_profile, const Profile &pin_profile)
    : bore(bore_profile)
    , pin(pin_profile)
    , is_round(bore_profile.is_round() && pin_profile.is_round())
    , r1(bore_profile.mean_radius())
    , r2(pin_profile.mean_radius())
    , min_clearance(bore_profile.min_radius() - pin_profile.max_radius())
    , bore_step{std::cos(two_pi / bore_profile.n_points()), std::sin(two_pi / bore_profile.n_points())}
    , pin_step{std::cos(two_pi / pin_profile.n_points()), std::sin(two_pi / pin_profile.n_points())}
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
    if (!std::isfinite(tb) || !std::isfinite(tp))
      {
        // A diverging trial stage: no contact direction exists; the integrator rejects it.
        r.penetration = std::numeric_limits<double>::quiet_NaN();
        return r;
      }
    const double phi_e = ne > 0 ? std::atan2(e.y(), e.x()) : 0.0;
    if (!(ne > min_clearance)) // no direction can touch: a continuous lower bound of −δ, exact in sign
      return at_direction(phi_e, ne - min_clearance, tb, tp);
    const Minimum m = minimize(ne, phi_e, tb, tp);
    return at_direction(m.phi, -m.g, tb, tp);
  }

  GapResult
  Gap::at_direction(double phi, double penetration, double tb, double tp) const
  {
    GapResult r;
    r.penetration = penetration;
    r.normal      = mbs::Vec2(std::cos(phi), std::sin(phi));
    r.bore_radius = bore.radius(phi - tb);
    r.pin_radius  = pin.radius(phi - tp);
    return r;
  }

  Gap::Minimum
  Gap::minimize(double ne, double phi_e, double tb, double tp) const
  {
    // Directions with e·u(φ) ≥ min_clearance: |φ − φ_e| ≤ acos(min_clearance/|e|).
    const double cos_half = min_clearance > 0 ? std::min(1.0, min_clearance / ne) : -1.0;
    const double half     = std::acos(cos_half);
    const double sin_half = std::sqrt(std::max(0.0, 1 - cos_half * cos_half));
    const double lo = phi_e - half, hi = phi_e + half;

    // Kinks of both profiles inside [lo, hi], merged in increasing order; between kinks
    // h(φ) = R1*(φ − θ_b) − R2*(φ − θ_p) is linear and g(φ) = h(φ) − |e| cos(φ − φ_e).
    KinkWalker bw(bore.samples(), tb, lo, phi_e, bore_step);
    KinkWalker pw(pin.samples(), tp, lo, phi_e, pin_step);
    Minimum    m{std::numeric_limits<double>::infinity(), phi_e};
    auto       consider = [&m](double x, double g) {
      if (g < m.g)
        m = {g, x};
    };
    double a = lo, ha = bw.radius_at(lo) - pw.radius_at(lo), sa = -sin_half;
    consider(a, ha - ne * cos_half);
    // The segment [a, x] that ends where h = hx, cos(x − φ_e) = cx, sin(x − φ_e) = sx.
    const auto segment = [&](const double x, const double hx, const double cx, const double sx) {
      // g' = slope + |e| sin(φ − φ_e) rises through 0 inside the segment: a minimum at
      // sin(φ − φ_e) = −slope/|e|, cos(φ − φ_e) = √(1 − (slope/|e|)²) (within ±90°).
      // The signs of g' × (x − a) > 0 at both ends decide, so that the division
      // (the walk's slowest operation) is taken only for such a segment.
      const double dx = x - a, dh = hx - ha;
      if (dh + ne * sa * dx < 0 && dh + ne * sx * dx > 0)
        {
          const double slope = dh / dx;
          const double q     = std::clamp(slope / ne, -1.0, 1.0);
          const double xs    = phi_e - std::asin(q);
          if (xs > a && xs < x)
            consider(xs, ha + slope * (xs - a) - ne * std::sqrt(1 - q * q));
        }
      consider(x, hx - ne * cx);
      a  = x;
      ha = hx;
      sa = sx;
    };
    // The kinks inside the window, the nearer walker's first (both at a common kink).
    for (;;)
      {
        const bool   bore_next = bw.angle <= pw.angle, both = bw.angle == pw.angle;
        const double x = bore_next ? bw.angle : pw.angle;
        if (!(x < hi))
          break;
        if (x > a) // a kink at the window's start is its first point, already considered
          {
            if (bore_next)
              segment(x, bw.next_radius() - (both ? pw.next_radius() : pw.radius_at(x)), bw.cos_rel, bw.sin_rel);
            else
              segment(x, bw.radius_at(x) - pw.next_radius(), pw.cos_rel, pw.sin_rel);
          }
        if (bore_next)
          bw.advance();
        if (!bore_next || both)
          pw.advance();
      }
    if (hi > a)
      segment(hi, bw.radius_at(hi) - pw.radius_at(hi), cos_half, sin_half);
    return m;
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
