// SPDX-License-Identifier: LGPL-2.1-or-later
// The files of `wearlink calibrate` (workflows/wear/calibration.h; names in
// io/output_names.h), each written atomically:
//  - calibration.json  the report (per joint and surface the calibrated coefficient with
//                      its 95 % interval and prior, measured and predicted mass loss with
//                      the ensemble's spread, the secant's runs and residuals);
//  - calibrated.prm    the scene with the calibrated coefficients (text made by the
//                      workflow);
//  - calibration.png   measured against predicted mass loss per surface [mg]: the
//                      measurement with its 95 % bar (± 1.96 σ_m), the ensemble's runs at
//                      the secant's k and their mean with its 95 % bar (± 1.96 std/√N).
#pragma once

#include "base/json.h"

#include <string>
#include <vector>

namespace wearlink::io
{
  /** Write the three files into @p directory (existing); returns the paths written. */
  std::vector<std::string>
  write_calibration_files(const std::string &directory, const Json &report, const std::string &calibrated_prm);
} // namespace wearlink::io
