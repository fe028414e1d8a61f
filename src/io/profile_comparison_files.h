// SPDX-License-Identifier: LGPL-2.1-or-later
// The files of `wearlink compare-profile`: a wear run's predicted surface read from its
// folder, and the comparison written out (JSON and an overlay PNG, each atomically).
//
// What a wear run's folder holds for a wearing joint J (io/wear_outputs.cc):
// bore_<J>.csv and pin_<J>.csv, the worn surfaces as scene profile files; and
// profiles_<J>.csv, columns angle_rad, bore_initial_m, bore_worn_m, pin_initial_m,
// pin_worn_m — the surfaces the run started from and those it ended with, at the same
// angles. The unworn radius r₀(ψ) against which a depth is measured is the run's
// starting surface from profiles_<J>.csv: it is exact for any starting profile (round
// or already worn), where summary.json holds no radii and the scene's nominal radius
// would be wrong for a run that started from profile files.
#pragma once

#include "analysis/profile_comparison.h"
#include "base/json.h"

#include <string>
#include <vector>

namespace wearlink::io
{
  /** A wearing surface of a run: as predicted at the end, and as it started. */
  struct RunSurface
  {
    analysis::PolarTrace worn;
    analysis::PolarTrace unworn;
    std::string          worn_file;   ///< RUN_DIR/<surface>_<J>.csv
    std::string          unworn_file; ///< RUN_DIR/profiles_<J>.csv
  };

  /** "bore" or "pin". */
  std::string
  surface_name(analysis::WornSurface surface);

  /**
   * The @p surface of joint @p joint in the wear run's folder @p run_directory (see the
   * top of the file). InputError if the folder or a file is missing (listing the joints
   * whose worn profiles the folder holds) or a file is malformed (file, line, column).
   */
  /**
   * The slice of the sliced joint @p joint of the run in @p run_directory that holds the
   * axial position @p z [m] from the bushing's mid-plane (its slices_<J>.csv): its name
   * ("B.s03"), and in @p centre its centre [m]. InputError if the run has no such sliced
   * joint or @p z lies beyond the bushing's ends.
   */
  std::string
  slice_at(const std::string &run_directory, const std::string &joint, double z, double &centre);

  RunSurface
  read_run_surface(const std::string &run_directory, const std::string &joint, analysis::WornSurface surface);

  /** What the overlay PNG is labelled with. */
  struct ProfileOverlayLabels
  {
    std::string joint;
    std::string surface;
    std::string measured_file;
  };

  /**
   * Write @p json as DIR/profile_comparison.json and the overlay of @p c as
   * DIR/profile_comparison.png (depth [µm] against the run-frame angle [°]: predicted,
   * measured after alignment, and their difference). Returns the files written (the PNG
   * only if gnuplot is installed).
   */
  std::vector<std::string>
  write_profile_comparison(const std::string                 &directory,
                           const Json                        &json,
                           const analysis::ProfileComparison &c,
                           const ProfileOverlayLabels        &labels);
} // namespace wearlink::io
