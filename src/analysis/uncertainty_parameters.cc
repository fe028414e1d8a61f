// SPDX-License-Identifier: LGPL-2.1-or-later
#include "analysis/uncertainty_parameters.h"

#include "base/exceptions.h"
#include "base/parameters.h"
#include "base/text.h"

#include <cmath>
#include <set>

namespace wearlink::analysis
{
  namespace P = dealii::Patterns;

  std::string
  uncertainty_syntax()
  {
    return "'ENTRY PATH: DISTRIBUTION(PARAMETERS)' separated by ';', with DISTRIBUTION(PARAMETERS) one of "
           "normal(mean, std), lognormal(median, sigma_log), uniform(low, high), "
           "truncated normal(mean, std, low, high), in the entry's own unit (sigma_log: the standard "
           "deviation of ln x, dimensionless)";
  }

  void
  declare_uncertainty(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Uncertainty");
    declare(prm,
            "Inputs",
            "",
            P::Anything(),
            "Uncertain inputs of an ensemble (`--ensemble N`): " + uncertainty_syntax() +
              ". E.g. 'Joint A/Clearance/archard/Pin wear coefficient: lognormal(4.6e-14, 0.3); "
              "Joint A/Clearance/modified-coulomb/Friction coefficient: uniform(0.1, 0.2)'. normal: std > 0; "
              "lognormal: ln x is normal with mean ln(median) and standard deviation sigma_log, median > 0, "
              "sigma_log > 0; uniform: low < high; truncated normal: the normal (mean, std) restricted to "
              "[low, high], low < high. Each entry must be a numeric entry of the scene, in a part it uses, "
              "listed once. Member k takes point k of the Sobol sequence (digitally shifted by Seed) through "
              "each distribution's inverse CDF, on top of the initial-angle perturbation; a single run uses "
              "the scene's own values. Long lists continue on the next line after a trailing backslash. "
              "Empty: no uncertain input.",
            "those of each entry");
    declare(prm,
            "Seed",
            "1",
            P::Integer(0, 2147483647),
            "Seed of the digital shift of the Sobol points of the uncertain inputs, 0 … 2^31 − 1 (0: the "
            "unshifted sequence). The same seed, the same input values for member k whatever the number "
            "of members or MPI ranks.",
            "none");
    prm.leave_subsection();
  }

  namespace
  {
    /** @p text as a finite double (the whole text), else NaN. */
    double
    number(const std::string &text)
    {
      try
        {
          std::size_t  used = 0;
          const double v    = std::stod(trim(text), &used);
          return used == trim(text).size() && std::isfinite(v) ? v : std::nan("");
        }
      catch (const std::exception &)
        {
          return std::nan("");
        }
    }

    /** The parameters between the parentheses of "family(a, b, …)", each checked finite. */
    std::vector<double>
    distribution_parameters(const std::string &text, const std::string &family, const std::size_t expected)
    {
      const auto open = text.find('('), close = text.rfind(')');
      if (open == std::string::npos || close == std::string::npos || close < open ||
          !trim(text.substr(close + 1)).empty())
        throw InputError("'" + text + "' is not of the form " + family + "(…)");
      std::vector<double> p;
      for (const auto &part : split(text.substr(open + 1, close - open - 1), ','))
        {
          p.push_back(number(part));
          if (!std::isfinite(p.back()))
            throw InputError("the parameter '" + part + "' of '" + text + "' is not a finite number");
        }
      if (p.size() != expected)
        throw InputError("'" + text + "' has " + std::to_string(p.size()) + " parameters; " + family + " takes " +
                         std::to_string(expected));
      return p;
    }
  } // namespace

  InputDistribution
  parse_distribution(const std::string &text)
  {
    using D                  = InputDistribution;
    const std::string family = trim(text.substr(0, text.find('(')));
    if (family == "normal")
      {
        const auto p = distribution_parameters(text, "normal(mean, std)", 2);
        return D::normal(p[0], p[1]);
      }
    if (family == "lognormal")
      {
        const auto p = distribution_parameters(text, "lognormal(median, sigma_log)", 2);
        return D::lognormal(p[0], p[1]);
      }
    if (family == "uniform")
      {
        const auto p = distribution_parameters(text, "uniform(low, high)", 2);
        return D::uniform(p[0], p[1]);
      }
    if (family == "truncated normal" || family == "truncated_normal")
      {
        const auto p = distribution_parameters(text, "truncated normal(mean, std, low, high)", 4);
        return D::truncated_normal(p[0], p[1], p[2], p[3]);
      }
    throw InputError("the distribution '" + family +
                     "' is unknown; the distributions are normal, lognormal, uniform and truncated normal");
  }

