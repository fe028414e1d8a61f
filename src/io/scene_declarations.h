// SPDX-License-Identifier: LGPL-2.1-or-later
// The declarations of a scene's parameter tree, assembled from the layers that read
// them: bodies, joints and the integrator (mbs/mbs_parameters.h), clearance joints
// (contact/clearance_parameters.h and wear/wear_settings.h), the wear loop
// (wear/wear_settings.h), the analyses, the life and the uncertain inputs (io/); this
// file itself declares the top (format, title, the mechanism's bodies, joints and
// gravity), the simulated interval and the output. --print-parameters prints this tree.
// The reader (scene_reader.cc) assembles the scene from it.
#pragma once

#include "base/parameters.h"

#include <string>
#include <vector>

namespace wearlink::io
{
  /** Rows time_series.csv may have (1e8 rows of ~50 columns: about 100 GB). */
  inline constexpr double max_time_series_rows = 1e8;

  /** Declare a scene's whole tree for the bodies @p bodies and the joints @p joints. */
  void
  declare_scene(dealii::ParameterHandler       &prm,
                const std::vector<std::string> &bodies,
                const std::vector<std::string> &joints);
} // namespace wearlink::io
