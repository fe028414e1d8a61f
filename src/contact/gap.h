// SPDX-License-Identifier: LGPL-2.1-or-later
// The gap between a (worn) bore and a (worn) pin (doc/models.md §1.5):
//   g(φ) = R1*(φ − θ_bushing) − R2*(φ − θ_pin) − e·u(φ),   u(φ) = (cos φ, sin φ),
// φ a global direction, R1* the bore profile in the bushing's frame, R2* the pin profile
// in the pin's frame, e the eccentricity (pin centre − bore centre). The penetration is
// δ = −min_φ g(φ), reached at the contact direction φ*. For round profiles this is
// δ = |e| − c with φ* the direction of e (seed eqs 1–5), computed in closed form.
//
// For non-round profiles g is minimized exactly over the directions that can touch at
// all (e·u(φ) ≥ min R1* − max R2*). The profiles are piecewise linear in angle, so
// between two consecutive kinks (sample angles of the bore, shifted by θ_bushing, and
// of the pin, shifted by θ_pin) g(φ) = a + b φ − |e| cos(φ − φ_e), which is convex
// within ±90° of φ_e and stationary at φ = φ_e − asin(b/|e|): the global minimum is
// at a kink or at one of these points, and all of them are visited (~2N·window/2π
// evaluations, each without a trigonometric call: the cosines and sines of the kinks
// relative to φ_e advance by a fixed rotation per sample spacing, and an arcsine is taken only
// for a segment whose g' changes sign). A grid plus golden-section search, used before, could stop in a local
// minimum of a jagged worn profile (measured up to 2e-7 m off, ~1 % of δ). The contact normal is taken radial, u(φ*) — the
// per-area model of seed eqs 28–33 with the exact gap; the profiles' slopes are small
// (wear depths ≪ radii).
#pragma once

#include "base/profile.h"
#include "mbs/types.h"

#include <cmath>

namespace wearlink::contact
{
  struct GapResult
  {
    double    penetration = 0; ///< δ = −min g [m]; < 0 means free flight
    mbs::Vec2 normal{1, 0};    ///< u(φ*): from the bore centre towards the contact
    double    bore_radius = 0; ///< R1*(φ* − θ_bushing) [m]
    double    pin_radius  = 0; ///< R2*(φ* − θ_pin) [m]

    /** The global contact direction φ* ∈ (−π, π] [rad] (not needed by the forces, so not kept). */
    double
    angle() const
    {
      return std::atan2(normal.y(), normal.x());
    }
  };

  class Gap
  {
  public:
    Gap(const Profile &bore, const Profile &pin);

    /** δ, φ* and the radii at the contact direction. */
    GapResult
    evaluate(const mbs::Vec2 &eccentricity, double bushing_angle, double pin_angle) const;

    /**
     * The seed's per-area form (eqs 28–29): the discrete area facing the eccentricity
     * decides, c*(n) = R1*(n) − R2*(n), δ*(n) = |e| − c*(n), with n the area in the
     * direction of e on each surface (bore: bushing frame, pin: pin frame) and the
     * normal along e. The radii are interpolated linearly between area centres so that
     * δ* is continuous in time (the integrator locates contact onsets on it). No
     * minimization over directions: a worn pocket next to the facing area is not seen.
     * Identical to evaluate() for round profiles.
     */
    GapResult
    evaluate_per_area(const mbs::Vec2 &eccentricity, double bushing_angle, double pin_angle) const;

    bool
    round() const
    {
      return is_round;
    }
    /** cos and sin of one sample spacing 2π/N of a profile. */
    struct Step
    {
      double cos, sin;
    };

    /** Nominal radial clearance c = mean R1* − mean R2* [m]. */
    double
    nominal_clearance() const
    {
      return bore.mean_radius() - pin.mean_radius();
    }

  private:
    /** The smallest gap g over the directions that can touch, and its direction φ. */
    struct Minimum
    {
      double g, phi;
    };
    Minimum
    minimize(double eccentricity_norm, double phi_e, double bushing_angle, double pin_angle) const;
    /** The result with contact direction @p phi and penetration @p penetration. */
    GapResult
    at_direction(double phi, double penetration, double bushing_angle, double pin_angle) const;

    Profile bore, pin;
    bool    is_round;
    double  r1, r2;        ///< radii when round
    double  min_clearance; ///< min R1* − max R2*
    Step    bore_step, pin_step;
  };
} // namespace wearlink::contact