  namespace
  {
    /**
     * Why @p path is no uncertain input of the scene (empty if it is one): not declared,
     * not numeric, or in a part the scene does not use.
     */
    std::string
    entry_problem(dealii::ParameterHandler &prm, const std::string &path, const std::vector<std::string> &inactive)
    {
      const auto parts = split(path, '/');
      if (parts.empty() || path.rfind("Uncertainty/", 0) == 0)
        return "it is not an entry of the scene's model";
      const std::vector<std::string> sections(parts.begin(), parts.end() - 1);
      if (!sections.empty() && !prm.subsection_path_exists(sections))
        return "the scene declares no subsection '" + join(sections, "/") + "'";
      std::string value;
      bool        declared = true;
      for (const auto &section : sections)
        prm.enter_subsection(section);
      // deal.II's get() returns "" for an undeclared entry in a release build; set() of
      // the value it has tells (it throws ExcEntryUndeclared, and changes nothing else).
      value = prm.get(parts.back());
      try
        {
          prm.set(parts.back(), value);
        }
      catch (const dealii::ParameterHandler::ExcEntryUndeclared &)
        {
          declared = false;
        }
      catch (const dealii::ExceptionBase &) // declared, but "" does not match its pattern
        {
        }
      for (std::size_t i = 0; i < sections.size(); ++i)
        prm.leave_subsection();
      if (!declared)
        return "the scene declares no entry '" + parts.back() + "' in '" + join(sections, "/") + "'";
      if (!std::isfinite(number(value)))
        return "its value '" + value + "' is not a number";
      for (const auto &prefix : inactive)
        if (path.rfind(prefix, 0) == 0)
          return "it belongs to '" + prefix + "', a part the scene does not use (the input would change nothing)";
      return "";
    }
  } // namespace

  UncertaintySettings
  read_uncertainty(dealii::ParameterHandler       &prm,
                   const std::string              &file,
                   const std::vector<std::string> &inactive_prefixes)
  {
    UncertaintySettings s;
    prm.enter_subsection("Uncertainty");
    const std::string inputs = prm.get("Inputs");
    s.seed                   = static_cast<std::uint64_t>(prm.get_integer("Seed"));
    prm.leave_subsection();
    const std::string     where = "In " + file + ", 'Uncertainty/Inputs'";
    std::set<std::string> seen;
    for (const auto &item : split(inputs, ';'))
      {
        if (item.empty())
          continue;
        const auto colon = item.rfind(':', item.find('('));
        if (colon == std::string::npos)
          throw InputError(where + " has the input '" + item + "' without ':' between entry and distribution; write " +
                           uncertainty_syntax() + ".");
        analysis::UncertainInput in;
        in.entry                  = join(split(item.substr(0, colon), '/'), "/");
        const std::string problem = entry_problem(prm, in.entry, inactive_prefixes);
        if (!problem.empty())
          throw InputError(where + " names the entry '" + in.entry + "', but " + problem +
                           ". Name a numeric entry of the scene by its full path (`wearlink --print-parameters "
                           "SCENE` lists them).");
        if (!seen.insert(in.entry).second)
          throw InputError(where + " lists the entry '" + in.entry + "' twice; give each input one distribution.");
        try
          {
            in.distribution = parse_distribution(trim(item.substr(colon + 1)));
          }
        catch (const InputError &e)
          {
            throw InputError(where + ", input '" + in.entry + "': " + trim(e.message(), " .\n") + ". Allowed: " +
                             uncertainty_syntax() + "; std > 0, median > 0, sigma_log > 0, low < high.");
          }
        s.inputs.push_back(in);
      }
    return s;
  }
} // namespace wearlink::analysis
