// SPDX-License-Identifier: LGPL-2.1-or-later
// The winkler pressure model on worn, jagged profiles (the state of the nine-bar's
// joints after 50,000 revolutions: a bore pocket ~60 µm deep over ±25° with per-area
// roughness of a few µm, a pin worn ~15 µm). Its force balance must reach the load to
// 1e-6 (the model's own acceptance; it throws a NumericalError otherwise) for loads from
// 10 mN, where the overlap is one or two sub-grid samples, to 5 kN, in every direction
// and at every relative rotation — a line search on |R| stalled here at up to 9 % of
// the load. Independent check: the pressures it returns, integrated over the bore areas,
// give the load to the area discretization: a narrow contact's force is attributed to
// its area's centre, up to half an area (0.5°) off its true direction, so the lateral
// error reaches F sin 0.5° = 8.7e-3 F (measured 3.6e-3 F); asserted to 1e-2 F.
#include "pressure_model_support.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace wearlink;
using namespace wearlink::wear::testing;

TEST(Winkler, ReachesEquilibriumOnWornJaggedProfiles)
{
  constexpr double    pi = 3.14159265358979323846;
  const unsigned int  n  = 360;
  std::vector<double> bore(n), pin(n);
  unsigned int        seed  = 12345;
  auto                noise = [&] { // deterministic pseudo-random numbers in [−1, 1]
    seed = 1103515245u * seed + 12345u;
    return ((seed >> 8) % 20001) / 10000.0 - 1.0;
  };
  for (unsigned int k = 0; k < n; ++k)
    {
      const double psi  = 2 * pi * k / n;
      const double x    = std::remainder(psi - 1.2, 2 * pi) / (25 * pi / 180);
      const double worn = std::abs(x) < 1 ? 60e-6 * (1 - x * x) + 4e-6 * noise() : 0.0;
      bore[k]           = 0.012 + std::max(worn, 0.0);
      pin[k] =
        0.0115 - 15e-6 * std::exp(-std::pow(std::remainder(psi - 3.0, 2 * pi), 2) / 0.5) - 1e-6 * std::abs(noise());
    }
  const contact::JointGeometry g = steel_joint(Profile::from_samples(bore, "bore"), Profile::from_samples(pin, "pin"));

  auto model = winkler_on(g);

  contact::SurfacePressure out;
  unsigned int             cases = 0;
  for (const double F : {0.01, 1.0, 50.0, 500.0, 5000.0})
    for (const double direction : {1.2, 1.25, 1.6, 3.0, -2.0})
      for (const double pin_angle : {0.0, 0.7, 2.5})
        {
          contact::ContactLoad load;
          load.bushing_angle = 0;
          load.pin_angle     = pin_angle;
          load.contact_angle = direction;
          load.normal_force  = F;
          load.force         = {{-F * std::cos(direction), -F * std::sin(direction)}};
          load.eccentricity  = {{5e-4 * std::cos(direction), 5e-4 * std::sin(direction)}};
          ASSERT_NO_THROW(model->evaluate(load, out)) << "F = " << F << " N, direction " << direction;
          double fx = 0, fy = 0;
          for (unsigned int k = 0; k < n; ++k)
            {
              const double psi = 2 * pi * k / n, w = g.axial_length * g.bore.radius(psi) * 2 * pi / n;
              fx += out.bore[k] * w * std::cos(psi);
              fy += out.bore[k] * w * std::sin(psi);
            }
          EXPECT_NEAR(fx, F * std::cos(direction), 1e-2 * F) << "F = " << F << ", direction " << direction;
          EXPECT_NEAR(fy, F * std::sin(direction), 1e-2 * F) << "F = " << F << ", direction " << direction;
          ++cases;
        }
  EXPECT_EQ(cases, 75u);
}


// A pin pushed into a worn pocket that is deeper than the pin's curvature can follow
// rests on the pocket's two rims. Bore: R1 = 12 mm plus a pocket 100 µm deep over ±30°
// (parabolic), pin R2 = 11.5 mm (c = 0.5 mm). Travelling along 0° the pin reaches the
// rims at s = c/cos 30° = 0.577 mm, the floor only at s = c + 0.1 mm = 0.6 mm: the rims
// carry it. A load at 10° lies inside the cone of the two rim normals (±30°), so both
// rims must carry a share — the lateral slide of the pin from the first rim to the
// second is what the solver's window must follow (the sums run over a window
// of the sub-grid; a window that missed the second rim would leave the pin penetrating
// it, with all pressure on one rim). Equilibrium: the bore pressures integrate to the
// load within the area discretization (1e-2 F, see the test above). The rims' shares
// from statics: two forces along ±30° (from the bore centre) balancing F at 10° give
// F_+30/F_−30 = sin 40°/sin 20° = 1.88; the contact arcs widen this a little, so only
// the ordering and both being > 10 % of F are asserted.
TEST(Winkler, APinInADeepPocketRestsOnBothRims)
{
  constexpr double    pi = 3.14159265358979323846;
  const unsigned int  n  = 360;
  std::vector<double> bore(n);
  for (unsigned int k = 0; k < n; ++k)
    {
      const double x = std::remainder(2 * pi * k / n, 2 * pi) / (30 * pi / 180);
      bore[k]        = 0.012 + (std::abs(x) < 1 ? 100e-6 * (1 - x * x) : 0.0);
    }
  const contact::JointGeometry g = steel_joint(Profile::from_samples(bore, "bore"), Profile::round(0.0115, n));

  auto model = winkler_on(g);

  const double         F = 500, direction = 10 * pi / 180;
  contact::ContactLoad load;
  load.contact_angle = direction;
  load.normal_force  = F;
  load.force         = {{-F * std::cos(direction), -F * std::sin(direction)}};
  load.eccentricity  = {{5.8e-4 * std::cos(direction), 5.8e-4 * std::sin(direction)}};
  contact::SurfacePressure out;
  ASSERT_NO_THROW(model->evaluate(load, out));
  double fx = 0, fy = 0, upper = 0, lower = 0;
  for (unsigned int k = 0; k < n; ++k)
    {
      const double psi = 2 * pi * k / n, w = g.axial_length * g.bore.radius(psi) * 2 * pi / n;
      fx += out.bore[k] * w * std::cos(psi);
      fy += out.bore[k] * w * std::sin(psi);
      const double deg = std::remainder(psi, 2 * pi) * 180 / pi;
      (deg > 0 ? upper : lower) += out.bore[k] * w;
    }
  EXPECT_NEAR(fx, F * std::cos(direction), 1e-2 * F);
  EXPECT_NEAR(fy, F * std::sin(direction), 1e-2 * F);
  EXPECT_GT(lower, 0.1 * F) << "the rim at −30° carries nothing";
  EXPECT_GT(upper, lower) << "the rim the load leans on (+30°) must carry more";
}
