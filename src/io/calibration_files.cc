// SPDX-License-Identifier: LGPL-2.1-or-later
#include "io/calibration_files.h"

#include "base/atomic_file.h"
#include "io/output_names.h"
#include "io/plot.h"

#include <cmath>

namespace wearlink::io
{
  namespace
  {
    /** A vertical bar at @p x from @p low to @p high into @p s (NaN-separated segments). */
    void
    add_bar(PlotSeries &s, const double x, const double low, const double high)
    {
      s.x.insert(s.x.end(), {x, x, NAN});
      s.y.insert(s.y.end(), {low, high, NAN});
    }

    /** calibration.png's plot (see the header). */
    PlotSpec
    mass_loss_plot(const Json &report)
    {
      PlotSpec p;
      p.title   = "Measured and predicted mass loss (bars: 95 %)";
      p.x_label = "surface";
      p.y_label = "mass loss [mg]";
      PlotSeries measured{"measured", {}, {}, points("black", 1.6, Marker::filled_square)};
      PlotSeries measured_bar{"", {}, {}, line("black", 2)};
      PlotSeries members{"runs at the secant's k", {}, {}, points("#1f77b4", 0.8, Marker::open_circle)};
      PlotSeries mean{"their mean", {}, {}, points("#d62728", 1.6)};
      PlotSeries mean_bar{"", {}, {}, line("#d62728", 2)};
      double     x = 0;
      for (auto j = report.at("joints").begin(); j != report.at("joints").end(); ++j)
        for (const std::string surface : {"pin", "bushing"})
          if (j.value().contains(surface + "_mass_loss_mg"))
            {
              const Json  &m  = j.value().at(surface + "_mass_loss_mg");
              const double mm = json_number(m.at("measured")), sm = json_number(m.at("measured_uncertainty"));
              const double pm = json_number(m.at("predicted_mean")), sp = json_number(m.at("predicted_std_of_mean"));
              p.categories.push_back(j.key() + " " + surface);
              measured.x.push_back(x - 0.1);
              measured.y.push_back(mm);
              add_bar(measured_bar, x - 0.1, mm - 1.96 * sm, mm + 1.96 * sm);
              for (const auto &v : m.at("predicted_members"))
                {
                  members.x.push_back(x + 0.1);
                  members.y.push_back(json_number(v));
                }
              mean.x.push_back(x + 0.1);
              mean.y.push_back(pm);
              add_bar(mean_bar, x + 0.1, pm - 1.96 * sp, pm + 1.96 * sp);
              x += 1;
            }
      p.x_range = Range{-0.5, x - 0.5};
      p.y_range = Range{0, NAN};
      p.series  = {measured_bar, mean_bar, measured, members, mean};
      return p;
    }
  } // namespace

  std::vector<std::string>
  write_calibration_files(const std::string &directory, const Json &report, const std::string &calibrated_prm)
  {
    std::vector<std::string> files;
    const std::string        dir = directory + "/";
    write_file_atomically(dir + outputs::calibration_report, report.dump(2));
    files.push_back(dir + outputs::calibration_report);
    write_file_atomically(dir + outputs::calibrated_scene, calibrated_prm);
    files.push_back(dir + outputs::calibrated_scene);
    if (plot_png(mass_loss_plot(report), dir + outputs::calibration_plot))
      files.push_back(dir + outputs::calibration_plot);
    return files;
  }
} // namespace wearlink::io
