// SPDX-License-Identifier: LGPL-2.1-or-later
// Registration of the FE layer's plugins: one line per plugin.
#include "contact/normal_force_law.h"
#include "contact/pressure_model.h"
#include "fe/fe_normal_force_law.h"
#include "fe/fe_pressure_model.h"

namespace wearlink::fe
{
  void
  register_fe_effects()
  {
    contact::pressure_models().add("fe",
                                   "2D plane-strain contact FE model of the actual (worn) pin and bushing: gmsh mesh, "
                                   "deal.II elasticity, condensed frictionless contact solved per load state "
                                   "(doc/models.md §5).",
                                   declare_fe_settings,
                                   [](ParameterReader &reader) -> std::unique_ptr<contact::PressureModel> {
                                     return std::make_unique<FePressureModel>(read_fe_settings(reader));
                                   });
    contact::normal_force_laws().add(
      "fe",
      "F = F_FE(δ, direction) (1 + 3(1 − c_e²) δ̇/(4 δ̇⁻)): the elastic force tabulated from the 2D contact FE "
      "model of the joint's current profiles, with the Lankarani–Nikravesh hysteresis. The approach δ is the "
      "overlap of the rigid profiles at the pin position of the FE equilibrium (bushing held on its outer edge, pin "
      "loaded through its rigid core, no rotation): the δ the joint computes from its gap (fe/fe_normal_force_law.h).",
      declare_fe_force_law,
      [](ParameterReader &reader) -> std::unique_ptr<contact::NormalForceLaw> {
        return std::make_unique<FeNormalForceLaw>(read_fe_force_law(reader));
      });
  }
} // namespace wearlink::fe
