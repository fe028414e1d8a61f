// SPDX-License-Identifier: LGPL-2.1-or-later
#include "workflows/ensemble/ensemble.h"

#include "analysis/ensemble_statistics.h"
#include "analysis/life_criteria.h"
#include "analysis/response_models.h"
#include "base/atomic_file.h"
#include "base/exceptions.h"
#include "base/interrupt.h"
#include "base/output_directory.h"
#include "base/text.h"
#include "base/timings.h"
#include "io/json_file.h"
#include "io/life_outputs.h"
#include "io/output_names.h"
#include "io/plot.h"
#include "io/uncertainty_plots.h"
#include "workflows/ensemble/uncertain_inputs.h"

#include <deal.II/base/mpi.h>

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace wearlink::workflows
{
  ParameterOverrides
  member_overrides(const io::Scene               &scene,
                   const ParameterOverrides      &base,
                   const EnsembleRequest         &request,
                   const unsigned int             k,
                   std::map<std::string, double> *shifts)
  {
    if (scene.drivers.empty())
      throw InputError("--ensemble perturbs the initial angle of the scene's angle drivers ('Joint <d>/Angle offset'), "
                       "but " +
                       scene.file + " has no angle driver.");
    const auto         z   = analysis::member_normals(request.seed, k, static_cast<unsigned int>(scene.drivers.size()));
    ParameterOverrides o   = base;
    auto              &prm = *scene.parameters;
    for (std::size_t d = 0; d < scene.drivers.size(); ++d)
      {
        const std::string name = scene.mechanism->get_constraints()[scene.drivers[d]]->name;
        prm.enter_subsection("Joint " + name);
        const double offset = prm.get_double("Angle offset");
        prm.leave_subsection();
        const double shift = request.perturbation * z[d];
        o.set("Joint " + name + "/Angle offset", offset + shift);
        if (shifts)
          (*shifts)[name] = shift;
      }
    return o;
  }

  std::map<std::string, double>
  summary_figures(const Json &summary)
  {
    std::map<std::string, double> f;
    const auto                    take = [&f](const Json &block, const std::string &key, const std::string &name) {
      if (block.contains(key) && block.at(key).is_number() && std::isfinite(json_number(block.at(key))))
        f[name] = json_number(block.at(key));
    };
    static const char *const joint_keys[] = {"wear_volume_pin_m3",
                                             "wear_volume_bushing_m3",
                                             "max_wear_depth_pin_m",
                                             "max_wear_depth_bushing_m",
                                             "envelope_wear_depth_pin_m",
                                             "envelope_wear_depth_bushing_m",
                                             "roughness_pin",
                                             "roughness_bushing",
                                             "mass_loss_pin_mg",
                                             "mass_loss_bushing_mg",
                                             "sliding_distance_m",
                                             "mean_normal_force_N",
                                             "max_normal_force_N",
                                             "fraction_in_contact"};
    if (summary.contains("clearance_joints"))
      for (auto it = summary.at("clearance_joints").begin(); it != summary.at("clearance_joints").end(); ++it)
        for (const char *key : joint_keys)
          take(it.value(), key, it.key() + "_" + key);
    if (summary.contains("bodies"))
      for (auto it = summary.at("bodies").begin(); it != summary.at("bodies").end(); ++it)
        for (const char *key : {"max_abs_ax_m_s2", "max_abs_ay_m_s2"}) // a slider's 1e-14 across its guide is no figure
          if (it.value().contains(key) && it.value().at(key).is_number() && json_number(it.value().at(key)) > 1e-6)
            take(it.value(), key, it.key() + "_" + key);
    if (summary.contains("response"))
      for (auto it = summary.at("response").begin(); it != summary.at("response").end(); ++it)
        if (it.key() != "cycles" && it.key() != "settling_cycles" && it.key() != "first_cycles_left_out")
          take(summary.at("response"), it.key(), "response_" + it.key());
    if (summary.contains("life"))
      {
        const Json &life = summary.at("life");
        take(life, "life_revolutions", "life_revolutions");
        for (auto it = life.at("criteria").begin(); it != life.at("criteria").end(); ++it)
          take(it.value(), "revolutions", "life_" + it.key() + "_revolutions");
      }
    return f;
  }

  namespace
  {
    constexpr const char *percentile_definition =
      "linear interpolation between the order statistics (Hyndman & Fan type 7, the default of R and NumPy): "
      "sorted x_1 … x_n, h = (n - 1) p, P = x_(floor(h)+1) + (h - floor(h)) (x_(floor(h)+2) - x_(floor(h)+1))";

    /** A finite number as JSON, else null. */
    Json
    number_or_null(const double v)
    {
      return std::isfinite(v) ? Json(v) : Json();
    }

    /** What the ensemble needs of a member's life block: per criterion status, revolutions, hours. */
    Json
    member_life(const Json &life)
    {
      Json criteria = Json::object();
      for (auto it = life.at("criteria").begin(); it != life.at("criteria").end(); ++it)
        {
          const Json &o = it.value();
          // A summary of an earlier version has no status: reached was then its decision.
          const std::string status =
            o.contains("status") ? o.at("status").get<std::string>() :
                                   (o.at("reached").get<bool>() ? std::string("decided") : std::string("not reached"));
          criteria[it.key()] = {{"status", status}, {"revolutions", o.at("revolutions")}, {"hours", o.at("hours")}};
          if (o.value("located_by", "") == "trend") // what the trend of the members' mean needs
            for (const char *key : {"located_by", "limit", "response_tolerance"})
              if (o.contains(key))
                criteria[it.key()][key] = o.at(key);
        }
      Json out = {{"criteria", criteria}, {"headline", life.value("first_criterion", Json())}};
      if (life.contains("response") && life.at("response").contains("revolutions"))
        out["response"] = {{"revolutions", life.at("response").at("revolutions")},
                           {"measures_m_s2", life.at("response").at("measures_m_s2")}};
      return out;
    }

    /** Mean, std, 95 % interval of the mean and P05 / P10 / P50 / P90 / P95 of @p values. */
    Json
    spread_of(const std::vector<double> &values)
    {
      const auto f = analysis::ensemble_figure(values);
      return {{"mean", number_or_null(f.mean)},
              {"std", number_or_null(f.std)},
              {"ci95_low", number_or_null(f.ci95_low)},
              {"ci95_high", number_or_null(f.ci95_high)},
              {"p05", number_or_null(analysis::percentile(values, 0.05))},
              {"p10", number_or_null(analysis::percentile(values, 0.1))},
              {"p50", number_or_null(analysis::percentile(values, 0.5))},
              {"p90", number_or_null(analysis::percentile(values, 0.9))},
              {"p95", number_or_null(analysis::percentile(values, 0.95))}};
    }

    /** One criterion over the members' life blocks @p lives: how many decided it, and the spread of their lives. */
    Json
    criterion_over_members(const std::string &name, const std::vector<Json> &lives)
    {
      std::vector<double> revolutions, hours;
      std::size_t         undecided = 0, not_reached = 0;
      for (const auto &l : lives)
        {
          const Json       &o      = l.at("criteria").at(name);
          const std::string status = o.at("status").get<std::string>();
          if (status == "decided")
            {
              revolutions.push_back(json_number(o.at("revolutions")));
              hours.push_back(json_number(o.at("hours")));
            }
          undecided += status == "undecided" ? 1 : 0;
          not_reached += status == "not reached" ? 1 : 0;
        }
      return {{"members_decided", revolutions.size()},
              {"members_undecided", undecided},
              {"members_not_reached", not_reached},
              {"revolutions", spread_of(revolutions)},
              {"hours", spread_of(hours)}};
    }

    /**
     * The response measures of @p lives averaged over the members at the revolutions they
     * all measured (a life run measures after each iteration; the last iterations differ
     * as each member approaches its own wear life): @p x the revolutions, @p y the means.
     * Empty if a member has no series or a non-finite measure there.
     */
    void
    mean_response(const std::vector<Json> &lives, std::vector<double> &x, std::vector<double> &y)
    {
      x.clear();
      y.clear();
      for (const auto &l : lives)
        if (!l.contains("response") || !l.at("response").contains("revolutions"))
          return;
      const auto &first = lives.front().at("response");
      for (std::size_t i = 0; i < first.at("revolutions").size(); ++i)
        {
          const double at  = json_number(first.at("revolutions")[i]);
          double       sum = 0;
          std::size_t  n   = 0;
          for (const auto &l : lives)
            {
              const auto &r = l.at("response");
              for (std::size_t k = 0; k < r.at("revolutions").size(); ++k)
                if (std::abs(json_number(r.at("revolutions")[k]) - at) <= 1e-9 * std::max(1.0, std::abs(at)) &&
                    r.at("measures_m_s2")[k].is_number())
                  {
                    sum += json_number(r.at("measures_m_s2")[k]);
                    ++n;
                    break;
                  }
            }
          if (n == lives.size())
            {
              x.push_back(at);
              y.push_back(sum / static_cast<double>(n));
            }
        }
    }

    /**
     * The trend criterion @p name decided on the members' mean response (mean_response):
     * the scatter of one member's measures falls by √members, so the ensemble can decide
     * a criterion its members cannot one by one. Decided as in a life run (the chosen
     * trend model, Life/Response tolerance), or first for certain: reached, its crossing's
     * whole 95 % interval before @p wear_p10, the smallest P10 of the wear criteria every
     * member decided. Null without a series.
     */
    Json
    trend_of_the_mean(const std::string &name, const std::vector<Json> &lives, const double wear_p10)
    {
      std::vector<double> x, y;
      mean_response(lives, x, y);
      const Json &spec = lives.front().at("criteria").at(name);
      if (x.size() < analysis::min_response_points || !spec.contains("response_tolerance"))
        return Json();
      const analysis::ResponseModels models(x, y, x.size());
      const double                   limit = json_number(spec.at("limit"));
      const auto t = analysis::trend_crossing(models, limit, x.back(), json_number(spec.at("response_tolerance")));
      const bool precise = t.status == analysis::CriterionStatus::decided;
      const bool first   = analysis::first_for_certain(t, wear_p10);
      const bool decided = precise || first;
      Json       o       = {{"measurements", x.size()},
                            {"trend_model", analysis::family_name(t.family)},
                            {"reached", t.reached},
                            {"decided", decided},
                            {"within_tolerance", precise},
                            {"revolutions", number_or_null(t.revolutions)},
                            {"interval_revolutions",
                 t.interval.bounded() ? Json::array({t.interval.low, t.interval.high}) : Json()},
                            {"rise_at_end_ci95_percent",
                 std::isfinite(t.rise_at_end.low) && std::isfinite(t.rise_at_end.high) ?
                               Json::array({t.rise_at_end.low, t.rise_at_end.high}) :
                               Json()}};
      o["reason"]        = precise ? std::string("decided on the trend of the members' mean response") :
                           first ? "reached on the trend of the members' mean response; its interval ends before the wear "
                                   "criteria's P10: it comes first, located less precisely than Life/Response tolerance" :
                                   t.reason;
      return o;
    }

    /**
     * A trend criterion that not every member decided, decided on the trend of the
     * members' mean response (trend_of_the_mean, added to its block in @p criteria). If
     * that trend puts it before @p best's P10 (the wear life of the ensemble; none: any),
     * it is the ensemble's life: @p out gets it and true is returned.
     */
    bool
    trend_life_of_the_mean(const std::vector<Json> &lives, const std::string &best, Json &criteria, Json &out)
    {
      const double wear_p10 = best.empty() ? std::numeric_limits<double>::infinity() :
                                             json_number(criteria.at(best).at("revolutions").at("p10"));
      std::string  life;
      for (auto it = criteria.begin(); it != criteria.end(); ++it)
        if (it.value().at("members_decided").get<std::size_t>() < lives.size() &&
            lives.front().at("criteria").at(it.key()).value("located_by", "") == "trend")
          {
            it.value()["trend_of_the_mean"] = trend_of_the_mean(it.key(), lives, wear_p10);
            const Json &t                   = it.value().at("trend_of_the_mean");
            if (!t.is_null() && t.at("decided").get<bool>() && json_number(t.at("revolutions")) < wear_p10)
              life = it.key();
          }
      out["criteria"] = criteria;
      if (life.empty())
        return false;
      const Json &c               = criteria.at(life);
      const Json &t               = c.at("trend_of_the_mean");
      out["criterion"]            = life;
      out["located_by"]           = "trend of the members' mean response";
      out["revolutions"]          = t.at("revolutions");
      out["interval_revolutions"] = t.at("interval_revolutions");
      out["within_tolerance"]     = t.at("within_tolerance");
      out["members_decided"]      = c.at("members_decided");
      out["reason"]               = life + ", decided on the trend of the members' mean response (" +
                      format_number(json_number(c.at("members_decided")), 6) + " of " + std::to_string(lives.size()) +
                      " members decided it one by one), comes before " +
                      (best.empty() ? std::string("any wear criterion") : best + "'s P10");
      return true;
    }
  } // namespace

  Json
  ensemble_life(const std::vector<Json> &members)
  {
    std::vector<Json> lives;
    for (const auto &m : members)
      if (m.at("status").get<std::string>() == "ok" && m.contains("life"))
        lives.push_back(m.at("life"));
    Json out                     = Json::object();
    out["percentile_definition"] = percentile_definition;
    out["members"]               = lives.size();
    Json criteria                = Json::object();
    if (!lives.empty())
      for (auto it = lives.front().at("criteria").begin(); it != lives.front().at("criteria").end(); ++it)
        criteria[it.key()] = criterion_over_members(it.key(), lives);
    // The life: of the criteria every member decided, the one with the smallest P10.
    std::string        best;
    std::ostringstream excluded;
    for (auto it = criteria.begin(); it != criteria.end(); ++it)
      {
        const std::size_t decided = it.value().at("members_decided").get<std::size_t>();
        if (decided < lives.size() || decided == 0)
          excluded << "; " << it.key() << " was decided by " << decided << " of " << lives.size()
                   << " members and is not a life of the ensemble";
        else if (best.empty() || json_number(it.value().at("revolutions").at("p10")) <
                                   json_number(criteria.at(best).at("revolutions").at("p10")))
          best = it.key();
      }
    if (trend_life_of_the_mean(lives, best, criteria, out))
      return out;
    out["criteria"]  = criteria;
    out["criterion"] = best.empty() ? Json() : Json(best);
    if (best.empty())
      {
        out["reason"] = "no criterion was decided by every member" + excluded.str();
        return out;
      }
    const Json &r                = criteria.at(best).at("revolutions");
    const Json &h                = criteria.at(best).at("hours");
    out["p10_revolutions"]       = r.at("p10");
    out["p10_hours"]             = h.at("p10");
    out["p50_revolutions"]       = r.at("p50");
    out["p90_revolutions"]       = r.at("p90");
    out["p50_hours"]             = h.at("p50");
    out["p90_hours"]             = h.at("p90");
    out["mean_revolutions"]      = r.at("mean");
    out["ci95_mean_revolutions"] = Json::array({r.at("ci95_low"), r.at("ci95_high")});
    out["members_decided"]       = criteria.at(best).at("members_decided");
    out["reason"]                = best + " has the smallest P10 of the criteria every member decided" + excluded.str();
    return out;
  }

  namespace
  {
    /** What one member produced (serialised to gather it on rank 0). */
    Json
    run_member(const EnsembleOptions &o, const MemberRun &run, const unsigned int k, const int rank)
    {
      const Stopwatch   wall;
      const std::string dir    = o.output_directory + "/" + member_directory_name(k, o.request.members);
      Json              m      = {{"index", k}, {"rank", rank}, {"directory", dir}};
      std::string       prefix = "member " + std::to_string(k) + ": ";
      try
        {
          io::Scene                     base = io::read_scene(o.scene_file, o.overrides);
          std::map<std::string, double> shifts;
          std::map<std::string, double> inputs;
          const auto                    mine  = with_uncertain_inputs(base,
                                                  member_overrides(base, o.overrides, o.request, k, &shifts),
                                                  o.request,
                                                  k,
                                                  shifts,
                                                  &inputs);
          io::Scene                     scene = io::read_scene(o.scene_file, mine);
          m["perturbation_rad"]               = shifts;
          if (!inputs.empty())
            m["inputs"] = inputs;
          Json summary;
          if (o.resume && std::filesystem::exists(dir + "/" + io::outputs::summary))
            summary = io::read_json_file(dir + "/" + io::outputs::summary);
          else
            summary = run(scene, dir, prefix, o.resume && std::filesystem::exists(dir + "/" + io::outputs::checkpoint));
          m["status"]  = "ok";
          m["figures"] = summary_figures(summary);
          if (summary.contains("life"))
            m["life"] = member_life(summary.at("life"));
        }
      catch (const Interrupted &) // SIGINT/SIGTERM stops the ensemble, not this member
        {
          throw;
        }
      catch (const NumericalError &e)
        {
          m["status"]  = "failed";
          m["message"] = trim(e.message());
        }
      m["wall_time_s"] = wall.seconds();
      return m;
    }

    /** Members round-robin over the ranks, gathered on rank 0 in member order. */
    std::vector<Json>
    run_members(const EnsembleOptions &o, const MemberRun &run, const MPI_Comm comm)
    {
      const unsigned int rank  = dealii::Utilities::MPI::this_mpi_process(comm);
      const unsigned int n     = dealii::Utilities::MPI::n_mpi_processes(comm);
      Json               mine  = Json::array();
      double             spent = 0;
      unsigned int       done = 0, on_this_rank = 0;
      for (unsigned int k = rank; k < o.request.members; k += n)
        ++on_this_rank;
      for (unsigned int k = rank; k < o.request.members; k += n)
        {
          mine.push_back(run_member(o, run, k, static_cast<int>(rank)));
          spent += json_number(mine.back().at("wall_time_s"));
          ++done;
          if (o.progress)
            std::cerr << "[wearlink] ensemble member " << k << " (rank " << rank
                      << "): " << mine.back().at("status").get<std::string>() << " in " << std::setprecision(3)
                      << json_number(mine.back().at("wall_time_s")) << " s; " << on_this_rank - done
                      << " more on this rank, about " << spent / done * (on_this_rank - done) << " s left\n";
        }
      const auto        gathered = dealii::Utilities::MPI::gather(comm, mine.dump(-1), 0);
      std::vector<Json> members(o.request.members);
      for (const auto &text : gathered)
        {
          const Json j = Json::parse(text);
          for (std::size_t i = 0; i < j.size(); ++i)
            members[static_cast<std::size_t>(json_number(j[i].at("index")))] = j[i];
        }
      return rank == 0 ? members : std::vector<Json>();
    }

    /** Per figure, the statistics over the members that ran (analysis/ensemble_statistics.h). */
    Json
    statistics_of(const std::vector<Json> &members)
    {
      std::vector<std::map<std::string, double>> figures;
      for (const auto &m : members)
        if (m.at("status").get<std::string>() == "ok")
          figures.push_back(m.at("figures").get<std::map<std::string, double>>());
      Json out = Json::object();
      for (const auto &[name, f] : analysis::ensemble_figures(figures))
        {
          std::vector<double> values;
          for (const auto &m : figures)
            if (m.count(name))
              values.push_back(m.at(name));
          out[name] = {{"mean", f.mean},
                       {"std", f.std},
                       {"ci95_low", f.ci95_low},
                       {"ci95_high", f.ci95_high},
                       {"p05", number_or_null(analysis::percentile(values, 0.05))},
                       {"p50", number_or_null(analysis::percentile(values, 0.5))},
                       {"p95", number_or_null(analysis::percentile(values, 0.95))},
                       {"members", f.members}};
        }
      return out;
    }

    /** ensemble.csv: one row per member, its status, perturbations and figures. */
    std::string
    members_csv(const Json &summary)
    {
      const Json        &members = summary.at("members");
      const Json        &stats   = summary.at("ensemble");
      std::ostringstream os;
      os << "member,status,rank,wall_time_s";
      std::vector<std::string> drivers;
      if (!members.empty() && members[0].contains("perturbation_rad"))
        for (auto it = members[0].at("perturbation_rad").begin(); it != members[0].at("perturbation_rad").end(); ++it)
          drivers.push_back(it.key());
      for (const auto &d : drivers)
        os << ",perturbation_" << d << "_rad";
      std::vector<std::string> inputs; // the uncertain inputs' entry paths, in the scene's order
      if (summary.contains("uncertainty"))
        for (const auto &in : summary.at("uncertainty").at("inputs"))
          inputs.push_back(in.at("entry").get<std::string>());
      for (const auto &e : inputs)
        os << ',' << e;
      for (auto it = stats.begin(); it != stats.end(); ++it)
        os << ',' << it.key();
      os << '\n' << std::setprecision(17);
      for (const auto &m : members)
        {
          os << json_number(m.at("index")) << ',' << m.at("status").get<std::string>() << ','
             << json_number(m.at("rank")) << ',' << json_number(m.at("wall_time_s"));
          for (const auto &d : drivers)
            os << ',' << (m.contains("perturbation_rad") ? json_number(m.at("perturbation_rad").at(d)) : NAN);
          for (const auto &e : inputs)
            os << ',' << (m.contains("inputs") ? json_number(m.at("inputs").at(e)) : NAN);
          for (auto it = stats.begin(); it != stats.end(); ++it)
            os << ','
               << (m.contains("figures") && m.at("figures").contains(it.key()) ?
                     json_number(m.at("figures").at(it.key())) :
                     NAN);
          os << '\n';
        }
      return os.str();
    }

    /**
     * ensemble.png: per figure, each member's deviation from the mean [%] (points) and
     * the 95 % interval of the mean (a bar).
     */
    void
    plot_spread(const Json &summary, const std::string &path)
    {
      const Json    &stats = summary.at("ensemble");
      io::PlotSpec   spec;
      io::PlotSeries points{"members", {}, {}, io::points("black", 1.2)};
      io::PlotSeries band{"95 % interval of the mean", {}, {}, io::line("#8080c0", 6)};
      int            i = 0;
      for (auto it = stats.begin(); it != stats.end(); ++it, ++i)
        {
          const double mean = json_number(it.value().at("mean"));
          spec.categories.push_back(it.key());
          if (!(std::abs(mean) > 0))
            continue;
          for (const auto &m : summary.at("members"))
            if (m.contains("figures") && m.at("figures").contains(it.key()))
              {
                points.x.push_back(i);
                points.y.push_back(100 * (json_number(m.at("figures").at(it.key())) / mean - 1));
              }
          const Json &lo = it.value().at("ci95_low"), &hi = it.value().at("ci95_high");
          if (lo.is_number() && hi.is_number())
            {
              band.x.insert(band.x.end(), {double(i), double(i), NAN});
              band.y.insert(band.y.end(),
                            {100 * (json_number(lo) / mean - 1), 100 * (json_number(hi) / mean - 1), NAN});
            }
        }
      spec.title =
        "Ensemble of " + std::to_string(summary.at("members").size()) + " members: each figure relative to its mean";
      spec.x_label = "";
      spec.y_label = "member / mean − 1 [%]";
      spec.series  = {band, points};
      spec.x_range = io::Range{-0.5, i - 0.5};
      spec.width   = 1400;
      spec.height  = 800;
      io::plot_png(spec, path);
    }

    /**
     * The ensemble's life.png: the band of the members' criteria against revolutions
     * (their life_history.csv), the P10 … P90 of their decided crossings and the interval
     * of a trend criterion's crossing on the members' mean.
     */
    void
    plot_life_band(const Json &summary, const std::vector<analysis::CriterionSpec> &criteria, const std::string &path)
    {
      std::vector<analysis::LifeHistory> histories;
      for (const auto &m : summary.at("members"))
        if (m.at("status").get<std::string>() == "ok")
          histories.push_back(
            io::read_life_history(m.at("directory").get<std::string>() + "/" + io::outputs::life_history, criteria));
      std::vector<io::CrossingSpread>    spreads;
      std::vector<io::MeanTrendCrossing> trends;
      const Json                        &life = summary.at("ensemble_life").at("criteria");
      for (auto it = life.begin(); it != life.end(); ++it)
        {
          const Json &r = it.value().at("revolutions");
          if (r.at("p10").is_number())
            spreads.push_back({it.key(), json_number(r.at("p10")), json_number(r.at("p50")), json_number(r.at("p90"))});
          const Json t = it.value().value("trend_of_the_mean", Json());
          if (!t.is_null() && t.at("revolutions").is_number() && t.at("interval_revolutions").is_array())
            trends.push_back({it.key(),
                              json_number(t.at("revolutions")),
                              json_number(t.at("interval_revolutions")[0]),
                              json_number(t.at("interval_revolutions")[1])});
        }
      io::plot_life_ensemble(path,
                             histories,
                             spreads,
                             trends,
                             "Life criteria of " + std::to_string(histories.size()) +
                               " members: smallest … largest (band) and median against revolutions");
    }
  } // namespace

  namespace
  {
    /** DIR/summary.json, ensemble.csv and the plots of the members that ran (rank 0). */
    void
    write_ensemble_files(const EnsembleOptions                      &o,
                         const Json                                 &summary,
                         const std::vector<Json>                    &members,
                         const std::vector<analysis::CriterionSpec> &criteria)
    {
      const auto ok = static_cast<std::size_t>(json_number(summary.at("members_ok")));
      make_output_directory(o.output_directory);
      write_file_atomically(o.output_directory + "/" + io::outputs::summary, summary.dump(2) + "\n");
      write_file_atomically(o.output_directory + "/" + io::outputs::ensemble_table, members_csv(summary));
      if (ok == 0)
        return;
      plot_spread(summary, o.output_directory + "/" + io::outputs::ensemble_plot);
      if (o.command == "life")
        {
          plot_life_band(summary, criteria, o.output_directory + "/" + io::outputs::life_plot);
          io::plot_life_cdf(decided_revolutions(members),
                            o.output_directory + "/life_cdf.png",
                            "Life criteria of " + std::to_string(ok) + " members: empirical CDF of the revolutions");
        }
      if (summary.contains("sensitivity"))
        io::plot_sensitivity(summary.at("sensitivity"), o.output_directory + "/sensitivity.png");
    }
  } // namespace

  Json
  run_ensemble(const EnsembleOptions &o, const MemberRun &run, bool &all_failed)
  {
    const MPI_Comm     comm    = MPI_COMM_WORLD;
    const unsigned int rank    = dealii::Utilities::MPI::this_mpi_process(comm);
    const unsigned int n_ranks = dealii::Utilities::MPI::n_mpi_processes(comm);
    const Stopwatch    wall;
    if (o.request.members < 2)
      throw InputError("--ensemble " + std::to_string(o.request.members) +
                       ": an ensemble needs at least 2 members (2 … 1000) for a spread.");
    std::vector<analysis::CriterionSpec> criteria; // of a life ensemble, for its life.png
    analysis::UncertaintySettings        uncertainty;
    Json                                 uncertainty_block;
    {
      io::Scene base = io::read_scene(o.scene_file, o.overrides);
      member_overrides(base, o.overrides, o.request, 0); // the scene can be perturbed (same on every rank)
      check_uncertain_members(o, base);                  // every member's inputs are accepted
      if (o.command == "life")
        criteria = analysis::active_criteria(base.life);
      uncertainty       = base.uncertainty;
      uncertainty_block = uncertainty_summary(base, o.request);
    }
    if (rank == 0 && o.progress)
      std::cerr << "[wearlink] ensemble of " << o.request.members << " members (seed " << o.request.seed
                << ", perturbation " << o.request.perturbation << " rad) on " << n_ranks << " MPI rank"
                << (n_ranks == 1 ? "" : "s") << "\n";
    const auto members = run_members(o, run, comm);
    all_failed         = false;
    if (rank != 0)
      return Json();
    Json summary                = Json::object();
    summary["scene"]            = o.scene_file;
    summary["command"]          = o.command;
    summary["overrides"]        = o.overrides.settings();
    summary["members_count"]    = o.request.members;
    summary["seed"]             = o.request.seed;
    summary["perturbation_rad"] = o.request.perturbation;
    summary["perturbation"] = "each angle driver's initial angle ('Joint <d>/Angle offset') + perturbation_rad × z, z "
                              "standard normal from the seed and the member index";
    summary["mpi_ranks"]    = n_ranks;
    summary["wall_time_s"]  = wall.seconds();
    summary["members"]      = members;
    summary["ensemble"]     = statistics_of(members);
    if (o.command == "life")
      summary["ensemble_life"] = ensemble_life(members);
    if (!uncertainty.inputs.empty())
      {
        summary["uncertainty"] = uncertainty_block;
        summary["sensitivity"] = ensemble_sensitivity(uncertainty, o.request, summary["ensemble"], members);
      }
    std::size_t ok = 0;
    for (const auto &m : members)
      ok += m.at("status").get<std::string>() == "ok" ? 1 : 0;
    summary["members_ok"] = ok;
    all_failed            = ok == 0;
    write_ensemble_files(o, summary, members, criteria);
    return summary;
  }

  std::string
  ensemble_table(const Json &summary)
  {
    std::ostringstream os;
    os << "figure                                      mean           std            95 % interval of the mean        "
          "members\n";
    const auto number = [](const Json &v) {
      return v.is_number() ? format_number(json_number(v), 5) : std::string("–");
    };
    for (auto it = summary.at("ensemble").begin(); it != summary.at("ensemble").end(); ++it)
      {
        const Json &f = it.value();
        os << std::left << std::setw(44) << it.key() << std::setw(15) << number(f.at("mean")) << std::setw(15)
           << number(f.at("std")) << std::setw(33) << (number(f.at("ci95_low")) + " … " + number(f.at("ci95_high")))
           << json_number(f.at("members")) << "\n";
      }
    if (summary.contains("ensemble_life"))
      os << ensemble_life_table(summary.at("ensemble_life"));
    if (summary.contains("sensitivity"))
      os << sensitivity_table(summary.at("sensitivity"));
    os << json_number(summary.at("members_ok")) << " of " << json_number(summary.at("members_count"))
       << " members ran; seed " << json_number(summary.at("seed")) << ", " << json_number(summary.at("mpi_ranks"))
       << " MPI rank(s), " << std::setprecision(4) << json_number(summary.at("wall_time_s")) << " s wall\n";
    return os.str();
  }

  std::string
  ensemble_life_table(const Json &life)
  {
    const auto number = [](const Json &v) {
      return v.is_number() ? format_number(json_number(v), 6) : std::string("-");
    };
    std::ostringstream os;
    os << "life criterion     decided   mean [rev]   std [rev]    95 % interval of the mean  P10 [rev]    P50 [rev]    "
          "P90 [rev]    P10 [h]\n";
    const auto members = json_number(life.at("members"));
    for (auto it = life.at("criteria").begin(); it != life.at("criteria").end(); ++it)
      {
        const Json &r = it.value().at("revolutions");
        os << std::left << std::setw(19) << it.key() << std::setw(10)
           << (format_number(json_number(it.value().at("members_decided")), 6) + " of " + format_number(members, 6))
           << std::setw(13) << number(r.at("mean")) << std::setw(13) << number(r.at("std")) << std::setw(27)
           << (number(r.at("ci95_low")) + " ... " + number(r.at("ci95_high"))) << std::setw(13) << number(r.at("p10"))
           << std::setw(13) << number(r.at("p50")) << std::setw(13) << number(r.at("p90"))
           << number(it.value().at("hours").at("p10")) << "\n";
      }
    for (auto it = life.at("criteria").begin(); it != life.at("criteria").end(); ++it)
      if (it.value().contains("trend_of_the_mean") && !it.value().at("trend_of_the_mean").is_null())
        {
          const Json &t = it.value().at("trend_of_the_mean");
          const Json &i = t.at("interval_revolutions");
          os << it.key() << " on the members' mean response (" << t.at("trend_model").get<std::string>() << ", "
             << number(t.at("measurements"))
             << " measurements): " << (t.at("decided").get<bool>() ? "decided" : "undecided") << ", crossing "
             << number(t.at("revolutions")) << " rev"
             << (i.is_null() ? std::string() : " (95 % " + number(i[0]) + " ... " + number(i[1]) + ")")
             << (t.at("decided").get<bool>() ? std::string() : " - " + t.at("reason").get<std::string>()) << "\n";
        }
    if (life.at("criterion").is_null())
      os << "ensemble life: none - " << life.at("reason").get<std::string>() << "\n";
    else if (life.contains("located_by"))
      {
        const Json &i = life.at("interval_revolutions");
        os << "ensemble life: " << life.at("criterion").get<std::string>() << ", " << number(life.at("revolutions"))
           << " rev" << (i.is_null() ? std::string() : " (95 % " + number(i[0]) + " ... " + number(i[1]) + ")") << " - "
           << life.at("reason").get<std::string>() << "\n";
      }
    else
      os << "ensemble life: " << life.at("criterion").get<std::string>() << ", P10 "
         << number(life.at("p10_revolutions")) << " rev (" << number(life.at("p10_hours")) << " h); P50 "
         << number(life.at("p50_revolutions")) << ", P90 " << number(life.at("p90_revolutions")) << " rev; mean "
         << number(life.at("mean_revolutions")) << " rev (95 % interval of the mean "
         << number(life.at("ci95_mean_revolutions")[0]) << " ... " << number(life.at("ci95_mean_revolutions")[1])
         << ") - " << life.at("reason").get<std::string>() << "\n";
    os << "percentiles: " << life.at("percentile_definition").get<std::string>() << "\n";
    return os.str();
  }
} // namespace wearlink::workflows
