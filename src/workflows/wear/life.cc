// SPDX-License-Identifier: LGPL-2.1-or-later
#include "workflows/wear/life.h"

#include "analysis/cycle_peaks.h"
#include "base/exceptions.h"
#include "base/numbers.h"
#include "base/text.h"
#include "io/life_outputs.h"
#include "io/output_names.h"
#include "io/scene_periods.h"
#include "io/wear_outputs.h"
#include "workflows/run/run.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>

namespace wearlink::workflows
{
  namespace
  {
    using numbers::nan;

    /** Index of the Life response body (Life/Response body, else Wear/Response body). */
    int
    life_response_body(const io::Scene &scene)
    {
      const auto &bodies = scene.mechanism->get_bodies();
      for (std::size_t i = 0; i < bodies.size(); ++i)
        if (!scene.life.response_body.empty() && bodies[i].name == scene.life.response_body)
          return static_cast<int>(i);
      return io::response_body(scene);
    }

    /**
     * One life run: the criteria and their history, and what it adds to the wear run's
     * phases (see the header).
     */
    class LifeRun
    {
    public:
      LifeRun(io::Scene &scene, const LifeRunOptions &options);

      /** The options of the wear run under this life. */
      WearRunOptions
      wear_options() const;

      /** The largest factor of the coming iteration (wear::WearLoop::set_factor_limit). */
      double
      factor_limit(const wear::StepPreview &p) const;

      /** The row of the iteration just done, before its commit. */
      void
      record(const wear::WearLoop &loop);

      /** True when the run is to end before the next iteration (then with its warnings). */
      bool
      stop(const wear::WearLoop &loop);

      /** summary.json's `life` block. */
      Json
      block() const;

      analysis::LifeHistory history;
      ValidityWarnings      response_warnings; ///< of the response runs

    private:
      bool
      done(const wear::WearLoop &loop) const;
      void
      warn_if_undecided_may_come_first();
      bool
      reached(std::size_t c) const;
      analysis::Crossing
      crossing(std::size_t c) const;
      analysis::ResponseModels
      models() const;
      analysis::TrendCrossing
      trend_state(std::size_t c) const;
      double
      earliest_wear_life() const;
      bool
      cannot_come_first(std::size_t c) const;
      bool
      first_for_certain(std::size_t c) const;
      bool
      settled(std::size_t c) const;
      double
      measure_response();
      /** One line: each criterion's value as a percentage of its limit. */
      std::string
      progress_line() const;
      Json
      wear_block(std::size_t c, analysis::CriterionOutcome &outcome) const;
      Json
      trend_block(std::size_t c, analysis::CriterionOutcome &outcome) const;
      Json
      headline(const std::vector<analysis::CriterionOutcome> &outcomes, const Json &criteria) const;

      io::Scene                            &scene;
      const LifeRunOptions                 &options;
      std::vector<analysis::JointDensities> densities;
      const double                          period;
      const int                             body;
      double                                revolutions_run = 0;
      unsigned int                          iterations_run  = 0;
    };

    LifeRun::LifeRun(io::Scene &scene, const LifeRunOptions &options)
      : scene(scene)
      , options(options)
      , period(io::cycle_period(scene))
      , body(life_response_body(scene))
    {
      history.criteria = analysis::active_criteria(scene.life);
      for (const auto &w : scene.wear)
        {
          // A slice's mass adds to its joint's (analysis::JointDensities).
          const std::string whole = io::whole_joint(scene, w->joint);
          densities.push_back(
            {w->archard.pin_density, w->archard.bushing_density, whole == w->joint ? std::string() : whole});
        }
      const std::string dir = options.output_directory;
      if (options.resume)
        {
          const auto state = wear::WearState::read(dir + "/" + io::outputs::checkpoint);
          history          = io::read_life_history(dir + "/" + io::outputs::life_history, history.criteria);
          history.truncate(state.iterations_done);
          revolutions_run = state.revolutions;
          iterations_run  = state.iterations_done;
          return;
        }
      const auto n = history.criteria.size();
      history.iterations.push_back(0);
      history.revolutions.push_back(0);
      history.factors.push_back(0);
      history.values.push_back(std::vector<double>(n, 0.0));
      history.joints.push_back(std::vector<std::string>(n, ""));
      const bool response = scene.life.limit(analysis::Criterion::response_rise) > 0;
      history.response.push_back(response ? measure_response() : nan);
      if (response && !(history.response[0] > 0))
        throw NumericalError("The response measure of " + scene.file + " with the fresh profiles is " +
                             format_number(history.response[0]) +
                             " m/s² (the body does not accelerate): a rise of it cannot be a criterion. Choose "
                             "another Life/Response body or another criterion.");
    }

