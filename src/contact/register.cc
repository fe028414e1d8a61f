// SPDX-License-Identifier: LGPL-2.1-or-later
// Registration of the contact layer's plugins: one line per family.
#include "contact/friction_law.h"
#include "contact/normal_force_law.h"
#include "contact/pressure_model.h"

namespace wearlink::contact
{
  void
  register_normal_force_laws();
  void
  register_friction_laws();
  void
  register_hertz_strip();
  void
  register_winkler();

  Registry<PressureModel> &
  pressure_models()
  {
    static Registry<PressureModel> r("pressure model");
    return r;
  }

  void
  register_contact_effects()
  {
    register_normal_force_laws();
    register_friction_laws();
    register_hertz_strip();
    register_winkler();
  }
} // namespace wearlink::contact
