// SPDX-License-Identifier: LGPL-2.1-or-later
#include "io/profile_file.h"

#include "base/atomic_file.h"
#include "base/exceptions.h"
#include "base/numbers.h"
#include "base/parameters.h"
#include "base/text.h"
#include "io/csv.h"

#include <algorithm>
#include <cmath>
#include <iomanip>

namespace wearlink::io
{
  namespace
  {
    /** The points of a profile file: angles and radii (each radius > 0) and their lines. */
    struct ProfilePoints
    {
      std::vector<double>      angles, radii;
      std::vector<std::size_t> lines;
    };

    ProfilePoints
    read_points(const std::string &file, const std::string &what)
    {
      const CsvTable table = CsvTable::read(file, what);
      if (table.n_columns() != 2)
        throw InputError("The " + what + " '" + file + "' has " + std::to_string(table.n_columns()) +
                         " columns; it needs two, 'angle_rad, radius_m'.");
      ProfilePoints p;
      p.angles = table.numbers(0, "Expected two numbers 'angle_rad, radius_m' per line.");
      p.radii  = table.numbers(1, "Expected two numbers 'angle_rad, radius_m' per line.");
      for (std::size_t k = 0; k < p.radii.size(); ++k)
        {
          p.lines.push_back(table.line_of(k));
          if (!(p.radii[k] > 0))
            throw InputError("In " + what + " '" + file + "' line " + std::to_string(p.lines[k]) +
                             ": the radius must be > 0 m (column 'radius_m' is " + format_number(p.radii[k], 6) + ").");
        }
      return p;
    }

    /** Two measured angles closer than this [rad] after wrapping are the same point. */
    constexpr double same_angle = 1e-9;

    /**
     * The largest arc without a point that a profile file may leave [rad]: a quarter
     * turn, twice the spacing of the coarsest profile (8 points, π/4 apart). A file that
     * covers less describes part of a surface (a trace of one flank), and the resampling
     * would bridge the rest with a straight line in r(ψ).
     */
    constexpr double largest_gap = numbers::pi / 2;

    /** InputError if the points @p p (angles increasing) leave an arc wider than largest_gap. */
    void
    check_coverage(const ProfilePoints &p, const std::string &file)
    {
      const std::size_t n = p.angles.size();
      if (n == 0)
        return;
      std::size_t after = 0; // the point after the widest gap (0: the gap wraps round)
      double      gap   = p.angles.front() + numbers::two_pi - p.angles.back();
      for (std::size_t k = 1; k < n; ++k)
        if (p.angles[k] - p.angles[k - 1] > gap)
          {
            gap   = p.angles[k] - p.angles[k - 1];
            after = k;
          }
      if (!(gap > largest_gap))
        return;
      const std::size_t before = after == 0 ? n - 1 : after - 1;
      throw InputError("In profile file '" + file + "', no point lies between line " + std::to_string(p.lines[before]) +
                       " (" + format_number(p.angles[before], 6) + " rad) and line " + std::to_string(p.lines[after]) +
                       " (" + format_number(p.angles[after], 6) + " rad" + (after == 0 ? " + 2π" : "") +
                       "): " + format_number(gap, 4) +
                       " rad of the circumference without a point, more than a quarter turn. A profile file "
                       "describes the whole surface: give points all the way round (0 … 2π), at most a quarter "
                       "turn apart.");
    }
  } // namespace

  Profile
  read_profile_csv(const std::string &file, const unsigned int n_points)
  {
    const ProfilePoints p = read_points(file, "profile file");
    for (std::size_t k = 1; k < p.angles.size(); ++k)
      if (!(p.angles[k] > p.angles[k - 1]))
        throw InputError("In profile file '" + file + "' line " + std::to_string(p.lines[k]) +
                         ": angles must increase strictly (a profile that turns back "
                         "on itself is self-intersecting).");
    check_coverage(p, file);
    return Profile::from_polar_points(p.angles, p.radii, n_points, "profile file '" + file + "'");
  }

  analysis::PolarTrace
  read_measured_profile_csv(const std::string &file)
  {
    const std::string what = "measured profile";
    const auto        p    = read_points(file, what);
    if (p.angles.size() < 8)
      throw InputError("The " + what + " '" + file + "' has " + std::to_string(p.angles.size()) +
                       " points; at least 8 are needed to compare a surface.");
    // Wrap into [0, 2π) and sort, keeping each point's line for the messages.
    std::vector<std::size_t> order(p.angles.size());
    std::vector<double>      wrapped(p.angles.size());
    for (std::size_t k = 0; k < order.size(); ++k)
      {
        order[k]   = k;
        wrapped[k] = p.angles[k] - numbers::two_pi * std::floor(p.angles[k] / numbers::two_pi);
        if (wrapped[k] >= numbers::two_pi)
          wrapped[k] = 0;
      }
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return wrapped[a] < wrapped[b]; });
    analysis::PolarTrace t;
    for (std::size_t s = 0; s < order.size(); ++s)
      {
        const std::size_t k = order[s], before = order[s == 0 ? order.size() - 1 : s - 1];
        const double      gap = s == 0 ? wrapped[k] + numbers::two_pi - wrapped[before] : wrapped[k] - wrapped[before];
        if (gap <= same_angle)
          throw InputError("In " + what + " '" + file + "', lines " + std::to_string(p.lines[before]) + " and " +
                           std::to_string(p.lines[k]) + " give the same angle (column 'angle_rad': " +
                           format_number(p.angles[before], 10) + " and " + format_number(p.angles[k], 10) +
                           " rad, the same within 1e-9 rad after wrapping into [0, 2π)): a surface has one "
                           "radius per angle. Remove one of them.");
        t.angle.push_back(wrapped[k]);
        t.radius.push_back(p.radii[k]);
      }
    return t;
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
  check_profile_radius(const ParameterReader &r,
                       const std::string     &entry,
                       const Profile         &profile,
                       const double           nominal,
                       const std::string     &nominal_entry)
  {
    const double mean = profile.mean_radius();
    if (!(std::abs(mean - nominal) <= 0.5 * nominal))
      r.fail(entry,
             "the profile's mean radius is " + format_number(mean, 6) + " m, but the joint's " + nominal_entry +
               " is " + format_number(nominal, 6) + " m; a worn surface lies within half its nominal radius of it",
             "Profile files give radii in metres (angle_rad, radius_m): a file in millimetres is 1000 times too "
             "large. Check the file, or the " +
               nominal_entry + ".");
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
