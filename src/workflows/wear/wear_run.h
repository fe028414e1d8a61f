// SPDX-License-Identifier: LGPL-2.1-or-later
// A wear run of a scene: the wear loop of wear/wear_loop.h driven by the scene's
// dynamics, with checkpoints and progress in the output directory, then the outputs
// after wear (doc/tutorials/wear_prediction.md): the response after wear from the initial assembly
// with the final profiles, the worn profiles and history, the summary, and — if the
// scene lists analyses — the dynamics before and after wear compared
// (workflows/compare/dynamics_comparison.h). A resumed run continues from its checkpoint.
#pragma once

#include "base/json.h"
#include "base/timings.h"
#include "base/validity_warnings.h"
#include "io/scene.h"
#include "wear/wear_loop.h"
#include "wear/wear_state.h"
#include "workflows/run/run.h"

#include <functional>
#include <memory>
#include <string>

namespace wearlink::workflows
{
  struct WearRunOptions
  {
    /** Output and checkpoint directory ("" : nothing is written; no resume). */
    std::string output_directory;
    /** Continue from output_directory/checkpoint.json. */
    bool resume = false;
    /** One line per iteration on stderr. */
    bool progress = true;
    /**
     * Stop after this many iterations of this process, leaving the checkpoint but no
     * final outputs, as a killed run would (tests). 0: no limit.
     */
    unsigned int stop_after = 0;
    /** More observers of every iteration's dynamics (tests). */
    std::vector<mbs::StepObserver *> observers;
    /** Skip the after-wear response run and the plots (tests, comparisons). */
    bool final_outputs = true;
    /** Prefix of the progress lines (an ensemble's member). */
    std::string progress_prefix;
    /**
     * If set, told after every iteration of the fraction of the iterations (of the target
     * revolutions, adaptive) done and of its progress line (workflows/run/run.h).
     */
    ProgressCallback on_progress;
  };

  struct WearRunResult
  {
    wear::WearState state;
    /** The run summary (only when the loop finished). */
    Json summary;
    /** Wall time by phase [s]. */
    PhaseTimings timings;
    bool         finished = false;
    /**
     * If the scene lists analyses: the before/after-wear comparison as Markdown (also in
     * before_after.md; its numbers are in summary["before_after"]).
     */
    std::string before_after_report;
    /**
     * Results beyond their models' validity, over all iterations of this process and the
     * response after wear (summary["warnings"]; not kept across --resume).
     */
    ValidityWarnings warnings;
  };

  /** True if some clearance joint of @p scene has a wear law. */
  bool
  has_wear(const io::Scene &scene);

  /**
   * A wear run in its three phases, for a workflow that composes more around them (the
   * life run of workflows/wear/life.h reads every iteration before its commit, limits
   * the factors and stops the loop on its criteria):
   *
   *     WearRun run(scene, options);          // set-up, start or resume
   *     while (!run.finished()) {
   *       run.iterate();                      // dynamics, wear, the iteration's files
   *       run.commit();                       // its checkpoint
   *     }
   *     auto result = run.finish();           // response after wear, summary, outputs
   *     run.write_summary(result);            // summary.json, parameters.prm
   *
   * The scene must outlive the run. Not copyable: the loop refers to the run's members.
   */
  class WearRun
  {
  public:
    WearRun(io::Scene &scene, const WearRunOptions &options);
    ~WearRun();
    WearRun(const WearRun &) = delete;
    WearRun &
    operator=(const WearRun &) = delete;

    /** True when the loop's iterations are done or its adaptive target is reached. */
    bool
    finished() const;

    /** The loop: its state, last factor and peak loads; set_factor_limit() on it. */
    wear::WearLoop &
    loop();

    /**
     * One iteration of the loop (with options.observers on its dynamics, and the
     * response before wear recorded in the first), then its files: the wear history,
     * the profile frames and, with Wear/FE output, the FE meshes and fields.
     */
    void
    iterate();

    /** The checkpoint of the iteration just done (wear::WearLoop::commit). */
    void
    commit();

    /**
     * The run so far, without the outputs after wear (the loop's state and timings): a
     * run that stops here leaves its last checkpoint, as a killed one would.
     */
    WearRunResult
    interrupted() const;

    /**
     * After the loop: the response after wear from the initial assembly with the final
     * profiles, the summary (with @p more_warnings, a composing workflow's own), the
     * worn profiles and plots, and the before/after-wear comparison if the scene lists
     * analyses.
     */
    WearRunResult
    finish(const ValidityWarnings *more_warnings = nullptr);

    /** summary.json and parameters.prm of @p result into the output directory (if any). */
    void
    write_summary(WearRunResult &result) const;

  private:
    struct Members;
    std::unique_ptr<Members> m;
  };

  /** Run (or resume) the wear loop of @p scene: WearRun's phases one after the other. */
  WearRunResult
  run_wear(io::Scene &scene, const WearRunOptions &options);
} // namespace wearlink::workflows
