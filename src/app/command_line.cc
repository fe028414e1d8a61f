// SPDX-License-Identifier: LGPL-2.1-or-later
#include "app/command_line.h"

#include "base/exceptions.h"
#include "base/text.h"

#include <deal.II/base/utilities.h>

#include <cmath>
#include <cstdlib>

namespace wearlink::app
{
  std::string
  ParsedArguments::value(const std::string &option, const std::string &fallback) const
  {
    const auto it = values.find(option);
    return it == values.end() || it->second.empty() ? fallback : it->second.back();
  }

  std::vector<std::string>
  ParsedArguments::all(const std::string &option) const
  {
    const auto it = values.find(option);
    return it == values.end() ? std::vector<std::string>() : it->second;
  }

  std::vector<std::string>
  ParsedArguments::list(const std::string &option, const std::string &fallback) const
  {
    std::vector<std::string> out;
    for (const auto &item : dealii::Utilities::split_string_list(value(option, fallback), ','))
      if (!item.empty())
        out.push_back(item);
    return out;
  }

  double
  ParsedArguments::number(const std::string &option, double fallback) const
  {
    if (!has(option))
      return fallback;
    const std::string text = value(option);
    std::size_t       used = 0;
    double            v    = 0;
    try
      {
        v = std::stod(text, &used);
      }
    catch (const std::exception &)
      {
        used = 0;
      }
    if (used != text.size() || text.empty() || !std::isfinite(v))
      throw InputError("The option " + option + " needs a finite number, not '" + text + "'.");
    return v;
  }

  ParsedArguments
  parse_arguments(const std::vector<std::string> &args, const std::vector<OptionSpec> &spec, const std::string &command)
  {
    ParsedArguments out;
    for (std::size_t i = 0; i < args.size(); ++i)
      {
        const std::string &a = args[i];
        if (a.size() > 1 && a[0] == '-' && !(a.size() > 1 && (std::isdigit(a[1]) || a[1] == '.')))
          {
            std::string name = a;
            std::string value;
            bool        inline_value = false;
            const auto  eq           = a.find('=');
            if (a.rfind("--", 0) == 0 && eq != std::string::npos)
              {
                name         = a.substr(0, eq);
                value        = a.substr(eq + 1);
                inline_value = true;
              }
            const OptionSpec *s = nullptr;
            for (const auto &o : spec)
              if (o.name == name)
                s = &o;
            if (s == nullptr)
              {
                std::string valid;
                for (const auto &o : spec)
                  valid += " " + o.name;
                throw InputError("Unknown option '" + name + "' for `wearlink " + command +
                                 "`. Valid options:" + valid + ". See `wearlink " + command + " --help`.");
              }
            if (s->takes_value)
              {
                if (!inline_value)
                  {
                    if (i + 1 >= args.size())
                      throw InputError("The option " + name + " needs a value.");
                    value = args[++i];
                  }
                if (trim(value).empty())
                  throw InputError("The option " + name + " of `wearlink " + command +
                                   "` is given an empty value. Give it a value (e.g. --output DIR names a "
                                   "directory), or leave the option out to use its default; see `wearlink " +
                                   command + " --help`.");
                auto &v = out.values[name];
                if (!v.empty() && !s->repeatable)
                  throw InputError("The option " + name + " is given twice.");
                v.push_back(value);
              }
            else
              {
                if (inline_value)
                  throw InputError("The option " + name + " takes no value.");
                out.flags.insert(name);
              }
          }
        else
          out.positional.push_back(a);
      }
    return out;
  }

  void
  refuse_several_ranks(const std::string &command, const std::string &instead)
  {
    // Open MPI's mpirun sets OMPI_COMM_WORLD_SIZE, MPICH's and Slurm's PMI_SIZE, before
    // MPI is initialised (a serial command never initialises it).
    for (const char *variable : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
      if (const char *value = std::getenv(variable))
        {
          const long ranks = std::strtol(value, nullptr, 10);
          if (ranks > 1)
            throw InputError("`wearlink " + command + "` runs serially, but it was started on " +
                             std::to_string(ranks) +
                             " MPI ranks: each would run the same scene into the same output folder. Start it "
                             "without mpirun, or " +
                             instead + ".");
        }
  }
} // namespace wearlink::app
