// SPDX-License-Identifier: LGPL-2.1-or-later
// `hertz-strip`: the seed's simplified pressure model. The normal force F_n of the
// multibody contact law is spread over a Hertz line-contact strip (REFERENCE.md §5,
// Johnson ch. 4) centred on the contact direction φ*:
//     P = F_n / L,  1/E* = (1 − ν1²)/E1 + (1 − ν2²)/E2,  R* = R1 R2/(R1 − R2),
//     b = √(4 P R*/(π E*)),  p0 = 2P/(π b),  p(s) = p0 √(1 − s²/b²), |s| ≤ b,
// with s the arc length from the contact point. R1, R2 are the profiles' radii at the
// contact direction (the worn per-area radii of seed eqs 28–31). Each discrete area
// receives the average of p over its arc, integrated in closed form
//     ∫ p ds = p0 b/2 [u √(1 − u²) + asin u],  u = s/b,
// so Σ p̄_k L R Δψ = F_n exactly even when the strip is narrower than one area (a fresh
// joint: b ≈ 0.1 mm against 0.2 mm areas at 360 areas). The worn shape enters only
// through the local radii: that is this model's limitation (Mukras et al. 2010).
// Hertz's theory assumes a contact narrow against the radii; a half-angle b/R2 past 90°
// (a strip wider than half the pin: soft materials, high loads, a conforming worn pair)
// is far outside it, and check_validity() warns with the worst half-angle evaluated.
#include "base/numbers.h"
#include "base/parameters.h"
#include "base/text.h"
#include "contact/hertz.h"
#include "contact/pressure_model.h"

#include <algorithm>
#include <cmath>

namespace wearlink::contact
{
  namespace
  {
    using numbers::pi;

    /** ∫_{-b}^{x} p0 √(1 − s²/b²) ds / (p0 b), clamped to the strip. */
    double
    strip_primitive(double x, double b)
    {
      const double u = std::clamp(x / b, -1.0, 1.0);
      return 0.5 * (u * std::sqrt(1 - u * u) + std::asin(u));
    }

    /** Wrap an angle to (−π, π]. */
    double
    wrap(double a)
    {
      a = std::fmod(a + pi, 2 * pi);
      if (a < 0)
        a += 2 * pi;
      return a - pi;
    }

    class HertzStrip : public PressureModel
    {
    public:
      explicit HertzStrip(ParameterReader &)
      {
      }

      void
      update_geometry(const JointGeometry &g) override
      {
        geometry = g;
      }

      void
      evaluate(const ContactLoad &load, SurfacePressure &out) override
      {
        const auto &bore = geometry.bore;
        const auto &pin  = geometry.pin;
        out.bore.assign(bore.n_points(), 0.0);
        out.pin.assign(pin.n_points(), 0.0);
        if (!(load.normal_force > 0))
          return;
        const double phi       = load.contact_angle;
        const double r1        = bore.radius(phi - load.bushing_angle);
        const double r2        = pin.radius(phi - load.pin_angle);
        const double e_star    = effective_modulus(geometry.bushing, geometry.pin_material);
        const double r_star    = r1 * r2 / std::max(r1 - r2, 1e-12 * r1);
        const double line_load = load.normal_force / geometry.axial_length;
        const auto   hertz     = hertz_line_contact(line_load, r_star, e_star);
        const double b         = hertz.half_width;
        const double p0        = hertz.peak_pressure;
        if (b / r2 > worst.half_angle)
          worst = {b / r2, load.normal_force};
        spread(bore, load.bushing_angle, r1, phi, b, p0, out.bore);
        spread(pin, load.pin_angle, r2, phi, b, p0, out.pin);
      }

      void
      check_validity(const std::string &joint, ValidityWarnings &w) const override
      {
        w.check({"joint " + joint + ": hertz-strip contact half-angle",
                 worst.half_angle * 180 / pi,
                 90,
                 "deg",
                 "a contact wider than half the pin; the worst at the normal force " +
                   format_number(worst.normal_force, 4) + " N",
                 "the hertz-strip pressure model assumes a contact narrow against the radii (Hertz line "
                 "contact), so its pressures and the wear computed from them are outside its validity; check "
                 "the elastic moduli and the loads, or use Pressure model = winkler or fe"});
      }

    private:
      /** Area averages of the strip on the areas of @p profile (body angle @p theta). */
      static void
      spread(const Profile       &profile,
             double               theta,
             double               radius,
             double               phi,
             double               b,
             double               p0,
             std::vector<double> &p)
      {
        const unsigned int n     = profile.n_points();
        const double       width = 2 * pi / n;
        // Only the areas within the strip's angular half-width (plus one) can be loaded:
        // area k's centre is at k·width + θ − φ, so they are a run of consecutive k.
        const double half = b / radius + width;
        if (half >= pi) // the strip wraps around the whole profile
          {
            for (unsigned int k = 0; k < n; ++k)
              p[k] = area_average(wrap(profile.angle(k) + theta - phi), radius, width, b, p0);
            return;
          }
        const double offset = theta - phi;
        const long   k_lo   = static_cast<long>(std::ceil((-half - offset) / width));
        const long   k_hi   = static_cast<long>(std::floor((half - offset) / width));
        const long   nn     = static_cast<long>(n);
        for (long k = k_lo; k <= k_hi; ++k)
          {
            const long j = ((k % nn) + nn) % nn;
            p[j]         = area_average(k * width + offset, radius, width, b, p0);
          }
      }

      /** Mean pressure over the area of angular @p width centred @p centre from the contact point. */
      static double
      area_average(double centre, double radius, double width, double b, double p0)
      {
        const double s0 = radius * (centre - 0.5 * width);
        const double s1 = radius * (centre + 0.5 * width);
        return p0 * b * (strip_primitive(s1, b) - strip_primitive(s0, b)) / (radius * width);
      }

      JointGeometry geometry;
      /** The widest strip evaluated so far: half-angle b / R2 [rad], and its F_n [N]. */
      struct WidestStrip
      {
        double half_angle   = 0;
        double normal_force = 0;
      };
      WidestStrip worst;
    };
  } // namespace

  void
  register_hertz_strip()
  {
    pressure_models().add("hertz-strip",
                          "the multibody normal force spread over a Hertz line-contact "
                          "strip at the contact direction (the seed's simplified route; "
                          "REFERENCE.md §5).",
                          {},
                          [](ParameterReader &r) { return std::make_unique<HertzStrip>(r); });
  }
} // namespace wearlink::contact
