// SPDX-License-Identifier: LGPL-2.1-or-later
#include "wear/archard.h"

#include "base/effect_ledger.h"

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
    EffectLedger::instance().add_resource("wear buffers");
    clear();
  }

  void
  ArchardAccumulator::set_geometry(const contact::JointGeometry &g)
  {
    geometry = g;
    clear();
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

  // The pressure is an area average per discrete area, so the wear of area k over the
  // sample's weight w is w k_D p_k |v_t| and its volume that times A_k.
  void
  ArchardAccumulator::add(const LoadSample &s)
  {
    const double speed = std::abs(s.sliding_speed);
    if (!(s.load.normal_force > 0) || !(speed > 0) || !(s.weight > 0))
      return;
    ++pressure_evaluations;
    model.evaluate(s.load, pressure);
    const double f_bore = s.weight * k_bore * speed;
    const double f_pin  = s.weight * k_pin * speed;
    for (unsigned int k = 0; k < bore_depth_.size(); ++k)
      if (pressure.bore[k] > 0)
        {
          const double dh = f_bore * pressure.bore[k];
          bore_depth_[k] += dh;
          bore_volume += dh * bore_area(k);
        }
    for (unsigned int k = 0; k < pin_depth_.size(); ++k)
      if (pressure.pin[k] > 0)
        {
          const double dh = f_pin * pressure.pin[k];
          pin_depth_[k] += dh;
          pin_volume += dh * pin_area(k);
        }
    bore_archard += f_bore * s.load.normal_force;
    pin_archard += f_pin * s.load.normal_force;
    sliding_distance += s.weight * speed;
  }
} // namespace wearlink::wear
