// SPDX-License-Identifier: LGPL-2.1-or-later
// One FE model per joint set-up, shared by whoever needs it: the `fe` pressure model and
// the `fe` normal force law of a joint ask for a model of the same geometry with the
// same FE settings (they read the same "fe" subsection), and meshing, factoring and the
// compliance columns — most of the FE cost — are then paid once. A live model is reused
// for a geometry when its mesh settings, materials, axial length and profile sample
// counts equal and its meshed profiles lie within FeSettings::remesh_depth of the
// requested ones (exactly equal when that is 0); the model's profiles are then set to
// the requested ones (PinBushingModel::update_profiles). Otherwise a new model is
// meshed. The pool holds models weakly: a model lives while a holder does.
//
// A holder that shares its model must set its own profiles before every solve
// (use_profiles), since another holder may have moved them.
#pragma once

#include "contact/pressure_model.h"
#include "fe/fe_settings.h"
#include "fe/pin_bushing_model.h"

#include <memory>

namespace wearlink::fe
{
  /**
   * A model for @p geometry: a live one within reach (see above) or a new one, meshed
   * into settings.mesh_directory (or a temporary directory that lives with the model),
   * its condensed solver prepared. @p reused (if given) tells which.
   */
  std::shared_ptr<PinBushingModel>
  shared_model(const contact::JointGeometry &geometry, const FeSettings &settings, bool *reused = nullptr);

  /** The live model that shared_model() would hand out for @p geometry, or nullptr (none is made). */
  std::shared_ptr<PinBushingModel>
  find_shared_model(const contact::JointGeometry &geometry, const FeSettings &settings);

  /** True if @p model may serve @p geometry under @p settings (see above). */
  bool
  within_reach(const PinBushingModel &model, const contact::JointGeometry &geometry, const FeSettings &settings);

  /** Set @p model's profiles to @p geometry's (a no-op when they are already). */
  void
  use_profiles(PinBushingModel &model, const contact::JointGeometry &geometry);
} // namespace wearlink::fe
