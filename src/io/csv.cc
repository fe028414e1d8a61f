// SPDX-License-Identifier: LGPL-2.1-or-later
#include "io/csv.h"

#include "base/exceptions.h"
#include "base/text.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace wearlink::io
{
  namespace
  {
    /**
     * split_fields() of a line that has commas but no quote, comment, tab or carriage
     * return (every row wearlink writes): the trimmed parts between the commas.
     */
    std::vector<std::string>
    split_plain_fields(const std::string &line)
    {
      std::vector<std::string> out;
      std::size_t              start = 0;
      while (true)
        {
          const std::size_t comma = std::min(line.find(',', start), line.size());
          std::size_t       first = start, last = comma;
          while (first < last && line[first] == ' ')
            ++first;
          while (last > first && line[last - 1] == ' ')
            --last;
          out.emplace_back(line, first, last - first);
          if (comma == line.size())
            return out;
          start = comma + 1;
        }
    }

    /**
     * The fields of one line: split at commas outside double quotes ("" inside quotes is
     * one quote), or at blanks if the line has no comma; a '#' outside quotes ends it.
     * Blanks around a field are dropped. Empty if the line holds only blanks or a comment.
     */
    std::vector<std::string>
    split_fields(const std::string &line)
    {
      if (line.find(',') != std::string::npos && line.find_first_of("\"#\r\t\n") == std::string::npos)
        return split_plain_fields(line);
      std::string body;
      bool        quoted = false, has_comma = false;
      for (const char c : line)
        {
          if (c == '"')
            quoted = !quoted;
          else if (c == '#' && !quoted)
            break;
          else if (c == '\r' && !quoted)
            continue;
          has_comma = has_comma || (c == ',' && !quoted);
          body += c;
        }
      std::vector<std::string> out;
      if (trim(body).empty())
        return out;
      const char  separator = has_comma ? ',' : ' ';
      std::string field;
      bool        in_quotes = false, was_quoted = false;
      auto        finish = [&] {
        out.push_back(was_quoted ? field : trim(field));
        field.clear();
        was_quoted = false;
      };
      for (std::size_t i = 0; i < body.size(); ++i)
        {
          const char c = body[i];
          if (c == '"')
            {
              if (in_quotes && i + 1 < body.size() && body[i + 1] == '"')
                field += body[++i];
              else
                {
                  if (!in_quotes)
                    field.clear(); // blanks before an opening quote
                  in_quotes  = !in_quotes;
                  was_quoted = true;
                }
            }
          else if (!in_quotes && (c == separator || (separator == ' ' && c == '\t')))
            {
              if (separator == ',' || !field.empty() || was_quoted)
                finish();
            }
          else if (!(was_quoted && !in_quotes))
            field += c; // blanks after a closing quote are dropped
        }
      if (separator == ',' || !field.empty() || was_quoted)
        finish();
      return out;
    }

    /** The fields of @p fields at @p indices (in range), in that order. */
    std::vector<std::string>
    select_fields(std::vector<std::string> &fields, const std::vector<std::size_t> &indices)
    {
      std::vector<std::string> out;
      out.reserve(indices.size());
      for (const auto c : indices)
        out.push_back(std::move(fields[c]));
      return out;
    }

    bool
    all_numbers(const std::vector<std::string> &fields)
    {
      double v = 0.0;
      return std::all_of(fields.begin(), fields.end(), [&](const std::string &f) { return parse_number(f, v); });
    }
  } // namespace

  bool
  parse_number(const std::string &text, double &value)
  {
    if (text.empty())
      return false;
    char *end = nullptr;
    value     = std::strtod(text.c_str(), &end);
    return end == text.c_str() + text.size();
  }

  CsvTable
  CsvTable::read(const std::string &file, const std::string &what)
  {
    return read(file, what, {});
  }

  CsvTable
  CsvTable::read(const std::string &file, const std::string &what, const std::vector<std::string> &only)
  {
    std::ifstream in(file);
    if (!in)
      throw InputError("Cannot open the " + what + " '" + file + "': it does not exist or is not readable.");
    CsvTable t;
    t.path        = file;
    t.description = what;
    std::vector<std::size_t> kept; // with a selection: the header's indices of the kept columns
    std::size_t              header_size = 0;
    std::string              line;
    for (std::size_t line_no = 1; std::getline(in, line); ++line_no)
      {
        std::vector<std::string> fields = split_fields(line);
        if (fields.empty())
          continue;
        if (t.rows.empty() && t.names.empty() && !all_numbers(fields))
          {
            header_size = fields.size();
            for (std::size_t c = 0; c < fields.size() && !only.empty(); ++c)
              if (std::find(only.begin(), only.end(), fields[c]) != only.end())
                kept.push_back(c);
            t.names = std::move(fields);
            if (!only.empty())
              t.names = select_fields(t.names, kept);
            continue;
          }
        if (!only.empty() && header_size > 0)
          {
            if (fields.size() < header_size)
              throw InputError("In '" + file + "', line " + std::to_string(line_no) + " has " +
                               std::to_string(fields.size()) + " fields; the header has " +
                               std::to_string(header_size) + ".");
            fields = select_fields(fields, kept);
          }
        t.rows.push_back(std::move(fields));
        t.lines.push_back(line_no);
      }
    return t;
  }

  std::size_t
  CsvTable::n_columns() const
  {
    std::size_t n = names.size();
    for (const auto &r : rows)
      n = std::max(n, r.size());
    return n;
  }

  std::size_t
  CsvTable::find(const std::string &name) const
  {
    const auto it = std::find(names.begin(), names.end(), name);
    return it == names.end() ? npos : static_cast<std::size_t>(it - names.begin());
  }

  std::string
  CsvTable::column_list() const
  {
    std::string list;
    for (const auto &c : names)
      list += (list.empty() ? "" : ", ") + c;
    return list;
  }

  std::string
  CsvTable::column_name(const std::size_t c) const
  {
    return c < names.size() ? "column '" + names[c] + "'" : "column " + std::to_string(c + 1);
  }

  const std::string &
  CsvTable::field(const std::size_t r, const std::size_t c) const
  {
    static const std::string empty;
    return c < rows[r].size() ? rows[r][c] : empty;
  }

  std::vector<double>
  CsvTable::numbers(const std::size_t c, const std::string &advice) const
  {
    std::vector<double> out;
    out.reserve(rows.size());
    for (std::size_t r = 0; r < rows.size(); ++r)
      {
        if (rows[r].size() <= c)
          throw InputError("In '" + path + "', line " + std::to_string(lines[r]) + " has " +
                           std::to_string(rows[r].size()) + " fields; " + column_name(c) + " needs " +
                           std::to_string(c + 1) +
                           (names.empty() ? "." : " (the header has " + std::to_string(names.size()) + ")."));
        double v = 0.0;
        if (!parse_number(rows[r][c], v) || !std::isfinite(v))
          throw InputError("In '" + path + "', line " + std::to_string(lines[r]) + ", " + column_name(c) + " is '" +
                           rows[r][c] + "', not a finite number." + (advice.empty() ? "" : " " + advice));
        out.push_back(v);
      }
    return out;
  }

  void
  CsvTable::require_rectangular() const
  {
    const std::size_t n = names.empty() ? (rows.empty() ? 0 : rows.front().size()) : names.size();
    for (std::size_t r = 0; r < rows.size(); ++r)
      if (rows[r].size() != n)
        throw InputError("In '" + path + "', line " + std::to_string(lines[r]) + " has " +
                         std::to_string(rows[r].size()) + " fields; " +
                         (names.empty() ? "the first row has " : "the header has ") + std::to_string(n) + ".");
  }
} // namespace wearlink::io
