// SPDX-License-Identifier: LGPL-2.1-or-later
// The `fe` normal force law's own conformal field (contact/conformal_contact.h): the
// resultant of the FE contact of a worn pin and bore as a function of the pin's
// displacement vector e in the bushing frame and of the relative angle θ_rel =
// θ_pin − θ_bushing, tabulated from displacement-controlled FE solves on the joint's
// shared model (fe/model_pool.h).
//
// Why displacement control. A worn joint is a conformal contact: the pin sits in a pocket
// of its own shape. Under force control (the force–approach table of
// fe/fe_normal_force_law.h) a frictionless pin slides sideways in the pocket as the load
// grows, so that its rigid overlap need not grow with the load, and the force acts along
// one direction per table point. With the pin centre given, every e has exactly one FE
// resultant, its direction included: the field the dynamics need.
//
// Grid (the knobs of the law: 'Table pin directions', 'Table bore directions',
// 'Table load levels'):
//   - relative angles θ_j = 2πj/n_p (n_p = 1 if the pin is round: the field then does
//     not depend on θ_rel);
//   - directions of e in the bushing frame α_i = 2πi/n_b;
//   - K overlap levels δ_k shared by every direction: the approach of the nominal round
//     pair (mean radii) at the table's load levels F_k (Johnson's line contact,
//     contact/cylindrical_contact.h), so that the levels are spaced logarithmically and
//     cover the loads the law is asked for.
// Node (j, i, k): the pin centre e = ρ u(α_i) on the ray α_i whose rigid overlap of the
// profiles (contact::Gap, bushing frame, pin at θ_j) is δ_k — the overlap grows with ρ
// along a ray where it is positive (it is a maximum of functions increasing in ρ), so
// ρ is found by bracketing and the Illinois method — and one FE solve under displacement
// control there. Stored: ln|F|, the deviation β of the force's direction from the
// inward ray (direction α_i + π + β, β in (−π, π]), ρ, and the potential (below).
//
// Evaluation at (e, θ_rel): δ = the rigid overlap at e (also overlap(), the event value:
// the force is > 0 exactly where δ > 0); α = atan2(e); periodic linear weights between
// the two neighbouring α's and θ's; per corner, ln|F| and β as monotone cubic Hermite
// functions of ln δ (Fritsch–Carlson slopes: C¹, and increasing for ln|F|), beyond the
// levels a power law of the end slope for |F| and β held at its end value (its end slope
// is set to zero, so the field stays C¹ in δ); ln|F| and β are blended with the weights
// (not the force vectors, which would shorten between directions that differ), and the
// force is |F| u(α + π + β), bushing frame.
//
// Couples: none of the contact's own. The FE model loads the pin through a rigid core that
// translates and does not rotate, its kept mesh carries the worn pin as radial offsets with
// radial normals, and the solve reports no couple; the couples that the slopes of worn
// profiles exert (−∂V/∂θ_rel on the pin, small: the slopes are wear depths over radii) are
// left out, so a relative rotation under load exchanges a little energy that the balance
// does not see (measured on the nine-bar's worn joint B: |∂V/∂θ_rel| ≤ 6 mJ/rad against a
// stored 3 mJ at 2.5 kN). What the field does carry is the moment of its force about the
// bore centre: the force acts on the line through the pin centre (the joint applies it
// there and through the bore centre), so the bushing, held at its centre, receives
// bushing_torque = −e × F; without it a joint that turns rigidly under a load that is not
// along e would do work (as the foundation, which has the same term).
//
// Potential: V = −∫ F·de along the ray from the onset of overlap, per node from the
// stored ρ(δ_k) (the integrand −F·u(α) = |F| cos β, as a power law of ρ − ρ_onset between
// levels: exact for a power-law force; below δ_0 the power law of the first level), and
// ln V interpolated like ln|F|. It only feeds the energy balance. Its accuracy: at the
// nodes the quadrature error of the piecewise power law, 0.55 % of V against a fine
// quadrature of the interpolated force on the tests' pocket; its slope along a ray is
// −F·u to 0.6 %; between rays it is not the exact line integral of the interpolated
// force, whose curl is not zero.
//
// Damping with a ConformalMotion m: the Lankarani–Nikravesh law F (1 + χ δ̇/v) generalized
// to a vector, stiffness-proportional: damped = F + χ Σ_modes λ (q·ṽ)/v_q q, the modes
// (λ, q) the eigenpairs of D = (δ / n_loc) sym(J), J = ∂F/∂e from the interpolant
// (∂F/∂δ ⊗ ∂δ/∂e + ∂F/∂α ⊗ ∂α/∂e, ∂δ/∂e = u(φ*) the deepest point's direction,
// ∂α/∂e = perp(e)/|e|²), n_loc = d ln|F|/d ln δ, ṽ = m.velocity, and per mode the L-N
// guard v_q = max(δ̇⁻, v_min, |q·ṽ|); λ > 0 (a direction in which the force would grow
// outward) is not damped. For a round pair D has the eigenpairs (−|F|, u(α)) and
// (−|F| δ/(n_loc |e|), the tangent): along the normal this is exactly the L-N law; the
// tangent, the turning of a central force, is damped by at most χ |F| δ/(n_loc |e|) (2e-4
// of |F| at 1 µm in a 0.5 mm clearance). In a pocket the flanks make the sideways mode
// stiff, and a pin sliding sideways is damped as it compresses them. The damped force is
// never tensile along the elastic force: the damping term is scaled down until it is not,
// so the damping power −(damped − F)·ṽ stays ≥ 0.
#pragma once

