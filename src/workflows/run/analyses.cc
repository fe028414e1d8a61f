// SPDX-License-Identifier: LGPL-2.1-or-later
#include "workflows/run/analyses.h"

#include "analysis/channels.h"
#include "analysis/nonlinear_dynamics.h"
#include "base/atomic_file.h"
#include "base/effect_ledger.h"
#include "base/exceptions.h"
#include "base/numbers.h"
#include "base/parameters.h"
#include "base/text.h"
#include "io/lyapunov_report.h"
#include "io/plot.h"
#include "io/recorded_run_files.h"
#include "io/scene.h"
#include "io/scene_periods.h"
#include "workflows/run/shadow_trajectory.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace wearlink::workflows
{
  namespace
  {
    using numbers::two_pi;

    /** Relative difference below which two driver speeds are the same [-]. */
    constexpr double same_speed = 1e-12;

    /** (position, velocity) channel pairs of a phase plane. */
    struct PhasePair
    {
      std::string position, velocity, title;
    };

    std::vector<PhasePair>
    phase_pairs(const analysis::AnalysesSettings &settings)
    {
      std::vector<PhasePair> out;
      for (const auto &j : settings.joints)
        {
          out.push_back({j + "_ex_m", j + "_vex_m_s", "joint " + j + ", journal centre x relative to the bushing"});
          out.push_back({j + "_ey_m", j + "_vey_m_s", "joint " + j + ", journal centre y relative to the bushing"});
        }
      for (const auto &b : settings.bodies)
        {
          out.push_back({b + "_x_m", b + "_vx_m_s", "body " + b + ", x"});
          out.push_back({b + "_y_m", b + "_vy_m_s", "body " + b + ", y"});
          out.push_back({b + "_theta_rad", b + "_omega_rad_s", "body " + b + ", angle"});
        }
      return out;
    }

    /** The channels whose Lyapunov exponent is estimated. */
    std::vector<std::string>
    lyapunov_channels(const analysis::AnalysesSettings &settings)
    {
      std::vector<std::string> out;
      for (const auto &j : settings.joints)
        for (const auto &d : settings.directions)
          out.push_back(j + "_e" + d + "_m");
      for (const auto &b : settings.bodies)
        for (const auto &d : settings.directions)
          out.push_back(b + "_" + d + "_m");
      return out;
    }

    std::string
    unit_label(const std::string &unit)
    {
      return "[" + unit + "]";
    }

    std::string
    label_suffix(const analysis::RecordedRun &run)
    {
      return run.label.empty() ? std::string() : " (" + run.label + ")";
    }
  } // namespace


  // -----------------------------------------------------------------------------------
  // The analyses of one run.

  SceneAnalyses::SceneAnalyses(const io::Scene &scene)
    : SceneAnalyses(scene, scene.analyses)
  {
  }

  SceneAnalyses::SceneAnalyses(const io::Scene &scene, const analysis::AnalysesSettings &settings)
    : scene(scene)
    , settings(settings)
  {
    auto &ledger = EffectLedger::instance();
    for (const auto &name : settings.names())
      ledger.record_construction("analysis", name);
    if (!settings.any())
      return;
    period                   = settings.poincare ? io::driving_period(scene) : 0.0;
    const double record_from = scene.start_time + settings.transient;
    const auto  &mech        = *scene.mechanism;

    if (settings.phase_portrait || settings.lyapunov)
      {
        std::vector<analysis::Channel> channels;
        for (const auto *j : scene.clearance_joints)
          if (std::find(settings.joints.begin(), settings.joints.end(), j->name()) != settings.joints.end())
            for (auto &c : analysis::clearance_joint_channels(*j))
              channels.push_back(std::move(c));
        for (const auto &b : settings.bodies)
          for (auto &c : analysis::body_channels(mech, mech.body_index(b)))
            channels.push_back(std::move(c));
        ledger.add_resource("analysis channels", static_cast<long>(channels.size()));
        series = std::make_unique<analysis::SeriesRecorder>(std::move(channels), record_from, settings.sample_interval);
      }
    if (settings.lyapunov && settings.two_trajectory)
      {
        ShadowTrajectorySettings st;
        st.begin_time = record_from;
        st.separation = settings.two_trajectory_separation;
        st.interval   = settings.renormalization_interval;
        double T      = period;
        if (!(T > 0.0))
          T = io::driving_period_if_known(scene);
        st.velocity_scale = T > 0.0 ? T / two_pi : 1.0;
        ledger.record_construction("analysis", "two-trajectory shadow");
        shadow = std::make_unique<ShadowTrajectory>(scene, st);
      }
    if (settings.poincare)
      {
        // Every state channel: a section point is the whole state at t_k.
        auto channels = analysis::all_channels(mech, scene.clearance_joints);
        ledger.add_resource("analysis channels", static_cast<long>(channels.size()));
        // First section at or after the end of the transient.
        const double t0    = scene.start_time + settings.section_phase;
        const double first = t0 + period * std::ceil(std::max(0.0, record_from - t0) / period - 1e-9);
        section            = std::make_unique<analysis::PoincareRecorder>(std::move(channels), first, period);
      }
  }

  SceneAnalyses::~SceneAnalyses() = default;

  std::vector<mbs::StepObserver *>
  SceneAnalyses::observers()
  {
    std::vector<mbs::StepObserver *> out;
    if (series)
      out.push_back(series.get());
    if (section)
      out.push_back(section.get());
    if (shadow)
      out.push_back(shadow.get());
    return out;
  }

  analysis::RecordedRun
  SceneAnalyses::recorded_run(const std::string &label) const
  {
    analysis::RecordedRun run;
    run.label = label;
    if (series)
      {
        run.series          = series->series();
        run.sample_interval = series->interval();
      }
    if (section)
      run.section = section->section();
    run.driving_period = period;
    if (!(run.driving_period > 0.0)) // only used to express exponents per period
      run.driving_period = io::driving_period_if_known(scene);
    return run;
  }

  Json
  SceneAnalyses::finish(const std::string &output_directory)
  {
    if (!settings.any())
      return Json();
    auto &ledger = EffectLedger::instance();
    if (series)
      ledger.add_calls("analysis samples", static_cast<long>(series->series().n_samples()));
    if (section)
      ledger.add_calls("poincare points", static_cast<long>(section->section().points.n_samples()));
    Json out = analyse_recorded_run(recorded_run(), settings, output_directory);
    if (shadow)
      {
        ledger.add_calls("lyapunov estimates", 1);
        Json j              = Json::object();
        j["channel"]        = "state";
        j["method"]         = "two-trajectory";
        j["exponent_per_s"] = shadow->exponent();
        j["unit"]           = "1/s (natural log)";
        const double T      = recorded_run().driving_period;
        if (T > 0.0)
          j["exponent_per_driving_period"] = shadow->exponent() * T;
        j["renormalizations"]           = shadow->n_renormalizations();
        j["renormalization_interval_s"] = settings.renormalization_interval;
        j["separation_m"]               = settings.two_trajectory_separation;
        if (!out.contains("lyapunov"))
          out["lyapunov"] = Json::array();
        out["lyapunov"].push_back(j);
        if (!output_directory.empty())
          {
            std::ostringstream csv;
            csv << std::setprecision(10) << "time_s,running_exponent_per_s\n";
            io::PlotSeries running;
            running.title = "running estimate";
            for (std::size_t k = 0; k < shadow->running_time().size(); ++k)
              {
                csv << shadow->running_time()[k] << ',' << shadow->running_exponent()[k] << '\n';
                running.x.push_back(shadow->running_time()[k]);
                running.y.push_back(shadow->running_exponent()[k]);
              }
            write_file_atomically(output_directory + "/lyapunov_state_two-trajectory.csv", csv.str());
            io::PlotSpec plot;
            plot.title = "Two-trajectory (Benettin) largest Lyapunov exponent of the state = " +
                         format_number(shadow->exponent(), 4) + " 1/s";
            plot.x_label = "time [s]";
            plot.y_label = "running estimate [1/s, natural log]";
            plot.series  = {running};
            io::plot_png(plot, output_directory + "/lyapunov_state_two-trajectory.png");
          }
      }
    return out;
  }

  // -----------------------------------------------------------------------------------
  // Outputs from a recorded run.

  namespace
  {
    /** Phase portraits: the series, and one PNG per position-velocity pair with the
     *  Poincaré points of the same pair in red (seed Figs 9-10). */
    void
    phase_portraits(const analysis::RecordedRun      &run,
                    const analysis::AnalysesSettings &settings,
                    const bool                        write,
                    const std::string                &dir,
                    Json                             &out,
                    Json                             &files)
    {
      Json pp                 = Json::object();
      pp["n_samples"]         = run.series.n_samples();
      pp["sample_interval_s"] = run.sample_interval;
      if (write)
        {
          for (const auto &pair : phase_pairs(settings))
            {
              const std::size_t ip = run.series.index(pair.position), iv = run.series.index(pair.velocity);
              io::PlotSpec      plot;
              plot.title   = "Phase portrait, " + pair.title + label_suffix(run);
              plot.x_label = pair.position + " " + unit_label(run.series.units[ip]);
              plot.y_label = pair.velocity + " " + unit_label(run.series.units[iv]);
              io::PlotSeries orbit;
              orbit.title = "phase orbit";
              orbit.x     = run.series.values[ip];
              orbit.y     = run.series.values[iv];
              orbit.look  = io::line("black", 0.5);
              plot.series.push_back(orbit);
              if (run.section.points.n_samples() > 0 && run.section.points.has(pair.position) &&
                  run.section.points.has(pair.velocity))
                {
                  io::PlotSeries points;
                  points.title = "Poincaré points (one per " + format_number(run.section.period, 4) + " s)";
                  points.look  = io::points("red", 0.8);
                  points.x     = run.section.points.values[run.section.points.index(pair.position)];
                  points.y     = run.section.points.values[run.section.points.index(pair.velocity)];
                  plot.series.push_back(points);
                }
              const std::string png = "phase_portrait_" + pair.position + ".png";
              if (io::plot_png(plot, dir + png))
                files.push_back(png);
            }
        }
      out["phase_portrait"] = pp;
    }

    /** Poincaré section: every state channel at t_k, and its spread. */
    void
    poincare_section(const analysis::RecordedRun      &run,
                     const analysis::AnalysesSettings &settings,
                     const bool                        write,
                     const std::string                &dir,
                     Json                             &out,
                     Json                             &files)
    {
      Json ps            = Json::object();
      ps["period_s"]     = run.section.period;
      ps["first_time_s"] = run.section.first_time;
      ps["n_points"]     = run.section.points.n_samples();
      Json spread        = Json::object();
      for (const auto &c : analysis::section_spread(run.section))
        spread[c.name] = c.spread;
      ps["spread"] = spread;
      if (write)
        {
          io::write_sampled_csv(run.section.points, dir + "poincare_section.csv", true);
          files.push_back("poincare_section.csv");
          for (const auto &pair : phase_pairs(settings))
            {
              if (!run.section.points.has(pair.position))
                continue;
              const auto       &p  = run.section.points;
              const std::size_t ip = p.index(pair.position), iv = p.index(pair.velocity);
              io::PlotSpec      plot;
              plot.title = "Poincaré section (t = " + format_number(run.section.first_time, 4) + " s + k · " +
                           format_number(run.section.period, 4) + " s), " + pair.title + label_suffix(run);
              plot.x_label = pair.position + " " + unit_label(p.units[ip]);
              plot.y_label = pair.velocity + " " + unit_label(p.units[iv]);
              io::PlotSeries points;
              points.title = std::to_string(p.n_samples()) + " section points";
              points.look  = io::points("red", 0.8);
              points.x     = p.values[ip];
              points.y     = p.values[iv];
              plot.series.push_back(points);
              const std::string png = "poincare_" + pair.position + ".png";
              if (io::plot_png(plot, dir + png))
                files.push_back(png);
            }
        }
      out["poincare"] = ps;
    }

    /** Largest Lyapunov exponents of the journal-centre coordinates. */
    void
    lyapunov_exponents(const analysis::RecordedRun      &run,
                       const analysis::AnalysesSettings &settings,
                       const bool                        write,
                       const std::string                &dir,
                       Json                             &out,
                       Json                             &files)
    {
      auto &ledger  = EffectLedger::instance();
      Json  results = Json::array();
      for (const auto &channel : lyapunov_channels(settings))
        for (const auto method : settings.methods)
          {
            analysis::LyapunovSettings ls;
            ls.method              = method;
            ls.embedding.delay     = settings.delay;
            ls.embedding.dimension = settings.dimension;
            const auto r           = analysis::lyapunov_of_channel(run, channel, ls);
            ledger.add_calls("lyapunov estimates", 1);
            const auto &e            = r.estimate;
            Json        j            = Json::object();
            j["channel"]             = channel;
            j["method"]              = analysis::method_name(method);
            j["exponent_per_s"]      = e.exponent();
            j["unit"]                = "1/s (natural log)";
            j["exponent_per_sample"] = e.exponent_per_sample;
            if (run.driving_period > 0.0)
              j["exponent_per_driving_period"] = r.per_driving_period;
            j["exponent_bits_per_s"]    = e.exponent() / std::log(2.0);
            j["n_samples"]              = r.n_samples;
            j["sample_interval_s"]      = r.sample_interval;
            j["delay_samples"]          = e.embedding.embedding.delay;
            j["embedding_dimension"]    = e.embedding.embedding.dimension;
            j["theiler_window_samples"] = e.embedding.theiler_window;
            j["delay_rule"] = e.embedding.delay_choice ? analysis::describe(e.embedding.delay_choice->rule) : "given";
            j["dimension_rule"] = e.embedding.dimension_choice ?
                                    (e.embedding.dimension_choice->below_threshold ?
                                       "false nearest neighbours below 1%" :
                                       "false nearest neighbours: none below 1%, smallest taken") :
                                    "given";
            if (e.rosenstein)
              {
                j["fit_begin_s"] = e.rosenstein->fit_begin * r.sample_interval;
                j["fit_end_s"]   = e.rosenstein->fit_end * r.sample_interval;
                j["saturated"]   = e.rosenstein->saturated;
                j["resolved"]    = e.rosenstein->resolved;
                j["fit_rule"]    = e.rosenstein->fit_rule;
              }
            if (e.wolf)
              j["evolution_time_s"] = e.wolf->evolution_steps * r.sample_interval;
            if (write)
              {
                const std::string stem = "lyapunov_" + channel + "_" + analysis::method_name(method);
                files.push_back(stem + ".csv");
                if (io::write_lyapunov_curve(e, channel, dir + stem))
                  files.push_back(stem + ".png");
              }
            results.push_back(j);
          }
      out["lyapunov"] = results;
    }
  } // namespace

  Json
  analyse_recorded_run(const analysis::RecordedRun      &run,
                       const analysis::AnalysesSettings &settings,
                       const std::string                &output_directory)
  {
    const bool write = !output_directory.empty();
    if (write)
      make_output_directory(output_directory);
    const std::string dir  = output_directory + "/";
    Json              out  = Json::object();
    Json              list = Json::array();
    for (const auto &n : settings.names())
      list.push_back(n);
    out["list"] = list;
    if (run.driving_period > 0.0)
      out["driving_period_s"] = run.driving_period;
    out["transient_s"] = settings.transient;
    Json files         = Json::array();


    // The recorded data, whenever there is some: io::read_recorded_run() reads it back.
    if (write && run.series.n_samples() > 0)
      {
        io::write_sampled_csv(run.series, dir + "analysis_series.csv", false);
        files.push_back("analysis_series.csv");
      }
    if (run.series.n_samples() > 0)
      {
        out["series_sample_interval_s"] = run.sample_interval;
        out["series_samples"]           = run.series.n_samples();
      }

    if (settings.phase_portrait)
      phase_portraits(run, settings, write, dir, out, files);
    if (settings.poincare)
      poincare_section(run, settings, write, dir, out, files);
    if (settings.lyapunov)
      lyapunov_exponents(run, settings, write, dir, out, files);
    if (write)
      out["files"] = files;
    return out;
  }

} // namespace wearlink::workflows
