// SPDX-License-Identifier: LGPL-2.1-or-later
#include "wear/archard.h"

#include "base/effect_ledger.h"
#include "base/numbers.h"

#include <cmath>
#include <cstring>

namespace wearlink::wear
{
  namespace
  {
    using numbers::two_pi;
  }

  bool
  identical_histories(const std::vector<LoadSample> &a, const std::vector<LoadSample> &b)
  {
    // Every member is a double (no padding): a new member that is not fails here.
    static_assert(sizeof(LoadSample) == 12 * sizeof(double), "identical_histories compares LoadSample's bytes");
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(LoadSample)) == 0);
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
    pending_bore = {std::vector<double>(geometry.bore.n_points(), 0.0), {}};
    pending_pin  = {std::vector<double>(geometry.pin.n_points(), 0.0), {}};
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
    if (!(sequential_factor > 0))
      {
        model.evaluate(s.load, pressure);
        deposit(s, pressure.bore, pressure.pin);
        return;
      }
    const auto c = compliance(s, 1.0);
    model.evaluate_wearing(s.load, c, pressure);
    const unsigned int n    = parts(s.load, c);
    LoadSample         part = s;
    part.weight             = s.weight / n;
    for (unsigned int m = 0; m < n; ++m)
      {
        if (m > 0)
          {
            ++pressure_evaluations;
            model.evaluate_wearing(s.load, compliance(part, 1.0), pressure);
          }
        deposit(part, pressure.bore, pressure.pin);
        flush();
      }
  }

  contact::WearCompliance
  ArchardAccumulator::compliance(const LoadSample &s, const double scale) const
  {
    const double ds = sequential_factor * std::abs(s.sliding_speed) * s.weight * scale;
    return {k_bore * ds, k_pin * ds};
  }

  unsigned int
  ArchardAccumulator::parts(const contact::ContactLoad &load, const contact::WearCompliance &c)
  {
    constexpr double max_parts = 4096; // a bound, far above what a scene needs (split_states counts them)
    const double     stable    = model.stable_compliance(load);
    if (!(c.total() > stable))
      return 1;
    ++split_states;
    return static_cast<unsigned int>(std::min(max_parts, std::ceil(c.total() / stable)));
  }

  void
  ArchardAccumulator::flush()
  {
    removed.clear();
    for (const unsigned int k : pending_bore.areas)
      {
        removed.bore_areas.push_back(k);
        removed.bore_depth.push_back(sequential_factor * pending_bore.depth[k]);
        pending_bore.depth[k] = 0;
      }
    for (const unsigned int k : pending_pin.areas)
      {
        removed.pin_areas.push_back(k);
        removed.pin_depth.push_back(sequential_factor * pending_pin.depth[k]);
        pending_pin.depth[k] = 0;
      }
    pending_bore.areas.clear();
    pending_pin.areas.clear();
    if (!removed.bore_areas.empty() || !removed.pin_areas.empty())
      model.remove_material(removed);
  }

  void
  ArchardAccumulator::deposit(const LoadSample &s, const std::vector<double> &bore, const std::vector<double> &pin)
  {
    const double speed      = std::abs(s.sliding_speed);
    const double f_bore     = s.weight * k_bore * speed;
    const double f_pin      = s.weight * k_pin * speed;
    const bool   sequential = sequential_factor > 0;
    for (unsigned int k = 0; k < bore_depth_.size(); ++k)
      if (bore[k] > 0)
        {
          const double dh = f_bore * bore[k];
          bore_depth_[k] += dh;
          bore_volume += dh * bore_area(k);
          if (sequential && dh > 0)
            pending_bore.add(k, dh);
        }
    for (unsigned int k = 0; k < pin_depth_.size(); ++k)
      if (pin[k] > 0)
        {
          const double dh = f_pin * pin[k];
          pin_depth_[k] += dh;
          pin_volume += dh * pin_area(k);
          if (sequential && dh > 0)
            pending_pin.add(k, dh);
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
        add_window(h, begin, end, key);
        begin = end;
      }
  }

  // Sequentially, the window's wear is one load state of the key's pressure shape: its
  // compliance is the sum of the samples' compliances, each scaled by F_n/F_n,key (the
  // shape is scaled to each sample's load), and the surfaces are worn after the window.
  void
  ArchardAccumulator::add_window(const std::vector<LoadSample> &h,
                                 const std::size_t              begin,
                                 const std::size_t              end,
                                 const std::size_t              key)
  {
    const auto &k = h[key];
    ++pressure_evaluations;
    if (!(sequential_factor > 0))
      {
        model.evaluate(k.load, pressure);
        const contact::SurfacePressure key_pressure = pressure;
        for (std::size_t i = begin; i < end; ++i)
          add_shaped(h[i], k, key_pressure);
        return;
      }
    if (!(k.load.normal_force > 0))
      return;
    contact::WearCompliance c;
    for (std::size_t i = begin; i < end; ++i)
      if (h[i].load.normal_force > 0 && h[i].weight > 0)
        {
          const auto ci = compliance(h[i], h[i].load.normal_force / k.load.normal_force);
          c.bore += ci.bore;
          c.pin += ci.pin;
        }
    model.evaluate_wearing(k.load, c, pressure);
    const unsigned int n = parts(k.load, c);
    for (unsigned int m = 0; m < n; ++m)
      {
        if (m > 0)
          {
            ++pressure_evaluations;
            model.evaluate_wearing(k.load, {c.bore / n, c.pin / n}, pressure);
          }
        const contact::SurfacePressure key_pressure = pressure;
        for (std::size_t i = begin; i < end; ++i)
          {
            LoadSample part = h[i];
            part.weight /= n;
            add_shaped(part, k, key_pressure);
          }
        flush();
      }
  }
} // namespace wearlink::wear
