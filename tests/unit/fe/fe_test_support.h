// SPDX-License-Identifier: LGPL-2.1-or-later
// Shared set-up of the FE tests: the example pair of params/pin_bushing.prm (steel bore
// R1 = 12 mm in a ring of outer radius 24 mm, steel pin R2 = 11.5 mm, L = 10 mm) and the
// Hertz line-contact numbers of doc/models.md §5.1 for it.
#pragma once

#include "contact/pressure_model.h"
#include "fe/fe_settings.h"
#include "fe/pin_bushing_model.h"
#include "support/test_support.h"

#include <cmath>
#include <string>
#include <vector>

namespace wearlink::fe::testing
{
  constexpr double pi = 3.14159265358979323846;
  constexpr double R1 = 0.012;
  constexpr double R2 = 0.0115;
  constexpr double L  = 0.01;

  inline contact::JointGeometry
  steel_pair(unsigned int n_points = 360)
  {
    contact::JointGeometry g;
    g.bore         = Profile::round(R1, n_points);
    g.pin          = Profile::round(R2, n_points);
    g.axial_length = L;
    g.bushing      = {207e9, 0.3};
    g.pin_material = {207e9, 0.3};
    return g;
  }

  /**
   * A worn pair as the wear loop makes it: a smooth dent of depth @p bore_depth in the
   * bore and @p pin_depth on the pin, both centred at −y (cos² over ±30°).
   */
  inline contact::JointGeometry
  dented_pair(const double bore_depth, const double pin_depth)
  {
    auto                g = steel_pair();
    const unsigned int  n = g.bore.n_points();
    std::vector<double> bore(n), pin(n);
    for (unsigned int k = 0; k < n; ++k)
      {
        const double x    = std::remainder(2 * pi * k / n + pi / 2, 2 * pi) / (pi / 6);
        const double dent = std::abs(x) < 1 ? std::pow(std::cos(0.5 * pi * x), 2) : 0.0;
        bore[k]           = R1 + bore_depth * dent;
        pin[k]            = R2 - pin_depth * dent;
      }
    g.bore = Profile::from_samples(bore, "dented bore");
    g.pin  = Profile::from_samples(pin, "dented pin");
    return g;
  }

  /** Settings refined on an arc of ±@p half_angle_deg about −y (the load direction). */
  inline FeSettings
  settings_about_minus_y(double surface_size, double half_angle_deg, double layer = 0.2e-3)
  {
    FeSettings s;
    s.surface_element_size    = surface_size;
    s.refined_layer_thickness = layer;
    s.outer_radius            = 0.024;
    s.refined_arc_half_angle  = half_angle_deg * pi / 180;
    s.refined_arc_bore_centre = -pi / 2;
    s.refined_arc_pin_centre  = -pi / 2;
    return s;
  }

  /** A force-controlled load of @p F newtons pushing the pin along −y. */
  inline LoadCase
  load_minus_y(double F)
  {
    LoadCase lc;
    lc.control = Control::force;
    lc.load    = {{0.0, -F}};
    return lc;
  }

  /** Hertz internal line contact (doc/models.md §5.1): half-width b [m] and peak p0 [Pa]. */
  struct Hertz
  {
    double b, p0;
  };
  inline Hertz
  hertz(const contact::JointGeometry &g, double F)
  {
    const double E = contact::effective_modulus(g.bushing, g.pin_material);
    const double R = R1 * R2 / (R1 - R2);
    const double P = F / g.axial_length;
    const double b = std::sqrt(4 * P * R / (pi * E));
    return {b, 2 * P / (pi * b)};
  }

  inline std::string
  mesh_file(const std::string &name)
  {
    return wearlink::testing::fresh_directory("fe_" + name) + "/pin_bushing.msh";
  }
} // namespace wearlink::fe::testing
