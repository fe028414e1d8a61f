// SPDX-License-Identifier: LGPL-2.1-or-later
#include "base/parameters.h"

#include "base/exceptions.h"
#include "base/text.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

namespace wearlink
{
  namespace
  {
    /** The text of a line without its comment and surrounding blanks. */
    std::string
    strip_comment(const std::string &line)
    {
      const auto hash = line.find('#');
      return trim(hash == std::string::npos ? line : line.substr(0, hash));
    }

    bool
    starts_with_word(const std::string &line, const std::string &word)
    {
      return line.compare(0, word.size(), word) == 0 &&
             (line.size() == word.size() || line[word.size()] == ' ' || line[word.size()] == '\t');
    }

    /** deal.II's messages end with a newline and often start with one. */
    std::string
    info_of(const dealii::ExceptionBase &e)
    {
      std::ostringstream os;
      e.print_info(os);
      return trim(os.str());
    }

    /** Undo deal.II's internal name mangling ("_20" for a blank, "." between levels). */
    std::string
    demangle_path(const std::string &mangled)
    {
      std::string out;
      for (std::size_t i = 0; i < mangled.size(); ++i)
        {
          if (mangled[i] == '.')
            out += '/';
          else if (mangled[i] == '_' && i + 2 < mangled.size() + 0 &&
                   std::isxdigit(static_cast<unsigned char>(mangled[i + 1])) &&
                   std::isxdigit(static_cast<unsigned char>(mangled[i + 2])))
            {
              out += static_cast<char>(std::stoi(mangled.substr(i + 1, 2), nullptr, 16));
              i += 2;
            }
          else
            out += mangled[i];
        }
      return out;
    }

    /** One parse of @p text (a balanced chunk of @p filename) into @p prm. */
    void
    parse_chunk(dealii::ParameterHandler &prm,
                const std::string        &text,
                const std::string        &filename,
                bool                      skip_undefined)
    {
      std::istringstream in(text);
      try
        {
          prm.parse_input(in, filename, "", skip_undefined);
        }
      catch (const Error &)
        {
          throw;
        }
      catch (const dealii::ExceptionBase &e)
        {
          throw InputError("Error in scene file '" + filename + "':\n  " + info_of(e) +
                           "\n  (`wearlink --print-parameters` lists every entry with its allowed range and why.)");
        }
    }
  } // namespace


  void
  declare(dealii::ParameterHandler            &prm,
          const std::string                   &name,
          const std::string                   &default_value,
          const dealii::Patterns::PatternBase &pattern,
          const std::string                   &doc,
          const std::string                   &unit)
  {
    prm.declare_entry(name, default_value, pattern, doc + " Units: " + unit + ".");
  }


  void
  declare_required(dealii::ParameterHandler            &prm,
                   const std::string                   &name,
                   const dealii::Patterns::PatternBase &pattern,
                   const std::string                   &doc,
                   const std::string                   &unit)
  {
    // deal.II wants a default that matches the pattern even for an entry the user must
    // set; it only shows in --print-parameters, where the doc says it is required.
    std::string placeholder;
    for (const char *candidate : {"", "0", "1", "0, 0", "none"})
      if (pattern.match(candidate))
        {
          placeholder = candidate;
          break;
        }
    if (dynamic_cast<const dealii::Patterns::Double *>(&pattern) != nullptr && !pattern.match(placeholder))
      {
        // "[Double 1e+06...1e+13 (inclusive)]": a range that excludes 0 and 1 gives its lower end.
        const std::string d = pattern.description(dealii::Patterns::PatternBase::Machine);
        const auto        b = d.find("Double ") + 7;
        placeholder         = d.substr(b, d.find("...", b) - b);
      }
    if (dynamic_cast<const dealii::Patterns::Selection *>(&pattern) != nullptr)
      {
        // "[Selection a|b|c ]": the first choice stands in for the missing default.
        const std::string d = pattern.description(dealii::Patterns::PatternBase::Machine);
        const auto        b = d.find(' ');
        placeholder = trim(d.substr(b + 1, d.find('|') == std::string::npos ? std::string::npos : d.find('|') - b - 1));
        if (!placeholder.empty() && placeholder.back() == ']')
          placeholder.pop_back();
        placeholder = trim(placeholder);
      }
    Assert(pattern.match(placeholder), dealii::ExcInternalError());
    prm.declare_entry(name, placeholder, pattern, doc + " Required (no default). Units: " + unit + ".", true);
  }


  dealii::Patterns::List
  point_pattern()
  {
    return dealii::Patterns::List(dealii::Patterns::Double(), 2, 2, ",");
  }


  ParameterReader::ParameterReader(dealii::ParameterHandler &prm, std::string file)
    : prm(prm)
    , filename(std::move(file))
  {
  }


