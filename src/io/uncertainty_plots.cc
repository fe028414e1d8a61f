// SPDX-License-Identifier: LGPL-2.1-or-later
#include "io/uncertainty_plots.h"

#include "io/plot.h"

#include <algorithm>
#include <cmath>

namespace wearlink::io
{
  namespace
  {
    double
    number_or_nan(const Json &v)
    {
      return v.is_number() ? json_number(v) : std::nan("");
    }

    /**
     * A bar from 0 to the estimate's value at height @p y and its 95 % interval
     * (thin, just below), each a segment ended by a gap.
     */
    void
    add_bar(const Json &estimate, const double y, PlotSeries &bars, PlotSeries &intervals)
    {
      // The bar as thin parallel lines 0.24 high: a thick line's caps would jut out at 0.
      const double v = number_or_nan(estimate.at("value"));
      for (int j = -6; j <= 6; ++j)
        {
          bars.x.insert(bars.x.end(), {0.0, v, NAN});
          bars.y.insert(bars.y.end(), {y + 0.02 * j, y + 0.02 * j, NAN});
        }
      intervals.x.insert(intervals.x.end(),
                         {number_or_nan(estimate.at("ci95_low")), number_or_nan(estimate.at("ci95_high")), NAN});
      intervals.y.insert(intervals.y.end(), {y - 0.18, y - 0.18, NAN});
    }

    /** One figure's tornado panel. */
    PlotSpec
    tornado(const std::string &figure, const Json &f)
    {
      PlotSpec   spec;
      const bool sobol = f.at("method").get<std::string>() == "sobol-indices";
      PlotSeries first{sobol ? "first-order index" : "rank correlation", {}, {}, line("#4060a0", 2)};
      PlotSeries total{"total index", {}, {}, line("#c06040", 2)};
      PlotSeries interval{"95 % interval", {}, {}, line("black", 2)};
      int        i = 0;
      for (auto it = f.at("inputs").begin(); it != f.at("inputs").end(); ++it, ++i)
        {
          spec.y_categories.push_back(it.key());
          if (sobol)
            {
              add_bar(it.value().at("first_order"), i + 0.1, first, interval);
              PlotSeries ignored;
              add_bar(it.value().at("total"), i - 0.1, total, ignored);
            }
          else
            add_bar(it.value().at("rank_correlation"), i, first, interval);
        }
      spec.title   = figure;
      spec.x_label = sobol ? "Sobol index [-]" : "Spearman rank correlation [-]";
      spec.series  = sobol ? std::vector<PlotSeries>{first, total, interval} : std::vector<PlotSeries>{first, interval};
      spec.y_range = Range{-0.7, i - 0.3};
      spec.x_range = Range{sobol ? -0.1 : -1.05, 1.05};
      spec.key     = KeyPlace::none;
      return spec;
    }
  } // namespace

  bool
  plot_sensitivity(const Json &sensitivity, const std::string &path)
  {
    std::vector<PlotSpec> panels;
    for (auto it = sensitivity.at("figures").begin(); it != sensitivity.at("figures").end(); ++it)
      if (it.value().contains("inputs"))
        panels.push_back(tornado(it.key(), it.value()));
    if (panels.empty())
      return false;
    const unsigned int columns = panels.size() > 1 ? 2 : 1;
    const auto         rows    = static_cast<int>((panels.size() + columns - 1) / columns);
    return plot_panels_png(
      panels,
      columns,
      "Sensitivity of the headline figures to the uncertain inputs: rank correlation (blue) or first-order "
      "(blue) and total (red) Sobol index, 95 % interval (black)",
      path,
      columns == 1 ? 1000 : 1800,
      std::max(500, 330 * rows));
  }

  bool
  plot_life_cdf(const std::map<std::string, std::vector<double>> &revolutions,
                const std::string                                &path,
                const std::string                                &title)
  {
    PlotSpec spec;
    for (const auto &[criterion, values] : revolutions)
      {
        std::vector<double> v = values;
        std::sort(v.begin(), v.end());
        PlotSeries s{criterion, {}, {}, line("", 2)};
        for (std::size_t i = 0; i < v.size(); ++i) // the empirical CDF's steps
          {
            s.x.insert(s.x.end(), {v[i], v[i]});
            s.y.insert(s.y.end(), {double(i) / v.size(), double(i + 1) / v.size()});
          }
        if (!v.empty())
          spec.series.push_back(s);
      }
    if (spec.series.empty())
      return false;
    spec.title   = title;
    spec.x_label = "revolutions at the criterion [rev]";
    spec.y_label = "fraction of the members [-]";
    spec.y_range = Range{0, 1.05};
    return plot_png(spec, path);
  }
} // namespace wearlink::io
