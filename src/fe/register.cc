// SPDX-License-Identifier: LGPL-2.1-or-later
// Registration of the FE layer's plugins: one line per plugin.
#include "contact/pressure_model.h"
#include "fe/fe_pressure_model.h"

namespace wearlink::fe
{
  void
  register_fe_effects()
  {
    contact::pressure_models().add("fe",
                                   "2D plane-strain contact FE model of the actual (worn) pin and bushing: gmsh mesh, "
                                   "deal.II elasticity, condensed frictionless contact solved per load state "
                                   "(REFERENCE.md §5).",
                                   declare_fe_settings,
                                   [](ParameterReader &reader) -> std::unique_ptr<contact::PressureModel> {
                                     return std::make_unique<FePressureModel>(read_fe_settings(reader));
                                   });
  }
} // namespace wearlink::fe
