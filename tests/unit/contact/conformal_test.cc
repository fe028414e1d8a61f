// SPDX-License-Identifier: LGPL-2.1-or-later
// The conformal contact of worn profiles (contact/conformal_contact.h, doc/models.md §1.7):
//  - a round pair carries the point law K δⁿ in the narrow-contact limit (the calibration),
//    for Hertz's n = 1.5 (a linear foundation) and for n = 1.3; a law given as a curve
//    (Foundation::of_curve) gives the foundation of its power law;
//  - on worn profiles the force is the integral of the foundation's pressure over the
//    overlap, against an independent quadrature of the continuous overlap on 200,000
//    points (the cells interpolate the overlap linearly: an error of order (cell)² × the
//    overlap's curvature);
//  - the field is the gradient of its energy (force and both couples by central
//    differences), positive exactly where the force is, and a symmetric pocket pushes
//    along its axis;
//  - the hysteresis dissipates and damps a pin sliding sideways in its pocket.
#include "base/numbers.h"
#include "base/profile.h"
#include "contact/conformal_contact.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace wearlink;
using namespace wearlink::contact;

namespace
{
  using numbers::pi;
  using numbers::two_pi;

  // The nine-bar's joint (doc/models.md §3): R1 = 12 mm, c = 0.5 mm, L = 10 mm; K of the
  // steel pair by seed eq. 10 with the internal R*.
  constexpr double R1 = 0.012, c = 0.5e-3, L = 0.01, K = 7.97e10;

  /** A bore worn into a pocket of depth @p depth about ψ = −π/2, the journal's imprint. */
  Profile
  imprinted_bore(const double depth, const unsigned int n = 360)
  {
    std::vector<double> r(n);
    for (unsigned int k = 0; k < n; ++k)
      {
        const double psi = two_pi * k / n;
        r[k]             = R1 + std::max(0.0, (c + depth) * std::cos(psi + pi / 2) - c);
      }
    return Profile::from_samples(r);
  }

  /** A pin worn on one side (pin frame), with a small ripple. */
  Profile
  worn_pin(const unsigned int n = 360)
  {
    std::vector<double> r(n);
    for (unsigned int k = 0; k < n; ++k)
      {
        const double psi = two_pi * k / n;
        r[k]             = R1 - c - 6e-6 * std::exp(-std::pow((psi - 1.0) / 0.4, 2)) + 0.3e-6 * std::cos(7 * psi);
      }
    return Profile::from_samples(r);
  }

  /**
   * The continuous field, independently: the elastic force and energy of the foundation
   * over the overlap d(ψ) = R2*(ψ − θ_rel) + e·u(ψ) − R1*(ψ) by the midpoint rule on
   * @p n points (no cells, no window).
   */
  ConformalForce
  reference_field(const Profile    &bore,
                  const Profile    &pin,
                  const Foundation &f,
                  const mbs::Vec2  &e,
                  const double      relative,
                  const unsigned    n = 200000)
  {
    ConformalForce out;
    const double   h  = two_pi / n;
    double         fx = 0, fy = 0, v = 0;
    for (unsigned k = 0; k < n; ++k)
      {
        const double psi = (k + 0.5) * h;
        const double d = pin.radius(psi - relative) + e.x() * std::cos(psi) + e.y() * std::sin(psi) - bore.radius(psi);
        if (d <= 0)
          continue;
        fx -= L * R1 * h * f.pressure(d) * std::cos(psi);
        fy -= L * R1 * h * f.pressure(d) * std::sin(psi);
        v += L * R1 * h * f.energy(d);
      }
    out.force     = mbs::Vec2(fx, fy);
    out.potential = v;
    return out;
  }
} // namespace

// B(m) = ∫(1 − t²)^m: B(1) = 4/3, B(0) = 2, B(1/2) = π/2.
TEST(Conformal, NarrowContactIntegral)
{
  EXPECT_NEAR(narrow_contact_integral(1.0), 4.0 / 3.0, 1e-14);
  EXPECT_NEAR(narrow_contact_integral(0.0), 2.0, 1e-14);
  EXPECT_NEAR(narrow_contact_integral(0.5), pi / 2, 1e-14);
}

