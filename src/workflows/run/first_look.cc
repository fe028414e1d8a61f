// SPDX-License-Identifier: LGPL-2.1-or-later
#include "workflows/run/first_look.h"

#include "base/concurrent.h"
#include "base/numbers.h"
#include "base/text.h"
#include "io/csv.h"
#include "io/output_names.h"
#include "io/plot.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <sstream>

namespace wearlink::workflows
{
  namespace
  {
    /** Digits of the printed summary (the test compares them with summary.json). */
    constexpr int summary_digits = 6;

    /** Points of the drawn clearance circle. */
    constexpr int circle_points = 361;

    /** Column @p name of @p table, scaled by @p scale. */
    std::vector<double>
    column(const io::CsvTable &table, const std::string &name, const double scale = 1.0)
    {
      auto v = table.numbers(table.find(name));
      for (auto &x : v)
        x *= scale;
      return v;
    }

    /** The time_series.csv columns of joint @p joint's eccentricity in the bushing frame (x, y). */
    std::array<std::string, 2>
    orbit_columns(const std::string &joint)
    {
      return {{joint + "_ex_local_m", joint + "_ey_local_m"}};
    }

    /** orbit_<J>.png: the eccentricity in the bushing frame inside the clearance circle [mm]. */
    io::PlotSpec
    orbit_plot(const io::CsvTable &table, const std::string &joint, const double clearance)
    {
      constexpr double mm = 1e3;
      io::PlotSpec     p;
      p.title = "Joint " + joint + ": journal-centre orbit in the bushing frame (radial clearance " +
                format_number(clearance * mm, 4) + " mm)";
      p.x_label    = "eccentricity e_x, bushing frame [mm]";
      p.y_label    = "eccentricity e_y, bushing frame [mm]";
      p.equal_axes = true;
      p.width      = 900;
      p.height     = 800;
      io::PlotSeries circle{"clearance circle", {}, {}, io::line("black", 2).dashed()};
      for (int k = 0; k < circle_points; ++k)
        {
          const double a = 2 * numbers::pi * k / (circle_points - 1);
          circle.x.push_back(clearance * mm * std::cos(a));
          circle.y.push_back(clearance * mm * std::sin(a));
        }
      io::PlotSeries orbit{"journal centre", {}, {}, io::line("#1f77b4", 1)};
      orbit.x = column(table, orbit_columns(joint)[0], mm);
      orbit.y = column(table, orbit_columns(joint)[1], mm);
      io::PlotSeries start{"start", {orbit.x.front()}, {orbit.y.front()}, io::points("#2ca02c", 1.5)};
      p.series            = {circle, orbit, start};
      const double extent = 1.2 * clearance * mm;
      p.x_range           = io::Range{-extent, extent};
      p.y_range           = io::Range{-extent, extent};
      p.key               = io::KeyPlace::inside_bottom_right;
      return p;
    }

    /** A curve of a history panel: its legend, its time_series.csv column, its colour. */
    struct Curve
    {
      std::string title, column, colour;
    };

    /** The curves of joint @p joint's panel of contact_forces.png. */
    std::vector<Curve>
    force_curves(const std::string &joint)
    {
      return {{"normal force", joint + "_normal_force_N", "#d62728"},
              {"friction force", joint + "_friction_force_N", "#7f7f7f"}};
    }

    /** The curves of body @p body's panel of accelerations.png. */
    std::vector<Curve>
    acceleration_curves(const std::string &body)
    {
      return {{"a_x", body + "_ax_m_s2", "#1f77b4"}, {"a_y", body + "_ay_m_s2", "#ff7f0e"}};
    }

    /** The columns of time_series.csv the plots of @p scene draw (@p bodies: the plot bodies). */
    std::vector<std::string>
    plotted_columns(const io::Scene &scene, const std::vector<std::string> &bodies)
    {
      std::vector<std::string> names = {"time_s"};
      for (const auto *j : scene.clearance_joints)
        {
          for (const auto &c : orbit_columns(j->name()))
            names.push_back(c);
          for (const auto &c : force_curves(j->name()))
            names.push_back(c.column);
        }
      for (const auto &b : bodies)
        for (const auto &c : acceleration_curves(b))
          names.push_back(c.column);
      return names;
    }

    /** One panel of contact_forces.png or accelerations.png: @p curves against time. */
    io::PlotSpec
    history_panel(const io::CsvTable        &table,
                  const std::vector<double> &time,
                  const std::string         &title,
                  const std::string         &y_label,
                  const std::vector<Curve>  &curves)
    {
      io::PlotSpec p;
      p.title   = title;
      p.x_label = "time [s]";
      p.y_label = y_label;
      for (const auto &c : curves)
        p.series.push_back({c.title, time, column(table, c.column), io::line(c.colour)});
      return p;
    }

    /** Panels stacked in one PNG, 420 px a panel. */
    bool
    stacked_png(const std::vector<io::PlotSpec> &panels, const std::string &title, const std::string &path)
    {
      const int height = 120 + 420 * static_cast<int>(panels.size());
      return io::plot_panels_png(panels, 1, title, path, 1400, height);
    }

    double
    peak_acceleration(const Json &body)
    {
      return std::max(json_number(body.at("max_abs_ax_m_s2")), json_number(body.at("max_abs_ay_m_s2")));
    }
  } // namespace

