// SPDX-License-Identifier: LGPL-2.1-or-later
// Which pressure models a comparison can build for a scene's joints: every registered
// one (contact::pressure_models(), in its order) whose required entries the scene sets
// for those joints. The comparisons and the accuracy study take their model lists from
// here, so a newly registered model shows up in them without editing them.
#pragma once

#include "io/scene.h"

#include <string>
#include <vector>

namespace wearlink::io
{
  /**
   * The registered pressure models whose required entries @p scene sets under
   * "Joint <J>/Clearance/<model>" for every joint J of @p joints, in the registry's
   * order (the contact layer's models, then the FE layer's `fe`): winkler only where
   * the scene gives its Layer thickness; the others have defaults throughout.
   */
  std::vector<std::string>
  configured_pressure_models(const Scene &scene, const std::vector<std::string> &joints);
} // namespace wearlink::io
