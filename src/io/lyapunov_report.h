// SPDX-License-Identifier: LGPL-2.1-or-later
// The convergence data and plot of one largest-Lyapunov-exponent estimate, shared by the
// `wearlink lyapunov` command and the scene analyses (workflows/run/analyses.h): for Wolf's method
// the running estimate against the evolution time, for Rosenstein's the mean log
// divergence <ln d(k)> against time with the fitted line. Units are always stated:
// natural log, per second when the sample interval is known, else per sample.
#pragma once

#include "analysis/lyapunov.h"

#include <string>

namespace wearlink::io
{
  /**
   * Write STEM.csv (the plotted data) and STEM.png (the plot) of @p est, an estimate for
   * the series called @p column. Both atomically. Returns false if the PNG could not be
   * made (gnuplot missing); the CSV is always written.
   */
  bool
  write_lyapunov_curve(const analysis::LyapunovEstimate &est, const std::string &column, const std::string &stem);
} // namespace wearlink::io
