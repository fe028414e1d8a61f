// SPDX-License-Identifier: LGPL-2.1-or-later
#include "io/profile_file.h"

#include "base/atomic_file.h"
#include "base/exceptions.h"
#include "base/parameters.h"
#include "base/text.h"
#include "io/csv.h"

#include <iomanip>

namespace wearlink::io
{
  Profile
  read_profile_csv(const std::string &file, const unsigned int n_points)
  {
    const CsvTable table = CsvTable::read(file, "profile file");
    if (table.n_columns() != 2)
      throw InputError("The profile file '" + file + "' has " + std::to_string(table.n_columns()) +
                       " columns; it needs two, 'angle_rad, radius_m'.");
    const std::vector<double> angles = table.numbers(0, "Expected two numbers 'angle_rad, radius_m' per line.");
    const std::vector<double> radii  = table.numbers(1, "Expected two numbers 'angle_rad, radius_m' per line.");
    for (std::size_t k = 0; k < radii.size(); ++k)
      {
        const std::string where = "In profile file '" + file + "' line " + std::to_string(table.line_of(k));
        if (!(radii[k] > 0))
          throw InputError(where + ": the radius must be > 0 m.");
        if (k > 0 && !(angles[k] > angles[k - 1]))
          throw InputError(where + ": angles must increase strictly (a profile that turns back "
                                   "on itself is self-intersecting).");
      }
    return Profile::from_polar_points(angles, radii, n_points, "profile file '" + file + "'");
  }

  void
  write_profile_csv(const Profile &profile, const std::string &file, const std::string &header_comment)
  {
    AtomicFile f(file);
    auto      &os = f.stream();
    if (!header_comment.empty())
      os << "# " << header_comment << '\n';
    os << "angle_rad,radius_m\n" << std::setprecision(17);
    for (unsigned int k = 0; k < profile.n_points(); ++k)
      os << profile.angle(k) << ',' << profile[k] << '\n';
    f.commit();
  }
  void
  check_pin_inside_bore(const ParameterReader &r, const Profile &bore, const Profile &pin)
  {
    if (!(pin.max_radius() < bore.min_radius()))
      r.fail_section("the pin profile reaches out to " + format_number(pin.max_radius(), 6) +
                     " m, beyond the narrowest radius of the bore profile (" + format_number(bore.min_radius(), 6) +
                     " m): the pin would cut through the bushing. Check the profile files (a radius of the "
                     "wrong unit or a damaged line).");
  }
} // namespace wearlink::io