  void
  ParameterReader::enter(const std::string &subsection)
  {
    prm.enter_subsection(subsection);
    sections.push_back(subsection);
  }


  void
  ParameterReader::leave()
  {
    Assert(!sections.empty(), dealii::ExcInternalError());
    prm.leave_subsection();
    sections.pop_back();
  }


  std::string
  ParameterReader::path(const std::string &entry) const
  {
    std::string p;
    for (const auto &s : sections)
      p += s + "/";
    return p + entry;
  }


  std::string
  ParameterReader::get(const std::string &entry) const
  {
    return prm.get(entry);
  }


  bool
  ParameterReader::get_bool(const std::string &entry) const
  {
    return prm.get_bool(entry);
  }


  long
  ParameterReader::get_integer(const std::string &entry) const
  {
    return prm.get_integer(entry);
  }


  double
  ParameterReader::get_double(const std::string &entry) const
  {
    const std::string text = trim(prm.get(entry));
    double            value;
    std::size_t       used = 0;
    try
      {
        value = std::stod(text, &used);
      }
    catch (const std::exception &)
      {
        fail(entry, "it must be a finite number");
      }
    if (used != text.size() || !std::isfinite(value))
      fail(entry, "it must be a finite number");
    return value;
  }


  double
  ParameterReader::get_positive(const std::string &entry) const
  {
    const double v = get_double(entry);
    if (!(v > 0))
      fail(entry, "it must be > 0");
    return v;
  }


  std::array<double, 2>
  ParameterReader::get_point(const std::string &entry) const
  {
    const auto parts = get_list(entry);
    if (parts.size() != 2)
      fail(entry, "it must be two numbers \"x, y\"");
    std::array<double, 2> p{};
    for (unsigned d = 0; d < 2; ++d)
      {
        std::size_t used = 0;
        try
          {
            p[d] = std::stod(parts[d], &used);
          }
        catch (const std::exception &)
          {
            fail(entry, "it must be two finite numbers \"x, y\"");
          }
        if (used != parts[d].size() || !std::isfinite(p[d]))
          fail(entry, "it must be two finite numbers \"x, y\"");
      }
    return p;
  }


  std::vector<std::string>
  ParameterReader::get_list(const std::string &entry) const
  {
    std::vector<std::string> out;
    for (const auto &s : dealii::Utilities::split_string_list(prm.get(entry), ','))
      {
        const auto t = trim(s);
        if (!t.empty())
          out.push_back(t);
      }
    return out;
  }


  void
  ParameterReader::fail(const std::string &entry, const std::string &allowed, const std::string &hint) const
  {
    std::string value;
    try
      {
        value = prm.get(entry);
      }
    catch (...)
      {
        value = "(not declared)";
      }
    std::string msg = "In " + filename + ", '" + path(entry) + "' is '" + value + "'; " + allowed + ".";
    if (!hint.empty())
      msg += " " + hint;
    throw InputError(msg);
  }


  void
  ParameterReader::fail_section(const std::string &what_is_wrong) const
  {
    std::string p;
    for (const auto &s : sections)
      p += (p.empty() ? "" : "/") + s;
    throw InputError("In " + filename + ", subsection '" + p + "': " + what_is_wrong);
  }


  namespace
  {
    /** Files deeper in a chain of includes than this are refused (a chain this long is a mistake). */
    constexpr std::size_t max_include_depth = 16;

    /** The chain "a.prm → b.prm → a.prm" of the files being read. */
    std::string
    chain_text(const std::vector<std::string> &chain, const std::string &last)
    {
      std::string text;
      for (const auto &f : chain)
        text += "'" + f + "' → ";
      return text + "'" + last + "'";
    }

    /** Open @p filename for reading, or throw an InputError that says why it cannot be. */
    std::ifstream
    open_prm_file(const std::string &filename)
    {
      namespace fs = std::filesystem;
      std::error_code ec;
      if (fs::is_directory(filename, ec))
        throw InputError("'" + filename +
                         "' is a directory, not a parameter file. Give the path of a .prm file "
                         "(see params/ for examples).");
      std::ifstream in(filename);
      if (!in)
        throw InputError("Cannot open the parameter file '" + filename +
                         "': it does not exist or is not readable. Check the path (relative "
                         "paths are taken from the current directory).");
      return in;
    }

    /** The file named by the `include` line @p body (line @p line_no of @p filename). */
    std::filesystem::path
    included_file(const std::string &body, const std::string &filename, const unsigned line_no)
    {
      namespace fs = std::filesystem;
      fs::path inc = trim(body.substr(7));
      if (inc.empty())
        throw InputError("In " + filename + " line " + std::to_string(line_no) + ": 'include' needs a file name.");
      if (inc.is_relative())
        inc = fs::path(filename).parent_path() / inc;
      std::error_code ec; // a name too long for the system is a name of no file, not an exception
      if (!fs::exists(inc, ec))
        throw InputError("In " + filename + " line " + std::to_string(line_no) + ": the included file '" +
                         inc.string() + "' does not exist" + (ec ? " (" + ec.message() + ")" : std::string()) +
                         " (include paths are relative to the including file).");
      return inc;
    }

