// SPDX-License-Identifier: LGPL-2.1-or-later
#include "io/life_outputs.h"

#include "analysis/ensemble_statistics.h"
#include "base/atomic_file.h"
#include "base/exceptions.h"
#include "io/csv.h"
#include "io/plot.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iterator>
#include <limits>
#include <sstream>

namespace wearlink::io
{
  namespace
  {
    bool
    has_response(const analysis::LifeHistory &h)
    {
      for (const auto &c : h.criteria)
        if (c.kind == analysis::Criterion::response_rise)
          return true;
      return false;
    }

    std::vector<std::string>
    header(const std::vector<analysis::CriterionSpec> &criteria, const bool response)
    {
      std::vector<std::string> names = {"iteration", "revolutions", "factor"};
      for (const auto &c : criteria)
        {
          names.push_back(c.name + "_" + (c.unit == "%" ? std::string("percent") : c.unit));
          names.push_back(c.name + "_joint");
        }
      if (response)
        names.push_back("response_measure_m_s2");
      return names;
    }
  } // namespace

  void
  write_life_history(const std::string &path, const analysis::LifeHistory &h)
  {
    const bool         response = has_response(h);
    std::ostringstream os;
    const auto         names = header(h.criteria, response);
    for (std::size_t k = 0; k < names.size(); ++k)
      os << (k ? "," : "") << names[k];
    os << '\n' << std::setprecision(17);
    for (std::size_t r = 0; r < h.rows(); ++r)
      {
        os << h.iterations[r] << ',' << h.revolutions[r] << ',' << h.factors[r];
        for (std::size_t c = 0; c < h.criteria.size(); ++c)
          os << ',' << h.values[r][c] << ',' << h.joints[r][c];
        if (response)
          os << ',' << h.response[r];
        os << '\n';
      }
    write_file_atomically(path, os.str());
  }

  analysis::LifeHistory
  read_life_history(const std::string &path, const std::vector<analysis::CriterionSpec> &criteria)
  {
    analysis::LifeHistory h;
    h.criteria          = criteria;
    const bool response = has_response(h);
    const auto table    = CsvTable::read(path, "life history");
    table.require_rectangular();
    if (table.columns() != header(criteria, response))
      throw InputError("Cannot resume the life run: '" + path + "' has the columns " + table.column_list() +
                       ", not those of this scene's Life criteria. Resume with the scene and --set options the "
                       "run was started with, or start afresh (`--overwrite`).");
    const auto iterations = table.numbers(0);
    h.revolutions         = table.numbers(1);
    h.factors             = table.numbers(2);
    h.values.assign(table.n_rows(), std::vector<double>(criteria.size()));
    h.joints.assign(table.n_rows(), std::vector<std::string>(criteria.size()));
    for (std::size_t c = 0; c < criteria.size(); ++c)
      {
        const auto v = table.numbers(3 + 2 * c);
        for (std::size_t r = 0; r < table.n_rows(); ++r)
          {
            h.values[r][c] = v[r];
            h.joints[r][c] = table.field(r, 4 + 2 * c);
          }
      }
    for (const double i : iterations)
      h.iterations.push_back(static_cast<unsigned int>(std::lround(i)));
    h.response = response ? table.numbers(3 + 2 * criteria.size()) :
                            std::vector<double>(table.n_rows(), std::numeric_limits<double>::quiet_NaN());
    return h;
  }

  namespace
  {
    /**
     * The value axis autoscaled within −1 … 5 limits: a rise of a response far from its
     * limit (thousands of percent from a near-zero fresh value) would flatten the rest.
     */
    const Range y_limits{-1, 5};

    /** Line colours of the criteria, in order. */
    const char *const colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e"};

