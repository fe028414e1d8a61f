// SPDX-License-Identifier: LGPL-2.1-or-later
// Before/after-wear comparison of the nonlinear dynamics (seed §4.4, Figs 9–12): two
// recorded runs of the same mechanism, one with the fresh and one with the worn joint
// profiles, side by side.
//
//  - Phase portraits of each analysed joint's journal centre (e vs ė, x and y), before
//    and after wear in two panels on the same axes, the Poincaré points in red.
//  - Largest Lyapunov exponents of the journal-centre coordinates, before and after, at
//    ONE embedding for both runs. On clearance-joint series a time-delay exponent is not
//    an invariant of the embedding: measured on the nine-bar, it falls roughly like
//    1/delay (about 500, 50 and 10 1/s at 1, 5 and 20 ms, before and after wear alike,
//    Wolf and Rosenstein alike), because the journal rattles on a millisecond scale
//    while the crank drives on a 0.5 s one. Exponents chosen with each run's own
//    automatic delay can therefore differ by the delays alone. The common delay (in
//    seconds) and dimension are given or taken from the before-wear run's automatic
//    choice, and the comparison is repeated over a scan of delays, so a reader sees
//    whether "after > before" holds at every scale or only at some.
//  - Robust indicators from the runs' summaries: impacts per driving period, fraction
//    of time in contact, peak contact force, spread of the Poincaré points, peak
//    accelerations of chosen bodies.
// Published exponents (the seed's 0.041 → 0.076 for A, 0.030 → 0.052 for B, with no
// unit or sample interval stated) are printed next to ours when the caller passes them.
#pragma once

#include "analysis/analyses_settings.h"
#include "analysis/lyapunov.h"
#include "analysis/recorded_run.h"
#include "base/json.h"

#include <optional>
#include <string>
#include <vector>

namespace wearlink::workflows
{
  /** A recorded run and its summary.json (may be null: then no robust indicators). */
  struct ComparedRun
  {
    analysis::RecordedRun run;
    Json                  summary;
  };

  /**
   * The exponent of the simulation itself (two-trajectory, workflows/run/shadow_trajectory.h),
   * measured in separate runs before and after wear; printed with the comparison.
   */
  struct SimulationExponents
  {
    double before     = 0.0; ///< [1/s]
    double after      = 0.0; ///< [1/s]
    double separation = 0.0; ///< d0 [m]
    double interval   = 0.0; ///< renormalization interval τ [s]
    double tolerance  = 0.0; ///< relative tolerance of both runs
    double duration   = 0.0; ///< measured time of each run [s]
    /** Why a run gave no exponent (NaN above): the integrator's numerical failure; "" if it ran. */
    std::string failure_before, failure_after;
  };

  struct DynamicsComparisonSettings
  {
    /** Clearance joints compared (their channels must be in both recordings). */
    std::vector<std::string> joints;
    /** Directions of the Lyapunov channels, "x" and/or "y". */
    std::vector<std::string> directions{"x"};
    /** Lyapunov estimators; empty: no exponents. */
    std::vector<analysis::LyapunovMethod> methods;
    /** Common delay [s]; 0: the before-wear run's automatic choice (mutual information). */
    double delay = 0.0;
    /** Common embedding dimension; 0: false nearest neighbours on the before-wear run. */
    unsigned int dimension = 0;
    /** Delays of the scan [s] (empty: no scan). */
    std::vector<double> delay_scan;
    /** Bodies whose peak accelerations are compared (from the summaries). */
    std::vector<std::string> bodies;
    /** Published exponents to print next to ours, and where they come from. */
    std::vector<analysis::PublishedExponents> published;
    std::string                               published_note;
    /** If set, the two-trajectory exponents of both states (one row "state"). */
    std::optional<SimulationExponents> simulation_exponents;
  };

  /** What compare_dynamics() produced. */
  struct DynamicsComparison
  {
    /** The "before_after" part of summary.json. */
    Json json;
    /** The tables as Markdown (also written to before_after.md, printed by the commands). */
    std::string report;
  };

  /**
   * Compare @p before and @p after. Writes, if @p output_directory is not empty, each
   * file atomically: before_after_phase_<J>_<x|y>.png, before_after_lyapunov.csv,
   * before_after_delay_scan.csv/.png, before_after.md. InputError if a compared channel
   * is missing from a recording, or a delay is shorter than a sample interval.
   */
  DynamicsComparison
  compare_dynamics(const ComparedRun                &before,
                   const ComparedRun                &after,
                   const DynamicsComparisonSettings &settings,
                   const std::string                &output_directory);
} // namespace wearlink::workflows
