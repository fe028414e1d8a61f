// SPDX-License-Identifier: LGPL-2.1-or-later
// Archard's law on both surfaces (wear/archard.h), against closed-form results.
//
// Setup: a fixed bushing (θ_b = 0) and a pin turning uniformly, θ_p = ω t, pressed into
// the bore by a constant force F along −y (contact direction φ* = −π/2), for an integer
// number of revolutions; pressure from the hertz-strip model (a Hertz strip of
// half-width b ≈ 0.09 mm, narrower than one 1° area). The relative sliding speed is
// v = ω R2, so the sliding distance is s = ω R2 T.
// Expected:
//  - both volumes Σ_k h_k A_k equal k_D F s ε/(2 J1(ε)): the strip's area forces are
//    integrated in closed form and the strip carries F as its resultant along the
//    contact direction, so Σ_k p_k A_k = F ε/(2 J1(ε)) at every sample, ε = b/R the
//    strip's half-angle on that surface (1 + 7e-6 here; J1 from std::cyl_bessel_j, an
//    independent reference; tolerance 1e-6 relative as required, the actual error is
//    the Gauss rule's and rounding, ~1e-13);
//  - the pin wears uniformly around its circumference: every pin area passes through
//    the fixed contact the same way, h = k_D F s ε/(2 J1(ε))/(2π R2 L) on every area
//    (the samples are periodic with 8 per area, so each area sees the same strip
//    positions; 1e-9 relative leaves room for rounding only);
//  - the bushing wear is localized: non-zero only within b/R1 + one area of φ*, with
//    its maximum on the area facing the load.
#include "base/numbers.h"
#include "base/parameters.h"
#include "contact/pressure_model.h"
#include "unit/contact/pressure_model_support.h"
#include "wear/archard.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace wearlink;
using namespace wearlink::wear::testing;

namespace
{
  using wearlink::numbers::pi;
} // namespace

TEST(Archard, ConstantLoadOnRotatingPin)
{
  const unsigned int n_areas = 360, per_area = 8, revolutions = 3;
  const auto         g     = steel_joint(n_areas);
  auto               model = pressure_model("hertz-strip");
  model->update_geometry(g);
  const double             k_pin = 2e-13, k_bore = 5e-14; // m³/(N m): different, to see both
  wear::ArchardAccumulator acc(g, k_bore, k_pin, *model);

  const double       force = 100, omega = 4 * pi; // N, rad/s
  const double       r2      = g.pin[0];
  const unsigned int n_steps = n_areas * per_area * revolutions;
  const double       dt      = revolutions * 2 * pi / omega / n_steps;
  for (unsigned int i = 0; i < n_steps; ++i)
    {
      wear::LoadSample s;
      s.load.bushing_angle = 0;
      s.load.pin_angle     = omega * i * dt;
      s.load.contact_angle = -pi / 2;
      s.load.normal_force  = force;
      s.load.force         = {{0, force}};
      s.sliding_speed      = omega * r2;
      s.weight             = dt; // periodic trapezoid = uniform weights
      acc.add(s);
    }
  const double distance  = omega * r2 * n_steps * dt;
  const double line_load = force / g.axial_length;
  const double e_star    = 1 / (2 * (1 - 0.09) / 207e9);
  const double r_star    = 0.012 * 0.0115 / 0.0005;
  const double b         = std::sqrt(4 * line_load * r_star / (pi * e_star));
  // Σ p A over F of a Hertz strip of half-angle ε carrying F as its resultant.
  const auto sum_over_resultant = [](const double epsilon) {
    return epsilon / (2 * std::cyl_bessel_j(1.0, epsilon));
  };
  const double pin_volume  = k_pin * force * distance * sum_over_resultant(b / r2);
  const double bore_volume = k_bore * force * distance * sum_over_resultant(b / 0.012);
  EXPECT_NEAR(acc.sliding_distance, distance, 1e-12 * distance);
  EXPECT_NEAR(acc.pin_volume, pin_volume, 1e-6 * pin_volume);
  EXPECT_NEAR(acc.bore_volume, bore_volume, 1e-6 * bore_volume);

  const double uniform = pin_volume / (2 * pi * r2 * g.axial_length);
  for (unsigned int k = 0; k < n_areas; ++k)
    ASSERT_NEAR(acc.pin_depth()[k], uniform, 1e-9 * uniform) << "pin area " << k;

  // Bushing: the area facing φ* = −π/2 is k = 270; nothing beyond b/R1 + 1 area.
  const auto &h    = acc.bore_depth();
  const auto  peak = std::max_element(h.begin(), h.end()) - h.begin();
  EXPECT_EQ(peak, 270);
  unsigned int loaded = 0;
  for (unsigned int k = 0; k < n_areas; ++k)
    {
      const double distance_deg = std::abs(static_cast<double>(k) - 270.0);
      if (h[k] > 0)
        {
          ++loaded;
          EXPECT_LE(distance_deg, (b / 0.012) * 180 / pi + 1.0) << "bore area " << k;
        }
    }
  EXPECT_LE(loaded, 3u);
  EXPECT_GT(h[270], 100 * uniform * k_bore / k_pin); // localized: far deeper than if spread
}

