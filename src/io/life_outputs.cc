// SPDX-License-Identifier: LGPL-2.1-or-later
#include "io/life_outputs.h"

#include "base/atomic_file.h"
#include "base/exceptions.h"
#include "io/csv.h"
#include "io/plot.h"

#include <cmath>
#include <iomanip>
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

  bool
  plot_life(const std::string &path, const analysis::LifeHistory &h, const std::string &title)
  {
    PlotSpec spec;
    spec.title   = title;
    spec.x_label = "revolutions";
    spec.y_label = "criterion value / its limit (1: reached)";
    spec.extra   = "set key inside top left box opaque\nset grid\n";
    int point    = 4;
    for (std::size_t c = 0; c < h.criteria.size(); ++c)
      {
        const auto        &cr = h.criteria[c];
        std::ostringstream name;
        name << cr.name << " (limit " << cr.limit << ' ' << cr.unit << ')';
        PlotSeries s{name.str(), h.revolutions, {}, "linespoints", "pt " + std::to_string(point++) + " ps 1.5 lw 2"};
        for (std::size_t r = 0; r < h.rows(); ++r)
          s.y.push_back(h.values[r][c] / cr.limit);
        spec.series.push_back(s);
      }
    if (!h.revolutions.empty())
      spec.series.push_back({"limit", {0.0, h.revolutions.back()}, {1.0, 1.0}, "lines", "dt 2 lw 1.5 lc rgb 'black'"});
    PlotSeries crossings{"crossing (revolutions to the criterion)", {}, {}, "points", "pt 7 ps 2 lc rgb 'red'"};
    for (std::size_t c = 0; c < h.criteria.size(); ++c)
      {
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
} // namespace wearlink::io
