// SPDX-License-Identifier: LGPL-2.1-or-later
// The declarations of a scene's parameter tree: every entry of the mechanism, its
// bodies, joints and clearance joints, the integrator, the simulated interval and the
// output, once, with its pattern (bounds), default, documentation and unit; the
// analyses, the wear loop and the life add their own subsections (declared by their
// modules). --print-parameters prints this tree. The reader (scene_reader.cc) reads
// what is declared here and assembles the scene.
#pragma once

#include "base/parameters.h"

#include <string>
#include <vector>

namespace wearlink::io
{
  /** The joint types a scene may give ('Joint <j>/Type'). */
  inline constexpr const char *joint_types = "revolute|translational|fixed-angle|angle-driver";
  /** Rows time_series.csv may have (1e8 rows of ~50 columns: about 100 GB). */
  inline constexpr double max_time_series_rows = 1e8;

  /** Declare a scene's whole tree for the bodies @p bodies and the joints @p joints. */
  void
  declare_scene(dealii::ParameterHandler       &prm,
                const std::vector<std::string> &bodies,
                const std::vector<std::string> &joints);
} // namespace wearlink::io
