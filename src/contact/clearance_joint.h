// SPDX-License-Identifier: LGPL-2.1-or-later
// The clearance revolute joint as a force element (doc/models.md §1, seed eqs 1–13):
// the bore sits in the bushing body, the pin in the pin body; their centres are the
// joint's attachment points. From the gap (contact/gap.h) it computes the penetration
// δ, the contact normal n and the contact points Q_bore = P_bushing + R1* n,
// Q_pin = P_pin + R2* n; the relative velocity of the material points there gives
// δ̇ = v_rel·n and the sliding velocity v_t = v_rel·t (t = n rotated +90°; material
// points, i.e. including the bodies' rotation, so a journal spinning in its bearing
// slides). The normal law gives F_n, the friction law F_t; the pin receives
// −F_n n + F_t t at Q_pin, the bushing the opposite at Q_bore.
//
// Mode: the joint is in a contact episode between a located onset and the following
// separation; at onset it captures the impact velocity δ̇⁻ = δ̇(t*) (seed eq. 11). Stages
// that penetrate before an onset has been located use the current δ̇ as provisional δ̇⁻.
#pragma once

#include "contact/axial_slices.h"
#include "contact/friction_law.h"
#include "contact/gap.h"
#include "contact/normal_force_law.h"
#include "contact/pressure_model.h"
#include "mbs/force_element.h"

#include <memory>
#include <string>
#include <vector>

namespace wearlink::contact
{
  /** How K's relative radius is formed (doc/models.md §1.3). */
  enum class EffectiveRadius
  {
    internal,    ///< R* = R1 R2/(R1 − R2): pin inside a bore (default)
    seed_printed ///< R* = R1 R2/(R1 + R2): as printed in seed eq. 10 (external form)
  };

  /**
   * How a joint with worn (non-round) profiles carries its contact (doc/models.md §1.5,
   * §1.7):
   *  - conformal: the resultant of the pressure over the whole arc where the profiles
   *    overlap, as a function of the pin's displacement (contact/conformal_contact.h;
   *    default);
   *  - deepest_point: the normal law at the deepest overlap of the exact gap
   *    g(φ) = R1*(φ − θ_bushing) − R2*(φ − θ_pin) − e·u(φ), along its radial direction,
   *    stiffness K from the nominal radii;
   *  - per_area: the seed's eqs 28–31, the area facing e decides: δ*(n) = |e| − c*(n),
   *    K*(n) from R1*(n), R2*(n) (with the chosen effective-radius form).
   * All three reduce to δ = |e| − c and the point law for round profiles.
   */
  enum class ClearanceForm
  {
    conformal,
    deepest_point,
    per_area
  };

  struct ClearanceJointDescription
  {
    std::string     name;
    std::string     normal_force_law = "lankarani-nikravesh"; ///< the law's registry name (for reports)
    int             bushing_body     = mbs::ground;
    mbs::Vec2       bushing_point{0, 0}; ///< bore centre in the bushing body's frame [m]
    int             pin_body = mbs::ground;
    mbs::Vec2       pin_point{0, 0}; ///< pin centre in the pin body's frame [m]
    JointGeometry   geometry;
    EffectiveRadius effective_radius = EffectiveRadius::internal;
    ClearanceForm   clearance_form   = ClearanceForm::conformal;
    /** Cells per discrete bore area of the conformal foundation (contact/conformal_contact.h). */
    unsigned int conformal_cells = 4;
    /**
     * Persistent contact held as a constraint (doc/models.md §1.6): taken up after a step
     * that ends in contact with |δ̇| < hold_velocity and |δ̈| < hold_acceleration, given up
     * when the held normal force is no longer compressive.
     */
    bool   hold_persistent_contact = false;
    double hold_velocity           = 1e-3; ///< [m/s]
    double hold_acceleration       = 50;   ///< [m/s²]
    /**
     * The joint's slice, when it is one of a sliced joint (contact/axial_slices.h): its
     * stiffness is slice.share of the joint's, computed from the nominal radii; its
     * bushing_point already holds the bore's offset. count = 1: the whole joint.
     */
    AxialSlice slice;
  };

