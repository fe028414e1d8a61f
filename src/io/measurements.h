// SPDX-License-Identifier: LGPL-2.1-or-later
// A measurements file for `wearlink calibrate` (deal.II parameter syntax, like a scene):
// per wearing joint J of the scene
//   subsection Joint J
//     set Revolutions                   = 50000   # mechanism revolutions of the test [-], > 0
//     set Pin mass loss                 = 6.3     # [mg], > 0 (optional)
//     set Pin mass loss uncertainty     = 0.1     # [mg, 1σ], ≥ 0 (required with the mass loss)
//     set Bushing mass loss             = ...     # [mg] (optional)
//     set Bushing mass loss uncertainty = ...     # [mg, 1σ]
//     set Pin profile file              = pin_A.csv  # (optional) a measured worn surface,
//     set Bore profile file             = ...        # 'angle_rad,radius_m' (io/profile_file.h),
//                                       # relative to this file's folder
//     set Profile uncertainty           = 2e-6    # [m, 1σ per point], > 0 (with a profile)
//     set Profile angle search          = 180     # [deg], 0 … 180 (default 180)
//   end
// A surface with a measured mass loss is fitted on it. A surface with only a profile is
// fitted on the profile's worn volume: its worn area against the scene's unworn surface
// (analysis::measured_worn_area) × the joint's axial length × the surface's density, as
// a mass loss [mg] with its 1σ from the per-point uncertainty (independent points). The
// run's own mass loss is Archard's volume × density, the same quantity to second order
// in depth / radius. Every profile is also compared with the worn surface a run at the
// calibrated coefficients predicts (analysis/profile_comparison.h: aligned within the
// angle search, RMS difference, worn areas), as a check of the calibration.
// A joint that is not a joint of the scene, or does not wear (Wear law = none), an entry
// that is not a finite number, a revolution count ≤ 0, a negative uncertainty, a mass loss
// ≤ 0 or without its uncertainty, a joint without any mass loss or profile, a profile whose
// worn area is not positive and a file without any
// measurement are InputErrors naming the file, the line (where it is one line) and the
// entry. Top-level `include` lines are not followed by the joint pre-scan: give each
// joint's subsection in the file itself.
#pragma once

#include "analysis/profile_comparison.h"
#include "io/scene.h"

#include <string>
#include <vector>

namespace wearlink::io
{
  /** One measured surface: a joint's pin or bushing. */
  struct SurfaceMeasurement
  {
    std::string joint;
    std::string surface;         ///< "pin" | "bushing"
    double      revolutions = 0; ///< of the test [-]
    double      mass_loss   = 0; ///< [mg]
    double      uncertainty = 0; ///< of the mass loss, 1σ [mg]
    std::string from_profile;    ///< the profile file it was derived from ("" if weighed)
  };

  /** One measured worn surface (fitted if its surface has no mass loss; always compared). */
  struct ProfileMeasurement
  {
    std::string          joint;
    std::string          surface;          ///< "pin" | "bore"
    std::string          file;             ///< as resolved (relative to the measurements file)
    double               revolutions  = 0; ///< of the joint's test [-]
    double               uncertainty  = 0; ///< 1σ per point [m]
    double               angle_search = 0; ///< [deg]
    analysis::PolarTrace trace;
  };

  struct Measurements
  {
    std::string                     file;
    std::vector<SurfaceMeasurement> surfaces; ///< in file order of the joints, pin before bushing
    std::vector<ProfileMeasurement> profiles; ///< in file order of the joints, pin before bore
  };

  /** Read and check @p file against @p scene (see the top of this file). */
  Measurements
  read_measurements(const std::string &file, const Scene &scene);

  /** The entry of the coefficient of @p surface ("pin" | "bushing") of @p joint in a scene. */
  std::string
  wear_coefficient_entry(const std::string &joint, const std::string &surface);
} // namespace wearlink::io
