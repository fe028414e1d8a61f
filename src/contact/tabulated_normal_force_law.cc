// SPDX-License-Identifier: LGPL-2.1-or-later
#include "contact/tabulated_normal_force_law.h"

#include <deal.II/base/exceptions.h>

#include <limits>

namespace wearlink::contact
{
  TabulatedNormalForceLaw::TabulatedNormalForceLaw(const double restitution, const double min_impact_velocity)
    : damping_factor(3 * (1 - restitution * restitution) / 4)
    , min_impact_velocity(min_impact_velocity)
  {
  }

  void
  TabulatedNormalForceLaw::evaluate(const NormalContactInput &in, NormalContactOutput &out) const
  {
    out = NormalContactOutput();
    if (!(in.penetration > 0))
      return;
    AssertThrow(!table.empty(), dealii::ExcMessage("A tabulated normal force law was evaluated before its table."));
    const auto v = table.evaluate(in.penetration, in.bore_angle, in.pin_angle);
    ++evaluations;
    above += v.region == ForceApproachTable::Region::above ? 1 : 0;
    below += v.region == ForceApproachTable::Region::below ? 1 : 0;
    out.elastic_force = v.force;
    out.force         = lankarani_nikravesh_force(v.force, in, damping_factor, min_impact_velocity);
  }

  double
  TabulatedNormalForceLaw::round_elastic_force(const double approach, double) const
  {
    AssertThrow(!table.empty(), dealii::ExcMessage("A tabulated normal force law was evaluated before its table."));
    return approach > 0 ? table.evaluate(approach, 0, 0).force : 0.0;
  }

  double
  TabulatedNormalForceLaw::potential(const NormalContactInput &in) const
  {
    return table.empty() ? 0.0 : table.potential(in.penetration, in.bore_angle, in.pin_angle);
  }

  double
  TabulatedNormalForceLaw::exponent() const
  {
    return std::numeric_limits<double>::quiet_NaN();
  }

  void
  TabulatedNormalForceLaw::update_geometry(const JointGeometry &geometry)
  {
    table = build_table(geometry);
  }

  bool
  TabulatedNormalForceLaw::uses_direction() const
  {
    return table.n_bore_directions() > 1 || table.n_pin_directions() > 1;
  }

  Json
  TabulatedNormalForceLaw::report() const
  {
    Json j;
    j["table_load_levels"]     = table.n_levels();
    j["table_bore_directions"] = table.n_bore_directions();
    j["table_pin_directions"]  = table.n_pin_directions();
    j["table_force_range_N"]   = table.empty() ? Json::array() : Json{table.forces().front(), table.forces().back()};
    j["evaluations"]           = evaluations;
    j["extrapolations_above_table"] = above;
    j["extrapolations_below_table"] = below;
    return j;
  }
} // namespace wearlink::contact
