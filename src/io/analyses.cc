// SPDX-License-Identifier: LGPL-2.1-or-later
#include "io/analyses.h"

#include "analysis/channels.h"
#include "analysis/nonlinear_dynamics.h"
#include "base/atomic_file.h"
#include "base/effect_ledger.h"
#include "base/exceptions.h"
#include "base/parameters.h"
#include "base/plot.h"
#include "io/dynamics_comparison.h"
#include "io/lyapunov_report.h"
#include "io/scene.h"
#include "io/shadow_trajectory.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace wearlink::io
{
  namespace
  {
    namespace P = dealii::Patterns;

    constexpr double two_pi = 6.28318530717958647692;

    const char *const analysis_names = "phase-portrait|poincare|lyapunov";

    /** Relative difference below which two driver speeds are the same [-]. */
    constexpr double same_speed = 1e-12;

    std::string
    format(const double v, const int digits = 4)
    {
      std::ostringstream s;
      s << std::setprecision(digits) << v;
      return s.str();
    }

    /** (position, velocity) channel pairs of a phase plane. */
    struct PhasePair
    {
      std::string position, velocity, title;
    };

    std::vector<PhasePair>
    phase_pairs(const AnalysesSettings &settings)
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
    lyapunov_channels(const AnalysesSettings &settings)
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

    void
    write_sampled_csv(const analysis::SampledChannels &s, const std::string &path, const bool with_index)
    {
      std::ostringstream csv;
      csv << std::setprecision(12);
      if (with_index)
        csv << "section,";
      csv << "time_s";
      for (const auto &n : s.names)
        csv << ',' << n;
      csv << '\n';
      for (std::size_t k = 0; k < s.n_samples(); ++k)
        {
          if (with_index)
            csv << k << ',';
          csv << s.time[k];
          for (const auto &v : s.values)
            csv << ',' << v[k];
          csv << '\n';
        }
      write_file_atomically(path, csv.str());
    }

    std::string
    label_suffix(const analysis::RecordedRun &run)
    {
      return run.label.empty() ? std::string() : " (" + run.label + ")";
    }
  } // namespace

  namespace
  {
    double
    driving_period(const Scene &scene, const AnalysesSettings &settings);
  }

  // -----------------------------------------------------------------------------------
  // Scene entries.

  std::vector<std::string>
  AnalysesSettings::names() const
  {
    std::vector<std::string> out;
    if (phase_portrait)
      out.emplace_back("phase-portrait");
    if (poincare)
      out.emplace_back("poincare");
    if (lyapunov)
      out.emplace_back("lyapunov");
    return out;
  }

  void
  declare_analyses(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Analyses");
    declare(prm,
            "List of analyses",
            "",
            P::MultipleSelection(analysis_names),
            "Nonlinear-dynamics analyses of this run (none by default; an analysis not "
            "listed is not built and records nothing). phase-portrait: journal-centre "
            "motion of each analysed clearance joint relative to its bushing (e_x vs de_x/dt, "
            "e_y vs de_y/dt), PNG + CSV; poincare: one point per driving period from the "
            "integrator's dense output at the exact section time, CSV + PNG + spread in "
            "summary.json; lyapunov: largest Lyapunov exponent of the journal-centre "
            "coordinates (subsection Lyapunov), in 1/s with natural log.",
            "none");
    declare(prm,
            "Joints",
            "",
            P::List(P::Anything()),
            "Clearance joints analysed; empty: every clearance joint of the scene.",
            "none");
    declare(prm,
            "Bodies",
            "",
            P::List(P::Anything()),
            "Bodies whose centre-of-mass motion (x, y, angle) is analysed as well; empty: "
            "none.",
            "none");
    declare(prm,
            "Driving period",
            "0",
            P::Double(0),
            "Period T of the driving: one Poincaré point per T. 0: 2π/|ω| of the angle "
            "drivers, which must then all turn at the same rate.",
            "s");
    declare(prm,
            "Section phase",
            "0",
            P::Double(0),
            "Poincaré sections are taken at Start time + Section phase + k T (k = 0, 1, ...); "
            "must be smaller than T.",
            "s");
    declare(prm,
            "Transient",
            "0",
            P::Double(0),
            "Nothing is recorded for the analyses before Start time + Transient (let the "
            "initial transient die out).",
            "s");
    declare(prm,
            "Sample interval",
            "1e-3",
            P::Double(0),
            "Sampling interval of the phase-portrait and Lyapunov series (dense output).",
            "s");
    prm.enter_subsection("Lyapunov");
    declare(prm,
            "Methods",
            "wolf, rosenstein",
            P::MultipleSelection("wolf|rosenstein|two-trajectory"),
            "Estimators of the largest Lyapunov exponent: wolf (Wolf et al. 1985, fixed "
            "evolution time, the seed's method) and rosenstein (Rosenstein et al. 1993) from "
            "the journal-centre series; two-trajectory (Benettin et al. 1980) from the "
            "simulation itself: a shadow copy of the scene a small distance away, "
            "renormalized every Renormalization interval (doubles the simulation cost). "
            "Only used if List of analyses has lyapunov.",
            "none");
    declare(prm,
            "Two-trajectory separation",
            "1e-6",
            P::Double(0),
            "two-trajectory: distance d0 of the shadow from the reference (positions, and "
            "velocities times T/2π); far above the integration tolerance, far below the "
            "clearance.",
            "m");
    declare(prm,
            "Renormalization interval",
            "0.02",
            P::Double(0),
            "two-trajectory: the shadow is put back at distance d0 this often.",
            "s");
    declare(prm,
            "Directions",
            "x",
            P::MultipleSelection("x|y"),
            "Coordinates analysed (global axes): of each analysed joint's journal centre "
            "relative to its bushing, and of each analysed body's centre of mass. x is the "
            "seed's choice (Figs 11–12).",
            "none");
    declare(prm,
            "Delay",
            "0",
            P::Integer(0),
            "Delay of the embedding in samples; 0: from the average mutual information "
            "(its first minimum; a map-like series: 1; a flow that decorrelates without a "
            "minimum: the first delay with I <= I(0)/e).",
            "samples");
    declare(prm,
            "Embedding dimension",
            "0",
            P::Integer(0, 64),
            "Embedding dimension; 0: false nearest neighbours (first dimension with < 1 % "
            "false).",
            "none");
    prm.leave_subsection();
    prm.enter_subsection("Before-after wear");
    declare(prm,
            "Delay",
            "0.005",
            P::Double(0),
            "Wear scenes with analyses run the dynamics once with the fresh and once with the "
            "worn profiles (Start time to End time) and compare them. Their exponents are "
            "computed at ONE embedding: this delay for both runs (0: the before-wear run's "
            "mutual-information choice). On clearance-joint series the exponent falls "
            "roughly like 1/delay, so exponents at different delays are not comparable. "
            "The default 5 ms is about the automatic choice before wear at 1 ms sampling "
            "on the nine-bar.",
            "s");
    declare(prm,
            "Embedding dimension",
            "0",
            P::Integer(0, 64),
            "Common embedding dimension; 0: false nearest neighbours on the before-wear run.",
            "none");
    declare(prm,
            "Delay scan",
            "0.002, 0.005, 0.01, 0.02, 0.05",
            P::List(P::Double(0)),
            "The comparison is repeated at these delays (same dimension) to show whether "
            "after > before holds at every scale; delays below the sample interval are "
            "skipped; empty: no scan.",
            "s");
    declare(prm,
            "Two-trajectory cycles",
            "10",
            P::Double(0),
            "If Lyapunov/Methods has two-trajectory: the exponent of the simulation itself "
            "is measured, before and after wear, in two separate runs of this many driving "
            "periods after Transient (the worn one reads the worn profiles back from the "
            "output directory), at the tolerance below. The main before/after runs do not "
            "carry the shadow trajectory.",
            "driving periods");
    declare(prm,
            "Two-trajectory tolerance",
            "1e-11",
            P::Double(0),
            "Relative tolerance of the two-trajectory runs; the scene's position and "
            "velocity tolerances are scaled by the same factor. The shadow's separation d0 "
            "(Lyapunov/Two-trajectory separation) must stay far above the integration "
            "error: on the nine-bar the scene's 1e-6 gives 285–1380 1/s for d0 = 1e-6 … "
            "1e-9 m (noise), 1e-11 gives 100–145 1/s before and 346–362 1/s after wear.",
            "none");
    declare(prm,
            "Published exponents",
            "",
            P::Anything(),
            "Published exponents printed next to ours, 'CHANNEL: BEFORE AFTER, ...' (e.g. "
            "the seed's 'A_ex_m: 0.041 0.076, B_ex_m: 0.030 0.052'); empty: none.",
            "as published");
    declare(prm,
            "Published note",
            "",
            P::Anything(),
            "Where the published exponents come from and in which units (printed with them).",
            "none");
    prm.leave_subsection();
    prm.leave_subsection();
  }

  AnalysesSettings
  parse_analyses(dealii::ParameterHandler &prm, const Scene &scene)
  {
    AnalysesSettings s;
    ParameterReader  r(prm, scene.file);
    r.enter("Analyses");
    for (const auto &name : r.get_list("List of analyses"))
      {
        if (name == "phase-portrait")
          s.phase_portrait = true;
        else if (name == "poincare")
          s.poincare = true;
        else if (name == "lyapunov")
          s.lyapunov = true;
        else
          r.fail("List of analyses", "valid analyses are " + std::string(analysis_names));
      }

    std::vector<std::string> clearance;
    for (const auto *j : scene.clearance_joints)
      clearance.push_back(j->name());
    s.joints = r.get_list("Joints");
    if (s.joints.empty())
      s.joints = clearance;
    for (const auto &j : s.joints)
      if (std::find(clearance.begin(), clearance.end(), j) == clearance.end())
        {
          std::string list;
          for (const auto &c : clearance)
            list += (list.empty() ? "" : ", ") + c;
          r.fail("Joints",
                 "'" + j + "' is not a clearance joint of this scene; the clearance joints are: " +
                   (list.empty() ? std::string("none") : list),
                 "Journal-centre motion exists only for joints with Model = clearance; analyse an "
                 "ideal mechanism through 'Bodies'.");
        }
    s.bodies = r.get_list("Bodies");
    for (const auto &b : s.bodies)
      if (scene.mechanism->body_index(b) < 0)
        r.fail("Bodies", "'" + b + "' is not a body of this scene (ground cannot be analysed)");

    s.given_driving_period = r.get_double("Driving period");
    s.section_phase        = r.get_double("Section phase");
    s.transient            = r.get_double("Transient");
    s.sample_interval      = r.get_double("Sample interval");
    if ((s.phase_portrait || s.lyapunov) && !(s.sample_interval > 0.0))
      r.fail("Sample interval", "it must be > 0 s when phase-portrait or lyapunov is listed");
    if (!(scene.start_time + s.transient < scene.end_time))
      r.fail("Transient",
             "it must end before the run does (End time − Start time = " +
               format_number(scene.end_time - scene.start_time) + " s)");

    r.enter("Lyapunov");
    for (const auto &m : r.get_list("Methods"))
      if (m == "two-trajectory")
        s.two_trajectory = true;
      else if (const auto method = analysis::parse_method(m))
        s.methods.push_back(*method);
    s.two_trajectory_separation = r.get_double("Two-trajectory separation");
    s.renormalization_interval  = r.get_double("Renormalization interval");
    if (s.lyapunov && s.two_trajectory && !(s.two_trajectory_separation > 0.0))
      r.fail("Two-trajectory separation", "it must be > 0 m");
    if (s.lyapunov && s.two_trajectory && !(s.renormalization_interval > 0.0))
      r.fail("Renormalization interval", "it must be > 0 s");
    s.directions = r.get_list("Directions");
    if (s.lyapunov && s.methods.empty() && !s.two_trajectory)
      r.fail("Methods", "at least one of wolf, rosenstein, two-trajectory is needed when lyapunov is listed");
    if (s.lyapunov && s.directions.empty())
      r.fail("Directions", "at least one of x, y is needed when lyapunov is listed");
    if (const long d = r.get_integer("Delay"); d > 0)
      s.delay = static_cast<std::size_t>(d);
    if (const long m = r.get_integer("Embedding dimension"); m > 0)
      s.dimension = static_cast<unsigned int>(m);
    r.leave();
    r.enter("Before-after wear");
    s.comparison_delay     = r.get_double("Delay");
    s.comparison_dimension = static_cast<unsigned int>(r.get_integer("Embedding dimension"));
    for (const auto &v : r.get_list("Delay scan"))
      s.delay_scan.push_back(std::stod(v));
    s.two_trajectory_cycles    = r.get_double("Two-trajectory cycles");
    s.two_trajectory_tolerance = r.get_double("Two-trajectory tolerance");
    if (s.lyapunov && s.two_trajectory && !(s.two_trajectory_cycles > 0.0))
      r.fail("Two-trajectory cycles", "it must be > 0 when Lyapunov/Methods has two-trajectory");
    if (s.lyapunov && s.two_trajectory && !(s.two_trajectory_tolerance > 0.0))
      r.fail("Two-trajectory tolerance", "it must be > 0");
    s.published_exponents = r.get("Published exponents");
    s.published_note      = r.get("Published note");
    try
      {
        parse_published_exponents(s.published_exponents, "");
      }
    catch (const InputError &e)
      {
        r.fail("Published exponents", e.message());
      }
    r.leave();
    r.leave();
    if (s.poincare)
      driving_period(scene, s); // throws if there is none, or the phase exceeds it
    if (s.lyapunov && !s.methods.empty() && s.joints.empty() && s.bodies.empty())
      throw InputError("In " + scene.file +
                       ", 'Analyses/List of analyses' has lyapunov but there is nothing to "
                       "analyse: the scene has no clearance joints and 'Analyses/Bodies' is empty.");
    return s;
  }

  namespace
  {
    double
    driving_period(const Scene &scene, const AnalysesSettings &s)
    {
      double      T = s.given_driving_period;
      if (!(T > 0.0))
        {
          std::vector<double> speeds;
          std::string         names;
          for (const auto d : scene.drivers)
            {
              const std::string &name = scene.mechanism->get_constraints()[d]->name;
              scene.parameters->enter_subsection("Joint " + name);
              const double omega = scene.parameters->get_double("Angular velocity");
              scene.parameters->leave_subsection();
              names += (names.empty() ? "" : ", ") + name + " " + format_number(omega) + " rad/s";
              if (omega != 0.0)
                speeds.push_back(std::abs(omega));
            }
          if (speeds.empty())
            throw InputError("In " + scene.file +
                             ", the driving period is needed (Poincaré sections, sweeps) but the "
                             "scene has no turning angle driver" +
                             (names.empty() ? std::string() : " (" + names + ")") +
                             ". Set 'Analyses/Driving period' (s).");
          for (const double w : speeds)
            if (std::abs(w - speeds.front()) > same_speed * speeds.front())
              throw InputError("In " + scene.file + ", the angle drivers turn at different rates (" +
                               names + "), so their common period is not obvious. Set "
                               "'Analyses/Driving period' (s) to it.");
          T = two_pi / speeds.front();
        }
      if (!(s.section_phase < T))
        throw InputError("In " + scene.file + ", 'Analyses/Section phase' is " +
                         format(s.section_phase, 6) + " s; it must be smaller than the driving period (" +
                         format(T, 6) + " s).");
      return T;
    }
  } // namespace

  double
  driving_period(const Scene &scene)
  {
    return driving_period(scene, scene.analyses);
  }

  // -----------------------------------------------------------------------------------
  // The analyses of one run.

  SceneAnalyses::SceneAnalyses(const Scene &scene)
    : SceneAnalyses(scene, scene.analyses)
  {}

  SceneAnalyses::SceneAnalyses(const Scene &scene, const AnalysesSettings &settings)
    : scene(scene)
    , settings(settings)
  {
    auto &ledger = EffectLedger::instance();
    for (const auto &name : settings.names())
      ledger.record_construction("analysis", name);
    if (!settings.any())
      return;
    period                   = settings.poincare ? driving_period(scene) : 0.0;
    const double record_from = scene.start_time + settings.transient;
    const auto & mech        = *scene.mechanism;

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
          try
            {
              T = driving_period(scene);
            }
          catch (const InputError &)
            {
              T = 0.0;
            }
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
    if (!(run.driving_period > 0.0))
      {
        try
          {
            run.driving_period = driving_period(scene);
          }
        catch (const InputError &)
          {
            run.driving_period = 0.0; // only used to express exponents per period
          }
      }
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
        Json j                        = Json::object();
        j["channel"]                  = "state";
        j["method"]                   = "two-trajectory";
        j["exponent_per_s"]           = shadow->exponent();
        j["unit"]                     = "1/s (natural log)";
        const double T                = recorded_run().driving_period;
        if (T > 0.0)
          j["exponent_per_driving_period"] = shadow->exponent() * T;
        j["renormalizations"]         = shadow->n_renormalizations();
        j["renormalization_interval_s"] = settings.renormalization_interval;
        j["separation_m"]             = settings.two_trajectory_separation;
        if (!out.contains("lyapunov"))
          out["lyapunov"] = Json::array();
        out["lyapunov"].push_back(j);
        if (!output_directory.empty())
          {
            std::ostringstream csv;
            csv << std::setprecision(10) << "time_s,running_exponent_per_s\n";
            PlotSeries running;
            running.title = "running estimate";
            for (std::size_t k = 0; k < shadow->running_time().size(); ++k)
              {
                csv << shadow->running_time()[k] << ',' << shadow->running_exponent()[k] << '\n';
                running.x.push_back(shadow->running_time()[k]);
                running.y.push_back(shadow->running_exponent()[k]);
              }
            write_file_atomically(output_directory + "/lyapunov_state_two-trajectory.csv", csv.str());
            PlotSpec plot;
            plot.title   = "Two-trajectory (Benettin) largest Lyapunov exponent of the state = " +
                         format(shadow->exponent()) + " 1/s";
            plot.x_label = "time [s]";
            plot.y_label = "running estimate [1/s, natural log]";
            plot.series  = {running};
            plot_png(plot, output_directory + "/lyapunov_state_two-trajectory.png");
          }
      }
    return out;
  }

  // -----------------------------------------------------------------------------------
  // Outputs from a recorded run.

  Json
  analyse_recorded_run(const analysis::RecordedRun &run,
                       const AnalysesSettings &     settings,
                       const std::string &          output_directory)
  {
    const bool write = !output_directory.empty();
    if (write)
      make_output_directory(output_directory);
    const std::string dir = output_directory + "/";
    Json              out = Json::object();
    Json              list = Json::array();
    for (const auto &n : settings.names())
      list.push_back(n);
    out["list"] = list;
    if (run.driving_period > 0.0)
      out["driving_period_s"] = run.driving_period;
    out["transient_s"] = settings.transient;
    Json files         = Json::array();

    const bool have_section = run.section.points.n_samples() > 0;

    // The recorded data, whenever there is some: read_recorded_run() reads it back.
    if (write && run.series.n_samples() > 0)
      {
        write_sampled_csv(run.series, dir + "analysis_series.csv", false);
        files.push_back("analysis_series.csv");
      }
    if (run.series.n_samples() > 0)
      {
        out["series_sample_interval_s"] = run.sample_interval;
        out["series_samples"]           = run.series.n_samples();
      }

    // Phase portraits: the series, and one PNG per position-velocity pair with the
    // Poincaré points of the same pair in red (seed Figs 9-10).
    if (settings.phase_portrait)
      {
        Json pp            = Json::object();
        pp["n_samples"]    = run.series.n_samples();
        pp["sample_interval_s"] = run.sample_interval;
        if (write)
          {
            for (const auto &pair : phase_pairs(settings))
              {
                const std::size_t ip = run.series.index(pair.position), iv = run.series.index(pair.velocity);
                PlotSpec          plot;
                plot.title   = "Phase portrait, " + pair.title + label_suffix(run);
                plot.x_label = pair.position + " " + unit_label(run.series.units[ip]);
                plot.y_label = pair.velocity + " " + unit_label(run.series.units[iv]);
                PlotSeries orbit;
                orbit.title   = "phase orbit";
                orbit.x       = run.series.values[ip];
                orbit.y       = run.series.values[iv];
                orbit.options = "lw 0.5 lc rgb 'black'";
                plot.series.push_back(orbit);
                if (have_section && run.section.points.has(pair.position) && run.section.points.has(pair.velocity))
                  {
                    PlotSeries points;
                    points.title   = "Poincaré points (one per " + format(run.section.period) + " s)";
                    points.style   = "points";
                    points.options = "pt 7 ps 0.8 lc rgb 'red'";
                    points.x       = run.section.points.values[run.section.points.index(pair.position)];
                    points.y       = run.section.points.values[run.section.points.index(pair.velocity)];
                    plot.series.push_back(points);
                  }
                const std::string png = "phase_portrait_" + pair.position + ".png";
                if (plot_png(plot, dir + png))
                  files.push_back(png);
              }
          }
        out["phase_portrait"] = pp;
      }

    // Poincaré section: every state channel at t_k, and its spread.
    if (settings.poincare)
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
            write_sampled_csv(run.section.points, dir + "poincare_section.csv", true);
            files.push_back("poincare_section.csv");
            for (const auto &pair : phase_pairs(settings))
              {
                if (!run.section.points.has(pair.position))
                  continue;
                const auto &      p  = run.section.points;
                const std::size_t ip = p.index(pair.position), iv = p.index(pair.velocity);
                PlotSpec          plot;
                plot.title = "Poincaré section (t = " + format(run.section.first_time) + " s + k · " +
                             format(run.section.period) + " s), " + pair.title + label_suffix(run);
                plot.x_label = pair.position + " " + unit_label(p.units[ip]);
                plot.y_label = pair.velocity + " " + unit_label(p.units[iv]);
                PlotSeries points;
                points.title   = std::to_string(p.n_samples()) + " section points";
                points.style   = "points";
                points.options = "pt 7 ps 0.8 lc rgb 'red'";
                points.x       = p.values[ip];
                points.y       = p.values[iv];
                plot.series.push_back(points);
                const std::string png = "poincare_" + pair.position + ".png";
                if (plot_png(plot, dir + png))
                  files.push_back(png);
              }
          }
        out["poincare"] = ps;
      }

    // Largest Lyapunov exponents of the journal-centre coordinates.
    if (settings.lyapunov)
      {
        auto &ledger = EffectLedger::instance();
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
              j["delay_rule"] = e.embedding.delay_choice ? analysis::describe(e.embedding.delay_choice->rule) :
                                                           "given";
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
                  if (write_lyapunov_curve(e, channel, dir + stem))
                    files.push_back(stem + ".png");
                }
              results.push_back(j);
            }
        out["lyapunov"] = results;
      }
    if (write)
      out["files"] = files;
    return out;
  }

  namespace
  {
    /** The unit of a channel from its name's suffix (analysis/channels.h). */
    std::string
    unit_of(const std::string &name)
    {
      for (const auto &[suffix, unit] : std::vector<std::pair<std::string, std::string>>{
             {"_rad_s", "rad/s"}, {"_m_s", "m/s"}, {"_rad", "rad"}, {"_m", "m"}})
        if (name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
          return unit;
      return "";
    }

    /** A CSV written by write_sampled_csv(); @p skip leading columns before time_s. */
    analysis::SampledChannels
    read_sampled_csv(const std::string &path, const std::size_t skip)
    {
      std::ifstream in(path);
      if (!in)
        throw InputError("Cannot read the recorded run file '" + path + "'.");
      analysis::SampledChannels s;
      std::string               line;
      std::getline(in, line);
      const auto header = dealii::Utilities::split_string_list(line, ',');
      if (header.size() < skip + 1 || header[skip] != "time_s")
        throw InputError("'" + path + "' is not a recorded series of wearlink (no time_s column).");
      for (std::size_t c = skip + 1; c < header.size(); ++c)
        {
          s.names.push_back(header[c]);
          s.units.push_back(unit_of(header[c]));
        }
      s.values.assign(s.names.size(), {});
      std::size_t line_no = 1;
      while (std::getline(in, line))
        {
          ++line_no;
          if (line.empty())
            continue;
          const auto fields = dealii::Utilities::split_string_list(line, ',');
          if (fields.size() != header.size())
            throw InputError("'" + path + "', line " + std::to_string(line_no) + ": " +
                             std::to_string(fields.size()) + " fields, the header has " +
                             std::to_string(header.size()) + ".");
          s.time.push_back(std::stod(fields[skip]));
          for (std::size_t c = 0; c < s.names.size(); ++c)
            s.values[c].push_back(std::stod(fields[skip + 1 + c]));
        }
      return s;
    }
  } // namespace

  analysis::RecordedRun
  read_recorded_run(const std::string &output_directory, const std::string &label)
  {
    const std::string dir     = output_directory + "/";
    const Json        summary = read_json_file(dir + "summary.json");
    if (!summary.contains("analyses"))
      throw InputError("The run in '" + output_directory +
                       "' recorded no analyses ('Analyses/List of analyses' was empty).");
    const Json &          a = summary.at("analyses");
    analysis::RecordedRun run;
    run.label = label;
    if (a.contains("driving_period_s"))
      run.driving_period = a.at("driving_period_s").as_number();
    if (a.contains("series_sample_interval_s"))
      {
        run.sample_interval = a.at("series_sample_interval_s").as_number();
        run.series          = read_sampled_csv(dir + "analysis_series.csv", 0);
      }
    if (a.contains("poincare"))
      {
        run.section.period     = a.at("poincare").at("period_s").as_number();
        run.section.first_time = a.at("poincare").at("first_time_s").as_number();
        run.section.points     = read_sampled_csv(dir + "poincare_section.csv", 1);
      }
    return run;
  }
} // namespace wearlink::io
