// SPDX-License-Identifier: LGPL-2.1-or-later
// What `wearlink lyapunov` does: the largest Lyapunov exponent of one column of a CSV
// series (analysis/lyapunov.h: Wolf or Rosenstein, delay and dimension given or chosen),
// a report of how it was obtained, and its files: lyapunov_<column>_<method>.csv/.png
// (the divergence curve, io/lyapunov_report.h) and .json (the figures).
#pragma once

#include "analysis/lyapunov.h"

#include <string>

namespace wearlink::workflows
{
  struct LyapunovSeriesRequest
  {
    std::string                file;   ///< the CSV series
    std::string                column; ///< the column to analyse
    analysis::LyapunovSettings settings;
    std::string                output_directory = ".";
  };

  /**
   * Estimate, write the files, and return the printed report. The sample interval is
   * the request's (--dt), else the file's time column's, else the exponent is per
   * sample. InputError for a missing file or column, a non-finite or too short series.
   */
  std::string
  analyse_lyapunov_series(const LyapunovSeriesRequest &request);
} // namespace wearlink::workflows