    WearRunOptions
    LifeRun::wear_options() const
    {
      WearRunOptions w;
      w.output_directory = options.output_directory;
      w.resume           = options.resume;
      w.progress         = options.progress;
      w.progress_prefix  = options.progress_prefix;
      return w;
    }

    /**
     * The response measure with the joints' current profiles: from the initial
     * assembly, one settling cycle, then the mean of Response cycles per-cycle peaks.
     */
    double
    LifeRun::measure_response()
    {
      for (auto *j : scene.clearance_joints)
        j->set_mode(false, 0);
      analysis::CyclePeakRecorder peaks(scene.mechanism->n_coordinates(), body, period, 1);
      RunOptions                  ro;
      ro.end_time  = scene.start_time + (1 + scene.life.response_cycles) * period;
      ro.observers = {&peaks};
      ro.analyses  = false;
      ro.warnings  = &response_warnings;
      integrate_scene(scene, ro);
      return peaks.mean_of_whole_cycles();
    }

    /**
     * The largest factor of the coming iteration: each wear criterion not yet reached
     * lands on its crossing within the tolerance (analysis::approach_factor), and the run
     * stays within Life/Maximum revolutions. A trend criterion does not limit it: its
     * crossing is its fitted model's, located by the statistics of all measurements, not by
     * an iteration's end.
     */
    double
    LifeRun::factor_limit(const wear::StepPreview &p) const
    {
      double limit = (scene.life.max_revolutions - p.revolutions) / p.cycles;
      for (std::size_t c = 0; c < history.criteria.size(); ++c)
        {
          const auto &spec = history.criteria[c];
          if (analysis::is_trend(spec) || reached(c))
            continue;
          const double f_reach = analysis::factor_to_reach(spec, p, densities, p.factor);
          limit = std::min(limit, analysis::approach_factor(f_reach, p.cycles, p.revolutions, scene.life.tolerance));
        }
      return limit;
    }

    /** The row of the iteration just done (before its checkpoint), and life_history.csv. */
    void
    LifeRun::record(const wear::WearLoop &loop)
    {
      const auto &st = loop.state();
      history.truncate(st.iterations_done - 1); // rows a killed run wrote past its checkpoint
      const bool response = scene.life.limit(analysis::Criterion::response_rise) > 0;
      history.iterations.push_back(st.iterations_done);
      history.revolutions.push_back(st.revolutions);
      history.factors.push_back(st.factors.back());
      history.response.push_back(response ? measure_response() : nan);
      std::vector<double>      values;
      std::vector<std::string> joints;
      for (const auto &c : history.criteria)
        if (c.kind == analysis::Criterion::response_rise)
          {
            const auto trend = models();
            values.push_back(trend.model(trend.chosen()).rise(st.revolutions));
            joints.push_back("");
          }
        else
          {
            const auto v = analysis::wear_criterion_value(c, st, densities);
            values.push_back(v.value);
            joints.push_back(v.joint);
          }
      history.values.push_back(values);
      history.joints.push_back(joints);
      revolutions_run = st.revolutions;
      iterations_run  = st.iterations_done;
      if (!options.output_directory.empty())
        io::write_life_history(options.output_directory + "/" + io::outputs::life_history, history);
      if (options.progress || options.on_progress)
        {
          const auto line = progress_line();
          if (options.progress)
            std::cerr << "[wearlink] " + line + "\n";
          if (options.on_progress)
            {
              double fraction = 0;
              for (std::size_t c = 0; c < history.criteria.size(); ++c)
                fraction = std::max(fraction, history.values.back()[c] / history.criteria[c].limit);
              options.on_progress(std::clamp(fraction, 0.0, 1.0), line);
            }
        }
    }