// The bookkeeping identity for a model that does not conserve Σ p A exactly (winkler,
// a wide arc when worn): the local volume Σ h_k A_k is what the depths say, by
// construction of add(); the global Archard volume k_D ∫ F |v| dt is computed
// separately. For a fresh joint under a moderate load the Winkler arc is narrow, so the
// two agree within the foundation's Σ p A / F − 1 = O(ε²) (ε the contact half-angle,
// ~3° here → 3e-3); we ask 1 %.
TEST(Archard, LocalVolumeMatchesGlobalForWinkler)
{
  const auto               g     = steel_joint(360);
  auto                     model = winkler_on(g);
  wear::ArchardAccumulator acc(g, 1e-13, 1e-13, *model);
  for (unsigned int i = 0; i < 720; ++i)
    {
      wear::LoadSample s;
      s.load.pin_angle     = 2 * pi * i / 720;
      s.load.contact_angle = 0.3;
      s.load.normal_force  = 200;
      s.load.force         = {{-200 * std::cos(0.3), -200 * std::sin(0.3)}};
      s.load.eccentricity  = {{5e-4 * std::cos(0.3), 5e-4 * std::sin(0.3)}};
      s.sliding_speed      = 0.1;
      s.weight             = 1e-3;
      acc.add(s);
    }
  double sum_pin = 0, sum_bore = 0;
  for (unsigned int k = 0; k < 360; ++k)
    {
      sum_pin += acc.pin_depth()[k] * acc.pin_area(k);
      sum_bore += acc.bore_depth()[k] * acc.bore_area(k);
    }
  EXPECT_NEAR(sum_pin, acc.pin_volume, 1e-12 * acc.pin_volume);
  EXPECT_NEAR(sum_bore, acc.bore_volume, 1e-12 * acc.bore_volume);
  EXPECT_NEAR(acc.pin_volume, acc.pin_archard, 1e-2 * acc.pin_archard);
  EXPECT_NEAR(acc.bore_volume, acc.bore_archard, 1e-2 * acc.bore_archard);
}

TEST(Archard, NoLoadOrNoSlidingNoWear)
{
  const auto g     = steel_joint(64);
  auto       model = pressure_model("hertz-strip");
  model->update_geometry(g);
  wear::ArchardAccumulator acc(g, 1e-13, 1e-13, *model);
  wear::LoadSample         s;
  s.load.normal_force = 0;
  s.sliding_speed     = 1;
  s.weight            = 1;
  acc.add(s);
  s.load.normal_force = 50;
  s.sliding_speed     = 0;
  acc.add(s);
  EXPECT_EQ(acc.pin_volume, 0.0);
  EXPECT_EQ(acc.bore_volume, 0.0);
  EXPECT_EQ(acc.pressure_evaluations, 0);
}

// "N load samples per cycle": the model is called once per window and the window's
// steps reuse that shape, scaled to their load and turned to their contact direction.
// The turn (linear interpolation on the periodic grid) and the scaling conserve Σ p A,
// while the number of model calls drops to one per window. The load here varies in
// magnitude (F = 100 (1.5 + sin ωt) N) and the pin turns, so both the scaling and the
// shift are exercised. The volumes equal the every-step ones up to the strip's
// Σ p A / F = ε/(2 J1(ε)) = 1 + ε²/8 + …, which a reused shape takes from its window's
// key rather than its own load (ε ∝ √F): at most ε_max²/8 = 7.3e-5 at the peak 250 N
// (b = 0.28 mm, ε = b/R2 = 0.024); asserted to 1e-4.
TEST(Archard, SampledShapesKeepTheVolume)
{
  const auto g     = steel_joint(360);
  auto       model = pressure_model("hertz-strip");
  model->update_geometry(g);
  wear::ArchardAccumulator      every(g, 1e-13, 2e-13, *model), sampled(g, 1e-13, 2e-13, *model);
  std::vector<wear::LoadSample> history;
  const double                  omega = 4 * pi, period = 2 * pi / omega, dt = period / 5000;
  for (unsigned int i = 0; i < 5000; ++i)
    {
      wear::LoadSample s;
      s.time               = i * dt;
      s.load.pin_angle     = omega * s.time;
      s.load.contact_angle = -pi / 2 + 0.3 * std::sin(omega * s.time);
      s.load.normal_force  = 100 * (1.5 + std::sin(omega * s.time));
      s.sliding_speed      = omega * 0.0115;
      s.weight             = dt;
      history.push_back(s);
    }
  every.add_history(history, true, 0, 0);
  sampled.add_history(history, false, period / 20, 0);
  EXPECT_EQ(sampled.pressure_evaluations, 20);
  EXPECT_NEAR(sampled.pin_volume, every.pin_volume, 1e-4 * every.pin_volume);
  EXPECT_NEAR(sampled.bore_volume, every.bore_volume, 1e-4 * every.bore_volume);
  // The shapes differ only by the strip width (∝ √F) within a window: the bore's peak
  // depth, where the strip dwells, agrees within 10 %.
  const double peak_every   = *std::max_element(every.bore_depth().begin(), every.bore_depth().end());
  const double peak_sampled = *std::max_element(sampled.bore_depth().begin(), sampled.bore_depth().end());
  EXPECT_NEAR(peak_sampled, peak_every, 0.1 * peak_every);
}
