// SPDX-License-Identifier: LGPL-2.1-or-later
#include "workflows/ensemble/uncertain_inputs.h"

#include "analysis/input_distributions.h"
#include "analysis/sensitivity.h"
#include "base/exceptions.h"
#include "base/text.h"

#include <cmath>

namespace wearlink::workflows
{
  namespace
  {
    analysis::InputSampling
    sampling_of(const EnsembleRequest &request)
    {
      return request.saltelli ? analysis::InputSampling::saltelli : analysis::InputSampling::sobol;
    }
  } // namespace

  ParameterOverrides
  with_uncertain_inputs(const io::Scene                     &scene,
                        const ParameterOverrides            &member,
                        const EnsembleRequest               &request,
                        const unsigned int                   k,
                        const std::map<std::string, double> &shifts,
                        std::map<std::string, double>       *values)
  {
    const auto &inputs = scene.uncertainty.inputs;
    if (inputs.empty())
      return member;
    const auto         x = analysis::member_inputs(scene.uncertainty, sampling_of(request), request.members, k);
    ParameterOverrides o = member;
    for (std::size_t i = 0; i < inputs.size(); ++i)
      {
        double shift = 0; // an uncertain initial angle of a driver keeps the chaos perturbation
        for (const auto &[driver, s] : shifts)
          if (inputs[i].entry == "Joint " + driver + "/Angle offset")
            shift = s;
        o.set(inputs[i].entry, x[i] + shift);
        if (values)
          (*values)[inputs[i].entry] = x[i];
      }
    return o;
  }

  void
  check_uncertain_members(const EnsembleOptions &options, const io::Scene &base)
  {
    const auto &inputs = base.uncertainty.inputs;
    if (inputs.empty())
      {
        if (options.request.saltelli)
          throw InputError("--sensitivity saltelli needs uncertain inputs, but " + options.scene_file +
                           " has none. List them in `subsection Uncertainty` (set Inputs = ENTRY: "
                           "DISTRIBUTION(...); …), or leave out --sensitivity.");
        return;
      }
    if (options.request.saltelli)
      analysis::member_design(base.uncertainty, options.request.members); // the member count
    for (unsigned int k = 0; k < options.request.members; ++k)
      {
        std::map<std::string, double> values;
        const auto mine = with_uncertain_inputs(base, options.overrides, options.request, k, {}, &values);
        try
          {
            io::read_scene(options.scene_file, mine);
          }
        catch (const InputError &e)
          {
            std::string drawn;
            for (const auto &in : inputs)
              drawn += (drawn.empty() ? "" : ", ") + in.entry + " = " + format_number(values.at(in.entry), 6) +
                       " from " + in.distribution.describe();
            throw InputError("In " + options.scene_file + ", 'Uncertainty/Inputs': ensemble member " +
                             std::to_string(k) + " draws " + drawn +
                             ", which the scene does not accept: " + trim(e.message()) +
                             " Narrow the distribution, or use a truncated normal / uniform within the entry's "
                             "allowed range.");
          }
      }
  }

  Json
  uncertainty_summary(const io::Scene &scene, const EnsembleRequest &request)
  {
    Json inputs = Json::array();
    for (const auto &in : scene.uncertainty.inputs)
      inputs.push_back({{"entry", in.entry}, {"distribution", in.distribution.describe()}});
    return {{"seed", scene.uncertainty.seed},
            {"sampling", request.saltelli ? "saltelli" : "sobol"},
            {"sampling_definition",
             request.saltelli ?
               "member k is point k of the Saltelli design (analysis/sensitivity.h) of members / (inputs + 2) "
               "base rows over the Sobol sequence of 2 × inputs dimensions, digitally shifted by the seed" :
               "member k takes point k of the Sobol sequence (one dimension per input), digitally shifted by the "
               "seed, through each input's inverse CDF"},
            {"lognormal", "lognormal(median, log_std): ln x is normal with mean ln(median) and std log_std"},
            {"inputs", inputs}};
  }

  namespace
  {
    Json
    estimate_json(const analysis::IndexEstimate &e)
    {
      const auto n = [](const double v) {
        return std::isfinite(v) ? Json(v) : Json();
      };
      return {{"value", n(e.value)}, {"ci95_low", n(e.ci95_low)}, {"ci95_high", n(e.ci95_high)}};
    }

    /** The figures the sensitivities are reported for (those of @p statistics). */
    std::vector<std::string>
    headline_figures(const Json &statistics)
    {
      static const char *const suffixes[] = {"_wear_volume_pin_m3",
                                             "_wear_volume_bushing_m3",
                                             "_max_wear_depth_pin_m",
                                             "_max_wear_depth_bushing_m",
                                             "_mass_loss_pin_mg",
                                             "_mass_loss_bushing_mg"};
      std::vector<std::string> out;
      for (auto it = statistics.begin(); it != statistics.end(); ++it)
        {
          const std::string &name = it.key();
          bool               take =
            name.rfind("life_", 0) == 0 && name.size() > 12 && name.compare(name.size() - 12, 12, "_revolutions") == 0;
          take = take || name == "life_revolutions";
          for (const char *s : suffixes)
            take = take || (name.size() > std::string(s).size() &&
                            name.compare(name.size() - std::string(s).size(), std::string::npos, s) == 0);
          if (take)
            out.push_back(name);
        }
      return out;
    }

