// SPDX-License-Identifier: LGPL-2.1-or-later
// The outputs of a wear run's sliced joints (doc/models.md §1.8), beside the per-slice
// files every wearing joint writes (a slice is a joint named J.s01, J.s02, …):
//   slices_<J>.csv                 per slice: z, mean normal force of the last iteration
//                                  and its share, worn volumes, deepest depths
//   wear_map_<J>_{bushing,pin}.png the worn depth over angle × axial position (final)
//   slices/<J>_{bushing,pin}.pvd   the worn surfaces as cylinders with the depth field
//                                  (VTU, one frame per iteration, at most ten frames
//                                  unless Wear/Every iteration output), for ParaView
// and the summary block sliced_joints: edge-to-mean force, deepest wear and its axial
// position, worn volume per slice.
#pragma once

#include "base/json.h"
#include "io/scene.h"
#include "wear/wear_state.h"

#include <string>

namespace wearlink::io
{
  /** True if a joint of @p scene is sliced. */
  bool
  has_sliced_joints(const Scene &scene);

  /** The summary block of the sliced joints' wear (an empty object without any). */
  Json
  sliced_wear_summary(const Scene &scene, const wear::WearState &state);

  /** The files above into @p dir (nothing without sliced joints). */
  void
  write_sliced_wear_outputs(const std::string &dir, const Scene &scene, const wear::WearState &state);
} // namespace wearlink::io