  std::vector<std::string>
  first_look_bodies(const io::Scene &scene, const Json &summary)
  {
    if (!scene.plot_bodies.empty())
      return scene.plot_bodies;
    std::string best;
    double      largest = -1;
    for (const auto &[name, body] : summary.at("bodies").items())
      if (peak_acceleration(body) > largest)
        {
          largest = peak_acceleration(body);
          best    = name;
        }
    return best.empty() ? std::vector<std::string>{} : std::vector<std::string>{best};
  }

  std::string
  first_look_summary(const Json &summary, const std::vector<std::string> &bodies)
  {
    std::ostringstream out;
    const auto         number = [](const Json &v) {
      return format_number(json_number(v), summary_digits);
    };
    for (const auto &[name, j] : summary.at("clearance_joints").items())
      out << "  joint " << name << ": contact fraction " << number(j.at("fraction_in_contact"))
          << ", peak normal force " << number(j.at("max_normal_force_N")) << " N, peak friction force "
          << number(j.at("max_friction_force_N")) << " N, impacts " << number(j.at("impacts")) << "\n";
    for (const auto &b : bodies)
      {
        const Json &x = summary.at("bodies").at(b);
        out << "  body " << b << ": peak acceleration |a_x| " << number(x.at("max_abs_ax_m_s2")) << " m/s², |a_y| "
            << number(x.at("max_abs_ay_m_s2")) << " m/s²\n";
      }
    return out.str();
  }

  std::vector<std::string>
  files_written_since(const std::string &directory, const std::filesystem::file_time_type start)
  {
    std::vector<std::string> out;
    std::error_code          ec;
    for (const auto &entry : std::filesystem::directory_iterator(directory, ec))
      if (entry.is_regular_file(ec) && entry.last_write_time(ec) >= start && entry.path().filename().c_str()[0] != '.')
        out.push_back(entry.path().string());
    std::sort(out.begin(), out.end());
    return out;
  }

  FirstLook
  write_first_look(const io::Scene &scene, const Json &summary, const std::string &directory)
  {
    FirstLook  look;
    const auto bodies = first_look_bodies(scene, summary);
    look.summary      = first_look_summary(summary, bodies);
    if (!scene.plots)
      return look;
    if (!scene.write_time_series)
      {
        look.notes.push_back("no plots: they are drawn from time_series.csv, and Output/Time series = false");
        return look;
      }
    if (!io::gnuplot_available())
      {
        look.notes.push_back("no plots: gnuplot is not installed (apt-get install gnuplot-nox)");
        return look;
      }
    const auto table =
      io::CsvTable::read(directory + "/" + io::outputs::time_series, "time series", plotted_columns(scene, bodies));
    const auto time = column(table, "time_s");
    // Each plot is its own gnuplot process: they are drawn side by side, then listed in order.
    std::vector<std::string>           paths;
    std::vector<std::function<bool()>> draw;
    std::vector<io::PlotSpec>          forces, accelerations;
    for (const auto *j : scene.clearance_joints)
      {
        paths.push_back(directory + "/orbit_" + j->name() + ".png");
        draw.push_back([spec = orbit_plot(table, j->name(), j->radial_clearance()), path = paths.back()] {
          return io::plot_png(spec, path);
        });
        forces.push_back(
          history_panel(table, time, "Joint " + j->name() + ": contact force", "force [N]", force_curves(j->name())));
      }
    for (const auto &b : bodies)
      accelerations.push_back(history_panel(table,
                                            time,
                                            "Body " + b + ": acceleration of its centre of mass",
                                            "acceleration [m/s²]",
                                            acceleration_curves(b)));
    // The time series samples the run; summary.json's peaks are over every accepted step.
    const std::string sampled =
      scene.output_interval > 0 ? "sampled every " + format_number(scene.output_interval, 4) + " s" : "every step";
    const std::string title = scene.title + " (" + sampled + "; summary.json's peaks: every integrator step)";
    for (const auto &[panels, name] : {std::pair{&forces, "contact_forces.png"}, {&accelerations, "accelerations.png"}})
      if (!panels->empty())
        {
          paths.push_back(directory + "/" + name);
          draw.push_back([&panels = *panels, &title, path = paths.back()] { return stacked_png(panels, title, path); });
        }
    std::vector<char>                  written(draw.size(), 0);
    std::vector<std::function<void()>> tasks;
    for (std::size_t k = 0; k < draw.size(); ++k)
      tasks.push_back([&, k] { written[k] = draw[k]() ? 1 : 0; });
    run_concurrently(tasks);
    for (std::size_t k = 0; k < paths.size(); ++k)
      if (written[k])
        look.plots.push_back(paths[k]);
      else
        look.notes.push_back("gnuplot could not draw " + paths[k]);
    return look;
  }

  LookedAtRun
  run_with_first_look(io::Scene &scene, const RunOptions &options)
  {
    const auto  start = std::filesystem::file_time_type::clock::now();
    LookedAtRun r;
    r.summary      = run_scene(scene, options);
    r.look         = write_first_look(scene, r.summary, options.output_directory);
    r.look.written = files_written_since(options.output_directory, start);
    return r;
  }
} // namespace wearlink::workflows
