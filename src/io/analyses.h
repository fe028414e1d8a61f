// SPDX-License-Identifier: LGPL-2.1-or-later
// The nonlinear-dynamics analyses a scene selects by name (ARCHITECTURE.md: "which
// analyses to run"; seed §4.4, Figs 9–12):
//   phase-portrait  journal-centre motion of each analysed clearance joint relative to
//                   its bushing, e_x vs ė_x and e_y vs ė_y (and x vs ẋ, y vs ẏ, θ vs ω
//                   of analysed bodies), sampled uniformly on the dense output;
//   poincare        one point per driving period T at t_k = start + phase + k T, taken
//                   from the integrator's dense output at exactly t_k;
//   lyapunov        largest Lyapunov exponent (Wolf 1985 and/or Rosenstein 1993, delay
//                   and dimension given or chosen by mutual information / false
//                   nearest neighbours) of the journal-centre coordinates, in 1/s
//                   (natural log), also per driving period.
// An analysis that is not listed is not constructed and its channels are not recorded:
// SceneAnalyses builds the series recorder only for phase-portrait or lyapunov and the
// section recorder only for poincare, and counts what it built in the effect ledger
// (family "analysis"; resources "analysis channels"; calls "analysis samples",
// "poincare points", "lyapunov estimates"), which summary.json prints.
//
// The outputs are computed from a RecordedRun (analysis/recorded_run.h) by
// analyse_recorded_run(), so the same code serves a run just made and, later, runs
// compared before and after wear.
#pragma once

#include "analysis/lyapunov.h"
#include "analysis/recorded_run.h"
#include "base/json.h"

#include <deal.II/base/parameter_handler.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace wearlink
{
  class ParameterReader;
}

namespace wearlink::io
{
  struct Scene;
  class ShadowTrajectory;

  /** What the scene's `subsection Analyses` asked for (names resolved and checked). */
  struct AnalysesSettings
  {
    bool phase_portrait = false;
    bool poincare       = false;
    bool lyapunov       = false;
    /** Clearance joints analysed (default: every clearance joint of the scene). */
    std::vector<std::string> joints;
    /** Bodies whose centre-of-mass motion is analysed too. */
    std::vector<std::string> bodies;
    /** Driving period T as given [s]; 0 = from the angle drivers (driving_period()). */
    double given_driving_period = 0.0;
    /** Sections at Start time + section_phase + k T [s]. */
    double section_phase = 0.0;
    /** Nothing is recorded before Start time + transient [s]. */
    double transient = 0.0;
    /** Sample interval of the phase-portrait / Lyapunov series [s]. */
    double sample_interval = 1e-3;
    /** Lyapunov: methods, directions ("x", "y") and embedding. */
    std::vector<analysis::LyapunovMethod> methods;
    /** Also the exponent of the simulation itself (io/shadow_trajectory.h). */
    bool   two_trajectory            = false;
    double two_trajectory_separation = 1e-6; ///< d0 [m]
    double renormalization_interval  = 0.02; ///< τ [s]
    std::vector<std::string>              directions;
    std::optional<std::size_t>            delay;
    std::optional<unsigned int>           dimension;

    /**
     * Wear scenes: the before/after-wear comparison (io/dynamics_comparison.h), from the
     * entries of `subsection Before-after wear`: common delay [s] and dimension (0 =
     * automatic on the before-wear run), delay scan [s], published exponents to print.
     */
    double                          comparison_delay     = 0.0;
    unsigned int                    comparison_dimension = 0;
    std::vector<double>             delay_scan;
    std::string                     published_exponents;
    std::string                     published_note;
    /** Two-trajectory exponent runs of the comparison: cycles after Transient, tolerance. */
    double two_trajectory_cycles    = 10;
    double two_trajectory_tolerance = 1e-11;

    /** True if any analysis is listed. */
    bool
    any() const
    {
      return phase_portrait || poincare || lyapunov;
    }
    /** The listed names, in the canonical order. */
    std::vector<std::string>
    names() const;
  };

  /** Declare `subsection Analyses` (called by the scene reader). */
  void
  declare_analyses(dealii::ParameterHandler &prm);

  /**
   * Read `subsection Analyses` of @p scene (already built: joints and bodies exist) from
   * @p prm and check it: listed joints must be clearance joints, bodies must exist, a
   * Poincaré section needs a driving period. InputError naming the entry otherwise.
   */
  AnalysesSettings
  parse_analyses(dealii::ParameterHandler &prm, const Scene &scene);

  /**
   * The driving period of @p scene [s]: Analyses/Driving period if given, otherwise
   * 2π/|ω| of its angle drivers, which must all turn at the same rate (|ω| equal to
   * 1e-12 relative). InputError if neither gives one.
   */
  double
  driving_period(const Scene &scene);

  /**
   * The analyses of one run: builds the recorders the listed analyses need, hands them
   * to the simulation as observers, and afterwards produces the outputs.
   */
  class SceneAnalyses
  {
  public:
    /** The analyses @p settings lists (default: the scene's own). */
    explicit SceneAnalyses(const Scene &scene);
    SceneAnalyses(const Scene &scene, const AnalysesSettings &settings);
    ~SceneAnalyses();

    /** Observers to add to the run (none if nothing is listed). */
    std::vector<mbs::StepObserver *>
    observers();

    /** What was recorded, labelled with @p label. */
    analysis::RecordedRun
    recorded_run(const std::string &label = "") const;

    /**
     * Compute the listed analyses from the recording and, if @p output_directory is not
     * empty, write their files there. Returns the "analyses" part of summary.json (null
     * if nothing is listed).
     */
    Json
    finish(const std::string &output_directory);

  private:
    const Scene &                               scene;
    AnalysesSettings                            settings;
    double                                      period = 0.0;
    std::unique_ptr<analysis::SeriesRecorder>   series;
    std::unique_ptr<analysis::PoincareRecorder> section;
    std::unique_ptr<ShadowTrajectory>           shadow;
  };

  /**
   * The outputs of @p settings' analyses for a recorded run: phase portraits (PNG per
   * position–velocity pair, Poincaré points overlaid in red if recorded, data in
   * the recorded series in analysis_series.csv), the Poincaré section (poincare_section.csv, PNG per pair, the
   * spread of each channel), the Lyapunov exponents (lyapunov_<channel>_<method>.csv and
   * .png, values in the returned JSON). Files only if @p output_directory is not empty;
   * every file atomically.
   */
  Json
  analyse_recorded_run(const analysis::RecordedRun &run,
                       const AnalysesSettings &     settings,
                       const std::string &          output_directory);

  /**
   * The RecordedRun of a run that wrote its analyses into @p output_directory
   * (summary.json, analysis_series.csv, poincare_section.csv), labelled @p label: a
   * run recorded earlier (say before wear) can be analysed or compared again without
   * re-running it. Values are read back as written (12 significant digits).
   * InputError if the directory holds no recorded analyses.
   */
  analysis::RecordedRun
  read_recorded_run(const std::string &output_directory, const std::string &label = "");
} // namespace wearlink::io
