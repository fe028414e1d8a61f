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

#include <functional>
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

    // Hooks of a run that is more than a wear run (workflows/wear/life.h); none by default.
    /** Limits every iteration's factor (wear::WearLoop::set_factor_limit). */
    wear::FactorLimit factor_limit;
    /**
     * Called after every iteration with the loop (the joints hold the new profiles),
     * after the iteration's own files and before its checkpoint.
     */
    std::function<void(const wear::WearLoop &loop)> after_iteration;
    /** Ends the loop before the next iteration when it returns true (then as if finished). */
    std::function<bool(const wear::WearLoop &loop)> stop;
    /** Adds to the summary of a finished run before it is written. */
    std::function<void(Json &summary)> extend_summary;
    /**
     * Warnings of other runs of this command (a life run's response runs), merged into
     * the summary's and printed with them; not kept in the checkpoint.
     */
    const ValidityWarnings *more_warnings = nullptr;
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

  /** Run (or resume) the wear loop of @p scene. */
  WearRunResult
  run_wear(io::Scene &scene, const WearRunOptions &options);
} // namespace wearlink::workflows
