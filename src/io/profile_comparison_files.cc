// SPDX-License-Identifier: LGPL-2.1-or-later
#include "io/profile_comparison_files.h"

#include "base/atomic_file.h"
#include "base/exceptions.h"
#include "base/numbers.h"
#include "base/text.h"
#include "contact/axial_slices.h"
#include "io/csv.h"
#include "io/output_names.h"
#include "io/plot.h"
#include "io/profile_file.h"

#include <cmath>
#include <filesystem>
#include <set>

namespace wearlink::io
{
  namespace
  {
    namespace fs = std::filesystem;

    /** The joints whose worn @p surface profile @p dir holds ("A, B"; "none"). */
    std::string
    joints_in(const std::string &dir, const std::string &surface)
    {
      std::set<std::string> joints;
      const std::string     prefix = surface + "_";
      std::error_code       ec;
      for (const auto &entry : fs::directory_iterator(dir, ec))
        {
          const std::string name = entry.path().filename().string();
          if (name.size() > prefix.size() + 4 && name.compare(0, prefix.size(), prefix) == 0 &&
              name.compare(name.size() - 4, 4, ".csv") == 0)
            joints.insert(name.substr(prefix.size(), name.size() - prefix.size() - 4));
        }
      std::string list;
      for (const auto &j : joints)
        list += (list.empty() ? "" : ", ") + j;
      return list.empty() ? "none" : list;
    }

    /** The starting surface of the run: column <surface>_initial_m of profiles_<J>.csv. */
    analysis::PolarTrace
    read_unworn(const std::string &file, const std::string &surface)
    {
      const CsvTable    table  = CsvTable::read(file, "run's profile table");
      const std::string column = surface + "_initial_m";
      const std::size_t a = table.find("angle_rad"), r = table.find(column);
      if (a == CsvTable::npos || r == CsvTable::npos)
        throw InputError("The run's profile table '" + file + "' has no columns 'angle_rad' and '" + column +
                         "' (its columns: " + table.column_list() +
                         "). It is written by a wear run; was the folder written by another program?");
      const std::string advice = "The file is a wear run's output; rerun the wear run if it was damaged.";
      return analysis::PolarTrace::of_profile(Profile::from_polar_points(table.numbers(a, advice),
                                                                         table.numbers(r, advice),
                                                                         0,
                                                                         "run's profile table '" + file + "'"));
    }
  } // namespace

  std::string
  surface_name(const analysis::WornSurface surface)
  {
    return surface == analysis::WornSurface::bore ? "bore" : "pin";
  }

  std::string
  slice_at(const std::string &run_directory, const std::string &joint, const double z, double &centre)
  {
    const std::string file = (fs::path(run_directory) / ("slices_" + joint + ".csv")).string();
    std::error_code   ec;
    if (!fs::exists(file, ec))
      throw InputError("--axial-position needs a sliced joint: the run folder '" + run_directory + "' holds no " +
                       fs::path(file).filename().string() + " (joint '" + joint +
                       "' is not cut into slices, or the folder is not a finished wear run). Leave out "
                       "--axial-position for a two-dimensional joint.");
    const CsvTable    table  = CsvTable::read(file, "run's slice table");
    const std::size_t column = table.find("z_m");
    if (column == CsvTable::npos || table.n_rows() < 2)
      throw InputError("The run's slice table '" + file +
                       "' has no column 'z_m' or fewer than two slices (its columns: " + table.column_list() +
                       "). It is written by a wear run; rerun it if it was damaged.");
    const auto   zs   = table.numbers(column, "The file is a wear run's output; rerun the wear run if it was damaged.");
    const double half = 0.5 * (zs[1] - zs[0]); // the slices are equal: L/(2n)
    if (!(std::abs(z) <= zs.back() + half))
      throw InputError("--axial-position is " + format_number(z, 6) + " m; joint '" + joint + "' of the run spans " +
                       format_number(zs.front() - half, 6) + " … " + format_number(zs.back() + half, 6) +
                       " m from the bushing's mid-plane. Give the position of the measured trace within it.");
    std::size_t nearest = 0;
    for (std::size_t i = 1; i < zs.size(); ++i)
      if (std::abs(zs[i] - z) < std::abs(zs[nearest] - z))
        nearest = i;
    centre = zs[nearest];
    return contact::slice_name(joint, static_cast<unsigned int>(nearest), static_cast<unsigned int>(zs.size()));
  }

