// SPDX-License-Identifier: LGPL-2.1-or-later
// The plots of an ensemble with uncertain inputs (workflows/ensemble/uncertain_inputs.h):
//  - sensitivity.png, a tornado per headline figure: one horizontal bar per uncertain
//    input, its rank correlation (or first-order and total Sobol index) with the figure,
//    and the 95 % interval as a thin line;
//  - life_cdf.png: the empirical CDF of each decided life criterion's revolutions over
//    the members (step i/n at the i-th smallest).
// Both are skipped with a warning when gnuplot is missing (summary.json holds the data).
#pragma once

#include "base/json.h"

#include <map>
#include <string>
#include <vector>

namespace wearlink::io
{
  /** sensitivity.png from summary.json's `sensitivity` block. False without gnuplot or figures. */
  bool
  plot_sensitivity(const Json &sensitivity, const std::string &path);

  /** life_cdf.png of each criterion's decided revolutions [rev]. False without gnuplot or data. */
  bool
  plot_life_cdf(const std::map<std::string, std::vector<double>> &revolutions,
                const std::string                                &path,
                const std::string                                &title);
} // namespace wearlink::io
