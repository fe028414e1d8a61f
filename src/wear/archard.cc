// SPDX-License-Identifier: LGPL-2.1-or-later
#include "wear/archard.h"

#include "base/effect_ledger.h"
#include "base/numbers.h"

#include <cmath>

namespace wearlink::wear
{
  namespace
  {
    using numbers::two_pi;
  }

  ArchardAccumulator::ArchardAccumulator(const contact::JointGeometry &g,
                                         double                        bore_coefficient,
                                         double                        pin_coefficient,
                                         contact::PressureModel       &model)
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
    if (!(s.load.normal_force > 0) || !(std::abs(s.sliding_speed) > 0) || !(s.weight > 0))
      return;
    ++pressure_evaluations;
    model.evaluate(s.load, pressure);
    deposit(s, pressure.bore, pressure.pin);
  }

  void
  ArchardAccumulator::deposit(const LoadSample &s, const std::vector<double> &bore, const std::vector<double> &pin)
  {
    const double speed  = std::abs(s.sliding_speed);
    const double f_bore = s.weight * k_bore * speed;
    const double f_pin  = s.weight * k_pin * speed;
    for (unsigned int k = 0; k < bore_depth_.size(); ++k)
      if (bore[k] > 0)
        {
          const double dh = f_bore * bore[k];
          bore_depth_[k] += dh;
          bore_volume += dh * bore_area(k);
        }
    for (unsigned int k = 0; k < pin_depth_.size(); ++k)
      if (pin[k] > 0)
        {
          const double dh = f_pin * pin[k];
          pin_depth_[k] += dh;
          pin_volume += dh * pin_area(k);
        }
    bore_archard += f_bore * s.load.normal_force;
    pin_archard += f_pin * s.load.normal_force;
    sliding_distance += s.weight * speed;
  }

  namespace
  {
    /** out[k] = scale · p(ψ_k − shift) on the periodic grid, linear between samples. */
    void
    shift_periodic(const std::vector<double> &p, double shift, double scale, std::vector<double> &out)
    {
      const auto n = static_cast<long>(p.size());
      out.assign(p.size(), 0.0);
      double x = shift / two_pi * n;
      x -= n * std::floor(x / n);
      const long   i = static_cast<long>(std::floor(x));
      const double f = x - i;
      // a = k − i and b = k − i − 1 modulo n, advanced without a division per sample.
      long a = ((-i) % n + n) % n, b = a == 0 ? n - 1 : a - 1;
      for (long k = 0; k < n; ++k)
        {
          out[k] = scale * ((1 - f) * p[a] + f * p[b]);
          b      = a;
          a      = a + 1 == n ? 0 : a + 1;
        }
    }
  } // namespace

  void
  ArchardAccumulator::add_shaped(const LoadSample &s, const LoadSample &key, const contact::SurfacePressure &p)
  {
    if (!(s.load.normal_force > 0) || !(std::abs(s.sliding_speed) > 0) || !(s.weight > 0) ||
        !(key.load.normal_force > 0))
      return;
    const double scale = s.load.normal_force / key.load.normal_force;
    // Contact direction in each body's frame, now and at the key.
    const double d_bore =
      (s.load.contact_angle - s.load.bushing_angle) - (key.load.contact_angle - key.load.bushing_angle);
    const double d_pin = (s.load.contact_angle - s.load.pin_angle) - (key.load.contact_angle - key.load.pin_angle);
    shift_periodic(p.bore, d_bore, scale, shifted_bore);
    shift_periodic(p.pin, d_pin, scale, shifted_pin);
    deposit(s, shifted_bore, shifted_pin);
  }

  void
  ArchardAccumulator::add_history(const std::vector<LoadSample> &h, bool every_step, double window, double t0)
  {
    if (every_step)
      {
        for (const auto &s : h)
          add(s);
        return;
      }
    std::size_t begin = 0;
    while (begin < h.size())
      {
        const double w   = std::floor((h[begin].time - t0) / window);
        std::size_t  end = begin;
        std::size_t  key = begin;
        while (end < h.size() && std::floor((h[end].time - t0) / window) == w)
          {
            if (h[end].load.normal_force > h[key].load.normal_force)
              key = end;
            ++end;
          }
        ++pressure_evaluations;
        model.evaluate(h[key].load, pressure);
        const contact::SurfacePressure key_pressure = pressure;
        for (std::size_t i = begin; i < end; ++i)
          add_shaped(h[i], h[key], key_pressure);
        begin = end;
      }
  }
} // namespace wearlink::wear
