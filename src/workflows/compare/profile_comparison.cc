// SPDX-License-Identifier: LGPL-2.1-or-later
#include "workflows/compare/profile_comparison.h"

#include "analysis/profile_comparison.h"
#include "base/atomic_file.h"
#include "base/exceptions.h"
#include "base/numbers.h"
#include "base/text.h"
#include "io/profile_comparison_files.h"
#include "io/profile_file.h"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace wearlink::workflows
{
  namespace
  {
    /** Digits of the printed table. */
    constexpr int profile_digits = 5;

    double
    degrees(const double radians)
    {
      return radians * 180 / numbers::pi;
    }

    analysis::WornSurface
    parse_surface(const std::string &surface)
    {
      if (surface == "bore")
        return analysis::WornSurface::bore;
      if (surface == "pin")
        return analysis::WornSurface::pin;
      throw InputError("--surface is '" + surface + "'; allowed: bore, pin.");
    }

    /** How the figures were obtained, in words, for a reader of the JSON file. */
    Json
    method_json(const analysis::Alignment &a)
    {
      Json m          = Json::object();
      m["difference"] = "radius difference measured - predicted on the common angles of both traces (each "
                        "interpolated linearly in angle onto the other's), RMS over the circle";
      m["alignment"]  = "scan in steps of " + format_number(degrees(a.scan_step), 4) +
                       " deg, then Brent's minimisation of the RMS; nothing but the rotation is fitted";
      m["objective_evaluations"] = a.evaluations;
      m["worn_area"] = "area enclosed by the worn minus the unworn surface (bore; the reverse for a pin), as "
                       "polygons on the common angles [m^2 = m^3 per m of joint length]";
      return m;
    }

    Json
    comparison_json(const ProfileComparisonOptions    &o,
                    const io::RunSurface              &run,
                    const analysis::PolarTrace        &measured,
                    const analysis::ProfileComparison &c)
    {
      const auto &a         = c.alignment;
      Json        j         = Json::object();
      j["run_directory"]    = o.run_directory;
      j["predicted_file"]   = run.worn_file;
      j["unworn_file"]      = run.unworn_file;
      j["unworn_radius"]    = "the run's starting surface, column " + o.surface + "_initial_m of " + run.unworn_file;
      j["measured_file"]    = o.measured_file;
      j["joint"]            = o.joint;
      j["surface"]          = o.surface;
      j["measured_points"]  = measured.size();
      j["predicted_points"] = run.worn.size();
      j["measured_largest_gap_deg"]      = degrees(c.largest_measured_gap);
      j["angle_search_deg"]              = o.angle_search_deg;
      j["rotation_deg"]                  = degrees(a.rotation);
      j["rotation_convention"]           = "the measured point at angle a lies at a + rotation in the run's body frame";
      j["rms_difference_unaligned_m"]    = a.unaligned_rms;
      j["rms_difference_m"]              = a.difference.rms;
      j["largest_difference_m"]          = a.difference.largest;
      j["largest_difference_angle_deg"]  = degrees(a.difference.largest_angle);
      j["max_depth_measured_m"]          = c.max_depth_measured;
      j["max_depth_measured_angle_deg"]  = degrees(c.max_depth_measured_angle);
      j["max_depth_predicted_m"]         = c.max_depth_predicted;
      j["max_depth_predicted_angle_deg"] = degrees(c.max_depth_predicted_angle);
      j["worn_area_measured_m2"]         = c.worn_area_measured;
      j["worn_area_predicted_m2"]        = c.worn_area_predicted;
      j["worn_area_difference_m2"]       = c.worn_area_measured - c.worn_area_predicted;
      j["method"]                        = method_json(a);
      return j;
    }

    std::string
    profile_table(const Json &j)
    {
      std::ostringstream out;
      const auto         number = [&](const char *key) {
        return format_number(json_number(j.at(key)), profile_digits);
      };
      const auto row = [&](const std::string &name, const std::string &value) {
        out << "  " << std::left << std::setw(34) << name << value << "\n";
      };
      out << "joint " << j.at("joint").get<std::string>() << " " << j.at("surface").get<std::string>() << ": "
          << j.at("measured_points") << " measured points against " << j.at("predicted_points") << " predicted\n";
      row("best rotation", number("rotation_deg") + " deg (within +-" + number("angle_search_deg") + " deg)");
      row("RMS radius difference",
          number("rms_difference_m") + " m (without rotation " + number("rms_difference_unaligned_m") + " m)");
      row("largest radius difference",
          number("largest_difference_m") + " m at " + number("largest_difference_angle_deg") + " deg");
      row("deepest wear, measured",
          number("max_depth_measured_m") + " m at " + number("max_depth_measured_angle_deg") + " deg");
      row("deepest wear, predicted",
          number("max_depth_predicted_m") + " m at " + number("max_depth_predicted_angle_deg") + " deg");
      row("worn area, measured", number("worn_area_measured_m2") + " m^2");
      row("worn area, predicted", number("worn_area_predicted_m2") + " m^2");
      row("worn area, measured - predicted", number("worn_area_difference_m2") + " m^2");
      return out.str();
    }
  } // namespace

  ProfileComparisonResult
  compare_profile(const ProfileComparisonOptions &o)
  {
    const analysis::WornSurface surface = parse_surface(o.surface);
    if (!(o.angle_search_deg >= 0 && o.angle_search_deg <= 180))
      throw InputError("--angle-search is " + format_number(o.angle_search_deg, 6) +
                       " deg; it must lie in [0, 180] (0: the measured trace's angular origin is the run's).");
    if (o.joint.empty())
      throw InputError("Name the joint with --joint (e.g. --joint A), as the scene names it.");
    // A sliced joint: the slice at the trace's axial position stands for the joint.
    ProfileComparisonOptions at     = o;
    double                   centre = 0;
    if (!std::isnan(o.axial_position))
      at.joint = io::slice_at(o.run_directory, o.joint, o.axial_position, centre);
    const auto measured = io::read_measured_profile_csv(o.measured_file);
    const auto run      = io::read_run_surface(o.run_directory, at.joint, surface);
    const auto c =
      analysis::compare_profile(measured, run.worn, run.unworn, surface, o.angle_search_deg * numbers::pi / 180);
    ProfileComparisonResult r;
    r.json = comparison_json(at, run, measured, c);
    if (!std::isnan(o.axial_position))
      {
        r.json["axial_position_m"] = o.axial_position;
        r.json["slice_centre_m"]   = centre;
      }
    r.table = profile_table(r.json);
    make_output_directory(o.output_directory);
    r.files = io::write_profile_comparison(o.output_directory, r.json, c, {at.joint, o.surface, o.measured_file});
    return r;
  }
} // namespace wearlink::workflows