  RunSurface
  read_run_surface(const std::string &run_directory, const std::string &joint, const analysis::WornSurface surface)
  {
    const std::string name = surface_name(surface);
    std::error_code   ec; // a name too long for the system: no such folder, not an exception
    if (!fs::is_directory(run_directory, ec))
      throw InputError("The run folder '" + run_directory + "' does not exist or is not a directory.");
    RunSurface s;
    s.worn_file   = (fs::path(run_directory) / (name + "_" + joint + ".csv")).string();
    s.unworn_file = (fs::path(run_directory) / ("profiles_" + joint + ".csv")).string();
    for (const auto &file : {s.worn_file, s.unworn_file})
      if (!fs::exists(file, ec))
        throw InputError("The run folder '" + run_directory + "' holds no " + fs::path(file).filename().string() +
                         ": is it the folder of a finished wear run in which joint '" + joint + "' wears? Its worn " +
                         name + " profiles are of the joints: " + joints_in(run_directory, name) +
                         " (--joint names one of them).");
    s.worn   = analysis::PolarTrace::of_profile(read_profile_csv(s.worn_file));
    s.unworn = read_unworn(s.unworn_file, name);
    return s;
  }

  namespace
  {
    /** @p s in the plot's units: degrees and micrometres. */
    PlotSeries
    series(const analysis::AngleSeries &s, const std::string &title, const Look &look)
    {
      PlotSeries p{title, {}, {}, look};
      for (std::size_t k = 0; k < s.angle.size(); ++k)
        {
          p.x.push_back(s.angle[k] * 180 / numbers::pi);
          p.y.push_back(s.value[k] * 1e6);
        }
      return p;
    }

    PlotSpec
    overlay_plot(const Json &json, const analysis::ProfileComparison &c, const ProfileOverlayLabels &labels)
    {
      PlotSpec p;
      p.title = "Joint " + labels.joint + " " + labels.surface + ": measured wear depth (turned by " +
                format_number(json_number(json.at("rotation_deg")), 4) + " deg) against the prediction";
      p.x_label    = "angle in the body's own frame (the run's) [deg]";
      p.y_label    = "wear depth [um]";
      p.width      = 1200;
      p.x_range    = Range{0, 360};
      p.x_tic_step = 45;
      p.key        = KeyPlace::below;
      // A sparse trace shows its points; a dense one would hide the prediction under them.
      const bool sparse = c.measured_depth.angle.size() <= 400;
      p.series          = {series(c.predicted_depth, "predicted (run)", line("#1f77b4", 2)),
                           series(c.measured_depth,
                         "measured: " + fs::path(labels.measured_file).filename().string(),
                         sparse ? line_points("#d62728", 1.5, Marker::filled_circle, 0.5) : line("#d62728", 1.5)),
                           series(c.depth_difference, "measured - predicted", line("#2ca02c", 1.5).dashed())};
      return p;
    }
  } // namespace

  std::vector<std::string>
  write_profile_comparison(const std::string                 &directory,
                           const Json                        &json,
                           const analysis::ProfileComparison &c,
                           const ProfileOverlayLabels        &labels)
  {
    std::vector<std::string> files;
    const std::string        png = directory + "/" + outputs::profile_comparison_plot;
    if (plot_png(overlay_plot(json, c, labels), png))
      files.push_back(png);
    const std::string file = directory + "/" + outputs::profile_comparison_json;
    write_file_atomically(file, json.dump(2));
    files.push_back(file);
    return files;
  }
} // namespace wearlink::io
