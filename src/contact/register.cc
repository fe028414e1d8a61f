// SPDX-License-Identifier: LGPL-2.1-or-later
// Registration of the contact layer's plugins: one line per plugin.
#include "contact/pressure_model.h"

namespace wearlink::contact
{
  Registry<PressureModel> &
  pressure_models()
  {
    static Registry<PressureModel> r("pressure model");
    return r;
  }

  void
  register_contact_effects()
  {}
} // namespace wearlink::contact
