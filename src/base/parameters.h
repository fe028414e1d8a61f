// SPDX-License-Identifier: LGPL-2.1-or-later
// Declaring and reading .prm entries the wearlink way (doc/contributing.md §4):
//  - every entry is declared once with a bounded pattern, a documented default and its
//    unit; declare() appends "Units: <unit>." to the documentation so that
//    --print-parameters always states it;
//  - physical data without a sensible default is declared required (has_to_be_set);
//  - ParameterReader reads entries while tracking the subsection path, so an error
//    names the file, the full entry path ("Joint A/Clearance/Radial clearance"), the
//    value, the allowed range and how to fix it.
//  - read_prm_file() parses a .prm file with `include` lines resolved relative to the
//    including file, keeping deal.II's own file:line error reporting.
#pragma once

#include "base/text.h"

#include <deal.II/base/parameter_handler.h>

#include <array>
#include <initializer_list>
#include <string>
#include <vector>

namespace wearlink
{
  /** Declare an entry; @p unit is appended to @p doc as "Units: unit.". */
  void
  declare(dealii::ParameterHandler            &prm,
          const std::string                   &name,
          const std::string                   &default_value,
          const dealii::Patterns::PatternBase &pattern,
          const std::string                   &doc,
          const std::string                   &unit);

  /** Declare an entry that the scene must set (no silent default for physical data). */
  void
  declare_required(dealii::ParameterHandler            &prm,
                   const std::string                   &name,
                   const dealii::Patterns::PatternBase &pattern,
                   const std::string                   &doc,
                   const std::string                   &unit);

  /** Pattern of a 2D point or vector "x, y". */
  dealii::Patterns::List
  point_pattern();

  /**
   * Read access to a parsed ParameterHandler that knows the file it came from and the
   * subsection path it is in, so that every error it raises is an InputError naming
   * file, entry path, value and the allowed range.
   */
  class ParameterReader
  {
  public:
    ParameterReader(dealii::ParameterHandler &prm, std::string file);

    void
    enter(const std::string &subsection);
    void
    leave();

    /** The full path of @p entry in the current subsection, e.g. "Joint A/Model". */
    std::string
    path(const std::string &entry) const;

    const std::string &
    file() const
    {
      return filename;
    }

    std::string
    get(const std::string &entry) const;
    bool
    get_bool(const std::string &entry) const;
    long
    get_integer(const std::string &entry) const;
    /** A finite double (deal.II's pattern has already checked its bounds). */
    double
    get_double(const std::string &entry) const;
    /** A double that must be > 0 (strictly). */
    double
    get_positive(const std::string &entry) const;
    std::array<double, 2>
    get_point(const std::string &entry) const;
    std::vector<std::string>
    get_list(const std::string &entry) const;

    /** Throw an InputError "In FILE, 'PATH' is VALUE; ALLOWED. HINT". */
    [[noreturn]] void
    fail(const std::string &entry, const std::string &allowed, const std::string &hint = "") const;

    /** Throw an InputError about the current subsection as a whole. */
    [[noreturn]] void
    fail_section(const std::string &what_is_wrong) const;

    dealii::ParameterHandler &
    handler() const
    {
      return prm;
    }

  private:
    dealii::ParameterHandler &prm;
    std::string               filename;
    std::vector<std::string>  sections;
  };

  /**
   * Parse the .prm file @p filename into @p prm. `include FILE` lines (top level only)
   * are resolved relative to the including file. A missing file, a malformed line, a
   * value outside its pattern, an undeclared entry (unless @p skip_undefined) all throw
   * an InputError naming the file and line. Required entries are not checked here (see
   * check_required_entries()), so that command-line overrides can still supply them.
   */
  void
  read_prm_file(dealii::ParameterHandler &prm, const std::string &filename, bool skip_undefined = false);

  /** Throw an InputError listing every required entry the scene did not set. */
  void
  check_required_entries(const dealii::ParameterHandler &prm, const std::string &filename);

  /** The required entries @p prm does not set, as paths ("Joint A/Clearance/winkler/Layer thickness"). */
  std::vector<std::string>
  unset_required_entries(const dealii::ParameterHandler &prm);

  /**
   * Settings "Section/Sub/Entry=value" applied over a scene file, in order (a later one
   * wins): the user's --set arguments as given, and the settings the program makes (a
   * study's knob values, a two-trajectory run's tolerances), written through set() so
   * that a number is formatted once, to 17 significant digits (it reads back exactly).
   */
  class ParameterOverrides
  {
  public:
    ParameterOverrides() = default;
    /** The user's --set arguments, "Path=value" each (checked when applied). */
    ParameterOverrides(std::vector<std::string> settings_as_given);
    ParameterOverrides(std::initializer_list<std::string> settings_as_given)
      : list(settings_as_given)
    {
    }

    ParameterOverrides &
    set(const std::string &path, const std::string &value);
    ParameterOverrides &
    set(const std::string &path, const char *value);
    /** @p value to 17 significant digits. */
    ParameterOverrides &
    set(const std::string &path, double value);
    /** Append @p later (applied after, so its settings win). */
    ParameterOverrides &
    append(const ParameterOverrides &later);
    /** Leave out every setting of a path that @p other also sets. */
    ParameterOverrides &
    remove_paths_set_in(const ParameterOverrides &other);

    /** True if a setting is for @p path (compared without surrounding blanks). */
    bool
    sets(const std::string &path) const;
    bool
    empty() const
    {
      return list.empty();
    }
    /** The settings as "Path=value" text, in order. */
    const std::vector<std::string> &
    settings() const
    {
      return list;
    }
    /** The path of one "Path=value" setting (trimmed). */
    static std::string
    path_of(const std::string &setting);

  private:
    std::vector<std::string> list;
  };

  /**
   * Apply @p overrides to @p prm in order. A setting without '=', an unknown path or a
   * value outside the entry's pattern is an InputError naming the setting.
   */
  void
  apply_overrides(dealii::ParameterHandler &prm, const ParameterOverrides &overrides);

  /** The value of entry "Section/Sub/Entry" of @p prm (left at the top level again). */
  std::string
  entry_value(dealii::ParameterHandler &prm, const std::string &path);

} // namespace wearlink