    /** The first crossing of the wear criterion @p c. */
    analysis::Crossing
    LifeRun::crossing(const std::size_t c) const
    {
      return analysis::first_crossing(history.revolutions, history.column(c), history.criteria[c].limit);
    }

    /** The models of the response measures so far. */
    analysis::ResponseModels
    LifeRun::models() const
    {
      return {history.revolutions, history.response, history.rows()};
    }

    /** Where the trend criterion @p c stands on every measurement so far (on the chosen model). */
    analysis::TrendCrossing
    LifeRun::trend_state(const std::size_t c) const
    {
      return analysis::trend_crossing(models(),
                                      history.criteria[c].limit,
                                      history.revolutions.back(),
                                      scene.life.response_tolerance);
    }

    bool
    LifeRun::reached(const std::size_t c) const
    {
      return analysis::is_trend(history.criteria[c]) ? trend_state(c).reached : crossing(c).reached;
    }

    /**
     * The fewest revolutions to a wear criterion if every wear criterion is reached (the
     * earliest decided life the trend criteria compete with), else NaN.
     */
    double
    LifeRun::earliest_wear_life() const
    {
      double earliest = std::numeric_limits<double>::infinity();
      for (std::size_t c = 0; c < history.criteria.size(); ++c)
        if (!analysis::is_trend(history.criteria[c]))
          {
            const auto x = crossing(c);
            if (!x.reached)
              return nan;
            earliest = std::min(earliest, x.revolutions);
          }
      return std::isfinite(earliest) ? earliest : nan;
    }

    /**
     * True if the trend criterion @p c can no longer be the life: every wear criterion is
     * reached and the upper 95 % bound of its rise at the earliest of them is below its
     * limit (its crossing, if any, comes later).
     */
    bool
    LifeRun::cannot_come_first(const std::size_t c) const
    {
      const double life = earliest_wear_life();
      if (!std::isfinite(life))
        return false;
      const auto trend = models();
      return trend.points() >= analysis::min_response_points &&
             trend.excess_band(trend.chosen(), life, history.criteria[c].limit).high < 0;
    }

    /**
     * True if the trend criterion @p c, reached but located less precisely than
     * Life/Response tolerance, is still certainly the first criterion reached: the upper
     * end of its crossing's 95 % interval comes before every wear criterion reached in
     * the run (those not reached come after its end). Then it is the life, with that
     * interval: the headline and the criteria's plot tell the same story.
     */
    bool
    LifeRun::first_for_certain(const std::size_t c) const
    {
      double wear_life = std::numeric_limits<double>::infinity();
      for (std::size_t w = 0; w < history.criteria.size(); ++w)
        if (!analysis::is_trend(history.criteria[w]) && crossing(w).reached)
          wear_life = std::min(wear_life, crossing(w).revolutions);
      return analysis::first_for_certain(trend_state(c), wear_life);
    }

    /**
     * A wear criterion is settled when reached. A trend criterion is settled when decided,
     * when it cannot come first, or when every wear criterion is reached: measurements past
     * the earliest wear life only narrow the interval of its model's crossing and cost
     * whole iterations, so a trend still undecided there is reported as undecided
     * (with a warning if its interval begins before the wear life).
     */
    bool
    LifeRun::settled(const std::size_t c) const
    {
      if (!analysis::is_trend(history.criteria[c]))
        return crossing(c).reached;
      return trend_state(c).status == analysis::CriterionStatus::decided || std::isfinite(earliest_wear_life()) ||
             cannot_come_first(c);
    }

