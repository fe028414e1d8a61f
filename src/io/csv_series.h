// SPDX-License-Identifier: LGPL-2.1-or-later
// One numeric column of a CSV file (read by io/csv.h; a header row of names is
// required), with the time column `t` or `time_s` if there is one: what `wearlink
// lyapunov` reads. Every problem is an InputError naming the file, the line and the
// column; a field that is not a finite number is refused, never skipped.
#pragma once

#include <string>
#include <vector>

namespace wearlink::io
{
  /** One column of a CSV file, and the time column if there is one. */
  struct CsvSeries
  {
    std::vector<double>      values;
    std::vector<double>      time;
    std::string              time_column; ///< "" if none
    std::vector<std::string> columns;
  };


  /** Column @p column of @p file (and its time column, if any). */
  CsvSeries
  read_csv_column(const std::string &file, const std::string &column);

  /**
   * The sample interval from the time column of @p s (read from @p file); InputError if
   * it does not increase uniformly (to a relative 1e-3 per step).
   */
  double
  sample_interval_from_time(const CsvSeries &s, const std::string &file);
} // namespace wearlink::io
