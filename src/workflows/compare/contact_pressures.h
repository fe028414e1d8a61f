// SPDX-License-Identifier: LGPL-2.1-or-later
// The pressure distributions of `wearlink compare-contact` (workflows/compare/contact_comparison.h):
// per clearance joint, four loads spanning the force range of the scene's dynamics, each
// pushing the pin into the bore in one direction, through every registered pressure
// model (contact/pressure_model.h) whose parameters the scene gives for the joint
// (io/configured_pressure_models.h: hertz-strip, winkler if the scene gives its Layer
// thickness, fe from the joint's `fe` subsection, as shipped), on the fresh profiles and,
// if given, on a wear run's worn ones; fe is the reference of the ratios. The pressure is
// the one the wear loop sees: one value per discrete area of the bore (bushing frame).
//
// Per curve two numbers:
//   p_max  the largest area pressure [Pa] (an area average: below the continuous peak
//          by ≈ Δs²/(24 b²) for a Hertz strip of half-width b on areas of arc Δs);
//   α_c    the contact half-angle [rad], α_c = 2 √(σ² − Δψ²/12), σ the angular standard
//          deviation of the area forces p_k A_k about their centroid and Δψ²/12 the share
//          of the area width (Sheppard's correction). For the elliptical Hertz
//          distribution this is its half-angle b/R (within 3 % from 2 areas on); for a
//          parabolic one (linear Winkler layer) 0.89 × its half-angle. A measure of the
//          spread that all models share; the table prints it from 1.5 areas on (within 6 %).
#pragma once

#include "contact/pressure_model.h"
#include "io/scene.h"

#include <string>
#include <vector>

namespace wearlink::workflows
{
  /** What the pressure distributions need of one clearance joint. */
  struct PressureJoint
  {
    std::string            name;
    contact::JointGeometry fresh, worn;
    bool                   has_worn      = false;
    double                 direction     = 0; ///< bushing-frame ψ0 of the contact [rad]
    double                 pin_direction = 0; ///< pin-frame angle facing the contact [rad]
    std::vector<double>    loads;             ///< [N]
  };

  /** One column of pressure.csv. */
  struct PressureCurve
  {
    std::string         joint, model, state; ///< state: "fresh" or "worn"
    double              load      = 0;       ///< normal force F [N]
    double              direction = 0;       ///< ψ0 [rad], bushing frame
    std::vector<double> pressure;            ///< [Pa] per bore area, on PressureDistributions::bore_angle
    double              peak       = 0;      ///< p_max [Pa]
    double              half_angle = 0;      ///< α_c [rad]
    double              area_width = 0;      ///< Δψ of the joint's bore areas [rad]
    /** The model's NumericalError if it failed at this load (the values are then NaN), else "". */
    std::string failure;
  };

  struct PressureDistributions
  {
    std::vector<double>        bore_angle; ///< ψ_k [rad], the finest joint's areas
    std::vector<PressureCurve> curves;
    std::string                load_range; ///< how the loads were chosen, one sentence

    /** Per joint, state and load: p_max and α_c of each model and their ratio to fe's. */
    std::string
    table() const;
  };

  /**
   * Four loads from @p mean to @p peak [N], spaced geometrically, rounded to three
   * significant digits; empty if the range is empty (mean ≤ 0 or peak ≤ mean).
   */
  std::vector<double>
  spanning_loads(double mean, double peak);

  /** The distributions of every joint, model, state and load (models built from @p scene). */
  PressureDistributions
  contact_pressures(io::Scene &scene, const std::vector<PressureJoint> &joints, bool progress);

  /**
   * pressure.csv: bore_angle_rad, then pressure_Pa_<model>_<state>_<joint>_<load>N per
   * curve; pressure.png: one panel per joint and state, near the contact.
   */
  void
  write_contact_pressures(const std::string &dir, const PressureDistributions &d);
} // namespace wearlink::workflows