    /** The run ends when every criterion is settled, or at Life/Maximum revolutions. */
    bool
    LifeRun::done(const wear::WearLoop &loop) const
    {
      if (loop.state().revolutions >= scene.life.max_revolutions * (1 - 1e-12))
        return true;
      for (std::size_t c = 0; c < history.criteria.size(); ++c)
        if (!settled(c))
          return false;
      return true;
    }

    /** done(), and the life's warnings once it is. */
    bool
    LifeRun::stop(const wear::WearLoop &loop)
    {
      if (!done(loop))
        return false;
      warn_if_undecided_may_come_first();
      return true;
    }

    /**
     * A validity warning for each trend criterion left undecided whose 95 % interval of
     * the crossing begins before the earliest wear life: the life may be shorter than the
     * headline says.
     */
    void
    LifeRun::warn_if_undecided_may_come_first()
    {
      const double life = earliest_wear_life();
      if (!std::isfinite(life))
        return;
      for (std::size_t c = 0; c < history.criteria.size(); ++c)
        {
          if (!analysis::is_trend(history.criteria[c]) || cannot_come_first(c))
            continue;
          const auto x = trend_state(c);
          if (x.status == analysis::CriterionStatus::decided)
            continue;
          if (first_for_certain(c))
            {
              response_warnings.check({"life: the width of " + history.criteria[c].name + "'s 95 % crossing interval",
                                       100 * (x.interval.high - x.interval.low) / x.revolutions,
                                       100 * scene.life.response_tolerance,
                                       "% of the crossing",
                                       "Life/Response tolerance",
                                       history.criteria[c].name +
                                         " is reached and comes first for certain (its interval ends before the "
                                         "wear life), so it is the life, but it is located only within " +
                                         format_number(std::max(x.interval.low, 0.0), 6) + " … " +
                                         format_number(x.interval.high, 6) +
                                         " revolutions; narrow it with more Life/Response cycles"});
              continue;
            }
          const double low = std::isfinite(x.interval.low) ? std::max(x.interval.low, 0.0) : 0.0;
          response_warnings.check(
            {"life: " + history.criteria[c].name + " (undecided) against the wear life",
             life,
             low,
             "rev",
             "the low end of the 95 % interval of " + history.criteria[c].name + "'s crossing",
             "the wear life exceeds the revolutions from which the undecided " + history.criteria[c].name +
               " may already have crossed its limit, so the life may be shorter than the headline; decide it with "
               "more Life/Response cycles or a wider Life/Response tolerance"});
        }
    }

    /** One line: each criterion's value as a percentage of its limit. */
    std::string
    LifeRun::progress_line() const
    {
      std::ostringstream os;
      os << options.progress_prefix << "life after " << std::setprecision(6) << history.revolutions.back() << " rev:";
      for (std::size_t c = 0; c < history.criteria.size(); ++c)
        {
          const auto &spec = history.criteria[c];
          os << "  " << spec.name << ' ' << std::setprecision(3) << 100 * history.values.back()[c] / spec.limit
             << " % of " << spec.limit << ' ' << spec.unit;
          if (!history.joints.back()[c].empty())
            os << " (" << history.joints.back()[c] << ')';
          if (analysis::is_trend(spec))
            os << " (" << analysis::status_name(trend_state(c).status) << ')';
          else if (reached(c))
            os << " reached";
        }
      return os.str();
    }

    /** The entries every criterion's block has. */
    Json
    common_block(const analysis::CriterionSpec &spec, const double value_at_end)
    {
      Json o            = Json::object();
      o["entry"]        = "Life/" + spec.entry;
      o["limit"]        = spec.limit;
      o["unit"]         = spec.unit;
      o["value_at_end"] = value_at_end;
      return o;
    }

    /** A pair of revolutions as JSON (null if either is not finite). */
    Json
    pair_or_null(const double low, const double high)
    {
      return std::isfinite(low) && std::isfinite(high) ? Json::array({low, high}) : Json();
    }

