// SPDX-License-Identifier: LGPL-2.1-or-later
// `hertz-strip`: the multibody normal force F_n spread over a Hertz line-contact strip
// (Johnson, Contact Mechanics ch. 4):
//     P = F_n / L,  1/E* = (1 − ν1²)/E1 + (1 − ν2²)/E2,
//     b = √(4 P R*/(π E*)),  p0 = 2P/(π b),  p(s) = p0 √(1 − s²/b²), |s| ≤ b,
// with s the arc length from the strip's centre. Each discrete area receives the
// strip's force on its arc, integrated in closed form
//     ∫ p ds = p0 b/2 [u √(1 − u²) + asin u],  u = s/b,
// over its surface L R_k Δψ, so that the areas carry the whole strip even when it is
// narrower than one area.
//
// The resultant. The strip's pressure acts along the normals of a curved surface, so
// its resultant along the contact direction, L ∫ p cos(s/R) ds, falls short of its sum
// F_n = L ∫ p ds by the factor 2 J1(ε)/ε, ε = b/R the strip's half-angle on that surface:
// −0.4 % at ε = 10°, −3.4 % at 30°, −9 % on the ±50° strip of a conforming worn pocket.
// The strip on each surface is therefore scaled by ε/(2 J1(ε)) (resultant_scale()), so
// that it carries the force the multibody model applied, F_n u(φ*) — the contract of
// every pressure model (contact/pressure_model.h). What that changes in the physics:
// the pressure of the whole strip, and with it Σ p A = F_n ε/(2 J1(ε)) ≥ F_n, rises by
// that factor, by less than 2e-4 for the narrow strips of unworn joints (ε ≤ 2°) and
// by per cents in a conforming worn pocket; the worn volume k Σ p A ds then exceeds
// Archard's global k ∫ F_n ds by the same factor, which is local Archard on a curved
// conformal contact, not a loss of balance (wear/archard.h). Unscaled, the wear of a
// worn pocket was computed for a load up to 10 % below the one the dynamics applied.
//
// Where the strip sits and how wide it is (entry "Relative radius"):
//  - conforming (default): the width from the worn surfaces over the strip's own
//    width. Between the pin pushed along the contact direction φ0 and the bore, the
//    radial gap is g(φ) = h(φ) − h(φ0) cos(φ − φ0), h(φ) = R1*(φ − θ_b) − R2*(φ − θ_p);
//    its least-squares parabola over the strip's half-angle (exact Legendre moments of
//    the piecewise-linear profiles) gives the curvature of the gap, g'' = h(φ0) + h''
//    [m/rad²], hence 1/R* = g''/(R1 R2) (= 1/R2 − 1/R1 for round profiles: the classic
//    internal R*). The half-width and the window are made consistent (b from the
//    curvature over ±b). A worn pocket whose curvature approaches the pin's spreads
//    the pressure, as an elastic contact of a conforming pair does; a feature shorter
//    than the contact width is averaged out. The strip is centred at φ0, the direction
//    of the multibody model's normal force.
//  - local radii: the seed's route (its eqs 28–31): R* = R1 R2/(R1 − R2) from the
//    radii at φ0, the strip centred at φ0. A pocket worn deeper reads as a larger bore
//    radius, hence a narrower strip and a higher peak: wear concentrates where there is
//    most. Kept to compare with the seed.
// Hertz's theory assumes a contact narrow against the radii; a half-angle b/R2 past 90°
// (a strip wider than half the pin: soft materials, high loads, a fully conforming worn
// pair) is far outside it, and check_validity() warns with the worst half-angle.
//
// The model is explicit: evaluate_wearing() returns the strip of the current surfaces.
// Against a change of the surfaces' shape at the contact width its stiffness is E*/(2b)
// (a dent of depth δ at the centre widens the strip and lowers p0 by δ E*/(2b)), so a
// load state is a stable step of the sequential wear update while its wear compliance is
// below 2b/E* (stable_compliance()).
#include "base/numbers.h"
#include "base/parameters.h"
#include "base/text.h"
#include "contact/hertz.h"
#include "contact/pressure_model.h"

