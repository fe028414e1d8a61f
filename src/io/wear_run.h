// SPDX-License-Identifier: LGPL-2.1-or-later
// The wear loop of a scene (ARCHITECTURE.md "The loop"; seed §4.2): for each iteration
//   1. simulate Cycles per iteration of the mechanism, continuing from the state where
//      the previous iteration ended, while a LoadRecorder keeps the load history of
//      every wearing joint;
//   2. feed that history through the joint's pressure model into Archard's law on
//      both surfaces (wear/archard.h);
//   3. extrapolate: multiply by the fixed factor, or by the adaptive one that caps the
//      largest depth increment, never past Target revolutions;
//   4. update the profiles (bore R1* += f h, pin R2* −= f h, each in its own frame),
//      rebuild the clearance joints' gap from them, give the pressure model the new
//      geometry (the fe model re-meshes every Remesh interval iterations);
//   5. checkpoint (wear/wear_state.h) and print one progress line.
// Then the dynamic response after wear is simulated from the initial assembly with the
// final profiles, and the outputs are written (see README "Wear runs").
// A resumed run reads the checkpoint and continues from its last finished iteration;
// everything the next iteration depends on is in the checkpoint, so it ends with the
// same profiles as an uninterrupted run.
#pragma once

#include "base/json.h"
#include "io/scene.h"
#include "wear/wear_state.h"

#include <map>
#include <string>

namespace wearlink::io
{
  struct WearRunOptions
  {
    /** Output and checkpoint directory ("" : nothing is written; no resume). */
    std::string output_directory;
    /** Continue from output_directory/checkpoint.txt. */
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
  };

  struct WearRunResult
  {
    wear::WearState state;
    /** The run summary (only when the loop finished). */
    Json summary;
    /** Wall time by phase [s]: dynamics, meshing, fe set-up, fe compliance, pressure
     *  evaluation, wear bookkeeping, outputs, total. */
    std::map<std::string, double> timings;
    bool finished = false;
    /**
     * If the scene lists analyses: the before/after-wear comparison as Markdown (also in
     * before_after.md; its numbers are in summary["before_after"]).
     */
    std::string before_after_report;
  };

  /** True if some clearance joint of @p scene has a wear law. */
  bool
  has_wear(const Scene &scene);

  /** Run (or resume) the wear loop of @p scene. */
  WearRunResult
  run_wear(Scene &scene, const WearRunOptions &options);

  /** Duration of one mechanism cycle [s] (Wear/Cycle period, or the first driver's). */
  double
  cycle_period(const Scene &scene);
} // namespace wearlink::io