    /** A model's change points as JSON: none for a line, a step's gap, a ramp's start and end [rev]. */
    Json
    change_points(const analysis::TrendModel &m)
    {
      if (m.family == analysis::TrendFamily::line)
        return Json();
      return Json::array({m.tau1, m.tau2});
    }

    /** @p v with each non-finite value as null (JSON has no NaN). */
    Json
    finite_or_null(const std::vector<double> &v)
    {
      Json a = Json::array();
      for (const double x : v)
        a.push_back(std::isfinite(x) ? Json(x) : Json());
      return a;
    }

    /**
     * Each fitted model of the response measures: its parameters, BIC and weight, and where
     * the criterion of limit @p limit [%] stands on it after @p revolutions_run (the chosen
     * one decides; the others are reported for comparison).
     */
    Json
    models_block(const analysis::ResponseModels &models,
                 const double                    limit,
                 const double                    revolutions_run,
                 const double                    tolerance)
    {
      Json       out  = Json::object();
      const auto best = models.model(models.chosen()).bic;
      for (const auto family : {analysis::TrendFamily::line, analysis::TrendFamily::step, analysis::TrendFamily::ramp})
        {
          if (!models.has(family))
            continue;
          const auto &m = models.model(family);
          const auto  x = analysis::trend_crossing(models, family, limit, revolutions_run, tolerance);
          Json        o = {{"parameters", m.parameters},
                           {"bic", m.bic},
                           {"delta_bic", m.bic - best},
                           {"weight", models.weight(family)},
                           {"fresh_m_s2", m.fit.a},
                           {"change_points_revolutions", change_points(m)},
                           {"residual_std_m_s2", models.residual_std(family)},
                           {"rise_at_end_percent", m.rise(revolutions_run)},
                           {"rise_at_end_ci95_percent", pair_or_null(x.rise_at_end.low, x.rise_at_end.high)},
                           {"crossing_revolutions", std::isfinite(x.revolutions) ? Json(x.revolutions) : Json()},
                           {"interval_revolutions", pair_or_null(x.interval.low, x.interval.high)},
                           {"reached", x.reached},
                           {"status", analysis::status_name(x.status)}};
          if (family == analysis::TrendFamily::step)
            o["jump_m_s2"] = m.fit.beta;
          else
            o["slope_m_s2_per_1000_rev"] = 1000 * m.fit.beta;
          if (family == analysis::TrendFamily::ramp)
            o["plateau_m_s2"] = m.value(m.tau2);
          out[analysis::family_name(family)] = o;
        }
      return out;
    }

    /** The block of the wear criterion @p c: decided when reached, with its bracket. */
    Json
    LifeRun::wear_block(const std::size_t c, analysis::CriterionOutcome &outcome) const
    {
      const auto &spec = history.criteria[c];
      const auto  x    = crossing(c);
      Json        o    = common_block(spec, history.values.back()[c]);
      o["located_by"]  = "bracket";
      if (analysis::row_of(spec.kind).depths)
        o["depth"] = "envelope over the contact width";
      outcome = {x.reached ? analysis::CriterionStatus::decided : analysis::CriterionStatus::not_reached,
                 x.reached ? x.revolutions : nan};
      o["reached"]     = x.reached;
      o["decided"]     = x.reached;
      o["status"]      = analysis::status_name(outcome.status);
      o["revolutions"] = x.reached ? Json(x.revolutions) : Json();
      o["hours"]       = x.reached ? Json(x.revolutions * period / 3600) : Json();
      o["joint"]       = x.reached ? history.joints[x.iteration][c] : history.joints.back()[c];
      if (!x.reached)
        {
          o["not_reached_within_revolutions"] = revolutions_run;
          return o;
        }
      const double width       = x.high - x.low;
      o["bracket_revolutions"] = Json::array({x.low, x.high});
      o["bracket_relative"]    = x.revolutions > 0 ? width / x.revolutions : 0.0;
      o["within_tolerance"]    = width <= scene.life.tolerance * x.revolutions * (1 + 1e-9);
      return o;
    }

