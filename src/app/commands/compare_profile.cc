// SPDX-License-Identifier: LGPL-2.1-or-later
// `wearlink compare-profile RUN_DIR MEASURED.csv --surface bore|pin --joint J`: a
// measured worn surface against a wear run's prediction (workflows/compare/profile_comparison.h):
// a printed table, profile_comparison.json and an overlay PNG.
#include "app/command_line.h"
#include "app/output_claim.h"
#include "base/exceptions.h"
#include "io/output_names.h"
#include "workflows/compare/profile_comparison.h"

#include <iostream>

namespace wearlink::app
{
  namespace
  {
    const std::string compare_profile_help =
      std::string(
        R"(wearlink compare-profile RUN_DIR MEASURED.csv --surface bore|pin --joint J
                         [--axial-position Z] [--angle-search DEG] [--output DIR]
                         [--overwrite] [--quiet]

Compares a measured worn surface (a profilometer or CMM trace of a pin or a bushing
bore) with the worn profile a wear run predicted, to see whether the run's wear
coefficients and pressure model reproduce the test.

RUN_DIR is the folder of a finished wear run (`wearlink run` or `wearlink life` of a
scene in which joint J wears). From it: J's predicted surface, bore_<J>.csv or
pin_<J>.csv, and the surface the run started from (profiles_<J>.csv), against which
depths are measured.
MEASURED.csv is a trace in the same format, 'angle_rad,radius_m' (a header row and
'#' comments allowed): angle [rad] in the body's own frame up to an unknown origin,
radius [m] from the joint centre (the absolute radius, not a deviation). Any number of
points (at least 8), any spacing, any order; angles are wrapped into [0, 2 pi).

  --surface bore|pin  which surface the trace is: a bore wears open (depth r - r0), a
                      pin wears thin (depth r0 - r)
  --joint J           the wearing joint, as the scene names it (e.g. A)
  --axial-position Z  for a joint cut into slices along the pin: the trace was taken
                      Z metres from the bushing's mid-plane (negative towards the
                      first slice); the slice that holds Z is compared (its worn
                      profile, bore_<J>.sNN.csv or pin_<J>.sNN.csv). Within the
                      bushing's length; the joint's slices_<J>.csv tells their centres
  --angle-search DEG  the measured origin is unknown: the trace is turned by the angle
                      within +-DEG (0 ... 180, default 180; 0: no turning) that
                      minimises the RMS radius difference; the measured point at
                      angle a then lies at a + rotation in the run's frame. Only the
                      rotation is fitted: an offset or eccentricity of the measured
                      radii stays in the difference.
  --output DIR        where to write (default output/compare_profile_<J>_<surface>)
  --quiet             no notes on stderr about the output folder

Both traces are compared on their common angles (each interpolated linearly in angle
onto the other's points); the RMS is over the whole circle, so a densely measured arc
weighs no more than a sparse one of equal length. Printed and written into DIR, each
file atomically:
  profile_comparison.json  rotation_deg; rms_difference_m (and without rotation),
                           largest_difference_m and its angle; max_depth_measured_m,
                           max_depth_predicted_m and their angles [deg, the run's body
                           frame]; worn_area_measured_m2, worn_area_predicted_m2 and
                           their difference [m^2: worn volume per metre of joint length];
                           the files it read
  profile_comparison.png   wear depth [um] against angle [deg]: predicted, measured
                           (turned by the rotation found), and their difference
)") + output_folder_help +
      R"(  --overwrite        replace the files of an earlier comparison in DIR

Exit status: 0 success; 2 bad input (a missing run folder or file, a line of a CSV
file that is not two finite numbers, a radius <= 0, two measured points at the same
angle, fewer than 8 points, an unknown --surface, --angle-search outside 0 ... 180,
--axial-position for a joint that is not sliced or beyond the bushing's ends;
also: output directory in use, earlier comparison's files) — the message names the
file, the line and the column, and nothing is written; 4 an output that cannot be
written; 1 an internal error (see `wearlink --help`).
)" + io::outputs::listing(io::outputs::compare_profile());

    int
    compare_profile(const std::vector<std::string> &args)
    {
      const auto a = parse_arguments(args,
                                     {{"--surface", true},
                                      {"--joint", true},
                                      {"--angle-search", true},
                                      {"--axial-position", true},
                                      {"--output", true},
                                      {"--overwrite", false},
                                      {"--quiet", false}},
                                     "compare-profile");
      if (a.positional.size() != 2)
        throw InputError("`wearlink compare-profile` needs a wear run's folder and a measured CSV file (given " +
                         std::to_string(a.positional.size()) + "). See `wearlink compare-profile --help`.");
      if (!a.has("--surface") || !a.has("--joint"))
        throw InputError("`wearlink compare-profile` needs --surface bore|pin and --joint J (the wearing joint, "
                         "e.g. A). See `wearlink compare-profile --help`.");
      workflows::ProfileComparisonOptions o;
      o.run_directory    = a.positional[0];
      o.measured_file    = a.positional[1];
      o.surface          = a.value("--surface");
      o.joint            = a.value("--joint");
      o.angle_search_deg = a.number("--angle-search", 180);
      if (a.has("--axial-position"))
        o.axial_position = a.number("--axial-position", 0);
      o.output_directory = a.value("--output", "output/compare_profile_" + o.joint + "_" + o.surface);
      const auto claimed = claim_output_directory(output_claim(o.output_directory, io::outputs::compare_profile(), a));
      const auto r       = workflows::compare_profile(o);
      std::cout << r.table << "files written:\n";
      for (const auto &f : r.files)
        std::cout << "  " << f << "\n";
      return 0;
    }
  } // namespace

  extern const Command compare_profile_command;
  const Command        compare_profile_command = {"compare-profile",
                                                  "compare-profile RUN_DIR MEASURED.csv --surface bore|pin --joint J  "
                                                         "measured against predicted worn profile",
                                                  compare_profile_help.c_str(),
                                                  compare_profile};
} // namespace wearlink::app
