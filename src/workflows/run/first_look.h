// SPDX-License-Identifier: LGPL-2.1-or-later
// The first look at a run: the PNGs a person opens first, and a short printed summary.
// Written by `wearlink run` after summary.json and time_series.csv (read back from that
// file, so only with Output/Time series = true), unless Output/Plots = false:
//   orbit_<J>.png        the journal-centre orbit of clearance joint J: the eccentricity
//                        in the bushing's frame (time_series.csv's <J>_ex_local_m,
//                        <J>_ey_local_m) inside the clearance circle, equal axis scales
//   contact_forces.png   normal and friction force of every clearance joint against time
//   accelerations.png    ax and ay of the plot bodies against time (Output/Plot bodies;
//                        by default the sliders, else the body with the largest peak)
// The summary's numbers are those of summary.json (contact fraction, peak forces,
// impacts per joint; peak acceleration components per plot body): peaks over every
// accepted integrator step, which the sampled time series (and so the plots) can miss
// between its samples; the plots' titles say how they were sampled.
#pragma once

#include "base/json.h"
#include "io/scene.h"
#include "workflows/run/run.h"

#include <filesystem>
#include <string>
#include <vector>

namespace wearlink::workflows
{
  struct FirstLook
  {
    /** The PNGs written (paths). */
    std::vector<std::string> plots;
    /** Why a plot was not written (no time series, gnuplot missing); empty if none. */
    std::vector<std::string> notes;
    /** The short summary, a line per joint and per plot body (from summary.json). */
    std::string summary;
    /** Every file of the run's output directory written by the run (sorted paths). */
    std::vector<std::string> written;
  };

  /** The regular files directly in @p directory last written at or after @p start, sorted. */
  std::vector<std::string>
  files_written_since(const std::string &directory, std::filesystem::file_time_type start);

  /**
   * The bodies whose acceleration the first look shows: the scene's plot bodies, or, if
   * it names none, the body with the largest peak acceleration component in
   * @p summary (its `bodies` block).
   */
  std::vector<std::string>
  first_look_bodies(const io::Scene &scene, const Json &summary);

  /** The short summary (FirstLook::summary) of a run's @p summary for @p bodies. */
  std::string
  first_look_summary(const Json &summary, const std::vector<std::string> &bodies);

  /**
   * Write the first-look PNGs of the run of @p scene whose summary is @p summary into
   * @p directory (which holds its time_series.csv), each atomically; with Output/Plots
   * = false only the summary.
   */
  FirstLook
  write_first_look(const io::Scene &scene, const Json &summary, const std::string &directory);

  /** What run_with_first_look() returns. */
  struct LookedAtRun
  {
    Json      summary;
    FirstLook look;
  };

  /**
   * `wearlink run` of a scene without wear: run_scene() into options.output_directory
   * (which must be set), then its first look, with every file the run wrote listed.
   */
  LookedAtRun
  run_with_first_look(io::Scene &scene, const RunOptions &options);
} // namespace wearlink::workflows
