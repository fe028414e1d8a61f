// SPDX-License-Identifier: LGPL-2.1-or-later
// Running a scene: assemble, integrate, record. The recorder watches every accepted
// step (extremes of body motion, joint forces, constraint violation, energy balance)
// and samples the time series on the dense output; results are written atomically into
// the output directory: summary.json, time_series.csv, parameters.prm (the effective
// scene, with overrides applied).
#pragma once

#include "analysis/recorded_run.h"
#include "base/atomic_file.h"
#include "base/json.h"
#include "base/validity_warnings.h"
#include "io/scene.h"
#include "mbs/simulation.h"

#include <functional>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

namespace wearlink::wear
{
  class LoadRecorder;
}

namespace wearlink::workflows
{
  /**
   * Told of a run's progress: the fraction done (0 … 1) and the progress line the program
   * prints (without its newline). It runs on the run's thread; what it throws stops the run
   * (its temporary files removed) and leaves the run.
   */
  using ProgressCallback = std::function<void(double fraction, const std::string &line)>;

  struct RunOptions
  {
    /** Where to write; empty: write nothing (library use, tests). */
    std::string output_directory;
    /** Progress lines on stderr. */
    bool progress = false;
    /** If set, told of the progress at each tenth of the run (whether or not it is printed). */
    ProgressCallback on_progress;
    /** More observers to notify after every accepted step. */
    std::vector<mbs::StepObserver *> observers;
    /**
     * If set, the load history of a wear iteration: the run hands it the diagnostics of
     * the clearance joints it evaluates at every accepted step for its own figures (before
     * the observers), so that each joint is evaluated once per step, not twice. The run
     * then evaluates the joints as the load history always has, without the bodies'
     * cos and sin from mbs::body_trig() (libmvec's differ from std::cos in the last bits):
     * the wear stays the same to the bit, and the run's own joint figures and energy
     * balance may differ from a run without it in the last bits (a wear iteration keeps
     * only their validity warnings).
     */
    wear::LoadRecorder *loads = nullptr;
    /**
     * Continuation (wear iterations): start from this full state [q | v | z] at
     * start_time instead of assembling, and stop at end_time (NaN: the scene's).
     */
    const Eigen::VectorXd *initial_state = nullptr;
    double                 start_time    = std::numeric_limits<double>::quiet_NaN();
    double                 end_time      = std::numeric_limits<double>::quiet_NaN();
    /** If set, receives the state at the end of the run. */
    Eigen::VectorXd *final_state = nullptr;
    /**
     * Build the analyses the scene lists (Analyses/List of analyses). The iterations of
     * a wear run switch them off: they are run once before and once after wear instead
     * (workflows/wear/wear_run.h).
     */
    bool analyses = true;
    /** If set, these analyses instead of the scene's (e.g. without the shadow trajectory). */
    const analysis::AnalysesSettings *analyses_settings = nullptr;
    /** If set (and analyses are on), receives what the analyses recorded. */
    analysis::RecordedRun *recorded = nullptr;
    /**
     * If set, receives this run's validity warnings (merged: a wear run collects those of
     * all its iterations). They are always in the summary's `warnings` list, and printed
     * to stderr when the run writes its summary.json.
     */
    ValidityWarnings *warnings = nullptr;
  };

  /** The columns of the time_series.csv a run of @p scene writes, in order. */
  std::vector<std::string>
  time_series_columns(const io::Scene &scene);

  /** What integrate_scene() returns: the run summary and its validity warnings. */
  struct IntegratedRun
  {
    Json             summary;
    ValidityWarnings warnings;
  };

  /**
   * Assemble (or continue from options.initial_state) and integrate @p scene, observed as
   * @p options say; the analyses it lists write their files into options.output_directory
   * if that is set, the run's own files are not written. @p time_series, if given, is
   * called once after assembly and returns the stream of the time series (or null).
   * The summary's `warnings` list names every result beyond the validity of its model
   * (run_validity_warnings()). Throws InputError for an impossible assembly,
   * NumericalError for a failure of the numerics.
   */
  IntegratedRun
  integrate_scene(io::Scene &scene, const RunOptions &options, const std::function<AtomicFile *()> &time_series = {});

  /**
   * A run of @p scene from its start to its end time: integrate_scene(), then, if
   * options.output_directory is set, its files (time_series.csv, parameters.prm,
   * summary.json). Returns the run summary (doc/running.md, "What a run writes").
   */
  Json
  run_scene(io::Scene &scene, const RunOptions &options);

  /**
   * The closing files of a run of @p scene in @p directory, each atomically: parameters.prm
   * (the effective scene), then @p summary as summary.json; @p warnings printed to stderr.
   * run_scene() ends with it, and so does a wear run.
   */
  void
  write_run_summary(const io::Scene        &scene,
                    const std::string      &directory,
                    const Json             &summary,
                    const ValidityWarnings &warnings);

  /**
   * The results of a run (its @p summary) beyond the validity of their models: a
   * penetration beyond 20 % of a joint's radial clearance, a constraint violation beyond
   * 1000 × the position tolerance (at least 1 µm), an energy balance off by more than
   * the integrator promises, an rk4 step above 1/100 of the driving period, evaluations
   * of a contact-law table beyond its largest load; after the scene's own warnings of
   * implausible entries (io::Scene::warnings).
   */
  ValidityWarnings
  run_validity_warnings(const io::Scene &scene, const Json &summary);

  /** Assemble @p scene at its start time (q, v); throws InputError if impossible. */
  void
  assemble_scene(const io::Scene &scene, Eigen::VectorXd &q, Eigen::VectorXd &v);
} // namespace wearlink::workflows