// A round pair on the conformal path carries K δⁿ where the contact is narrow: the arc
// ±√(2δ/c) must be resolved by the cells (≥ 8 cells over it: δ ≥ 0.3 µm at 0.25° cells),
// and δ ≪ c (the calibration's d ≈ δ − c ψ²/2 holds to O(δ/c): the overlap's curvature is
// c + δ). Tolerance 0.5 % + δ/c: the cells' linear overlap across an arc of 8 cells misses
// (1/8)²/12 ≈ 0.1 % of its area, and the curvature changes the force by less than δ/c.
TEST(Conformal, RoundPairCarriesThePointLawInTheNarrowLimit)
{
  const Profile bore = Profile::round(R1, 360), pin = Profile::round(R1 - c, 360);
  for (const double n : {1.5, 1.3})
    {
      const OverlapFoundation field(bore, pin, L, R1, foundation_of_power_law(K, n, c, R1, L), 4);
      for (const double delta : {3e-7, 1e-6, 3e-6, 1e-5})
        for (const double phi : {0.0, 0.0011, 0.0023, 1.9})
          {
            ConformalForce  cf;
            const mbs::Vec2 e((c + delta) * std::cos(phi), (c + delta) * std::sin(phi));
            field.evaluate(e, 0.37, nullptr, false, cf);
            EXPECT_NEAR(cf.force.norm() / (K * std::pow(delta, n)), 1.0, 5e-3 + delta / c)
              << "n = " << n << ", δ = " << delta << ", φ = " << phi;
            EXPECT_NEAR(cf.overlap, delta, 1e-3 * delta + 2e-9); // the largest edge overlap: ρ (1 − cos(cell/2)) below
            EXPECT_NEAR(std::atan2(-cf.force.y(), -cf.force.x()), phi, 1e-5)
              << "the force is along e (to the cells' µrad)";
          }
    }
}

// A law given as a curve: of_curve of K δ^1.5 is the power law's foundation (local exponent
// exact for a power law; the table interpolates in ln d: 1e-9 relative).
TEST(Conformal, FoundationOfACurveMatchesThePowerLaw)
{
  const Foundation power = foundation_of_power_law(K, 1.5, c, R1, L);
  const Foundation curve = Foundation::of_curve([](double d) { return K * std::pow(d, 1.5); }, c, R1, L, 1e-12, c, 161);
  for (double d = 1e-13; d < 1e-3; d *= 3.7)
    {
      EXPECT_NEAR(curve.pressure(d) / power.pressure(d), 1.0, 1e-9) << d;
      EXPECT_NEAR(curve.energy(d) / power.energy(d), 1.0, 1e-9) << d;
    }
}

// Worn profiles: the cells' field against the continuous overlap's. Tolerance 0.5 % of
// the force: a cell of 0.25° interpolates the overlap with an error ≤ |e| (cell)²/8 ≈ 1 nm
// against overlaps of 0.3–2 µm over arcs of tens of cells.
TEST(Conformal, WornPairMatchesTheContinuousOverlap)
{
  const Profile           bore = imprinted_bore(30e-6), pin = worn_pin();
  const Foundation        f = foundation_of_power_law(K, 1.5, c, R1, L);
  const OverlapFoundation field(bore, pin, L, R1, f, 4);
  for (const double lateral : {0.0, 4e-6, -9e-6})
    for (const double approach : {0.3e-6, 2e-6})
      for (const double relative : {0.0, 2.2})
        {
          const mbs::Vec2 e(lateral, -(c + 30e-6 + approach));
          ConformalForce  cf;
          field.evaluate(e, relative, nullptr, true, cf);
          const ConformalForce ref = reference_field(bore, pin, f, e, relative);
          ASSERT_GT(ref.force.norm(), 0);
          EXPECT_NEAR((cf.force - ref.force).norm() / ref.force.norm(), 0, 5e-3)
            << "lateral " << lateral << ", approach " << approach << ", θ_rel " << relative;
          EXPECT_NEAR(cf.potential / ref.potential, 1.0, 1e-2);
        }
}

// The force and the couples are the gradient of the energy (a conservative field), checked
// by central differences of the potential: Q_e = −∂V/∂e, Q_θp = −∂V/∂θ_p, and the
// bushing's Q_θb = −∂V/∂θ_b where θ_b turns the bore and its frame (e fixed globally, so
// e's bushing-frame coordinates turn back). Tolerance: the differences' truncation,
// 1e-6 of the largest generalized force.
TEST(Conformal, FieldIsTheGradientOfItsEnergy)
{
  const Profile           bore = imprinted_bore(25e-6), pin = worn_pin();
  const OverlapFoundation field(bore, pin, L, R1, foundation_of_power_law(K, 1.5, c, R1, L), 4);
  const mbs::Vec2         e_global(3e-6, -(c + 25e-6 + 1.5e-6));
  const double            theta_b = 0.02, theta_p = 1.3;
  const auto              energy = [&](const mbs::Vec2 &eg, const double tb, const double tp) {
    ConformalForce cf;
    const double   co = std::cos(tb), si = std::sin(tb);
    field.evaluate(mbs::Vec2(co * eg.x() + si * eg.y(), -si * eg.x() + co * eg.y()), tp - tb, nullptr, true, cf);
    return cf.potential;
  };
  ConformalForce cf;
  const double   co = std::cos(theta_b), si = std::sin(theta_b);
  field.evaluate(mbs::Vec2(co * e_global.x() + si * e_global.y(), -si * e_global.x() + co * e_global.y()),
                 theta_p - theta_b,
                 nullptr,
                 true,
                 cf);
  const mbs::Vec2 force(co * cf.force.x() - si * cf.force.y(), si * cf.force.x() + co * cf.force.y());
  const double    h = 1e-9, ha = 1e-7, scale = cf.force.norm();
  const double    dvx =
    (energy(e_global + mbs::Vec2(h, 0), theta_b, theta_p) - energy(e_global - mbs::Vec2(h, 0), theta_b, theta_p)) /
    (2 * h);
  const double dvy =
    (energy(e_global + mbs::Vec2(0, h), theta_b, theta_p) - energy(e_global - mbs::Vec2(0, h), theta_b, theta_p)) /
    (2 * h);
  const double dvp = (energy(e_global, theta_b, theta_p + ha) - energy(e_global, theta_b, theta_p - ha)) / (2 * ha);
  const double dvb = (energy(e_global, theta_b + ha, theta_p) - energy(e_global, theta_b - ha, theta_p)) / (2 * ha);
  EXPECT_NEAR(force.x(), -dvx, 1e-6 * scale);
  EXPECT_NEAR(force.y(), -dvy, 1e-6 * scale);
  EXPECT_NEAR(cf.pin_torque, -dvp, 1e-6 * scale * R1);
  EXPECT_NEAR(cf.bushing_torque, -dvb, 1e-6 * scale * R1);
  EXPECT_GT(std::abs(cf.pin_torque), 1e-3 * scale * R1 * 1e-3) << "a worn pin carries a couple";
}

