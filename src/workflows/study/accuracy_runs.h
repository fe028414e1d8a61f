// SPDX-License-Identifier: LGPL-2.1-or-later
// The runs of an accuracy study (workflows/study/accuracy_study.h): each an effective scene,
// read, built and run once — a wear run without its final outputs, or a plain run —
// measuring its wall time, the worn volume, largest depth and depth profile of every
// wearing joint's surfaces, the peak contact force of every clearance joint and the peak
// acceleration of the response body.
//
// The runs are spread over the ranks of MPI_COMM_WORLD when MPI is initialised
// (`mpirun -np R wearlink study accuracy ...`; one rank, or no MPI, runs them all): the
// runs are queued largest predicted cost first, and each rank takes the next one from
// the queue whenever it is free (a counter on rank 0 incremented with MPI's one-sided
// atomics), so no rank idles while runs are left; a run's result does not depend on the
// rank that runs it. Each rank prints a line per run with an estimate of the time left:
// the predicted cost of the runs not yet taken, shared by the ranks, at its measured
// seconds per unit of predicted cost. The predicted cost of a run is the
// simulated driving cycles it integrates (wear iterations × cycles per iteration, or the
// simulated time over the driving period) × (scene relative tolerance / its own)^(1/5)
// (a 5th-order method's step count), × 1.3 for dop853 and × 2 for the fe pressure model:
// a guess, corrected by the measured rate as runs finish. At the end each rank prints its
// wall and CPU time: the CPU times say what the study takes on cores of its own when the
// machine is shared.
#pragma once

#include "base/json.h"
#include "base/parameters.h"
#include "io/scene.h"

#include <map>
#include <string>
#include <vector>

namespace wearlink::workflows
{
  /** What one run of a study measured. */
  struct Measurement
  {
    bool        ok = true;
    std::string failure;
    double      wall_time = 0; ///< reading + building + running [s]
    double      cpu_time  = 0; ///< the process's CPU time over the same [s] (wall time on a quiet core)
    std::map<std::string, double>              quantities; ///< e.g. "A V_pin" [m³], "A F_peak" [N], "a_peak"
    std::map<std::string, std::vector<double>> profiles;   ///< depth per area [m], e.g. "A profile_pin"
  };

  /** Run the scene @p file under @p overrides and measure it (a failed run: ok = false). */
  Measurement
  measure(const std::string &file, const ParameterOverrides &overrides);

  Json
  to_json(const Measurement &m);
  Measurement
  measurement_from_json(const Json &j);

  /** One run of a study's plan. */
  struct StudyJob
  {
    ParameterOverrides overrides;
    std::string        label;    ///< for progress lines, e.g. "baumgarte = 2.5; 2.5"
    double             cost = 1; ///< predicted, relative (see the file comment)
  };

  /** The predicted cost of a run of @p scene relative to the study's @p reference scene. */
  double
  predicted_cost(const io::Scene &scene, const io::Scene &reference);

  /**
   * Measure every job of @p file (on the ranks, if MPI is initialised). Returns the
   * measurements in job order on rank 0, an empty list on the other ranks.
   */
  std::vector<Measurement>
  measure_jobs(const std::string &file, const std::vector<StudyJob> &jobs, bool progress);

  /** True on rank 0 of MPI_COMM_WORLD, or without MPI. */
  bool
  is_study_root();
} // namespace wearlink::workflows