  /** Everything about the joint at one state, for recording and pressure models. */
  struct JointDiagnostics
  {
    mbs::Vec2 eccentricity{0, 0};               ///< pin centre − bore centre, global [m]
    mbs::Vec2 local_eccentricity{0, 0};         ///< the same in the bushing body's frame [m]
    double    penetration      = 0;             ///< δ [m]
    double    penetration_rate = 0;             ///< δ̇ [m/s] (0 out of contact)
    double    sliding_velocity = 0;             ///< v_t [m/s] (0 out of contact)
    double    normal_force     = 0;             ///< F_n [N]
    double    elastic_force    = 0;             ///< its elastic part, without the hysteresis damping [N]
    double    friction_force   = 0;             ///< F_t [N]
    mbs::Vec2 normal{1, 0};                     ///< n, global
    double    contact_angle = 0;                ///< φ* [rad], global
    mbs::Vec2 force_on_pin{0, 0};               ///< −F_n n + F_t t [N]
    double    bushing_angle = 0, pin_angle = 0; ///< θ of both bodies [rad]
    mbs::Vec2 pin_deflection{0, 0};             ///< a bent pin's at this slice, global (in eccentricity) [m]
    double    potential_energy = 0;             ///< stored energy [J], as ClearanceJoint::potential_energy() gives it
  };

  class ClearanceJoint : public mbs::ForceElement
  {
  public:
    ClearanceJoint(ClearanceJointDescription       description,
                   std::unique_ptr<NormalForceLaw> normal_law,
                   std::unique_ptr<FrictionLaw>    friction_law);

    const std::string &
    name() const override
    {
      return description.name;
    }

    void
    add_forces(double t, const mbs::StateView &s, mbs::ForceAccumulator &out) const override;

    double
    potential_energy(const mbs::StateView &s) const override;

    /**
     * In contact: the penetration δ (position and velocity: the normal law's stiffness
     * and damping) and, with a friction law, the sliding velocity v_t (the friction
     * ramp), as gradients over the coordinates.
     */
    void
    stiff_directions(const mbs::StateView             &s,
                     unsigned int                      n_coordinates,
                     std::vector<mbs::StiffDirection> &out) const override;

    bool
    has_event() const override
    {
      return true;
    }
    double
    event_value(const mbs::StateView &s) const override;
    bool
    mode() const override
    {
      return in_contact;
    }
    void
    on_event(double t, const mbs::StateView &s, bool onset) override;

    bool
    can_hold() const override
    {
      return description.hold_persistent_contact;
    }
    bool
    holds_contact() const override
    {
      return held;
    }
    void
    held_contact(const mbs::StateView &s, mbs::HeldContact &out) const override;
    void
    set_held_force(double force) const override
    {
      held_normal_force = force;
    }
    double
    held_force() const override
    {
      return held ? held_normal_force : 0.0;
    }
    bool
    update_hold(double t, const mbs::StateView &s, const double *a) override;

    /**
     * Full evaluation at a state (not counted as a force evaluation), with the stored
     * energy: one evaluation of the contact serves an observer's figures and its energy
     * balance.
     */
    JointDiagnostics
    diagnostics(const mbs::StateView &s) const;

    /** K [N/mⁿ] (seed eq. 10 with the chosen relative radius). */
    double
    stiffness() const
    {
      return contact_stiffness;
    }
    double
    radial_clearance() const
    {
      return gap.nominal_clearance();
    }
    const ClearanceJointDescription &
    get_description() const
    {
      return description;
    }
    /**
     * Replace the profiles (worn geometry). With ClearanceForm::exact the stiffness
     * stays nominal; with per_area it follows the local radii (seed eq. 31).
     */
    void
    set_profiles(const Profile &bore, const Profile &pin);

