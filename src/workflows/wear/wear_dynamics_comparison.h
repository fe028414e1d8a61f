// SPDX-License-Identifier: LGPL-2.1-or-later
// The dynamics of a wear scene before and after its wear, compared (the wear run's
// `Analyses` block: workflows/compare/dynamics_comparison.h).
#pragma once

#include "io/scene.h"
#include "wear/wear_state.h"
#include "workflows/compare/dynamics_comparison.h"

#include <string>
#include <vector>

namespace wearlink::workflows
{
  /**
   * The scene's analyses once with the fresh and once with the worn profiles, each run
   * from assembly at Start time to End time (outputs in DIR/dynamics_before and
   * DIR/dynamics_after), then compared (workflows/compare/dynamics_comparison.h) into DIR. The joints
   * are left with the worn profiles.
   */
  DynamicsComparison
  before_after_dynamics(io::Scene                                    &scene,
                        const wear::WearState                        &st,
                        const std::vector<contact::ClearanceJoint *> &joints,
                        const std::string                            &response,
                        const std::string                            &dir,
                        bool                                          progress);
} // namespace wearlink::workflows
