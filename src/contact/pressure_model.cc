// SPDX-License-Identifier: LGPL-2.1-or-later
// The part of every pressure model that is the same for all (contact/pressure_model.h):
// the current geometry and its wear update, written once.
#include "contact/pressure_model.h"

namespace wearlink::contact
{
  void
  PressureModel::update_geometry(const JointGeometry &geometry)
  {
    current = geometry;
    geometry_changed();
  }

  void
  PressureModel::remove_material(const SurfaceWear &wear)
  {
    auto &bore = current.bore.samples();
    auto &pin  = current.pin.samples();
    for (std::size_t i = 0; i < wear.bore_areas.size(); ++i)
      bore[wear.bore_areas[i]] += wear.bore_depth[i];
    for (std::size_t i = 0; i < wear.pin_areas.size(); ++i)
      pin[wear.pin_areas[i]] -= wear.pin_depth[i];
    material_removed(wear);
  }
} // namespace wearlink::contact
