// SPDX-License-Identifier: LGPL-2.1-or-later
// `wearlink compare-signal`: a simulated signal (one column of a run's time_series.csv)
// against a measured one (a CSV file with time_s and a value column), compared by
// analysis/signal_analysis.h on a common uniform grid. The simulated signal is read
// from a finished run's folder (--simulated DIR) or made by running the scene into
// OUTPUT/simulated/. Everything given is checked before anything is run or written
// (the scene, the channel among the columns a run of it writes, the measured file), so
// bad input leaves no output; the outputs are written atomically:
//   signal_overlay.png       both signals on the common grid, and the measured one
//                            shifted back by the lag
//   signal_spectrum.png      both amplitude spectra
//   signal_comparison.json   `measured` and `simulated` blocks (dominant_frequency_Hz,
//                            dominant frequencies and amplitudes, peak_per_cycle and its
//                            mean, rms, mean), lag_s, the grid, the cycle period
#pragma once

#include "base/json.h"
#include "base/parameters.h"

#include <string>
#include <vector>

namespace wearlink::workflows
{
  struct SignalComparisonOptions
  {
    std::string        scene_file;
    ParameterOverrides overrides;
    std::string        measured_file;
    /** The simulated channel: a column of time_series.csv. */
    std::string channel;
    /** The measured file's value column; empty: its only column besides time_s. */
    std::string measured_column;
    /** A finished run's folder holding time_series.csv; empty: run the scene. */
    std::string simulated_directory;
    std::string output_directory;
    bool        progress = false;
  };

  struct SignalComparisonResult
  {
    /** What signal_comparison.json holds. */
    Json json;
    /** The printed table. */
    std::string table;
    /** The files written. */
    std::vector<std::string> files;
  };

  /** Compare as described above; InputError for bad input, before anything is written. */
  SignalComparisonResult
  compare_signal(const SignalComparisonOptions &options);
} // namespace wearlink::workflows