    /** One member's figure @p name (NaN if it failed or lacks it). */
    double
    figure_of(const Json &member, const std::string &name)
    {
      if (member.at("status").get<std::string>() != "ok" || !member.at("figures").contains(name))
        return std::nan("");
      return json_number(member.at("figures").at(name));
    }

    /** The sensitivities of one figure, by input entry. */
    Json
    figure_sensitivity(const analysis::UncertaintySettings &u,
                       const EnsembleRequest               &request,
                       const std::string                   &name,
                       const std::vector<Json>             &members)
    {
      std::vector<double>              y;
      std::vector<std::vector<double>> x;
      for (const auto &m : members)
        {
          y.push_back(figure_of(m, name));
          std::vector<double> row;
          for (const auto &in : u.inputs)
            row.push_back(m.contains("inputs") ? json_number(m.at("inputs").at(in.entry)) : std::nan(""));
          x.push_back(row);
        }
      const auto r = request.saltelli ? analysis::analyse_sensitivity(analysis::member_design(u, request.members), y) :
                                        analysis::rank_correlations(x, y);
      Json       inputs = Json::object();
      for (std::size_t i = 0; i < u.inputs.size(); ++i)
        inputs[u.inputs[i].entry] =
          r.method == analysis::SensitivityMethod::sobol_indices ?
            Json{{"first_order", estimate_json(r.inputs[i].first_order)}, {"total", estimate_json(r.inputs[i].total)}} :
            Json{{"rank_correlation", estimate_json(r.inputs[i].rank_correlation)}};
      return {{"method", analysis::method_name(r.method)},
              {"samples", r.samples},
              {"dropped", r.dropped},
              {"inputs", inputs}};
    }
  } // namespace

  Json
  ensemble_sensitivity(const analysis::UncertaintySettings &uncertainty,
                       const EnsembleRequest               &request,
                       const Json                          &statistics,
                       const std::vector<Json>             &members)
  {
    Json        figures = Json::object();
    std::string method;
    for (const auto &name : headline_figures(statistics))
      try
        {
          figures[name] = figure_sensitivity(uncertainty, request, name, members);
          method        = figures[name].at("method").get<std::string>();
        }
      catch (const InputError &e) // too few members that ran
        {
          figures[name] = {{"error", trim(e.message())}};
        }
    return {
      {"method", method.empty() ? Json() : Json(method)},
      {"method_definition",
       "sobol-indices: first-order (Saltelli 2010) and total (Jansen 1999) Sobol indices with percentile-bootstrap "
       "95 % intervals over the base rows; rank-correlation: Spearman's rank correlation of each input with the "
       "figure over the members that ran, 95 % interval from Fisher's z with standard error sqrt(1.06 / (n - 3))"},
      {"figures", figures}};
  }

  std::string
  sensitivity_table(const Json &sensitivity)
  {
    const auto number = [](const Json &v) {
      return v.is_number() ? format_number(json_number(v), 3) : std::string("-");
    };
    const auto estimate = [&number](const Json &e) {
      return number(e.at("value")) + " (95 % interval " + number(e.at("ci95_low")) + " ... " +
             number(e.at("ci95_high")) + ")";
    };
    std::string out =
      "sensitivities (" +
      (sensitivity.at("method").is_null() ? std::string("none") : sensitivity.at("method").get<std::string>()) + "):\n";
    for (auto f = sensitivity.at("figures").begin(); f != sensitivity.at("figures").end(); ++f)
      {
        if (!f.value().contains("inputs"))
          {
            out += "  " + f.key() + ": " + f.value().at("error").get<std::string>() + "\n";
            continue;
          }
        for (auto i = f.value().at("inputs").begin(); i != f.value().at("inputs").end(); ++i)
          out +=
            "  " + f.key() + " <- " + i.key() + ": " +
            (i.value().contains("rank_correlation") ?
               "rank correlation " + estimate(i.value().at("rank_correlation")) :
               "first order " + estimate(i.value().at("first_order")) + ", total " + estimate(i.value().at("total"))) +
            "\n";
      }
    return out;
  }

  std::map<std::string, std::vector<double>>
  decided_revolutions(const std::vector<Json> &members)
  {
    std::map<std::string, std::vector<double>> out;
    for (const auto &m : members)
      if (m.at("status").get<std::string>() == "ok" && m.contains("life"))
        for (auto it = m.at("life").at("criteria").begin(); it != m.at("life").at("criteria").end(); ++it)
          if (it.value().at("status").get<std::string>() == "decided")
            out[it.key()].push_back(json_number(it.value().at("revolutions")));
    return out;
  }
} // namespace wearlink::workflows