    /** Refuse to read @p file again while it is being read (a cycle), or too deep a chain. */
    void
    check_include_chain(const std::vector<std::string> &chain, const std::string &file, const unsigned line_no)
    {
      namespace fs = std::filesystem;
      std::error_code ec;
      for (const auto &f : chain)
        if (fs::equivalent(f, file, ec))
          throw InputError("In " + chain.back() + " line " + std::to_string(line_no) + ": including '" + file +
                           "' makes a cycle of includes: " + chain_text(chain, file) +
                           ". A file must not include itself, directly or through other files; remove "
                           "one of these include lines.");
      if (chain.size() >= max_include_depth)
        throw InputError("In " + chain.back() + " line " + std::to_string(line_no) + ": including '" + file +
                         "' nests includes " + std::to_string(chain.size() + 1) + " files deep; at most " +
                         std::to_string(max_include_depth) + " are allowed. Chain: " + chain_text(chain, file) + ".");
    }

    /** The UTF-8 byte-order mark some editors write at the start of a text file. */
    void
    strip_byte_order_mark(std::string &first_line)
    {
      if (first_line.compare(0, 3, "\xEF\xBB\xBF") == 0)
        first_line.erase(0, 3);
    }

    /** read_prm_file() with the chain of files that include @p filename. */
    void
    read_prm_file_in_chain(dealii::ParameterHandler &prm,
                           const std::string        &filename,
                           bool                      skip_undefined,
                           std::vector<std::string> &chain)
    {
      std::ifstream in = open_prm_file(filename);
      chain.push_back(filename);

      // Split the file into balanced chunks at top-level `include` lines. Each chunk is
      // padded with empty lines so that deal.II's line numbers stay those of the file.
      std::string line;
      std::string chunk;
      unsigned    line_no = 0;
      int         depth   = 0;
      while (std::getline(in, line))
        {
          if (++line_no == 1)
            strip_byte_order_mark(line);
          if (!is_valid_utf8(line))
            throw InputError("In " + filename + " line " + std::to_string(line_no) +
                             ": the line is not valid UTF-8 text (a stray byte, e.g. a Latin-1 "
                             "character or a binary file). Save the file as UTF-8.");
          const std::string body = strip_comment(line);
          if (starts_with_word(body, "subsection"))
            ++depth;
          else if (body == "end")
            --depth;

          if (!starts_with_word(body, "include"))
            {
              chunk += line + '\n';
              continue;
            }
          if (depth != 0)
            throw InputError("In " + filename + " line " + std::to_string(line_no) +
                             ": 'include' is only allowed outside subsections. Move it "
                             "to the top level of the file.");
          const auto inc = included_file(body, filename, line_no);
          parse_chunk(prm, chunk, filename, skip_undefined);
          check_include_chain(chain, inc.string(), line_no);
          read_prm_file_in_chain(prm, inc.string(), skip_undefined, chain);
          chunk = std::string(line_no, '\n');
        }
      parse_chunk(prm, chunk, filename, skip_undefined);
      chain.pop_back();
    }
  } // namespace


  void
  read_prm_file(dealii::ParameterHandler &prm, const std::string &filename, bool skip_undefined)
  {
    std::vector<std::string> chain;
    read_prm_file_in_chain(prm, filename, skip_undefined, chain);
  }


  std::vector<std::string>
  unset_required_entries(const dealii::ParameterHandler &prm)
  {
    std::vector<std::string> paths;
    for (const auto &m : prm.get_entries_wrongly_not_set())
      paths.push_back(demangle_path(m));
    return paths;
  }


  void
  check_required_entries(const dealii::ParameterHandler &prm, const std::string &filename)
  {
    const auto missing = unset_required_entries(prm);
    if (missing.empty())
      return;
    std::string list;
    for (const auto &m : missing)
      list += "\n  " + m;
    throw InputError("In " + filename +
                     ", these required entries are not set (physical data has no default; "
                     "set them in the scene or with --set):" +
                     list);
  }


  ParameterOverrides::ParameterOverrides(std::vector<std::string> settings_as_given)
    : list(std::move(settings_as_given))
  {
  }

  ParameterOverrides &
  ParameterOverrides::set(const std::string &path, const std::string &value)
  {
    list.push_back(path + "=" + value);
    return *this;
  }

  ParameterOverrides &
  ParameterOverrides::set(const std::string &path, const char *value)
  {
    return set(path, std::string(value));
  }

