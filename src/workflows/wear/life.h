// SPDX-License-Identifier: LGPL-2.1-or-later
// `wearlink life SCENE`: when is the joint worn out? The wear loop of a wear run
// (workflows/wear/wear_run.h: checkpoints, resume, the output folder, atomic files, validity
// warnings, the outputs after wear) run until the stop criteria of the scene's `Life`
// section are decided (analysis/life_criteria.h), with every iteration's extrapolation
// limited so that each wear criterion is located within `Life/Tolerance`. Reports, per
// criterion, its status and the revolutions to reach it (and the hours at the scene's
// driving speed), in summary.json (`life`) and in life_history.csv / life.png.
//
// What a life run adds to the phases of a wear run (workflows::WearRun):
//  - the factor limit of every iteration (the crossing of the nearest wear criterion);
//  - after every iteration: the criteria's values, and with `Response rise` a run of
//    1 + Response cycles cycles from the initial assembly with the current profiles for
//    the response measure (the fresh one before the first iteration), into
//    life_history.csv — written before the iteration's checkpoint, read back on
//    --resume (rows past the checkpoint dropped);
//  - the end: every criterion settled — a wear criterion reached; the response criterion
//    decided on its trend (analysis/life_criteria.h), or unable to come before the wear
//    lives once they are all reached (the upper 95 % bound of its rise at the earliest of
//    them below its limit) — or Life/Maximum revolutions, or Life/Maximum iterations
//    (which replaces Wear/Number of iterations; with adaptive extrapolation
//    Life/Maximum revolutions replaces Wear/Target revolutions).
// The life (`headline`, `first_criterion`, `life_revolutions`) is the decided criterion
// with the fewest revolutions; an undecided one is reported with what is known (its
// trend's crossing and 95 % interval, and why it is not decided) and is not the life,
// unless it is reached and its whole interval ends before every reached wear criterion.
#pragma once

#include "base/json.h"
#include "io/scene.h"
#include "workflows/wear/wear_run.h"

#include <string>

namespace wearlink::workflows
{
  struct LifeRunOptions
  {
    std::string output_directory; ///< "" : nothing is written (tests)
    bool        resume   = false; ///< continue the run in output_directory
    bool        progress = true;
    std::string progress_prefix; ///< of the progress lines (an ensemble's member)
    /**
     * If set, told after every iteration of the life's progress — the largest criterion's
     * value over its limit, at most 1 — and of its progress line (workflows/run/run.h).
     */
    ProgressCallback on_progress;
  };

  struct LifeRunResult
  {
    WearRunResult         wear;
    analysis::LifeHistory history;
    /** summary.json's `life` block (doc/tutorials/life_and_ensembles.md). */
    Json life;
  };

  /**
   * For `wearlink life`: InputError naming the file and every criterion entry with its
   * unit and range unless @p scene switches on at least one criterion and wears.
   */
  void
  check_life_criteria(const io::Scene &scene);

  /**
   * Run (or resume) the life of @p scene. InputError (before anything is written) if it
   * has no wearing joint or no criterion.
   */
  LifeRunResult
  run_life(io::Scene &scene, const LifeRunOptions &options);

  /**
   * The printed table of a life block: per criterion its limit, status, revolutions,
   * hours, joint and bracket (wear) or 95 % interval (trend; with why it is undecided),
   * then the life and why.
   */
  std::string
  life_table(const Json &life);
} // namespace wearlink::workflows
