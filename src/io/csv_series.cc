// SPDX-License-Identifier: LGPL-2.1-or-later
#include "io/csv_series.h"

#include "base/exceptions.h"
#include "base/text.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>

namespace wearlink::io
{
  namespace
  {
    /** Largest relative deviation of a time step from the mean step [-]. */
    constexpr double time_step_tolerance = 1e-3;

    std::vector<std::string>
    split_row(const std::string &line)
    {
      std::vector<std::string> out;
      std::stringstream        ss(line);
      std::string              field;
      while (std::getline(ss, field, ','))
        out.push_back(trim(field, " \t\r\""));
      if (!line.empty() && line.back() == ',')
        out.push_back("");
      return out;
    }

    /** Parse a whole field as a number; false if it is not one. */
    bool
    parse_number(const std::string &text, double &value)
    {
      if (text.empty())
        return false;
      char *end = nullptr;
      value     = std::strtod(text.c_str(), &end);
      return end == text.c_str() + text.size();
    }
  } // namespace

  CsvSeries
  read_csv_column(const std::string &file, const std::string &column)
  {
    std::ifstream in(file);
    if (!in)
      throw InputError("Cannot open the series file '" + file + "': it does not exist or is not readable.");
    CsvSeries   out;
    std::string line;
    std::size_t line_no = 0;
    while (std::getline(in, line))
      {
        ++line_no;
        if (!trim(line, " \t\r\"").empty() && trim(line, " \t\r\"")[0] != '#')
          break;
      }
    out.columns = split_row(line);
    if (out.columns.empty() || (out.columns.size() == 1 && out.columns[0].empty()))
      throw InputError("The series file '" + file +
                       "' is empty; it needs a header row "
                       "with column names and one row per sample.");
    std::string list;
    for (const auto &c : out.columns)
      list += (list.empty() ? "" : ", ") + c;
    const auto it = std::find(out.columns.begin(), out.columns.end(), column);
    if (it == out.columns.end())
      throw InputError("The series file '" + file + "' has no column '" + column + "'. Its columns are: " + list +
                       ". Choose one with --column.");
    const std::size_t col      = it - out.columns.begin();
    std::size_t       time_col = std::numeric_limits<std::size_t>::max();
    for (const char *name : {"t", "time_s"})
      {
        const auto t = std::find(out.columns.begin(), out.columns.end(), name);
        if (t != out.columns.end() && std::size_t(t - out.columns.begin()) != col)
          {
            time_col        = t - out.columns.begin();
            out.time_column = name;
            break;
          }
      }

    while (std::getline(in, line))
      {
        ++line_no;
        const std::string trimmed = trim(line, " \t\r\"");
        if (trimmed.empty() || trimmed[0] == '#')
          continue;
        const std::vector<std::string> fields = split_row(line);
        const std::size_t needed = std::max(col, time_col == std::numeric_limits<std::size_t>::max() ? 0 : time_col);
        if (fields.size() <= needed)
          throw InputError("In '" + file + "', line " + std::to_string(line_no) + " has " +
                           std::to_string(fields.size()) + " fields; the header has " +
                           std::to_string(out.columns.size()) + ".");
        double v = 0.0;
        if (!parse_number(fields[col], v) || !std::isfinite(v))
          throw InputError("In '" + file + "', line " + std::to_string(line_no) + ", column '" + column + "' is '" +
                           fields[col] +
                           "', not a finite number. The Lyapunov exponent needs a complete "
                           "series: remove or repair that sample.");
        out.values.push_back(v);
        if (time_col != std::numeric_limits<std::size_t>::max())
          {
            double t = 0.0;
            if (!parse_number(fields[time_col], t) || !std::isfinite(t))
              throw InputError("In '" + file + "', line " + std::to_string(line_no) + ", the time column '" +
                               out.time_column + "' is '" + fields[time_col] + "', not a finite number.");
            out.time.push_back(t);
          }
      }
    return out;
  }

  double
  sample_interval_from_time(const CsvSeries &s, const std::string &file)
  {
    const std::size_t n  = s.time.size();
    const double      dt = (s.time.back() - s.time.front()) / (n - 1);
    if (!(dt > 0.0))
      throw InputError("In '" + file + "', the time column '" + s.time_column +
                       "' does not increase; give the sample interval with --dt.");
    for (std::size_t i = 1; i < n; ++i)
      if (std::abs(s.time[i] - s.time[i - 1] - dt) > time_step_tolerance * dt)
        throw InputError("In '" + file + "', the time column '" + s.time_column + "' is not uniformly sampled: step " +
                         std::to_string(i) + " is " + std::to_string(s.time[i] - s.time[i - 1]) + " s, the mean step " +
                         std::to_string(dt) +
                         " s. Resample the series at a fixed interval "
                         "(or give --dt if the time column is only approximate).");
    return dt;
  }

} // namespace wearlink::io
