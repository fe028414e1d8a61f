// SPDX-License-Identifier: LGPL-2.1-or-later
// A recorded run on disk: the sampled series (analysis_series.csv) and Poincaré section
// (poincare_section.csv) that a run's analyses write, and reading them back with the
// run's summary.json so that a run made earlier can be analysed or compared again.
#pragma once

#include "analysis/recorded_run.h"

#include <string>

namespace wearlink::io
{
  /**
   * Write @p s as CSV to @p path (atomically): `time_s` then one column per channel,
   * 12 significant digits; with @p with_index a leading `section` column.
   */
  void
  write_sampled_csv(const analysis::SampledChannels &s, const std::string &path, bool with_index);

  /**
   * The RecordedRun of a run that wrote its analyses into @p output_directory
   * (summary.json, analysis_series.csv, poincare_section.csv), labelled @p label: a
   * run recorded earlier (say before wear) can be analysed or compared again without
   * re-running it. Values are read back as written (12 significant digits).
   * InputError if the directory holds no recorded analyses.
   */
  analysis::RecordedRun
  read_recorded_run(const std::string &output_directory, const std::string &label = "");
} // namespace wearlink::io
