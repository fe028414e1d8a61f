// SPDX-License-Identifier: LGPL-2.1-or-later
// `wearlink compare-profile`: a measured trace of a worn pin or bore against the worn
// profile a wear run predicted (analysis/profile_comparison.h for the math,
// io/profile_comparison_files.h for the files). Everything is read and checked before
// anything is written, so bad input leaves no output; then, atomically:
//   profile_comparison.json  the alignment (rotation_deg, the search, the RMS without
//                            rotation), rms_difference_m, largest_difference_m and its
//                            angle, the deepest wear measured and predicted with their
//                            angles, the worn areas [m², volume per unit length]
//                            measured, predicted and their difference, the sources
//   profile_comparison.png   wear depth against angle: predicted, measured (aligned),
//                            and their difference
#pragma once

#include "base/json.h"

#include <limits>
#include <string>
#include <vector>

namespace wearlink::workflows
{
  struct ProfileComparisonOptions
  {
    /** A finished wear run's folder (bore_<J>.csv, pin_<J>.csv, profiles_<J>.csv). */
    std::string run_directory;
    /** The measured trace: CSV angle_rad, radius_m (io/profile_file.h). */
    std::string measured_file;
    /** "bore" or "pin". */
    std::string surface;
    /** The joint's name, as in the scene ("A"). */
    std::string joint;
    /**
     * For a sliced joint: the trace's axial position from the bushing's mid-plane [m];
     * the slice that holds it is compared. NaN: the joint is not sliced.
     */
    double axial_position = std::numeric_limits<double>::quiet_NaN();
    /** The rotation is searched within ± this [deg], 0 … 180. */
    double      angle_search_deg = 180;
    std::string output_directory;
  };

  struct ProfileComparisonResult
  {
    /** What profile_comparison.json holds. */
    Json json;
    /** The printed table. */
    std::string table;
    /** The files written. */
    std::vector<std::string> files;
  };

  /** Compare as described above; InputError for bad input, before anything is written. */
  ProfileComparisonResult
  compare_profile(const ProfileComparisonOptions &options);
} // namespace wearlink::workflows
