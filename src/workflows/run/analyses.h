// SPDX-License-Identifier: LGPL-2.1-or-later
// The nonlinear-dynamics analyses a scene selects by name (doc/architecture.md §4;
// seed §4.4, Figs 9–12):
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

#include "analysis/analyses_settings.h"
#include "analysis/recorded_run.h"
#include "base/json.h"
#include "io/scene.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>


namespace wearlink::workflows
{
  class ShadowTrajectory;


  /**
   * The analyses of one run: builds the recorders the listed analyses need, hands them
   * to the simulation as observers, and afterwards produces the outputs.
   */
  class SceneAnalyses
  {
  public:
    /** The analyses @p settings lists (default: the scene's own). */
    explicit SceneAnalyses(const io::Scene &scene);
    SceneAnalyses(const io::Scene &scene, const analysis::AnalysesSettings &settings);
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
    const io::Scene                            &scene;
    analysis::AnalysesSettings                  settings;
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
  analyse_recorded_run(const analysis::RecordedRun      &run,
                       const analysis::AnalysesSettings &settings,
                       const std::string                &output_directory);

} // namespace wearlink::workflows