#include "contact/conformal_contact.h"
#include "contact/gap.h"
#include "contact/pressure_model.h"

#include <memory>
#include <string>
#include <vector>

namespace wearlink::fe
{
  class PinBushingModel;
  struct FeForceLawSettings;
  struct TableBuild;

  /** The FE resultant of a worn pair against the pin's displacement (see the file comment). */
  class FeConformalTable : public contact::ConformalField
  {
  public:
    /** The values of the nodes, (j, i, k) at (j n_b + i) K + k. */
    struct Nodes
    {
      unsigned int        n_pin = 1, n_bore = 1; ///< n_p relative angles, n_b directions of e
      std::vector<double> overlaps;              ///< δ_k [m], K ≥ 2, positive and increasing
      std::vector<double> ln_force;              ///< ln |F| [ln N], increasing in k
      std::vector<double> deviation;             ///< β [rad] in (−π, π]
      std::vector<double> radius;                ///< ρ [m]
      std::vector<double> onset;                 ///< per direction (j, i): ρ where the overlap is 0 [m]
    };

    /** The field of the nodes @p nodes of the pair @p bore, @p pin. InputError if the nodes are inconsistent. */
    FeConformalTable(const Profile &bore, const Profile &pin, Nodes nodes);

    double
    overlap(const mbs::Vec2 &e, double relative_angle) const override;

    void
    evaluate(const mbs::Vec2                &e,
             double                          relative_angle,
             const contact::ConformalMotion *motion,
             bool                            with_potential,
             contact::ConformalForce        &out) const override;

    const Nodes &
    nodes() const
    {
      return data;
    }
    /** The elastic force |F| [N] of node (j, i, k). */
    double
    node_force(unsigned int j, unsigned int i, unsigned int k) const;
    /** The potential V [J] of node (j, i, k). */
    double
    node_potential(unsigned int j, unsigned int i, unsigned int k) const;

    /** Evaluations with an overlap (for the run summary), and those below δ_0 and above δ_{K−1}. */
    long
    n_evaluations() const
    {
      return evaluations;
    }
    long
    n_below() const
    {
      return below;
    }
    long
    n_above() const
    {
      return above;
    }

  private:
    /** ln|F|, β (and ln V) of one corner at x = ln δ, with their derivatives in x. */
    struct CornerValue
    {
      double ln_f = 0, d_ln_f = 0, beta = 0, d_beta = 0, ln_v = 0;
    };
    CornerValue
    corner(std::size_t run, double x, bool with_potential) const;
    /** The corners around (α, θ_rel) blended at x = ln δ, with the derivatives of the blend. */
    struct Blend
    {
      double ln_f = 0, d_ln_f = 0, beta = 0, d_beta = 0, ln_v = 0; ///< values, d/dx
      double ln_f_alpha = 0, beta_alpha = 0;                       ///< d/dα at fixed x
    };
    Blend
    blend(double alpha, double relative_angle, double x, bool with_potential) const;

    contact::Gap        gap;
    Nodes               data;
    unsigned int        K = 0;
    std::vector<double> x;                            ///< ln δ_k
    std::vector<double> slope_f, slope_beta, slope_v; ///< Hermite slopes per node (d/d ln δ)
    std::vector<double> ln_v;                         ///< ln V per node
    mutable long        evaluations = 0, below = 0, above = 0;
  };

  /**
   * The overlap levels of a conformal table: the approach of the nominal round pair of
   * @p geometry (mean radii) at the load levels @p forces [N] by Johnson's line contact;
   * beyond the largest load for which that approach still grows with a margin
   * (contact::cylindrical_valid_max_force) the power law of its slope there, so the levels
   * increase whatever the range.
   */
  std::vector<double>
  conformal_overlap_levels(const contact::JointGeometry &geometry, const std::vector<double> &forces);

  /**
   * The conformal table of @p geometry (see the file comment) on the joint's shared
   * model (kept in @p shared if given), from the cache if it holds it. @p build receives
   * the solves, times, failures (filled from their neighbours along the levels, as the
   * force–approach table's) and repairs.
   */
  std::unique_ptr<FeConformalTable>
  build_conformal_table(const contact::JointGeometry     &geometry,
                        const FeForceLawSettings         &settings,
                        TableBuild                       &build,
                        std::shared_ptr<PinBushingModel> *shared = nullptr);
} // namespace wearlink::fe