#include <deal.II/base/quadrature_lib.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace wearlink::contact
{
  namespace
  {
    using numbers::pi;
    using numbers::two_pi;

    /** ∫_{-b}^{x} p0 √(1 − s²/b²) ds / (p0 b), clamped to the strip. */
    double
    strip_primitive(double x, double b)
    {
      const double u = std::clamp(x / b, -1.0, 1.0);
      return 0.5 * (u * std::sqrt(1 - u * u) + std::asin(u));
    }

    /**
     * The scale that makes a strip of angular half-width @p epsilon carry its force as
     * the resultant along its centre: ∫ p ds / ∫ p cos α ds over the part of the strip
     * the profile holds, |α| ≤ min(ε, π) (spread() cuts a strip wider than the whole
     * circumference at ±π, far outside Hertz's validity). With α = ε sin t the pressure
     * is p0 cos t, so ∫ p ds ∝ ∫ cos² t dt = π/2 over the whole strip and
     * ∫ p cos α ds ∝ ∫ cos² t cos(ε sin t) dt over |t| ≤ asin(min(1, π/ε)): a smooth
     * integrand, which 24 Gauss points integrate to rounding. Uncut (ε ≤ π) the scale
     * is ε/(2 J1(ε)) = 1 + ε²/8 + … (J1 the Bessel function of order 1).
     */
    double
    resultant_scale(const double epsilon)
    {
      // Per Gauss point t over |t| ≤ top: the factor 2 top w cos² t and sin t.
      using Points            = std::vector<std::array<double, 2>>;
      const auto points_up_to = [](const double top) {
        static const dealii::QGauss<1> rule(24);
        Points                         p(rule.size());
        for (unsigned int q = 0; q < rule.size(); ++q)
          {
            const double t = top * (2 * rule.point(q)[0] - 1), c = std::cos(t);
            p[q] = {{2 * top * rule.weight(q) * c * c, std::sin(t)}};
          }
        return p;
      };
      // Every uncut strip integrates up to top = π/2: those points once for all calls.
      static const Points whole  = points_up_to(std::asin(1.0));
      const double        cut    = std::min(1.0, pi / epsilon);
      const Points        partly = cut < 1.0 ? points_up_to(std::asin(cut)) : Points();
      double              along  = 0;
      for (const auto &[factor, sine] : cut < 1.0 ? partly : whole)
        along += factor * std::cos(epsilon * sine);
      return 0.5 * pi / along;
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

    /**
     * Legendre coefficients (c0, c1, c2) of a profile's radius less @p ref over
     * [ψc − w, ψc + w]: R(ψc + w t) − ref ≈ c0 + c1 t + c2 (3t² − 1)/2, the least-squares
     * parabola. The profile is linear between its samples, so each segment's moments are
     * integrated exactly (two Gauss points per segment: the integrand is a cubic).
     * @p w ≤ π. With ref the mean radius the moments of a round profile are exactly 0
     * (the curvature 3 c2/w² would otherwise carry the rounding of R/w²).
     */
    std::array<double, 3>
    legendre_moments(const std::vector<double> &r, const double centre, const double w, const double ref)
    {
      const long   n  = static_cast<long>(r.size());
      const double d  = two_pi / n;
      const double lo = centre - w, hi = centre + w;
      const double g  = 1 / std::sqrt(3.0);
      long         k  = static_cast<long>(std::floor(lo / d)); // the segment [k d, (k + 1) d] holds lo
      long         i  = ((k % n) + n) % n;
      double       a  = lo;
      double       m0 = 0, m1 = 0, m2 = 0;
      while (a < hi)
        {
          const long   j   = i + 1 == n ? 0 : i + 1;
          const double x0  = k * d;
          const double b   = std::min(hi, x0 + d);
          const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
          const double r0 = r[i] - ref, slope = (r[j] - r[i]) / d;
          for (const double x : {mid - g * half, mid + g * half})
            {
              const double t   = (x - centre) / w;
              const double rad = r0 + slope * (x - x0);
              m0 += half * rad;
              m1 += half * rad * t;
              m2 += half * rad * (1.5 * t * t - 0.5);
            }
          a = b;
          ++k;
          i = j;
        }
      // c_n = (2n + 1)/2 ∫_{-1}^{1} R P_n dt, and dt = dψ / w.
      return {{0.5 * m0 / w, 1.5 * m1 / w, 2.5 * m2 / w}};
    }

    /** Where the strip sits: centre φc (global), half-width b, and the radii there. */
    struct Strip
    {
      double centre = 0, half_width = 0, peak = 0;
      double bore_radius = 0, pin_radius = 0;
    };

    class HertzStrip : public PressureModel
    {
    public:
      explicit HertzStrip(ParameterReader &r)
        : conforming(r.get("Relative radius") == "conforming")
      {
      }

      void
      evaluate(const ContactLoad &load, SurfacePressure &out) override
      {
        out.bore.assign(geometry().bore.n_points(), 0.0);
        out.pin.assign(geometry().pin.n_points(), 0.0);
        last_half_width = 0;
        if (!(load.normal_force > 0))
          return;
        const Strip s   = conforming ? conforming_strip(load) : local_radii_strip(load);
        last_half_width = s.half_width;
        if (s.half_width / s.pin_radius > worst.half_angle)
          worst = {s.half_width / s.pin_radius, load.normal_force};
        spread(geometry().bore, load.bushing_angle, s.bore_radius, s.centre, s.half_width, s.peak, out.bore);
        spread(geometry().pin, load.pin_angle, s.pin_radius, s.centre, s.half_width, s.peak, out.pin);
      }

      double
      stable_compliance(const ContactLoad &) const override
      {
        // The profile resolves no dent narrower than one area, so the fit's stiffness is
        // that of a strip at least that wide.
        if (!(last_half_width > 0))
          return std::numeric_limits<double>::infinity();
        return 2 * std::max(last_half_width, radius_pin * min_window) / modulus();
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

    protected:
      void
      geometry_changed() override
      {
        const auto &g = geometry();
        radius_bore   = g.bore.mean_radius();
        radius_pin    = g.pin.mean_radius();
        // The most conforming gap admitted: R* at most 1e4 × the nominal one.
        curvature_floor = 1e-4 * std::max(radius_bore - radius_pin, 1e-9 * radius_bore);
        min_window      = two_pi / std::min(g.bore.n_points(), g.pin.n_points());
      }

    private:
      /** The seed's strip: R* from the radii at φ0, centred at φ0. */
      Strip
      local_radii_strip(const ContactLoad &load) const
      {
        Strip s;
        s.centre        = load.contact_angle;
        s.bore_radius   = geometry().bore.radius(s.centre - load.bushing_angle);
        s.pin_radius    = geometry().pin.radius(s.centre - load.pin_angle);
        const double r1 = s.bore_radius, r2 = s.pin_radius;
        const double r_star = r1 * r2 / std::max(r1 - r2, 1e-12 * r1);
        const auto   h      = hertz_line_contact(load.normal_force / geometry().axial_length, r_star, modulus());
        s.half_width        = h.half_width;
        s.peak              = h.peak_pressure;
        return s;
      }

      /**
       * The conforming strip (file comment). The half-angle w of a Hertz strip satisfies
       * w² g''(w) = T := 4 P R1 R2/(π E* R2²), with g''(w) the gap's curvature fitted over
       * ±w; round profiles give the classic strip at once. A worn pocket that conforms
       * to the pin (g'' → 0 inside it) pushes the root out to where the fit takes in
       * the pocket's flanks. The strip stays centred at the contact direction, along
       * which the multibody model's force acts (a strip centred elsewhere would not
       * carry that force; moved to the fitted vertex of the gap, it followed the kinks
       * of the worn profile and left steps of 5–10 % of the depth on a pocket's flanks).
       */
      Strip
      conforming_strip(const ContactLoad &load) const
      {
        const double line   = load.normal_force / geometry().axial_length;
        const double target = 4 * line * radius_bore * radius_pin / (pi * modulus() * radius_pin * radius_pin);
        Fit          fit;
        half_angle(load, load.contact_angle, target, fit);
        Strip s;
        s.centre      = load.contact_angle;
        s.bore_radius = geometry().bore.radius(s.centre - load.bushing_angle);
        s.pin_radius  = geometry().pin.radius(s.centre - load.pin_angle);
        const auto h  = hertz_line_contact(line, s.bore_radius * s.pin_radius / fit.curvature, modulus());
        s.half_width  = h.half_width;
        s.peak        = h.peak_pressure;
        return s;
      }

      /** The gap's parabola over a window: its curvature g'' at the centre [m/rad²]. */
      struct Fit
      {
        double curvature = 0, window = 0;
      };

      /** The fit of the gap over ±max(@p w, one area) around @p centre. */
      Fit
      fit_gap(const ContactLoad &load, const double centre, const double w) const
      {
        Fit f;
        f.window      = std::clamp(w, min_window, pi);
        const auto mb = legendre_moments(geometry().bore.samples(), centre - load.bushing_angle, f.window, radius_bore);
        const auto mp = legendre_moments(geometry().pin.samples(), centre - load.pin_angle, f.window, radius_pin);
        const double h0 =
          (radius_bore - radius_pin) + (mb[0] - 0.5 * mb[2]) - (mp[0] - 0.5 * mp[2]); // h at the centre [m]
        f.curvature = std::max(h0 + 3 * (mb[2] - mp[2]) / (f.window * f.window), curvature_floor);
        return f;
      }

      /**
       * The root of w² g''(w) = @p target (see conforming_strip), to 1e-12 of the target
       * (the strip's width then carries no error of its own into the depths); @p fit is
       * the fit there.
       */
      double
      half_angle(const ContactLoad &load, const double centre, const double target, Fit &fit) const
      {
        constexpr double tight  = 1e-12;
        const auto       excess = [&](const double w, Fit &f) {
          f = fit_gap(load, centre, w);
          return w * w * f.curvature - target;
        };
        double w_lo = std::sqrt(target / (radius_bore - radius_pin)), w_hi = w_lo;
        Fit    f_lo, f_hi;
        double e_lo = excess(w_lo, f_lo), e_hi = e_lo;
        f_hi = f_lo;
        if (std::abs(e_lo) <= tight * target) // round profiles: the nominal strip
          {
            fit = f_lo;
            return w_lo;
          }
        for (int k = 0; k < 40 && e_hi < 0 && w_hi < pi; ++k)
          {
            w_lo = w_hi, e_lo = e_hi, f_lo = f_hi;
            w_hi = std::min(pi, 2 * w_hi);
            e_hi = excess(w_hi, f_hi);
          }
        for (int k = 0; k < 40 && e_lo > 0 && w_lo > 1e-9; ++k)
          {
            w_hi = w_lo, e_hi = e_lo, f_hi = f_lo;
            w_lo = 0.5 * w_lo;
            e_lo = excess(w_lo, f_lo);
          }
        if (!(e_hi >= 0)) // a strip as wide as the pin
          {
            fit = f_hi;
            return w_hi;
          }
        if (!(e_lo <= 0))
          {
            fit = f_lo;
            return w_lo;
          }
        // Illinois regula falsi on w² (w² g'' is linear in w² where g'' is constant).
        double x_lo = w_lo * w_lo, x_hi = w_hi * w_hi;
        int    side = 0;
        fit         = std::abs(e_lo) < std::abs(e_hi) ? f_lo : f_hi;
        double w    = std::abs(e_lo) < std::abs(e_hi) ? w_lo : w_hi;
        for (int k = 0; k < 100 && x_hi - x_lo > tight * x_hi; ++k)
          {
            const double x = e_hi == e_lo ? 0.5 * (x_lo + x_hi) : (x_lo * e_hi - x_hi * e_lo) / (e_hi - e_lo);
            w              = std::sqrt(x);
            const double e = excess(w, fit);
            if (std::abs(e) <= tight * target)
              break;
            if (e > 0)
              {
                x_hi = x, e_hi = e;
                if (side == 1)
                  e_lo *= 0.5;
                side = 1;
              }
            else
              {
                x_lo = x, e_lo = e;
                if (side == -1)
                  e_hi *= 0.5;
                side = -1;
              }
          }
        return w;
      }

      double
      modulus() const
      {
        return effective_modulus(geometry().bushing, geometry().pin_material);
      }

      /**
       * The strip on the areas of @p profile (body angle @p theta): area k carries the
       * strip's force on its arc (the angles ψ_k + θ − φ ± Δψ/2 from the strip's centre,
       * s = @p radius × angle), scaled by resultant_scale(b / radius), as a pressure
       * over its surface L R_k Δψ.
       */
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
        const double       scale = resultant_scale(b / radius);
        // Only the areas within the strip's angular half-width (plus one) can be loaded:
        // area k's centre is at k·width + θ − φ, so they are a run of consecutive k.
        const double half = b / radius + width;
        if (half >= pi) // the strip wraps around the whole profile
          {
            for (unsigned int k = 0; k < n; ++k)
              p[k] =
                scale * arc_force(wrap(profile.angle(k) + theta - phi), radius, width, b, p0) / (profile[k] * width);
            return;
          }
        const double offset = theta - phi;
        const long   k_lo   = static_cast<long>(std::ceil((-half - offset) / width));
        const long   k_hi   = static_cast<long>(std::floor((half - offset) / width));
        const long   nn     = static_cast<long>(n);
        for (long k = k_lo; k <= k_hi; ++k)
          {
            const auto j = static_cast<unsigned int>(((k % nn) + nn) % nn);
            p[j]         = scale * arc_force(k * width + offset, radius, width, b, p0) / (profile[j] * width);
          }
      }

      /**
       * ∫ p ds [N/m] of the unscaled strip over the arc of angular @p width centred
       * @p centre from the strip's centre, at @p radius.
       */
      static double
      arc_force(double centre, double radius, double width, double b, double p0)
      {
        const double s0 = radius * (centre - 0.5 * width);
        const double s1 = radius * (centre + 0.5 * width);
        return p0 * b * (strip_primitive(s1, b) - strip_primitive(s0, b));
      }

      const bool conforming;
      double     radius_bore = 0, radius_pin = 0; ///< mean radii of the geometry [m]
      double     curvature_floor = 0;             ///< smallest gap curvature admitted [m/rad²]
      double     min_window      = 0;             ///< one discrete area [rad]
      double     last_half_width = 0;             ///< b of the last evaluation [m]
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
    pressure_models().add(
      "hertz-strip",
      "the multibody normal force spread over a Hertz line-contact strip at the contact "
      "direction, its width from the curvature of the worn surfaces over the strip "
      "(or, as the seed, from the local radii).",
      [](dealii::ParameterHandler &prm) {
        declare(prm,
                "Relative radius",
                "conforming",
                dealii::Patterns::Selection("conforming|local radii"),
                "How the strip's relative radius R* and centre are found. 'conforming': from "
                "the least-squares curvature and vertex of the gap between the worn surfaces "
                "over the strip's own width (a worn pocket that conforms to the pin spreads the "
                "pressure; features shorter than the contact width are averaged out); 'local "
                "radii': the seed's R* = R1 R2/(R1 − R2) from the radii at the contact "
                "direction, the strip centred there (a deeper area reads as a larger bore "
                "radius and concentrates the pressure: kept to compare with the seed).",
                "none");
      },
      [](ParameterReader &r) { return std::make_unique<HertzStrip>(r); });
  }
} // namespace wearlink::contact
