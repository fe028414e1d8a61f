// SPDX-License-Identifier: LGPL-2.1-or-later
// "Validating simplified contact" (doc/architecture.md §1, use 2): one load history of every
// wearing clearance joint, recorded once from the multibody dynamics of the scene, is
// fed through several pressure models (default: every registered one whose parameters
// the scene gives for those joints, io/configured_pressure_models.h), each with the
// joint's own parameters from the scene, into Archard's law on both surfaces.
// Same loads, same k_D: the differences are the pressure models' alone. Reported per
// joint and model: worn volume of each surface, largest depth and where it is, the
// relative L2 difference of the depth profiles against the reference model (the last
// one listed: fe by default, which the FE layer registers last), and the wall time. Mukras et al. (2010) found similar
// volumes but different profiles for foundation and FE pressure.
#pragma once

#include "io/scene.h"

#include <string>
#include <vector>

namespace wearlink::workflows
{
  struct PressureComparisonRow
  {
    std::string         joint, model;
    double              volume_pin = 0, volume_bore = 0;         ///< Σ h A over the history [m³]
    double              archard_volume = 0;                      ///< k_D,pin ∫ F |v| dt [m³]
    double              max_depth_pin = 0, max_depth_bore = 0;   ///< [m]
    double              peak_angle_pin = 0, peak_angle_bore = 0; ///< body frames [deg]
    double              difference_pin = 0, difference_bore = 0; ///< ‖h − h_ref‖/‖h_ref‖
    double              wall_time   = 0;                         ///< set-up + evaluations [s]
    long                evaluations = 0;
    std::vector<double> depth_pin, depth_bore; ///< [m] per area
  };

  struct PressureComparison
  {
    double                             cycles = 0; ///< simulated cycles
    std::vector<PressureComparisonRow> rows;
    /** The table as text (what the command prints). */
    std::string
    table() const;
  };

  /**
   * Record @p cycles cycles of the scene's dynamics from its assembly and evaluate
   * @p models (empty: the default of the file comment) on that history. The scene needs
   * at least one joint with a wear law.
   */
  PressureComparison
  compare_pressure_models(io::Scene &scene, const std::vector<std::string> &models, double cycles);

  /** Write compare_pressure.csv, compare_depth_<J>.csv and .png into @p dir. */
  void
  write_pressure_comparison(const std::string &dir, const PressureComparison &c);
} // namespace wearlink::workflows