    /**
     * The block of the trend criterion @p c: its status on all measurements on the chosen
     * model, that model's crossing (the life if decided, else an estimate) and its 95 %
     * interval.
     */
    Json
    LifeRun::trend_block(const std::size_t c, analysis::CriterionOutcome &outcome) const
    {
      const auto  &spec    = history.criteria[c];
      const auto   x       = trend_state(c);
      const bool   precise = x.status == analysis::CriterionStatus::decided;
      const bool   first   = first_for_certain(c);
      const bool   decided = precise || first;
      Json         o       = common_block(spec, history.values.back()[c]);
      std::string  reason  = x.reason;
      const double life    = earliest_wear_life();
      if (first)
        reason += "; its interval ends before every wear criterion reached: it is the first criterion reached, "
                  "located less precisely than Life/Response tolerance";
      else if (!decided && cannot_come_first(c))
        reason += "; it cannot come before the wear life at " + format_number(std::round(life), 15) +
                  " rev (the upper 95 % bound of its rise there is below the limit), so the run did not go on";
      else if (!decided && std::isfinite(life))
        reason += "; the run stopped when every wear criterion was reached (the wear life " +
                  format_number(std::round(life), 15) + " rev), which it may precede";
      const auto status               = decided ? analysis::CriterionStatus::decided : x.status;
      outcome                         = {status, decided ? x.revolutions : nan};
      o["located_by"]                 = "trend";
      o["reached"]                    = x.reached;
      o["decided"]                    = decided;
      o["status"]                     = analysis::status_name(status);
      o["within_tolerance"]           = precise;
      o["revolutions"]                = decided ? Json(x.revolutions) : Json();
      o["hours"]                      = decided ? Json(x.revolutions * period / 3600) : Json();
      o["joint"]                      = "";
      o["trend_model"]                = analysis::family_name(x.family);
      o["trend_crossing_revolutions"] = std::isfinite(x.revolutions) ? Json(x.revolutions) : Json();
      o["interval_revolutions"]       = pair_or_null(x.interval.low, x.interval.high);
      o["interval_hours"]             = pair_or_null(x.interval.low * period / 3600, x.interval.high * period / 3600);
      o["interval_relative"] =
        x.interval.bounded() && x.revolutions > 0 ? Json((x.interval.high - x.interval.low) / x.revolutions) : Json();
      o["response_tolerance"]           = scene.life.response_tolerance;
      o["rise_at_end_ci95_percent"]     = pair_or_null(x.rise_at_end.low, x.rise_at_end.high);
      o["last_measurement_revolutions"] = revolutions_run;
      if (!precise)
        o["reason"] = reason;
      if (x.status == analysis::CriterionStatus::not_reached)
        o["not_reached_within_revolutions"] = revolutions_run;
      return o;
    }

    /**
     * The headline: the decided criterion with the fewest revolutions, and why (the
     * criteria that are not a life, with their status).
     */
    Json
    LifeRun::headline(const std::vector<analysis::CriterionOutcome> &outcomes, const Json &criteria) const
    {
      const auto         first = analysis::headline_criterion(outcomes);
      Json               h     = Json::object();
      std::ostringstream why;
      if (first)
        {
          const auto &name = history.criteria[*first].name;
          const Json &o    = criteria.at(name);
          h["criterion"]   = name;
          h["revolutions"] = outcomes[*first].revolutions;
          h["hours"]       = outcomes[*first].revolutions * period / 3600;
          h["located_by"]  = o.at("located_by");
          h["range_revolutions"] =
            o.contains("bracket_revolutions") ? o.at("bracket_revolutions") : o.at("interval_revolutions");
          why << name << " is the decided criterion with the fewest revolutions";
        }
      else
        {
          h["criterion"] = Json();
          why << "no criterion was decided within the run's " << format_number(revolutions_run, 6) << " revolutions ("
              << iterations_run << " iterations)";
        }
      for (std::size_t c = 0; c < outcomes.size(); ++c)
        if (outcomes[c].status != analysis::CriterionStatus::decided)
          {
            const Json &o = criteria.at(history.criteria[c].name);
            why << "; " << history.criteria[c].name << " is " << analysis::status_name(outcomes[c].status)
                << (o.contains("reason") ? " (" + o.at("reason").get<std::string>() + ")" : std::string())
                << " and not a life";
          }
      h["reason"] = why.str();
      return h;
    }

