// SPDX-License-Identifier: LGPL-2.1-or-later
// Command-line parsing shared by the sub-commands: positional arguments, options that
// take a value (--output DIR, --set X=Y repeatable), and flags. Unknown options are an
// InputError that lists the valid ones.
#pragma once

#include <map>
#include <set>
#include <string>
#include <vector>

namespace wearlink::app
{
  struct OptionSpec
  {
    std::string name;        ///< "--output"
    bool        takes_value; ///< "--output DIR" vs "--resume-flag"
    bool        repeatable = false;
  };

  struct ParsedArguments
  {
    std::vector<std::string>                        positional;
    std::map<std::string, std::vector<std::string>> values;
    std::set<std::string>                           flags;

    bool
    has(const std::string &option) const
    {
      return values.count(option) > 0 || flags.count(option) > 0;
    }
    /** The value of a single-valued option, or @p fallback if absent. */
    std::string
    value(const std::string &option, const std::string &fallback = "") const;
    /** All values of a repeatable option. */
    std::vector<std::string>
    all(const std::string &option) const;
    /** The comma-separated items of a single-valued option (empty items dropped). */
    std::vector<std::string>
    list(const std::string &option, const std::string &fallback = "") const;
    /** A numeric option value; InputError if not a number. */
    double
    number(const std::string &option, double fallback) const;
  };

  /** Parse @p args (without the program and command name) against @p spec. */
  ParsedArguments
  parse_arguments(const std::vector<std::string> &args,
                  const std::vector<OptionSpec>  &spec,
                  const std::string              &command);

  /**
   * InputError if this process is one of several ranks started by an MPI launcher
   * (mpirun, mpiexec, srun: their environment says how many) for a command that runs
   * serially: every rank would run the same command into the same folder. @p command
   * names it ("run without --ensemble"), @p instead says what to do.
   */
  void
  refuse_several_ranks(const std::string &command, const std::string &instead);

  /** A sub-command of the wearlink program. */
  struct Command
  {
    const char *name;
    const char *synopsis; ///< one line, for `wearlink --help`
    const char *help;     ///< full text, for `wearlink COMMAND --help`
    int (*run)(const std::vector<std::string> &args);
  };
} // namespace wearlink::app