    /** Select the gap form (see ClearanceForm) and the conformal foundation's cells per area. */
    void
    set_clearance_form(ClearanceForm form, unsigned int conformal_cells = 4);

    /**
     * The elastic force of the bushing on the pin [N] (bushing frame) with the pin centre
     * at @p e (bushing frame) [m] and the relative angle θ_pin − θ_bushing [rad], for the
     * current profiles and clearance form (the conformal field, or the point law).
     */
    mbs::Vec2
    elastic_force(const mbs::Vec2 &e, double relative_angle) const;

    /**
     * The pin centre (bushing frame) at which the current profiles carry the elastic
     * force @p force (bushing frame) at relative angle @p relative_angle, by Newton's
     * method from @p start; @p converged tells whether the force was matched to 1e-9 of
     * its size (otherwise the best point found is returned).
     */
    mbs::Vec2
    eccentricity_carrying(const mbs::Vec2 &force, double relative_angle, const mbs::Vec2 &start, bool &converged) const;

    /**
     * The rigid profiles' overlap with the pin centre at @p e (bushing frame) [m] and the
     * relative angle @p relative_angle [rad]: the conformal field's, or the gap's
     * (negative: apart).
     */
    double
    overlap(const mbs::Vec2 &e, double relative_angle) const;

    /** The conformal field in use (worn profiles, ClearanceForm::conformal), or nullptr. */
    const ConformalField *
    conformal_field() const
    {
      return field;
    }

    const NormalForceLaw &
    normal_force_law() const
    {
      return *normal_law;
    }

    long
    n_force_evaluations() const
    {
      return force_evaluations;
    }
    long
    n_impacts() const
    {
      return impacts;
    }
    double
    impact_velocity() const
    {
      return captured_impact_velocity;
    }
    /** Restore the mode (checkpoint / continuation); @p hold: the contact was held. */
    void
    set_mode(bool contact, double impact_velocity, bool hold = false)
    {
      in_contact               = contact;
      captured_impact_velocity = impact_velocity;
      held                     = contact && hold;
    }
    /** Episodes of held contact so far. */
    long
    n_holds() const
    {
      return holds;
    }

  private:
    /** The pin centre at this slice, global [m]: the pin body's point, moved by the bent pin's deflection. */
    mbs::Vec2
    pin_centre(const mbs::StateView &s) const;
    /** Kinematics at the contact for state @p s; false if not penetrating. */
    struct Contact
    {
      GapResult gap;
      mbs::Vec2 q_bore, q_pin, t;
      double    rate = 0, slide = 0;
      /**
       * Conformal contact: the magnitudes of the elastic and of the damped resultant [N],
       * the couples on both bodies [N m] and the power the hysteresis dissipates [W].
       */
      bool   conformal = false;
      double elastic = 0, damped = 0, pin_torque = 0, bushing_torque = 0, damping_power = 0;
      double stiffness     = 0;                ///< K, or K*(n) of the facing area (per_area) [N/mⁿ]
      double bushing_angle = 0, pin_angle = 0; ///< θ of both bodies [rad]
      double potential = 0;                    ///< the conformal field's stored energy [J], if asked for
    };
    NormalContactInput
    normal_input(const Contact &c) const;
    /** @p with_potential: the conformal field's stored energy too (Contact::potential). */
    void
    contact_kinematics(const mbs::StateView &s, Contact &c, bool with_potential = false) const;
    /** The conformal field's contact (direction, overlap, resultants, couples) into @p c. */
    void
    conformal_contact(const mbs::StateView &s, const mbs::Vec2 &e, Contact &c, bool with_potential) const;
    /** The energy stored in contact @p c [J] (from contact_kinematics() with the potential). */
    double
    stored_energy(const mbs::StateView &s, const Contact &c) const;
    /** True while a held contact is quasi-static (see the .cc). */
    bool
    quasi_static(const mbs::StateView &s) const;
    /** The largest relative difference of the held and the compliant elastic force of a held conformal contact. */
    static constexpr double hold_force_tolerance = 0.25;
    /** The held row's K and exponent of a conformal contact at @p s (see the .cc). */
    void
    local_power_law(const mbs::StateView &s, const Contact &c, double &stiffness, double &exponent) const;
    /** Build the conformal field for the current profiles (or none: round, other forms). */
    void
    update_field();
    void
    forces(const Contact &c, double &fn, double &fel, double &ft) const;

