// SPDX-License-Identifier: LGPL-2.1-or-later
// Closed-form force–approach relations of a pin in a bore (internal contact of parallel
// cylinders), the ones `wearlink compare-contact` sets against the FE model, and the
// normal force laws `johnson` and `esdu-78035` built from them.
//
// With the line load P = F/L, the plane-strain modulus 1/E* = (1 − ν1²)/E1 + (1 − ν2²)/E2
// and the radial clearance ΔR = R1 − R2 (Pereira, Ramalho & Ambrósio, Nonlinear Dyn. 63
// (2011) 681–697, who compare these against FE):
//   Johnson (Contact Mechanics, 1985)   δ = P/(π E*) [ln(4π E* ΔR / P) − 1]
//   ESDU-78035 (1978)                   δ = P/(π E*) [ln(4π E* ΔR / P) + 1]
// Both give δ(F); the force at a given approach is the root of δ(F) = δ. They hold while
// δ increases with P, i.e. for ln(4π E* ΔR/P) > 2 (Johnson) or > 0 (ESDU): the largest
// force cylindrical_valid_max_force() keeps a margin of 1 in the logarithm.
//   sphere (Hertz, seed eq. 10)          F = K δ^1.5, K = 4/(3(σ1 + σ2)) √R*
//   Winkler layer, round profiles       F = (E_c L R1/h) [e(φ0 + sin φ0 cos φ0) − 2 c sin φ0],
//                                       e = c + δ, cos φ0 = c/e, E_c the layers in series
//                                       (the `winkler` pressure model, linear layer).
#pragma once

#include "contact/force_approach_table.h"
#include "contact/pressure_model.h"

namespace wearlink::contact
{
  enum class CylindricalLaw
  {
    johnson,
    esdu_78035
  };

  /** What the closed forms need of a joint. */
  struct CylinderPair
  {
    double bore_radius = 0, pin_radius = 0; ///< R1 > R2 [m]
    double axial_length      = 0;           ///< L [m]
    double effective_modulus = 0;           ///< E* [Pa]

    static CylinderPair
    of(const JointGeometry &g);
  };

  /** δ(F) [m] of @p law for force @p force [N]. */
  double
  cylindrical_approach(CylindricalLaw law, const CylinderPair &pair, double force);

  /** The largest force for which @p law's δ(F) still increases with a margin [N]. */
  double
  cylindrical_valid_max_force(CylindricalLaw law, const CylinderPair &pair);

  /** F(δ) [N] of @p law: the root of δ(F) = @p approach (bisection in ln F to 1e-12). */
  double
  cylindrical_force(CylindricalLaw law, const CylinderPair &pair, double approach);

  /** F(δ) [N] of a linear Winkler layer of thickness @p thickness on round profiles. */
  double
  winkler_round_force(const JointGeometry &g, double thickness, double approach);

  /**
   * @p law as a one-direction table over @p n_levels forces from @p min_force to the
   * valid maximum: what the normal force laws `johnson` and `esdu-78035` evaluate
   * (monotone C¹ interpolation; the table reproduces the closed form to < 0.1 % at 60
   * levels from 1 N to the valid maximum, see tests/unit/contact).
   */
  ForceApproachTable
  tabulate_cylindrical_law(CylindricalLaw law, const CylinderPair &pair, double min_force, unsigned int n_levels);
} // namespace wearlink::contact