    /** A closed polygon from @p low to @p high over @p x (forward along low, back along high). */
    PlotSeries
    band_series(const std::string         &title,
                const std::vector<double> &x,
                const std::vector<double> &low,
                const std::vector<double> &high,
                const std::string         &colour)
    {
      Look look;
      look.mark   = Mark::area;
      look.colour = colour;
      PlotSeries band{title, {}, {}, look};
      for (std::size_t k = 0; k < x.size(); ++k)
        if (std::isfinite(low[k]) && std::isfinite(high[k]))
          {
            band.x.push_back(x[k]);
            band.y.push_back(low[k]);
          }
      for (std::size_t k = x.size(); k-- > 0;)
        if (std::isfinite(low[k]) && std::isfinite(high[k]))
          {
            band.x.push_back(x[k]);
            band.y.push_back(high[k]);
          }
      return band;
    }

    /** @p n + 1 equally spaced revolutions from 0 to @p end. */
    std::vector<double>
    grid(const double end, const std::size_t n)
    {
      std::vector<double> x(n + 1);
      for (std::size_t k = 0; k <= n; ++k)
        x[k] = end * static_cast<double>(k) / static_cast<double>(n);
      return x;
    }

    /**
     * The response criterion's final trend on the model its measurements chose (rise /
     * limit) and its 95 % band over the run, each measurement as a rise over that model's
     * fresh level, and the 95 % interval of its crossing at 1 (series appended to @p spec).
     */
    void
    add_trend(PlotSpec                      &spec,
              const analysis::LifeHistory   &h,
              const analysis::CriterionSpec &c,
              const std::string             &colour)
    {
      const analysis::ResponseModels models(h.revolutions, h.response, h.rows());
      if (models.points() < 3 || h.revolutions.empty())
        return;
      const auto          family = models.chosen();
      const auto         &model  = models.model(family);
      const auto          name   = analysis::family_name(family);
      const auto          x      = grid(h.revolutions.back(), 200);
      std::vector<double> line, low, high;
      for (const double n : x)
        {
          const auto band = models.rise_interval(family, n);
          line.push_back(model.rise(n) / c.limit);
          low.push_back(band.low / c.limit);
          high.push_back(band.high / c.limit);
        }
      spec.series.push_back(band_series("95 % band of the " + c.name + " trend (" + name + ")", x, low, high, colour));
      spec.series.push_back(
        {c.name + " trend: " + name + " (least squares, chosen by BIC)", x, line, io::line(colour, 2).dotted()});
      PlotSeries measured{"response measure as a rise over the " + name + "'s fresh level",
                          {},
                          {},
                          points("#555555", 1)};
      for (std::size_t r = 0; r < h.rows(); ++r)
        if (std::isfinite(h.response[r]))
          {
            measured.x.push_back(h.revolutions[r]);
            measured.y.push_back(100 * (h.response[r] / model.fit.a - 1) / c.limit);
          }
      spec.series.push_back(measured);
      const auto   interval = models.crossing_interval(family, c.limit);
      const double crossing = model.crossing(c.limit);
      if (interval.bounded())
        spec.series.push_back({"95 % interval of the " + c.name + " crossing (" + name + " at " +
                                 std::to_string(static_cast<long>(std::lround(crossing))) + " rev)",
                               {interval.low, interval.high},
                               {1.0, 1.0},
                               line_points(colour, 5, Marker::filled_diamond, 1.5)});
    }

    /** The value of a history's column at @p at revolutions (linear; NaN past its end). */
    double
    value_at(const std::vector<double> &x, const std::vector<double> &y, const double at)
    {
      for (std::size_t k = 1; k < x.size() && k < y.size(); ++k)
        if (at <= x[k])
          return x[k] > x[k - 1] ? y[k - 1] + (at - x[k - 1]) / (x[k] - x[k - 1]) * (y[k] - y[k - 1]) : y[k];
      return x.size() == 1 && at == x[0] ? y[0] : std::numeric_limits<double>::quiet_NaN();
    }
  } // namespace

