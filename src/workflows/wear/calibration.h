// SPDX-License-Identifier: LGPL-2.1-or-later
// `wearlink calibrate`: the Archard wear coefficients of a scene's wearing joints from
// measured mass losses (io/measurements.h), by whole wear runs (the worn gap feeds back
// on the dynamics).
//
// A forward run is the scene (with the user's --set) with every measured surface's
// coefficient overridden ('Joint J/Clearance/archard/Pin|Bushing wear coefficient') and
// the wear loop stretched to the measurement's revolutions R: with Extrapolation = fixed
// 'Wear/Extrapolation factor' = R / (Cycles per iteration × Number of iterations), with
// adaptive 'Wear/Target revolutions' = R. Joints measured after different revolution
// counts take one run per count. Nothing of a forward run is written; its mass losses are
// the wear volume × density of the wear state.
//
// The steps (formulas in analysis/calibration.h):
//  1. the secant: forward runs of the unperturbed scene from the prior coefficients until
//     every surface's predicted mass loss is within the tolerance of the measurement (or
//     the run limit) → k* and the slope S = d log m / d log k of each surface;
//  2. the ensemble: N runs at k* whose initial angles are perturbed as by `run
//     --ensemble` (workflows/ensemble/ensemble.h member_overrides; member n on MPI rank n mod R)
//     → the mean m̄ and the sample std s of each predicted mass loss. N = 1: no ensemble,
//     m̄ the secant's own run at k*, s not estimated (0);
//  3. the calibrated value k = k* (m / m̄)^(1/S) (the mean of the ensemble, not one
//     chaotic sample, meets the measurement; one secant step on the mean), and its 95 %
//     interval from σ_m and σ_c = s sqrt(1 + 1/N) through S: the measured test is itself
//     one sample of the chaotic wear (it scatters about the mean by s) and the mean is
//     known to s/√N;
//  4. measured profiles, if any: one unperturbed run per revolution count at the
//     calibrated coefficients, its worn surfaces compared with them
//     (analysis::compare_profile: aligned within the angle search; RMS difference,
//     worn areas). A check of the calibration, not part of the fit.
// The secant runs are the same on every rank (each rank runs them: no communication, the
// same k* everywhere); the members are spread over the ranks and gathered on rank 0,
// which writes the outputs.
#pragma once

#include "analysis/calibration.h"
#include "base/json.h"
#include "base/parameters.h"
#include "io/measurements.h"
#include "io/scene.h"

#include <cstdint>
#include <string>

namespace wearlink::workflows
{
  struct CalibrationOptions
  {
    std::string              scene_file;
    std::string              measurements_file;
    ParameterOverrides       overrides;           ///< the user's --set, for every forward run
    unsigned int             members      = 4;    ///< of the ensemble at k*; 1: none
    std::uint64_t            seed         = 1;    ///< of the ensemble's perturbations
    double                   perturbation = 1e-9; ///< σ of each angle driver's initial angle [rad]
    analysis::SecantSettings secant;
    std::string              output_directory; ///< "": nothing written
    bool                     progress = true;  ///< a line per forward run on stderr (rank 0)
  };

  /**
   * @p o with the numbers of its request checked: @p members a whole number 1 … 1000,
   * @p seed 0 … 2⁵³, @p perturbation > 0 and ≤ 1e-3 rad, @p tolerance in (0, 1),
   * @p max_runs 1 … 100 (InputError naming the option, --ensemble, --seed, ...).
   */
  CalibrationOptions
  calibration_options(CalibrationOptions o,
                      double             members,
                      double             seed,
                      double             perturbation,
                      double             tolerance,
                      double             max_runs);

  /** The scene and the measurements of a calibration, read and checked. */
  struct CalibrationProblem
  {
    io::Scene        scene; ///< read with the user's overrides (the prior coefficients)
    io::Measurements measurements;
  };

  /**
   * Read the scene and the measurements of @p options (InputError for bad input, before
   * anything runs or is written; also for a scene without wear).
   */
  CalibrationProblem
  load_calibration(const CalibrationOptions &options);

  /**
   * Calibrate (see the top of this file) and, on rank 0 with an output directory, write
   * calibration.json, calibrated.prm and calibration.png there (io/calibration_files.h).
   * Returns calibration.json's content (on every rank: the ranks differ only in whether
   * they write). NumericalError if a secant run fails or every member of the ensemble
   * does; InputError if the scene predicts no wear of a measured surface.
   */
  Json
  calibrate(CalibrationProblem &problem, const CalibrationOptions &options);

  /** The printed summary of calibration.json @p report: per surface k, interval, masses. */
  std::string
  calibration_table(const Json &report);
} // namespace wearlink::workflows
