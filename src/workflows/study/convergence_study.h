// SPDX-License-Identifier: LGPL-2.1-or-later
// Do a wear scene's worn profiles converge? `wearlink study convergence SCENE.prm`
// refines the discretization of the worn surfaces together with the wear step and runs
// an ensemble at every level, so that the differences between levels stand beside the
// chaos floor (the spread of runs that differ only in a ~1e-9 rad perturbation).
//
// A level is a refinement factor r (default 1, 2, 4; the scene's own settings are r = 1):
//  - the surfaces: every wearing joint on the hertz-strip or winkler pressure model gets
//    r × the scene's Number of discrete areas; one on the fe model r × finer surface
//    elements (fe/Surface element size ÷ r), its profile keeping the scene's areas;
//  - the wear step: fixed extrapolation, r × the iterations of a factor ÷ r (the same
//    revolutions; r × iterations must be a whole number); adaptive, Maximum depth
//    increment ÷ r.
// Each level runs `members` ensemble members (the scene's own run and members − 1
// perturbed as `--ensemble` perturbs them, workflows/ensemble/ensemble.h), on the MPI ranks with
// the accuracy study's job queue (workflows/study/accuracy_runs.h).
//
// Per level, joint and surface: the members' mean depth profile and its band (the
// members' smallest and largest depth at each angle), the mean of the members' largest
// depth, envelope depth (wear/depth_measures.h), worn volume and roughness, and the mean
// wall time. Each level is compared with the finest: the relative L2 difference of the
// mean profiles on the coarser level's angles ("point by point"; the finer profile
// interpolated periodically), the largest pointwise difference relative to the finest
// largest depth, and the relative differences of the largest depth, envelope depth and
// volume. The chaos floor beside them: the L2 difference two single runs of the finest
// level have (the mean over member pairs), and the standard error of a level's mean
// profile (‖std‖/√members, relative): a difference of two mean profiles below about
// 2√2 standard errors is not resolved by the ensemble.
#pragma once

#include "analysis/richardson.h"
#include "base/json.h"
#include "base/parameters.h"
#include "workflows/study/accuracy_runs.h"

#include <cstdint>
#include <string>
#include <vector>

namespace wearlink::workflows
{
  struct ConvergenceRequest
  {
    ParameterOverrides  overrides;                ///< the user's --set, for every run
    std::vector<double> refinements  = {1, 2, 4}; ///< r of each level, increasing
    unsigned int        members      = 4;         ///< ensemble members per level (≥ 2)
    std::uint64_t       seed         = 1;         ///< of the perturbations
    double              perturbation = 1e-9;      ///< [rad]
    bool                progress     = true;
  };

  /** One surface (pin or bushing of a wearing joint) at one level. */
  struct SurfaceLevel
  {
    std::vector<double> mean, low, high;                                      ///< depth per area over the members [m]
    double              largest = 0, envelope = 0, volume = 0, roughness = 0; ///< members' means [m, m, m³, -]
    double              standard_error = 0;                    ///< ‖std of the mean profile‖ / ‖mean‖ [-]
    double              largest_error = 0, envelope_error = 0; ///< standard errors of largest, envelope [m]
    double              pair_difference = 0;                   ///< mean relative L2 difference of two members [-]
    // Against the finest level (0 for the finest itself):
    double l2 = 0, pointwise = 0, largest_change = 0, envelope_change = 0, volume_change = 0;
  };

  struct ConvergenceLevel
  {
    double                    refinement = 1;
    std::vector<std::string>  settings;      ///< "Entry=value" of the level (what it changes)
    unsigned int              ran = 0;       ///< members that ran
    std::vector<std::string>  failures;      ///< of members that failed
    double                    wall_time = 0; ///< mean over the members [s]
    std::vector<SurfaceLevel> surfaces;      ///< in ConvergenceStudy::surfaces order
  };

  /**
   * The Richardson estimate of a surface's largest and envelope depths from the three
   * finest levels (analysis/richardson.h): each level's error against the extrapolated
   * value, so a reader sees what the scene's own level costs in accuracy.
   */
  struct SurfaceExtrapolation
  {
    analysis::RichardsonEstimate largest, envelope;
  };

  struct ConvergenceStudy
  {
    std::string                   scene_file;
    std::vector<std::string>      base_overrides;
    unsigned int                  members = 0;
    std::vector<std::string>      surfaces; ///< "A pin", "A bushing", …
    std::vector<ConvergenceLevel> levels;   ///< coarse → fine
    /** Per surface, from the three finest levels if they refine by one ratio (else empty). */
    std::vector<SurfaceExtrapolation> extrapolations;
    double                            extrapolation_ratio = 0;    ///< their ratio (0: none)
    bool                              root                = true; ///< false on MPI ranks other than 0

    /** convergence.md: the table of every level and surface, and the floor. */
    std::string
    markdown() const;
    /** convergence.json: the same, machine readable. */
    Json
    json() const;
  };

  /**
   * Run the levels of @p request on @p scene_file (a wear scene; InputError before any
   * run otherwise, or for refinements that do not make whole iteration counts). The
   * study is complete on rank 0 (root = false elsewhere).
   */
  ConvergenceStudy
  run_convergence_study(const std::string &scene_file, const ConvergenceRequest &request);

  /**
   * convergence.md, convergence.csv, convergence.json and, per joint and surface,
   * convergence_<J>_<pin|bushing>.csv (angle, each level's mean, low and high) and .png
   * (the mean profiles with the members' bands) into @p dir, each atomically.
   */
  void
  write_convergence_study(const std::string &dir, const ConvergenceStudy &study);
} // namespace wearlink::workflows
