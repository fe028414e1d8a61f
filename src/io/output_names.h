// SPDX-License-Identifier: LGPL-2.1-or-later
// The names of the files each command writes, one table per command. The writers take
// the names from here, --overwrite removes exactly the names of its command's table
// (app/output_claim.h), and each command's --help ends with the table's listing(). A
// '*' stands for a joint, a channel, a method, an iteration or a member.
#pragma once

#include "base/output_directory.h"

#include <string>

namespace wearlink::io::outputs
{
  // `wearlink run` (plain and wear runs); also written by `life` and ensemble members.
  inline constexpr const char *summary         = "summary.json";
  inline constexpr const char *parameters      = "parameters.prm";
  inline constexpr const char *time_series     = "time_series.csv";
  inline constexpr const char *checkpoint      = "checkpoint.json";
  inline constexpr const char *wear_history    = "wear_history.csv";
  inline constexpr const char *response_before = "response_before.csv";
  inline constexpr const char *response_after  = "response_after.csv";
  // `wearlink life`
  inline constexpr const char *life_history = "life_history.csv";
  inline constexpr const char *life_plot    = "life.png";
  // an ensemble's folder (`run`/`life` --ensemble N)
  inline constexpr const char *ensemble_table = "ensemble.csv";
  inline constexpr const char *ensemble_plot  = "ensemble.png";
  // `wearlink contact`
  inline constexpr const char *contact_mesh = "pin_bushing.msh";
  // `wearlink study accuracy`
  inline constexpr const char *accuracy_table  = "accuracy.csv";
  inline constexpr const char *accuracy_report = "accuracy.md";
  inline constexpr const char *accuracy_floor  = "accuracy_floor.csv";
  // `wearlink study convergence`
  inline constexpr const char *convergence_report = "convergence.md";
  inline constexpr const char *convergence_table  = "convergence.csv";
  inline constexpr const char *convergence_json   = "convergence.json";
  // `wearlink sweep`
  inline constexpr const char *bifurcation_table = "bifurcation.csv";
  inline constexpr const char *bifurcation_plot  = "bifurcation.png";
  inline constexpr const char *sweep_members     = "members.csv";
  inline constexpr const char *sweep_json        = "sweep.json";
  // `wearlink compare-contact`
  inline constexpr const char *force_approach_table = "force_approach.csv";
  inline constexpr const char *force_approach_plot  = "force_approach.png";
  inline constexpr const char *deviations           = "deviations.csv";
  inline constexpr const char *effects              = "effects.csv";
  inline constexpr const char *pressure_table       = "pressure.csv";
  inline constexpr const char *pressure_plot        = "pressure.png";
  inline constexpr const char *compare_contact_log  = "compare_contact.txt";
  // `wearlink compare-pressure`
  inline constexpr const char *compare_pressure_table = "compare_pressure.csv";
  // `wearlink compare-dynamics` (and a wear run whose scene lists analyses)
  inline constexpr const char *before_after_report = "before_after.md";
  inline constexpr const char *before_after_table  = "before_after_lyapunov.csv";
  // `wearlink compare-signal`
  inline constexpr const char *signal_overlay    = "signal_overlay.png";
  inline constexpr const char *signal_spectrum   = "signal_spectrum.png";
  inline constexpr const char *signal_comparison = "signal_comparison.json";
  inline constexpr const char *signal_simulated  = "simulated";
  // `wearlink compare-profile`
  inline constexpr const char *profile_comparison_plot = "profile_comparison.png";
  inline constexpr const char *profile_comparison_json = "profile_comparison.json";
  // `wearlink calibrate`
  inline constexpr const char *calibration_report = "calibration.json";
  inline constexpr const char *calibrated_scene   = "calibrated.prm";
  inline constexpr const char *calibration_plot   = "calibration.png";

  /** Every file and folder of `wearlink run` (plain and wear runs). */
  RunFiles
  run();
  /** `wearlink life`: a run's files and the life's own. */
  RunFiles
  life();
  /** The files an ensemble writes beside its members' folders (`run`/`life` --ensemble). */
  RunFiles
  ensemble();
  /** `wearlink contact`. */
  RunFiles
  contact();
  /** `wearlink study accuracy`. */
  RunFiles
  accuracy_study();
  /** `wearlink study convergence`. */
  RunFiles
  convergence_study();
  /** `wearlink sweep`. */
  RunFiles
  sweep();
  /** `wearlink compare-contact`. */
  RunFiles
  compare_contact();
  /** `wearlink compare-pressure`. */
  RunFiles
  compare_pressure();
  /** `wearlink compare-dynamics`. */
  RunFiles
  compare_dynamics();
  /** `wearlink compare-signal`. */
  RunFiles
  compare_signal();
  /** `wearlink compare-profile`. */
  RunFiles
  compare_profile();
  /** `wearlink calibrate`. */
  RunFiles
  calibrate();
  /** `wearlink lyapunov`: per column and method a CSV, a JSON and a PNG. */
  RunFiles
  lyapunov();

  /**
   * The paragraph of a command's --help that names every file and folder of @p files
   * (what --overwrite removes; with @p removable false, a command that keeps earlier
   * files), wrapped at 88 columns.
   */
  std::string
  listing(const RunFiles &files, bool removable = true);
} // namespace wearlink::io::outputs
