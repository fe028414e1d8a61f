// SPDX-License-Identifier: LGPL-2.1-or-later
#include "workflows/life.h"

#include "analysis/cycle_peaks.h"
#include "base/exceptions.h"
#include "base/text.h"
#include "io/life_outputs.h"
#include "io/life_parameters.h"
#include "io/wear_outputs.h"
#include "workflows/run.h"

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
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();

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
     * One life run: the criteria, their history, and the hooks it gives the wear run
     * (see the header).
     */
    class LifeRun
    {
    public:
      LifeRun(io::Scene &scene, const LifeRunOptions &options);

      /** The wear run's options with the life run's hooks (valid while this object lives). */
      WearRunOptions
      wear_options();

      /** summary.json's `life` block. */
      Json
      block() const;

      analysis::LifeHistory history;

    private:
      double
      factor_limit(const wear::StepPreview &p) const;
      double
      response_reach(const wear::StepPreview &p, const analysis::CriterionSpec &c, std::size_t index) const;
      void
      after_iteration(const wear::WearLoop &loop);
      bool
      done(const wear::WearLoop &loop) const;
      bool
      reached(std::size_t c) const;
      analysis::Crossing
      crossing(std::size_t c) const;
      double
      measure_response();
      void
      print_progress() const;
      Json
      criterion_block(std::size_t c) const;

      io::Scene                            &scene;
      const LifeRunOptions                 &options;
      std::vector<analysis::JointDensities> densities;
      const double                          period;
      const int                             body;
      ValidityWarnings                      response_warnings; ///< of the response runs
      double                                revolutions_run = 0;
      unsigned int                          iterations_run  = 0;
    };

    LifeRun::LifeRun(io::Scene &scene, const LifeRunOptions &options)
      : scene(scene)
      , options(options)
      , period(cycle_period(scene))
      , body(life_response_body(scene))
    {
      history.criteria = analysis::active_criteria(scene.life);
      for (const auto &w : scene.wear)
        densities.push_back({w->archard.pin_density, w->archard.bushing_density});
      const std::string dir = options.output_directory;
      if (options.resume)
        {
          const auto state = wear::WearState::read(dir + "/checkpoint.json");
          history          = io::read_life_history(dir + "/life_history.csv", history.criteria);
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
      const bool response = scene.life.response_rise > 0;
      history.response.push_back(response ? measure_response() : nan);
      if (response && !(history.response[0] > 0))
        throw NumericalError("The response measure of " + scene.file + " with the fresh profiles is " +
                             format_number(history.response[0]) +
                             " m/s² (the body does not accelerate): a rise of it cannot be a criterion. Choose "
                             "another Life/Response body or another criterion.");
    }

    WearRunOptions
    LifeRun::wear_options()
    {
      WearRunOptions w;
      w.output_directory = options.output_directory;
      w.resume           = options.resume;
      w.progress         = options.progress;
      w.progress_prefix  = options.progress_prefix;
      w.factor_limit     = [this](const wear::StepPreview &p) {
        return factor_limit(p);
      };
      w.after_iteration = [this](const wear::WearLoop &loop) {
        after_iteration(loop);
      };
      w.stop = [this](const wear::WearLoop &loop) {
        return done(loop);
      };
      w.extend_summary = [this](Json &summary) {
        summary["life"] = block();
      };
      w.more_warnings = &response_warnings;
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
      run_scene(scene, ro);
      return peaks.mean_of_whole_cycles();
    }

    /**
     * The largest factor of the coming iteration: each criterion not yet reached lands
     * on its crossing within the tolerance (analysis::approach_factor), and the run stays
     * within Life/Maximum revolutions.
     */
    double
    LifeRun::factor_limit(const wear::StepPreview &p) const
    {
      double limit = (scene.life.max_revolutions - p.revolutions) / p.cycles;
      for (std::size_t c = 0; c < history.criteria.size(); ++c)
        {
          if (reached(c))
            continue;
          const auto  &spec    = history.criteria[c];
          const double f_reach = spec.kind == analysis::Criterion::response_rise ?
                                   response_reach(p, spec, c) :
                                   analysis::factor_to_reach(spec, p, densities, p.factor);
          limit = std::min(limit, analysis::approach_factor(f_reach, p.cycles, p.revolutions, scene.life.tolerance));
        }
      return limit;
    }

    /**
     * The factor at which the response criterion @p c (column @p index) is predicted to
     * cross, from the slope of the response trend; +∞ without a rising trend or before it
     * has enough points (then the iteration takes the loop's own factor).
     */
    double
    LifeRun::response_reach(const wear::StepPreview &p, const analysis::CriterionSpec &c, const std::size_t index) const
    {
      const std::size_t k     = history.rows();
      const auto        trend = analysis::response_trend(history.revolutions, history.response, k);
      if (trend.points < analysis::min_response_points - 1)
        return std::numeric_limits<double>::infinity();
      const double slope = 100 * trend.slope / trend.fresh; // [% per revolution]
      if (!(slope > 0) || !std::isfinite(slope))
        return std::numeric_limits<double>::infinity();
      return std::max(0.0, (c.limit - history.values[k - 1][index]) / slope / p.cycles);
    }

    /** The row of the iteration just done (before its checkpoint), and life_history.csv. */
    void
    LifeRun::after_iteration(const wear::WearLoop &loop)
    {
      const auto &st = loop.state();
      history.truncate(st.iterations_done - 1); // rows a killed run wrote past its checkpoint
      const bool response = scene.life.response_rise > 0;
      history.iterations.push_back(st.iterations_done);
      history.revolutions.push_back(st.revolutions);
      history.factors.push_back(st.factors.back());
      history.response.push_back(response ? measure_response() : nan);
      std::vector<double>      values;
      std::vector<std::string> joints;
      for (const auto &c : history.criteria)
        if (c.kind == analysis::Criterion::response_rise)
          {
            const auto trend = analysis::response_trend(history.revolutions, history.response, history.rows());
            values.push_back(trend.rise(st.revolutions));
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
        io::write_life_history(options.output_directory + "/life_history.csv", history);
      if (options.progress)
        print_progress();
    }

    /**
     * The first crossing of criterion @p c; the response's counts from its
     * min_response_points-th measurement (a trend of fewer points is not one).
     */
    analysis::Crossing
    LifeRun::crossing(const std::size_t c) const
    {
      auto         values = history.column(c);
      const double limit  = history.criteria[c].limit;
      if (history.criteria[c].kind == analysis::Criterion::response_rise)
        for (std::size_t k = 0; k + 1 < analysis::min_response_points && k < values.size(); ++k)
          values[k] = std::min(values[k], limit * (1 - 1e-6));
      return analysis::first_crossing(history.revolutions, values, limit);
    }

    bool
    LifeRun::reached(const std::size_t c) const
    {
      return crossing(c).reached;
    }

    bool
    LifeRun::done(const wear::WearLoop &loop) const
    {
      if (loop.state().revolutions >= scene.life.max_revolutions * (1 - 1e-12))
        return true;
      for (std::size_t c = 0; c < history.criteria.size(); ++c)
        if (!reached(c))
          return false;
      return true;
    }

    /** One line: each criterion's value as a percentage of its limit. */
    void
    LifeRun::print_progress() const
    {
      std::ostringstream os;
      os << "[wearlink] " << options.progress_prefix << "life after " << std::setprecision(6)
         << history.revolutions.back() << " rev:";
      for (std::size_t c = 0; c < history.criteria.size(); ++c)
        {
          const auto &spec = history.criteria[c];
          os << "  " << spec.name << ' ' << std::setprecision(3) << 100 * history.values.back()[c] / spec.limit
             << " % of " << spec.limit << ' ' << spec.unit;
          if (!history.joints.back()[c].empty())
            os << " (" << history.joints.back()[c] << ')';
          if (reached(c))
            os << " reached";
        }
      std::cerr << os.str() << "\n";
    }

    /** One criterion of the `life` block. */
    Json
    LifeRun::criterion_block(const std::size_t c) const
    {
      const auto &spec  = history.criteria[c];
      const auto  x     = analysis::first_crossing(history.revolutions, history.column(c), spec.limit);
      Json        o     = Json::object();
      o["entry"]        = "Life/" + spec.entry;
      o["limit"]        = spec.limit;
      o["unit"]         = spec.unit;
      o["reached"]      = x.reached;
      o["value_at_end"] = history.values.back()[c];
      o["revolutions"]  = x.reached ? Json(x.revolutions) : Json();
      o["hours"]        = x.reached ? Json(x.revolutions * period / 3600) : Json();
      o["joint"]        = x.reached ? history.joints[x.iteration][c] : history.joints.back()[c];
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

    Json
    LifeRun::block() const
    {
      Json life               = Json::object();
      life["tolerance"]       = scene.life.tolerance;
      life["cycle_period_s"]  = period;
      life["revolutions_run"] = revolutions_run;
      life["hours_run"]       = revolutions_run * period / 3600;
      life["iterations"]      = iterations_run;
      Json        criteria    = Json::object();
      std::string first;
      double      first_revolutions = std::numeric_limits<double>::infinity();
      for (std::size_t c = 0; c < history.criteria.size(); ++c)
        {
          const Json o                       = criterion_block(c);
          criteria[history.criteria[c].name] = o;
          if (o.at("reached").get<bool>() && json_number(o.at("revolutions")) < first_revolutions)
            {
              first             = history.criteria[c].name;
              first_revolutions = json_number(o.at("revolutions"));
            }
        }
      life["criteria"]         = criteria;
      life["first_criterion"]  = first.empty() ? Json() : Json(first);
      life["life_revolutions"] = first.empty() ? Json() : Json(first_revolutions);
      life["life_hours"]       = first.empty() ? Json() : Json(first_revolutions * period / 3600);
      if (scene.life.response_rise > 0)
        {
          const auto trend = analysis::response_trend(history.revolutions, history.response, history.rows());
          life["response"] = {{"body", scene.mechanism->get_bodies()[body].name},
                              {"cycles", scene.life.response_cycles},
                              {"measured_fresh_m_s2", history.response.front()},
                              {"measured_last_m_s2", history.response.back()},
                              {"trend_fresh_m_s2", trend.fresh},
                              {"trend_slope_percent_per_1000_rev", 1e5 * trend.slope / trend.fresh},
                              {"scatter_percent", 100 * trend.scatter},
                              {"measurements", trend.points}};
        }
      return life;
    }
  } // namespace

  LifeRunResult
  run_life(io::Scene &scene, const LifeRunOptions &options)
  {
    io::check_life_criteria(scene);
    LifeRun life(scene, options); // the fresh response, or the history of a resumed run
    scene.wear_loop.n_iterations = scene.life.max_iterations;
    if (scene.wear_loop.extrapolation == wear::Extrapolation::adaptive)
      scene.wear_loop.target_revolutions = scene.life.max_revolutions;
    LifeRunResult result;
    result.wear    = run_wear(scene, life.wear_options());
    result.history = life.history;
    if (result.wear.finished)
      {
        result.life = life.block();
        if (!options.output_directory.empty())
          io::plot_life(options.output_directory + "/life.png",
                        life.history,
                        "Life criteria against revolutions: " + scene.title);
      }
    return result;
  }

  std::string
  life_table(const Json &life)
  {
    std::ostringstream os;
    os << "criterion            limit            revolutions      hours        joint  bracket (rev)\n";
    for (auto it = life.at("criteria").begin(); it != life.at("criteria").end(); ++it)
      {
        const Json        &o = it.value();
        std::ostringstream limit;
        limit << std::setprecision(4) << json_number(o.at("limit")) << ' ' << o.at("unit").get<std::string>();
        os << std::left << std::setw(21) << it.key() << std::setw(17) << limit.str() << std::setprecision(6);
        if (o.at("reached").get<bool>())
          os << std::setw(17) << json_number(o.at("revolutions")) << std::setw(13) << json_number(o.at("hours"))
             << std::setw(7) << o.at("joint").get<std::string>() << json_number(o.at("bracket_revolutions")[0]) << " … "
             << json_number(o.at("bracket_revolutions")[1])
             << (o.at("within_tolerance").get<bool>() ? "" : "  (wider than the tolerance)");
        else
          os << "not reached within " << json_number(o.at("not_reached_within_revolutions")) << " rev";
        os << "\n";
      }
    return os.str();
  }
} // namespace wearlink::workflows
