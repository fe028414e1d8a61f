// SPDX-License-Identifier: LGPL-2.1-or-later
// Shared set-up of the pressure-model and wear tests: a steel-on-steel joint and the winkler pressure model
// on it.
#pragma once

#include "base/parameters.h"
#include "contact/pressure_model.h"

#include <memory>
#include <string>

namespace wearlink::wear::testing
{
  /** Steel on steel (E = 207 GPa, ν = 0.3), 10 mm long, with the given profiles. */
  inline contact::JointGeometry
  steel_joint(const Profile &bore, const Profile &pin)
  {
    contact::JointGeometry g;
    g.bore         = bore;
    g.pin          = pin;
    g.axial_length = 0.01;
    g.bushing      = {207e9, 0.3};
    g.pin_material = {207e9, 0.3};
    return g;
  }

  /** The round pair: bore radius 12 mm, pin radius 11.5 mm, @p n_areas areas each. */
  inline contact::JointGeometry
  steel_joint(const unsigned int n_areas)
  {
    return steel_joint(Profile::round(0.012, n_areas), Profile::round(0.0115, n_areas));
  }

  /** The pressure model @p name with its defaults (winkler: a 1 mm layer), no geometry yet. */
  inline std::unique_ptr<contact::PressureModel>
  pressure_model(const std::string &name)
  {
    dealii::ParameterHandler prm;
    contact::pressure_models().declare_all(prm);
    prm.enter_subsection("winkler");
    prm.set("Layer thickness", "1e-3");
    prm.leave_subsection();
    ParameterReader reader(prm, "test");
    return contact::pressure_models().create(name, reader, "Pressure model");
  }

  /** The winkler pressure model (1 mm layer) on @p g. */
  inline std::unique_ptr<contact::PressureModel>
  winkler_on(const contact::JointGeometry &g)
  {
    auto model = pressure_model("winkler");
    model->update_geometry(g);
    return model;
  }
} // namespace wearlink::wear::testing