    ClearanceJointDescription       description;
    std::unique_ptr<NormalForceLaw> normal_law;
    std::unique_ptr<FrictionLaw>    friction_law;
    Gap                             gap;
    double                          contact_stiffness;
    /** The nominal bore radius and radial clearance, which K and the foundation are calibrated with [m]. */
    double reference_radius, reference_clearance;
    /** The foundation, if the law has no field of its own (a slice's may be shared: contact/shared_fields.h). */
    std::shared_ptr<const ConformalField> own_field;
    const ConformalField                 *field = nullptr; ///< the field in use, or nullptr (point contact)

    /** ∂(w·q̇)/∂q q̇ of the held row: δ̇ along a small shift of q by q̇ (central difference). */
    double
    convective_rate(const mbs::StateView &s, unsigned int n) const;
    /** ∂(v_rel·dir)/∂q̇ over @p n coordinates: pin +, bushing − (a stiff or held row). */
    void
    velocity_gradient(const mbs::StateView &s, const Contact &c, const mbs::Vec2 &dir, double sign, double *w) const;

    bool                        in_contact               = false;
    double                      captured_impact_velocity = 0;
    long                        impacts                  = 0;
    mutable long                force_evaluations        = 0;
    bool                        held                     = false;
    long                        holds                    = 0;
    mutable double              held_normal_force        = 0;
    mutable std::vector<double> shifted;  ///< (q, q̇) shifted along q̇ (convective_rate)
    std::vector<double>         hold_row; ///< w of update_hold()
  };

  /**
   * Slice @p i of the joint @p joint cut as @p layout says (contact/axial_slices.h): its
   * name, its share of the length, its bore centre moved by the misalignment's offset
   * (bushing_point), its pin radius less the crown and its bore radius plus the relief.
   * @p joint's profiles are the slice's before crown and relief (its K is computed from
   * them, as the joint's). For layout.count = 1, @p joint itself.
   */
  ClearanceJointDescription
  slice_of(const ClearanceJointDescription &joint, const SliceLayout &layout, unsigned int i);

  /**
   * The elastic force of the bushing on the pin [N] (bushing frame), summed over
   * @p slices of one joint (or one whole joint), with the pin centre at @p e from the
   * first slice's bore centre (bushing frame) [m]: slice j sees e + o₀ − o_j, o the
   * slices' bore offsets.
   */
  mbs::Vec2
  slices_elastic_force(const std::vector<const ClearanceJoint *> &slices, const mbs::Vec2 &e, double relative_angle);

  /**
   * The pin centre (from the first slice's bore centre, bushing frame) at which
   * @p slices carry @p force together (see slices_elastic_force()), by a damped Newton
   * method from @p start; @p converged tells whether the force was matched to 1e-9 of
   * its size (otherwise the best point found is returned).
   */
  mbs::Vec2
  eccentricity_carrying(const std::vector<const ClearanceJoint *> &slices,
                        const mbs::Vec2                           &force,
                        double                                     relative_angle,
                        const mbs::Vec2                           &start,
                        bool                                      &converged);

  /** K = 4/(3(σ1 + σ2)) √R* (seed eq. 10), R* per @p form from the nominal radii. */
  double
  contact_stiffness(double          bore_radius,
                    double          pin_radius,
                    const Material &bushing,
                    const Material &pin,
                    EffectiveRadius form);
} // namespace wearlink::contact
