// SPDX-License-Identifier: LGPL-2.1-or-later
#include "wear/archard.h"

#include <cmath>

namespace wearlink::wear
{
  namespace
  {
    constexpr double two_pi = 6.283185307179586476925286766559;
  }

  ArchardAccumulator::ArchardAccumulator(const contact::JointGeometry &g,
                                         double                        bore_coefficient,
                                         double                        pin_coefficient,
                                         contact::PressureModel &      model)
    : geometry(g)
    , k_bore(bore_coefficient)
    , k_pin(pin_coefficient)
    , model(model)
  {
    clear();
  }

  void
  ArchardAccumulator::set_geometry(const contact::JointGeometry &g)
  {
    geometry = g;
  }

  void
  ArchardAccumulator::clear()
  {
    bore_depth_.assign(geometry.bore.n_points(), 0.0);
    pin_depth_.assign(geometry.pin.n_points(), 0.0);
    bore_volume = pin_volume = bore_archard = pin_archard = sliding_distance = 0;
  }

  double
  ArchardAccumulator::bore_area(unsigned int k) const
  {
    return geometry.axial_length * geometry.bore[k] * two_pi / geometry.bore.n_points();
  }

  double
  ArchardAccumulator::pin_area(unsigned int k) const
  {
    return geometry.axial_length * geometry.pin[k] * two_pi / geometry.pin.n_points();
  }

  void
  ArchardAccumulator::rate(const contact::ContactLoad &load, double sliding_speed, WearRate &out)
  {
    out.bore.assign(geometry.bore.n_points(), 0.0);
    out.pin.assign(geometry.pin.n_points(), 0.0);
    out.bore_volume = out.pin_volume = out.bore_archard = out.pin_archard = 0;
    out.sliding_speed = std::abs(sliding_speed);
    out.active        = load.normal_force > 0 && out.sliding_speed > 0;
    if (!out.active)
      return;
    ++pressure_evaluations;
    model.evaluate(load, pressure);
    for (unsigned int k = 0; k < out.bore.size(); ++k)
      if (pressure.bore[k] > 0)
        {
          out.bore[k] = k_bore * pressure.bore[k] * out.sliding_speed;
          out.bore_volume += out.bore[k] * bore_area(k);
        }
    for (unsigned int k = 0; k < out.pin.size(); ++k)
      if (pressure.pin[k] > 0)
        {
          out.pin[k] = k_pin * pressure.pin[k] * out.sliding_speed;
          out.pin_volume += out.pin[k] * pin_area(k);
        }
    out.bore_archard = k_bore * load.normal_force * out.sliding_speed;
    out.pin_archard  = k_pin * load.normal_force * out.sliding_speed;
  }

  void
  ArchardAccumulator::add(const WearRate &r, double weight)
  {
    if (!r.active)
      return;
    for (unsigned int k = 0; k < bore_depth_.size(); ++k)
      bore_depth_[k] += weight * r.bore[k];
    for (unsigned int k = 0; k < pin_depth_.size(); ++k)
      pin_depth_[k] += weight * r.pin[k];
    bore_volume += weight * r.bore_volume;
    pin_volume += weight * r.pin_volume;
    bore_archard += weight * r.bore_archard;
    pin_archard += weight * r.pin_archard;
    sliding_distance += weight * r.sliding_speed;
  }
} // namespace wearlink::wear