  ParameterOverrides &
  ParameterOverrides::set(const std::string &path, const double value)
  {
    std::ostringstream v;
    v << std::setprecision(17) << value;
    return set(path, v.str());
  }

  ParameterOverrides &
  ParameterOverrides::append(const ParameterOverrides &later)
  {
    list.insert(list.end(), later.list.begin(), later.list.end());
    return *this;
  }

  ParameterOverrides &
  ParameterOverrides::remove_paths_set_in(const ParameterOverrides &other)
  {
    list.erase(std::remove_if(list.begin(), list.end(), [&](const std::string &s) { return other.sets(path_of(s)); }),
               list.end());
    return *this;
  }

  bool
  ParameterOverrides::sets(const std::string &path) const
  {
    const std::string p = trim(path);
    return std::any_of(list.begin(), list.end(), [&](const std::string &s) { return path_of(s) == p; });
  }

  std::string
  ParameterOverrides::path_of(const std::string &setting)
  {
    return trim(setting.substr(0, setting.find('=')));
  }

  namespace
  {
    /**
     * The parts "Section", "Sub", "Entry" of the override @p setting ("Section/Sub/Entry=value"),
     * or an InputError if it has no '=', an empty path or an empty part ("A//B", "/B", "A/").
     */
    std::vector<std::string>
    override_path_parts(const std::string &setting)
    {
      const std::string form = " Write it as --set \"Section/Sub/Entry=value\", e.g. --set \"Simulation/End "
                               "time=0.5\"; `wearlink --print-parameters` lists the entries.";
      const auto        eq   = setting.find('=');
      if (eq == std::string::npos)
        throw InputError("The override '--set " + setting + "' has no '='." + form);
      const std::string path = trim(setting.substr(0, eq));
      if (path.empty())
        throw InputError("The override '--set " + setting + "' names no entry before the '='." + form);
      std::vector<std::string> parts;
      std::size_t              begin = 0;
      while (true)
        {
          const auto slash = path.find('/', begin);
          parts.push_back(trim(path.substr(begin, slash == std::string::npos ? std::string::npos : slash - begin)));
          if (parts.back().empty())
            throw InputError("The override '--set " + setting + "' has an empty section or entry name in '" + path +
                             "'." + form);
          if (slash == std::string::npos)
            return parts;
          begin = slash + 1;
        }
    }
  } // namespace

  void
  apply_overrides(dealii::ParameterHandler &prm, const ParameterOverrides &overrides)
  {
    for (const auto &o : overrides.settings())
      {
        const auto        parts = override_path_parts(o);
        const std::string path  = trim(o.substr(0, o.find('=')));
        const std::string value = trim(o.substr(o.find('=') + 1));
        if (!is_valid_utf8(o))
          throw InputError("The override '--set " + path +
                           "=…' is not valid UTF-8 text (a stray byte, e.g. a Latin-1 character). "
                           "Write it in UTF-8.");
        const std::string              entry = parts.back();
        const std::vector<std::string> sections(parts.begin(), parts.end() - 1);
        if (!sections.empty() && !prm.subsection_path_exists(sections))
          throw InputError("The override '--set " + o + "' names the subsection '" + path.substr(0, path.rfind('/')) +
                           "', which this scene does not declare. Run `wearlink "
                           "--print-parameters` to see the declared entries.");
        for (const auto &s : sections)
          prm.enter_subsection(s);
        bool        ok = true;
        std::string why;
        try
          {
            prm.get(entry);
          }
        catch (const dealii::ExceptionBase &)
          {
            ok  = false;
            why = "there is no entry '" + entry +
                  "' there. Run `wearlink --print-parameters` "
                  "to see the declared entries.";
          }
        if (ok)
          try
            {
              prm.set(entry, value);
            }
          catch (const dealii::ExceptionBase &e)
            {
              ok  = false;
              why = info_of(e);
            }
        for (std::size_t i = 0; i < sections.size(); ++i)
          prm.leave_subsection();
        if (!ok)
          throw InputError("The override '--set " + o + "' cannot be applied: " + why +
                           " (`wearlink --print-parameters` lists every entry with its allowed range and why.)");
      }
  }


  std::string
  entry_value(dealii::ParameterHandler &prm, const std::string &path)
  {
    std::vector<std::string> parts(1);
    for (const char c : path)
      if (c == '/')
        parts.emplace_back();
      else
        parts.back() += c;
    for (std::size_t i = 0; i + 1 < parts.size(); ++i)
      prm.enter_subsection(parts[i]);
    const std::string v = prm.get(parts.back());
    for (std::size_t i = 0; i + 1 < parts.size(); ++i)
      prm.leave_subsection();
    return v;
  }
} // namespace wearlink
