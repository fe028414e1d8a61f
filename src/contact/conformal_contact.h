// SPDX-License-Identifier: LGPL-2.1-or-later
// The contact of a worn (non-round) pin and bore as the resultant of the pressure over the
// whole arc where the rigid profiles overlap (doc/models.md §1.7), not as one point.
//
// A worn joint is a conformal contact: the pin sits in a pocket of its own shape and the
// pressure spreads over tens of degrees, so that the force depends on the pin's whole
// displacement vector in the bore, not on the deepest point of the gap alone. A
// ConformalField gives, for the pin centre e in the bushing's frame and the relative
// angle θ_rel = θ_pin − θ_bushing:
//   - the largest overlap of the rigid profiles (the contact's event function, > 0 in
//     contact),
//   - the elastic force of the bushing on the pin (its own direction),
//   - the generalized forces on the two bodies' angles that the slopes of the worn
//     profiles produce (with them the field is the gradient of its potential, so a worn
//     pocket conserves energy),
//   - the stored energy.
//
// OverlapFoundation, the conformal form of the closed-form laws: an elastic foundation
// over the overlap field
//     d(ψ) = R2*(ψ − θ_rel) + e·u(ψ) − R1*(ψ)      (ψ in the bushing frame),
// carrying p(d) ≥ 0 wherever d > 0, with the energy V = L R ∫ P(d(ψ)) dψ (P' = p) and the
// force −∂V/∂e = −L R ∫ p(d) u(ψ) dψ. The foundation is calibrated so that a round pair
// reproduces the point law it stands for in the narrow-contact limit: there
// d ≈ δ − c ψ²/2 over an arc ±√(2δ/c), and p(d) = k d^m gives
//     F = L R k √(2/c) B(m) δ^(m+1/2),   B(m) = ∫_{-1}^{1} (1 − t²)^m dt = √π Γ(m+1)/Γ(m+3/2),
// so the law K δⁿ is carried by m = n − 1/2, k = K / (L R √(2/c) B(m)) (Hertz's n = 1.5: a
// linear foundation, B = 4/3). A law that is no power law (a force–approach table of a
// cylindrical closed form) is carried by the foundation that has its local exponent and
// force at every overlap (the same relation with n the local slope d ln F / d ln δ).
//
// Discretization: the overlap is taken at the edges of cells of 1/S of a bore area in the
// bushing frame and interpolated linearly across each cell, and each cell's energy and
// force are the exact integrals of P and p of that linear overlap (closed forms for a
// power law, Gauss–Legendre where it is smooth). So the force is continuous with a
// continuous derivative in e (no kink where a cell starts to touch), the field is the
// exact gradient of the cells' energy, and the event function — the largest edge
// overlap — is positive exactly where the force is.
#pragma once

#include "base/profile.h"
#include "mbs/types.h"

#include <functional>
#include <memory>
#include <vector>

namespace wearlink::contact
{
  /**
   * The motion of the pair and the hysteresis the contact carries (the normal force law's
   * Lankarani–Nikravesh factor and guard), for the damped force: at each point of the
   * overlap the pressure is p (1 + χ ḋ / max(δ̇⁻, v_min, |ḋ|)), never tensile, with ḋ the
   * rate of the overlap there — so that a pin moving sideways in its pocket is damped by
   * the flanks it compresses, as a point contact is along its normal.
   */
  struct ConformalMotion
  {
    mbs::Vec2 velocity{0, 0};      ///< d/dt of the pin centre seen from the bushing, bushing frame [m/s]
    double    relative_rate   = 0; ///< θ̇_pin − θ̇_bushing [rad/s]
    double    factor          = 0; ///< χ of the hysteresis [-]; 0: none
    double    impact_velocity = 0; ///< δ̇⁻ of the contact [m/s]
    double    min_velocity    = 0; ///< v_min of the guard [m/s]
  };

  /** The contact of a worn pair at one pose. */
  struct ConformalForce
  {
    mbs::Vec2 force{0, 0};        ///< elastic force of the bushing on the pin, bushing frame [N]
    mbs::Vec2 damped{0, 0};       ///< with the hysteresis (= force without a motion), bushing frame [N]
    double    pin_torque     = 0; ///< generalized force on θ_pin of the damped pressure, centres held [N m]
    double    bushing_torque = 0; ///< on θ_bushing [N m]
    double    damping_power  = 0; ///< power the hysteresis dissipates [W]
    double    overlap        = 0; ///< largest overlap of the rigid profiles [m] (> 0: contact)
    double    deepest        = 0; ///< the direction of that overlap, bushing frame [rad]
    double    potential      = 0; ///< stored energy [J] (only if asked for)
  };

