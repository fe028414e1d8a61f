// SPDX-License-Identifier: LGPL-2.1-or-later
// Surface profiles as files: two columns, angle [rad] and radius [m] (a header row and
// '#' comments allowed; read by io/csv.h), the form a wear run writes its worn profiles in
// and a scene's 'Bore profile file' / 'Pin profile file' reads.
#pragma once

#include "analysis/profile_comparison.h"
#include "base/profile.h"

#include <string>

namespace wearlink
{
  class ParameterReader;
}

namespace wearlink::io
{
  /**
   * Read @p file and resample it onto @p n_points uniform angles (Profile::from_polar_points;
   * n_points = 0 keeps the file's count, which then must be uniformly spaced). InputError
   * naming the file and line for a missing file, a field that is not a finite number, a
   * radius ≤ 0, angles that do not increase strictly, fewer than 8 points, and points
   * that leave more than a quarter turn of the circumference without a point (the
   * radius there would be invented by the resampling).
   */
  Profile
  read_profile_csv(const std::string &file, unsigned int n_points = 0);

  /**
   * A measured trace of a surface (a profilometer or CMM record) in the same format:
   * any number of points at any spacing, angles of any value (wrapped into [0, 2π) and
   * sorted; the order of the lines does not matter), radii in metres. InputError naming
   * the file, the line and the column for a missing file, a field that is not a finite
   * number (NaN included) or a radius ≤ 0; naming both lines for two points at the
   * same angle (within 1e-9 rad after wrapping, 0 and 2π included); and for fewer than
   * 8 points.
   */
  analysis::PolarTrace
  read_measured_profile_csv(const std::string &file);

  /**
   * Wear only opens a bore and thins a pin: a pin profile whose largest radius reaches the
   * bore profile's narrowest one is a damaged file (a radius of the wrong unit, a damaged
   * line), not a worn pair. ParameterReader::fail_section of @p r (the section that names
   * the profile files) unless the pin fits inside the bore everywhere.
   */
  void
  check_pin_inside_bore(const ParameterReader &r, const Profile &bore, const Profile &pin);

  /**
   * A profile file describes the surface of its joint: its mean radius lies within half
   * the @p nominal radius (entry @p nominal_entry) of it. Wear moves a surface by
   * micrometres, at most a few clearances; a file in millimetres is 1000 times too large
   * and would leave the pin rattling in a bore metres wide, never touching it.
   * ParameterReader::fail of @p r for @p entry otherwise.
   */
  void
  check_profile_radius(const ParameterReader &r,
                       const std::string     &entry,
                       const Profile         &profile,
                       double                 nominal,
                       const std::string     &nominal_entry);

  /** Write @p profile as "angle_rad,radius_m" rows (17 digits, atomically), after a '#' comment. */
  void
  write_profile_csv(const Profile &profile, const std::string &file, const std::string &header_comment = "");
} // namespace wearlink::io
