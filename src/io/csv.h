// SPDX-License-Identifier: LGPL-2.1-or-later
// The one CSV reader of wearlink: series for `wearlink lyapunov`, the recorded runs the
// analyses read back, surface profiles, response files. A file is rows of fields
// separated by commas (a row without a comma: by blanks); a field in double quotes may
// hold commas and '#' ("" is a quote inside it); '#' elsewhere starts a comment that runs
// to the end of the line; blank lines are skipped; blanks around a field are dropped. The first row is a header of column names if any of its fields is not a
// number. Fields stay text until a column is asked for as numbers; then every field of it
// must be a finite number, else an InputError names the file, the line and the column.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace wearlink::io
{
  class CsvTable
  {
  public:
    /** Read @p file; @p what names it in messages (e.g. "series file"). */
    static CsvTable
    read(const std::string &file, const std::string &what);

    /**
     * Read only the columns called @p only of @p file (a file with a header; without
     * one, every column): the table then holds those of them the header has, in the
     * file's order. A long time series read for a few of its columns keeps a few of its
     * fields in memory. A row shorter than the header is an InputError here.
     */
    static CsvTable
    read(const std::string &file, const std::string &what, const std::vector<std::string> &only);

    const std::string &
    file() const
    {
      return path;
    }
    /** The header's names; empty if the file has no header row. */
    const std::vector<std::string> &
    columns() const
    {
      return names;
    }
    std::size_t
    n_rows() const
    {
      return rows.size();
    }
    /** Fields of the widest row (the header's count if there is one). */
    std::size_t
    n_columns() const;
    /** Index of column @p name, or npos. */
    std::size_t
    find(const std::string &name) const;
    /** The header's names as "a, b, c" (for messages). */
    std::string
    column_list() const;

    /**
     * Column @p c of every row as numbers. InputError naming file, line and column if a
     * row is too short or a field is not a finite number; @p advice ends that message.
     */
    std::vector<double>
    numbers(std::size_t c, const std::string &advice = "") const;

    /** Field @p c of data row @p r as text ("" if the row is shorter). */
    const std::string &
    field(std::size_t r, std::size_t c) const;

    /** InputError unless every row has exactly the header's number of fields. */
    void
    require_rectangular() const;

    /** Line number in the file of data row @p r (for messages). */
    std::size_t
    line_of(std::size_t r) const
    {
      return lines[r];
    }

    static constexpr std::size_t npos = static_cast<std::size_t>(-1);

  private:
    std::string                           path, description;
    std::vector<std::string>              names;
    std::vector<std::vector<std::string>> rows;
    std::vector<std::size_t>              lines;

    std::string
    column_name(std::size_t c) const;
  };

  /** A whole field as a number (strtod, nothing left over); false if it is not one. */
  bool
  parse_number(const std::string &text, double &value);
} // namespace wearlink::io