  /** A worn pair's contact as a function of the pin's displacement (see the file comment). */
  class ConformalField
  {
  public:
    virtual ~ConformalField() = default;

    /** The largest overlap at pin centre @p e (bushing frame) [m] and relative angle θ_pin − θ_bushing [rad]. */
    virtual double
    overlap(const mbs::Vec2 &e, double relative_angle) const = 0;

    /**
     * Everything of ConformalForce; the damped force with @p motion (else = the elastic
     * one), the potential only if @p with_potential.
     */
    virtual void
    evaluate(const mbs::Vec2       &e,
             double                 relative_angle,
             const ConformalMotion *motion,
             bool                   with_potential,
             ConformalForce        &out) const = 0;
  };

  /**
   * The foundation's pressure against the overlap, p(d) [Pa] for d [m] > 0: a power law
   * k d^m, or piecewise power laws between the nodes of a table (power-law ends).
   */
  class Foundation
  {
  public:
    /** p = @p k d^@p m. */
    static Foundation
    power_law(double k, double m);

    /**
     * The foundation that carries the round pair's elastic law @p force (δ [m] → F [N]) in
     * the narrow-contact limit (file comment), tabulated at @p n_nodes overlaps spaced
     * logarithmically over [@p smallest, @p largest] [m].
     */
    static Foundation
    of_curve(const std::function<double(double)> &force,
             double                               clearance,
             double                               radius,
             double                               length,
             double                               smallest,
             double                               largest,
             unsigned int                         n_nodes);

    /** p(d) [Pa]; 0 for d ≤ 0. */
    double
    pressure(double d) const;
    /** P(d) = ∫₀^d p [Pa m]; 0 for d ≤ 0. */
    double
    energy(double d) const;

    bool
    is_power_law() const
    {
      return ln_d.empty();
    }
    double
    coefficient() const
    {
      return k;
    }
    double
    exponent() const
    {
      return m;
    }

  private:
    double              k = 0, m = 1;           ///< the power law (or the table's lower end)
    std::vector<double> ln_d, ln_p, slope, cum; ///< table: nodes, exponents to the next, P at the nodes
  };

  /**
   * B(m) = ∫_{-1}^{1} (1 − t²)^m dt: the narrow-contact integral of a foundation p = k d^m
   * over the arc of a round pair (file comment).
   */
  double
  narrow_contact_integral(double m);

  /**
   * The foundation p = k d^(n − 1/2) that carries the point law K δⁿ of a round pair of
   * radial clearance @p clearance, bore radius @p radius and axial length @p length [m]
   * in the narrow-contact limit.
   */
  Foundation
  foundation_of_power_law(double stiffness, double exponent, double clearance, double radius, double length);

  /** The elastic foundation over the overlap field of two worn profiles (file comment). */
  class OverlapFoundation : public ConformalField
  {
  public:
    /**
     * @p bore, @p pin the profiles; @p radius the bore radius the foundation was
     * calibrated with (the arc element L R dψ) [m]; @p cells_per_area S ≥ 1.
     */
    OverlapFoundation(const Profile &bore,
                      const Profile &pin,
                      double         length,
                      double         radius,
                      Foundation     foundation,
                      unsigned int   cells_per_area);

    double
    overlap(const mbs::Vec2 &e, double relative_angle) const override;

    void
    evaluate(const mbs::Vec2       &e,
             double                 relative_angle,
             const ConformalMotion *motion,
             bool                   with_potential,
             ConformalForce        &out) const override;

  private:
    /**
     * Visit, in increasing order, every edge that can bound an overlapping cell at pin
     * centre @p e and relative angle @p relative_angle: @p visit(d, edge, rise, adjacent)
     * with the edge's overlap d, its index, the pin's rise over the pin segment it lies on,
     * and whether the edge visited before it is its neighbour. A bore area whose edges
     * surely all stay clear (an upper bound of the overlap inside it ≤ 0) is passed over:
     * only its far edge is visited. Returns the largest overlap visited (the event value:
     * exact wherever it is above the bounds' slack, and at every sign change).
     */
    template <class Visit>
    double
    scan(const mbs::Vec2 &e, double relative_angle, Visit &&visit) const;

    std::vector<double> r1, ux, uy;      ///< per edge: bore radius, direction (bushing frame)
    std::vector<double> r2;              ///< pin samples [m]
    unsigned int        cells       = 1; ///< cells per bore area (S)
    double              cell        = 0; ///< cell width [rad]
    double              pin_spacing = 0, weight = 0, min_clearance = 0;
    /**
     * How far R2* rises above its chord across a bore area at most: its concave kinks
     * inside the area (the bore is linear there) [m].
     */
    double     pin_bulge = 0;
    Foundation foundation;
  };
} // namespace wearlink::contact