  bool
  plot_life(const std::string &path, const analysis::LifeHistory &h, const std::string &title)
  {
    PlotSpec spec;
    spec.title    = title;
    spec.x_label  = "revolutions";
    spec.y_label  = "criterion value / its limit (1: reached)";
    spec.key      = KeyPlace::below;
    spec.y_limits = y_limits;
    int point     = 4;
    for (std::size_t c = 0; c < h.criteria.size(); ++c)
      {
        const auto        &cr     = h.criteria[c];
        const std::string  colour = colours[c % std::size(colours)];
        std::ostringstream name;
        name << cr.name << " (limit " << cr.limit << ' ' << cr.unit << ')';
        PlotSeries s{name.str(),
                     h.revolutions,
                     {},
                     numbered_shape(line_points(colour, 2, Marker::automatic, 1.5), point++)};
        for (std::size_t r = 0; r < h.rows(); ++r)
          s.y.push_back(h.values[r][c] / cr.limit);
        spec.series.push_back(s);
        if (analysis::is_trend(cr))
          add_trend(spec, h, cr, colour);
      }
    if (!h.revolutions.empty())
      spec.series.push_back({"limit", {0.0, h.revolutions.back()}, {1.0, 1.0}, line("black", 1.5).dashed()});
    PlotSeries crossings{"wear crossing (revolutions to the criterion)", {}, {}, points("red", 2)};
    for (std::size_t c = 0; c < h.criteria.size(); ++c)
      {
        if (analysis::is_trend(h.criteria[c]))
          continue;
        const auto x = analysis::first_crossing(h.revolutions, h.column(c), h.criteria[c].limit);
        if (x.reached)
          {
            crossings.x.push_back(x.revolutions);
            crossings.y.push_back(1.0);
          }
      }
    if (!crossings.x.empty())
      spec.series.push_back(crossings);
    return plot_png(spec, path);
  }

  bool
  plot_life_ensemble(const std::string                        &path,
                     const std::vector<analysis::LifeHistory> &members,
                     const std::vector<CrossingSpread>        &spreads,
                     const std::vector<MeanTrendCrossing>     &trends,
                     const std::string                        &title)
  {
    PlotSpec spec;
    spec.title    = title;
    spec.x_label  = "revolutions";
    spec.y_label  = "criterion value / its limit (1: reached)";
    spec.key      = KeyPlace::inside_top_left;
    spec.y_limits = y_limits;
    if (members.empty())
      return plot_png(spec, path);
    double end = 0;
    for (const auto &m : members)
      end = m.revolutions.empty() ? end : std::max(end, m.revolutions.back());
    const auto x = grid(end, 200);
    for (std::size_t c = 0; c < members.front().criteria.size(); ++c)
      {
        const auto         &cr     = members.front().criteria[c];
        const std::string   colour = colours[c % std::size(colours)];
        std::vector<double> low, high, median;
        for (const double at : x)
          {
            std::vector<double> v;
            for (const auto &m : members)
              if (c < m.criteria.size() && std::isfinite(value_at(m.revolutions, m.column(c), at)))
                v.push_back(value_at(m.revolutions, m.column(c), at) / cr.limit);
            low.push_back(v.empty() ? NAN : *std::min_element(v.begin(), v.end()));
            high.push_back(v.empty() ? NAN : *std::max_element(v.begin(), v.end()));
            median.push_back(v.empty() ? NAN : analysis::percentile(v, 0.5));
          }
        spec.series.push_back(band_series(cr.name + ": smallest … largest of the members", x, low, high, colour));
        spec.series.push_back({cr.name + ": median of the members", x, median, line(colour, 2)});
        for (const auto &s : spreads)
          if (s.criterion == cr.name)
            spec.series.push_back({cr.name + ": crossings P10 … P90, P50",
                                   {s.p10, s.p50, s.p90},
                                   {1.0, 1.0, 1.0},
                                   line_points(colour, 5, Marker::filled_triangle, 1.8)});
        for (const auto &t : trends)
          if (t.criterion == cr.name)
            spec.series.push_back({"95 % interval of the " + cr.name + " crossing of the members' mean (at " +
                                     std::to_string(static_cast<long>(std::lround(t.at))) + " rev)",
                                   {t.low, t.high},
                                   {1.0, 1.0},
                                   line_points(colour, 5, Marker::filled_diamond, 1.5)});
      }
    spec.series.push_back({"limit", {0.0, end}, {1.0, 1.0}, line("black", 1.5).dashed()});
    return plot_png(spec, path);
  }
} // namespace wearlink::io
