// SPDX-License-Identifier: LGPL-2.1-or-later
// A signal in a CSV file: a `time_s` column and a value column (a measured signal for
// `wearlink compare-signal`, or a channel of a run's time_series.csv). Read by
// io/csv.h; every problem is an InputError that names the file and the column: a
// missing file, no header, no time_s column, a missing value column (or several when
// none is named), a field that is not a finite number (with its line), a time that does
// not increase strictly (with its line), fewer than min_signal_samples rows.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace wearlink::io
{
  /** Fewest samples a signal file must hold. */
  inline constexpr std::size_t min_signal_samples = 16;

  struct TimeSignal
  {
    std::string         file, column;
    std::vector<double> time, values;
  };

  /**
   * Column @p column of the CSV file @p file with its `time_s` column; with @p column
   * empty, the file's only other column. @p what names the file in messages (e.g.
   * "measured signal"), @p option the command-line option that chooses the column
   * (e.g. "--column").
   */
  TimeSignal
  read_time_signal(const std::string &file,
                   const std::string &column,
                   const std::string &what,
                   const std::string &option);
} // namespace wearlink::io
