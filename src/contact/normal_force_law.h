// SPDX-License-Identifier: LGPL-2.1-or-later
// Normal force laws of the clearance joint (doc/models.md §1.2, seed eqs 9–11):
//   hertz               F = K δⁿ
//   lankarani-nikravesh F = K δⁿ (1 + 3(1 − c_e²) δ̇ / (4 δ̇⁻))
//   flores              F = K δⁿ (1 + 8(1 − c_e) δ̇ / (5 c_e δ̇⁻))
//   fe                  F = F_FE(δ, ψ_b, ψ_p) (1 + 3(1 − c_e²) δ̇ / (4 δ̇⁻)): the elastic
//                       force tabulated from the FE model of the joint's current profiles
//                       (fe/fe_normal_force_law.h) with the L-N hysteresis on top
// δ penetration [m], δ̇ its rate [m/s], δ̇⁻ the penetration rate at contact onset, K the
// stiffness [N/mⁿ] computed by the joint from geometry and materials (seed eq. 10).
//
// Guard against δ̇⁻ → 0: a contact that starts with (almost) no impact velocity — the
// continuous-contact regime — would make the damping factor 3(1 − c_e²)/(4 δ̇⁻)
// unbounded; worse, a contact that began grazing and is then loaded (δ̇ ≫ δ̇⁻) would
// meet a huge viscous damper. The hysteresis term therefore uses
//     v_ref = max(δ̇⁻, v_min, |δ̇|)
// in place of δ̇⁻ (v_min = "Minimum impact velocity", default 1e-4 m/s). For a genuine
// impact |δ̇| ≤ δ̇⁻ during compression and restitution, so the published law is
// unchanged; otherwise the damping force stays within 3(1 − c_e²)/4 (L-N) of the elastic
// force. Measured on the nine-bar (tests/scenes/nine_bar_test.cc): with v_min = 1e-2 m/s
// slow impacts were nearly elastic and the pin chattered; with a tiny v_min and no |δ̇|
// bound a loaded grazing contact blew up (226× the ideal joint force, 3e7 steps).
// The force is never tensile (F ≥ 0): at the end of restitution the damping term may
// exceed the elastic one.
#pragma once

#include "base/json.h"
#include "base/registry.h"
#include "base/timings.h"
#include "contact/conformal_contact.h"
#include "contact/pressure_model.h"

#include <algorithm>
#include <cmath>

namespace wearlink::contact
{
  struct NormalContactInput
  {
    double penetration      = 0; ///< δ > 0 [m]
    double penetration_rate = 0; ///< δ̇ [m/s]
    double impact_velocity  = 0; ///< δ̇⁻ captured at onset (unguarded) [m/s]
    double stiffness        = 0; ///< K [N/mⁿ]
    /** Contact direction in the bushing's and in the pin's frame [rad] (laws that use it). */
    double bore_angle = 0, pin_angle = 0;
  };

  struct NormalContactOutput
  {
    double force         = 0; ///< total normal force, ≥ 0 [N]
    double elastic_force = 0; ///< K δⁿ, the conservative part [N]
    double potential     = 0; ///< ∫ K δⁿ dδ = K δⁿ⁺¹/(n + 1) [J]
  };

  class NormalForceLaw
  {
  public:
    virtual ~NormalForceLaw() = default;
    virtual void
    evaluate(const NormalContactInput &in, NormalContactOutput &out) const = 0;
    /** The exponent n of K δⁿ (tabulated laws: the nominal one, for reports). */
    virtual double
    exponent() const = 0;
    /** ∫₀^δ F_elastic ds [J] (default: K δⁿ⁺¹/(n + 1)). */
    virtual double
    potential(const NormalContactInput &in) const;
    /** The law's hysteresis: χ of F = F_el (1 + χ δ̇/v_ref) and the guard v_min (factor 0: none). */
    struct Hysteresis
    {
      double factor              = 0; ///< χ [-]
      double min_impact_velocity = 0; ///< v_min [m/s]
    };
    virtual Hysteresis
    hysteresis() const
    {
      return {};
    }
    /**
     * The law's elastic force for the joint's nominal round pair at the approach
     * @p approach [m], with the joint's stiffness @p stiffness: the curve that the
     * conformal foundation of worn profiles carries in the narrow-contact limit.
     * Default: K δⁿ.
     */
    virtual double
    round_elastic_force(double approach, double stiffness) const;
    /**
     * The law's own conformal field for the current worn geometry (the fe law: the FE
     * resultant against the pin's displacement), or nullptr: the joint then uses the
     * foundation that carries round_elastic_force() (contact/conformal_contact.h).
     */
    virtual const ConformalField *
    conformal_field() const
    {
      return nullptr;
    }
    /**
     * Whether the joint asks worn profiles for a conformal field (ClearanceForm::conformal)
     * or for the point law along the deepest point (the other forms): called by the joint
     * before update_geometry() at construction and whenever its form changes, so that a
     * law built from the geometry builds only what the form needs (and rebuilds here if
     * the form changed). Default: nothing to do.
     */
    virtual void
    use_conformal(bool)
    {
    }
    /**
     * The joint's geometry changed (at construction and after every profile update):
     * laws built from the geometry rebuild here. Default: nothing to do.
     */
    virtual void
    update_geometry(const JointGeometry &)
    {
    }
    /** True if evaluate() needs NormalContactInput's contact-direction angles. */
    virtual bool
    uses_direction() const
    {
      return false;
    }
    /** What the run summary should say about the law (e.g. a table's size); default none. */
    virtual Json
    report() const
    {
      return Json::object();
    }
    /**
     * Wall time spent building the law from the geometry so far, in contact_law_tables
     * [s] (the fe law's tables, with the FE model's set-up when a table build made it).
     * Closed-form laws report nothing.
     */
    virtual PhaseTimings
    timings() const
    {
      return {};
    }
  };

  /**
   * The Lankarani–Nikravesh total force from the elastic force @p elastic: the hysteresis
   * factor 3(1 − c_e²)/4 = @p factor with the guarded reference velocity
   * max(δ̇⁻, v_min, |δ̇|) (see above), never tensile. Shared by every law with L-N damping.
   */
  inline double
  lankarani_nikravesh_force(const double elastic, const NormalContactInput &in, const double factor, const double v_min)
  {
    const double v_impact = std::max({in.impact_velocity, v_min, std::abs(in.penetration_rate)});
    return std::max(0.0, elastic * (1 + factor * in.penetration_rate / v_impact));
  }

  Registry<NormalForceLaw> &
  normal_force_laws();
} // namespace wearlink::contact