    Json
    LifeRun::block() const
    {
      Json life                                        = Json::object();
      life["tolerance"]                                = scene.life.tolerance;
      life["cycle_period_s"]                           = period;
      life["revolutions_run"]                          = revolutions_run;
      life["hours_run"]                                = revolutions_run * period / 3600;
      life["iterations"]                               = iterations_run;
      Json                                    criteria = Json::object();
      std::vector<analysis::CriterionOutcome> outcomes(history.criteria.size());
      for (std::size_t c = 0; c < history.criteria.size(); ++c)
        criteria[history.criteria[c].name] =
          analysis::is_trend(history.criteria[c]) ? trend_block(c, outcomes[c]) : wear_block(c, outcomes[c]);
      life["criteria"]         = criteria;
      const Json head          = headline(outcomes, criteria);
      const bool any           = !head.at("criterion").is_null();
      life["headline"]         = head;
      life["first_criterion"]  = head.at("criterion");
      life["life_revolutions"] = any ? head.at("revolutions") : Json();
      life["life_hours"]       = any ? head.at("hours") : Json();
      if (scene.life.limit(analysis::Criterion::response_rise) > 0)
        {
          const auto trend = models();
          life["response"] = {{"body", scene.mechanism->get_bodies()[body].name},
                              {"cycles", scene.life.response_cycles},
                              {"measured_fresh_m_s2", history.response.front()},
                              {"measured_last_m_s2", history.response.back()},
                              {"measurements", trend.points()},
                              {"revolutions", history.revolutions},
                              {"measures_m_s2", finite_or_null(history.response)},
                              {"trend_model", analysis::family_name(trend.chosen())},
                              {"model_choice", "the smallest BIC = n ln(RSS/n) + p ln n"},
                              {"models",
                               models_block(trend,
                                            scene.life.limit(analysis::Criterion::response_rise),
                                            revolutions_run,
                                            scene.life.response_tolerance)}};
        }
      return life;
    }
  } // namespace

  void
  check_life_criteria(const io::Scene &scene)
  {
    if (!analysis::active_criteria(scene.life).empty() && !scene.wear.empty())
      return;
    if (scene.wear.empty())
      throw InputError("`wearlink life` runs the wear loop, but no clearance joint of " + scene.file +
                       " has a Wear law: set 'Joint <J>/Clearance/Wear law = archard' with its Pressure "
                       "model and archard data (see params/nine_bar_wear.prm).");
    std::string entries;
    for (const auto &row : analysis::criteria_table())
      {
        const int   power = static_cast<int>(std::lround(std::log10(row.upper)));
        const bool  round = power >= 4 && std::abs(row.upper - std::pow(10.0, power)) < 1e-9 * row.upper;
        std::string upper = round ? "1e" + std::to_string(power) : format_number(row.upper, 6); // 1e9, 0.1
        entries +=
          std::string(entries.empty() ? "" : ", ") + "'Life/" + row.entry + "' (" + row.unit + ", > 0 … " + upper + ")";
      }
    throw InputError("In " + scene.file +
                     ", subsection 'Life' sets no stop criterion, so `wearlink life` would not know when "
                     "the joint is worn out. Set at least one of " +
                     entries + " to a positive limit, e.g. --set \"Life/Maximum wear depth=5e-5\".");
  }

