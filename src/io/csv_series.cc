// SPDX-License-Identifier: LGPL-2.1-or-later
#include "io/csv_series.h"

#include "base/exceptions.h"
#include "io/csv.h"

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
  } // namespace

  CsvSeries
  read_csv_column(const std::string &file, const std::string &column)
  {
    const CsvTable table = CsvTable::read(file, "series file");
    if (table.columns().empty())
      throw InputError("The series file '" + file +
                       "' has no header row; it needs one with column names, then one row per sample.");
    CsvSeries out;
    out.columns         = table.columns();
    const std::size_t c = table.find(column);
    if (c == CsvTable::npos)
      throw InputError("The series file '" + file + "' has no column '" + column +
                       "'. Its columns are: " + table.column_list() + ". Choose one with --column.");
    out.values = table.numbers(c, "The Lyapunov exponent needs a complete series: remove or repair that sample.");
    for (const char *name : {"t", "time_s"})
      {
        const std::size_t t = table.find(name);
        if (t != CsvTable::npos && t != c)
          {
            out.time_column = name;
            out.time        = table.numbers(t);
            break;
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