// The event value (largest overlap) is positive exactly where the force is, and the force
// rises continuously from zero at the onset.
TEST(Conformal, OverlapIsPositiveExactlyWhereTheForceIs)
{
  const Profile           bore = imprinted_bore(25e-6), pin = worn_pin();
  const OverlapFoundation field(bore, pin, L, R1, foundation_of_power_law(K, 1.5, c, R1, L), 4);
  for (const double angle : {-pi / 2, -pi / 2 + 0.3, 0.4, 2.5})
    for (double rho = c - 5e-6; rho < c + 40e-6; rho += 0.173e-6)
      {
        const mbs::Vec2 e(rho * std::cos(angle), rho * std::sin(angle));
        ConformalForce  cf;
        field.evaluate(e, 0.8, nullptr, false, cf);
        EXPECT_EQ(cf.overlap, field.overlap(e, 0.8));
        EXPECT_EQ(cf.overlap > 0, cf.force.norm() > 0) << "ρ = " << rho << ", angle " << angle;
        if (cf.overlap > 0) // F ≤ the force of the whole overlap arc at its largest overlap: continuous onset
          {
            EXPECT_LT(cf.force.norm(),
                      2 * L * R1 * pi * foundation_of_power_law(K, 1.5, c, R1, L).pressure(cf.overlap));
          }
      }
}

// A pocket symmetric about ψ = −π/2 with a round pin pushes the pin back along its axis
// when e lies on it.
TEST(Conformal, SymmetricPocketPushesAlongItsAxis)
{
  const Profile           bore = imprinted_bore(30e-6), pin = Profile::round(R1 - c, 360);
  const OverlapFoundation field(bore, pin, L, R1, foundation_of_power_law(K, 1.5, c, R1, L), 4);
  ConformalForce          cf;
  field.evaluate(mbs::Vec2(0, -(c + 31e-6)), 0.3, nullptr, false, cf);
  EXPECT_GT(cf.force.y(), 0);
  EXPECT_NEAR(cf.force.x(), 0, 1e-9 * cf.force.y());
  EXPECT_NEAR(cf.pin_torque, 0, 1e-12) << "a round pin carries no couple";
}

// The hysteresis: without motion the damped force is the elastic one; a pin pressing in
// is pushed harder, one leaving less, and one sliding sideways in its pocket meets a force
// against its motion; the dissipated power is never negative.
TEST(Conformal, HysteresisDampsEveryMotionIntoThePocket)
{
  const Profile           bore = imprinted_bore(30e-6), pin = Profile::round(R1 - c, 360);
  const OverlapFoundation field(bore, pin, L, R1, foundation_of_power_law(K, 1.5, c, R1, L), 4);
  const mbs::Vec2         e(0, -(c + 31e-6));
  ConformalForce          rest, in, out, side;
  ConformalMotion         m;
  m.factor          = 3 * (1 - 0.5 * 0.5) / 4;
  m.impact_velocity = 0.01;
  m.min_velocity    = 1e-4;
  field.evaluate(e, 0, &m, false, rest);
  EXPECT_EQ(rest.damped, rest.force);
  m.velocity = mbs::Vec2(0, -1e-3); // pressing into the pocket (−y)
  field.evaluate(e, 0, &m, false, in);
  m.velocity = mbs::Vec2(0, 1e-3);
  field.evaluate(e, 0, &m, false, out);
  m.velocity = mbs::Vec2(1e-3, 0);
  field.evaluate(e, 0, &m, false, side);
  EXPECT_GT(in.damped.y(), in.force.y());
  EXPECT_LT(out.damped.y(), out.force.y());
  EXPECT_LT(side.damped.x(), -1e-3 * side.force.norm()) << "sliding sideways is resisted";
  for (const auto &r : {in, out, side})
    EXPECT_GT(r.damping_power, 0);
}
