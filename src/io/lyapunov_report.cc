// SPDX-License-Identifier: LGPL-2.1-or-later
#include "io/lyapunov_report.h"

#include "base/atomic_file.h"
#include "base/text.h"
#include "io/plot.h"

#include <iomanip>
#include <sstream>

namespace wearlink::io
{
  namespace
  {
  } // namespace

  bool
  write_lyapunov_curve(const analysis::LyapunovEstimate &est, const std::string &column, const std::string &stem)
  {
    using analysis::LyapunovEstimate;
    const auto        &emb       = est.embedding;
    const double       dt        = est.sample_interval.value_or(1.0);
    const std::string  time_name = est.sample_interval ? "time_s" : "time_samples";
    const std::string  rate_unit = est.sample_interval ? "per_s" : "per_sample";
    PlotSpec           plot;
    std::ostringstream csv;
    csv << std::setprecision(10);
    if (est.wolf)
      {
        const auto &w = *est.wolf;
        PlotSeries  running;
        running.title = "running estimate";
        csv << "evolution_" << time_name << ",running_exponent_" << rate_unit << "\n";
        for (std::size_t s = 0; s < w.running_time.size(); ++s)
          {
            const double t = w.running_time[s] * dt, l = w.running_exponent[s] / dt;
            csv << t << "," << l << "\n";
            running.x.push_back(t);
            running.y.push_back(l);
          }
        PlotSeries final_value;
        final_value.title = "final " + format_number(est.exponent(), 4);
        final_value.x     = {running.x.front(), running.x.back()};
        final_value.y     = {est.exponent(), est.exponent()};
        final_value.look  = line("red", 2).dashed();
        plot.series       = {running, final_value};
        plot.title =
          "Wolf et al. 1985: largest Lyapunov exponent of '" + column + "' = " + format_number(est.exponent(), 4) +
          " " + (est.sample_interval ? "1/s" : "1/sample") + " (m = " + std::to_string(emb.embedding.dimension) +
          ", tau = " + std::to_string(emb.embedding.delay) + ", E = " + std::to_string(w.evolution_steps) + " samples)";
        plot.x_label = est.sample_interval ? "evolution time [s]" : "evolution time [samples]";
        plot.y_label =
          est.sample_interval ? "running estimate [1/s, natural log]" : "running estimate [1/sample, natural log]";
      }
    else
      {
        const auto &r = *est.rosenstein;
        PlotSeries  curve;
        curve.title = "<ln d(k)>";
        PlotSeries line;
        line.title = "fit: slope " + format_number(est.exponent(), 4);
        line.look  = io::line("red", 3);
        csv << time_name << ",mean_log_divergence,fitted_line\n";
        for (std::size_t k = 0; k < r.mean_log_divergence.size(); ++k)
          {
            const double t = k * dt;
            csv << t << "," << r.mean_log_divergence[k] << ",";
            curve.x.push_back(t);
            curve.y.push_back(r.mean_log_divergence[k]);
            if (k >= r.fit_begin && k <= r.fit_end)
              {
                const double f = r.intercept + r.exponent_per_sample * k;
                csv << f;
                line.x.push_back(t);
                line.y.push_back(f);
              }
            csv << "\n";
          }
        plot.series = {curve, line};
        plot.title  = "Rosenstein et al. 1993: largest Lyapunov exponent of '" + column +
                     "' = " + format_number(est.exponent(), 4) + " " + (est.sample_interval ? "1/s" : "1/sample") +
                     " (m = " + std::to_string(emb.embedding.dimension) +
                     ", tau = " + std::to_string(emb.embedding.delay) + " samples)";
        plot.x_label = est.sample_interval ? "time [s]" : "time [samples]";
        plot.y_label = "mean log divergence <ln d(k)> [ln(units of '" + column + "')]";
      }
    write_file_atomically(stem + ".csv", csv.str());
    return plot_png(plot, stem + ".png");
  }
} // namespace wearlink::io
