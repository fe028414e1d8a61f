// SPDX-License-Identifier: LGPL-2.1-or-later
#include "io/signal_file.h"

#include "base/exceptions.h"
#include "io/csv.h"

namespace wearlink::io
{
  namespace
  {
    constexpr const char *time_column = "time_s";

    /** The index of the value column: @p column, or the only column besides time_s. */
    std::size_t
    value_column(const CsvTable &table, const std::string &column, const std::string &what, const std::string &option)
    {
      const std::string where = "The " + what + " '" + table.file() + "'";
      if (!column.empty())
        {
          const std::size_t c = table.find(column);
          if (c == CsvTable::npos)
            throw InputError(where + " has no column '" + column + "'. Its columns are: " + table.column_list() +
                             ". Choose one with " + option + ".");
          return c;
        }
      if (table.columns().size() != 2)
        throw InputError(where + " has " + std::to_string(table.columns().size()) + " columns (" + table.column_list() +
                         "); name the value column with " + option + ".");
      return table.find(time_column) == 0 ? 1 : 0;
    }

    /** InputError unless @p time increases strictly. */
    void
    require_increasing(const CsvTable &table, const std::vector<double> &time, const std::string &what)
    {
      for (std::size_t i = 1; i < time.size(); ++i)
        if (!(time[i] > time[i - 1]))
          throw InputError("In the " + what + " '" + table.file() + "', line " + std::to_string(table.line_of(i)) +
                           ", column '" + time_column + "' is " + std::to_string(time[i]) +
                           " s, not later than the line before (" + std::to_string(time[i - 1]) +
                           " s): the time must increase strictly. Sort the rows and remove repeated times.");
    }
  } // namespace

  TimeSignal
  read_time_signal(const std::string &file,
                   const std::string &column,
                   const std::string &what,
                   const std::string &option)
  {
    const CsvTable table = CsvTable::read(file, what);
    if (table.columns().empty())
      throw InputError("The " + what + " '" + file + "' has no header row; it needs one naming the columns, '" +
                       time_column + "' and a value column, then one row per sample.");
    const std::size_t t = table.find(time_column);
    if (t == CsvTable::npos)
      throw InputError("The " + what + " '" + file + "' has no column '" + time_column +
                       "' (the time in seconds). Its columns are: " + table.column_list() + ".");
    const std::size_t c = value_column(table, column, what, option);
    if (table.n_rows() < min_signal_samples)
      throw InputError("The " + what + " '" + file + "' has " + std::to_string(table.n_rows()) + " samples; at least " +
                       std::to_string(min_signal_samples) + " are needed.");
    TimeSignal s;
    s.file   = file;
    s.column = table.columns()[c];
    s.time   = table.numbers(t, "Every sample needs its time.");
    s.values = table.numbers(c, "Remove or repair that sample; a gap is not interpolated.");
    require_increasing(table, s.time, what);
    return s;
  }
} // namespace wearlink::io