  LifeRunResult
  run_life(io::Scene &scene, const LifeRunOptions &options)
  {
    check_life_criteria(scene);
    LifeRun life(scene, options); // the fresh response, or the history of a resumed run
    scene.wear_loop.n_iterations = scene.life.max_iterations;
    if (scene.wear_loop.extrapolation == wear::Extrapolation::adaptive)
      scene.wear_loop.target_revolutions = scene.life.max_revolutions;
    WearRun run(scene, life.wear_options());
    run.loop().set_factor_limit([&life](const wear::StepPreview &p) { return life.factor_limit(p); });
    while (!run.finished() && !life.stop(run.loop()))
      {
        run.iterate();
        life.record(run.loop()); // its row belongs to the iteration's checkpoint
        run.commit();
      }
    LifeRunResult result;
    result.wear                 = run.finish(&life.response_warnings);
    result.life                 = life.block();
    result.wear.summary["life"] = result.life;
    run.write_summary(result.wear);
    result.history = life.history;
    if (!options.output_directory.empty())
      io::plot_life(options.output_directory + "/" + io::outputs::life_plot,
                    life.history,
                    "Life criteria against revolutions: " + scene.title);
    return result;
  }

  namespace
  {
    /** "a … b" of a JSON pair of numbers. */
    std::string
    range_text(const Json &pair)
    {
      return format_number(json_number(pair[0]), 6) + " … " + format_number(json_number(pair[1]), 6);
    }

    /** The last column of a criterion's row: its bracket, its interval or why it is no life. */
    std::string
    range_column(const Json &o)
    {
      const std::string status = o.at("status").get<std::string>();
      if (o.at("located_by") == "bracket")
        return status == "decided" ?
                 range_text(o.at("bracket_revolutions")) + " (bracket" +
                   (o.at("within_tolerance").get<bool>() ? ")" : ", wider than the tolerance)") :
                 "not reached within " + format_number(json_number(o.at("not_reached_within_revolutions")), 6) + " rev";
      std::string text = o.at("interval_revolutions").is_null() ? "no bounded interval" :
                                                                  range_text(o.at("interval_revolutions")) + " (95 %)";
      if (status != "decided")
        {
          if (!o.at("trend_crossing_revolutions").is_null())
            text = o.at("trend_model").get<std::string>() + " crosses at " +
                   format_number(json_number(o.at("trend_crossing_revolutions")), 6) + ", " + text;
          text += "; " + o.at("reason").get<std::string>();
        }
      return text;
    }
  } // namespace

  std::string
  life_table(const Json &life)
  {
    std::ostringstream os;
    os << "criterion          limit          status       revolutions    hours        joint  bracket or 95 % interval "
          "(rev)\n";
    for (auto it = life.at("criteria").begin(); it != life.at("criteria").end(); ++it)
      {
        const Json        &o = it.value();
        std::ostringstream limit;
        limit << std::setprecision(4) << json_number(o.at("limit")) << ' ' << o.at("unit").get<std::string>();
        const bool decided = o.at("decided").get<bool>();
        os << std::left << std::setw(19) << it.key() << std::setw(15) << limit.str() << std::setw(13)
           << o.at("status").get<std::string>() << std::setw(15)
           << (decided ? format_number(json_number(o.at("revolutions")), 6) : "-") << std::setw(13)
           << (decided ? format_number(json_number(o.at("hours")), 6) : "-") << std::setw(7)
           << o.at("joint").get<std::string>() << range_column(o) << "\n";
      }
    const Json &h = life.at("headline");
    if (h.at("criterion").is_null())
      os << "life: none decided — " << h.at("reason").get<std::string>() << "\n";
    else
      os << "life: " << h.at("criterion").get<std::string>() << ", "
         << format_number(json_number(h.at("revolutions")), 6) << " revolutions ("
         << format_number(json_number(h.at("hours")), 6) << " h) — " << h.at("reason").get<std::string>() << "\n";
    return os.str();
  }
} // namespace wearlink::workflows
