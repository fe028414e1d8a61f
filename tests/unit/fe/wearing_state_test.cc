// SPDX-License-Identifier: LGPL-2.1-or-later
// The implicit load state of the sequential wear update (PressureModel::evaluate_wearing):
// the surfaces wear by c × p while they carry p. When c is much larger than the contact's
// own compliance (a long dwell extrapolated by a large factor), the elastic part of the
// approach vanishes beside the worn one and the result no longer depends on the model:
// the pin, pushed along the load, digs its own shape into the surfaces — the rigid
// imprint, worn depth (c_r + a) cos Δ − c_r at the angle Δ from the load (c_r the radial
// clearance, a the depth at the centre), while the pressure still carries the load. The
// winkler foundation (stiffness 1/(1/k + c)) and the fe model (c/∫N ds added to its
// compliance's diagonal) must both give it; an explicit step of the same state (the
// simultaneous update) digs a trench as narrow as the Hertz strip instead.
#include "fe_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

using namespace wearlink;
using namespace wearlink::fe::testing;

namespace
{
  std::unique_ptr<contact::PressureModel>
  create(const std::string &name)
  {
    dealii::ParameterHandler prm;
    contact::pressure_models().declare_all(prm);
    prm.enter_subsection("winkler");
    prm.set("Layer thickness", "1e-3");
    prm.leave_subsection();
    prm.enter_subsection("fe");
    prm.set("Surface element size", "2e-4");
    prm.set("Refined layer thickness", "0");
    prm.leave_subsection();
    ParameterReader reader(prm, "test");
    return contact::pressure_models().create(name, reader, "Pressure model");
  }

  /** The bushing pushes the pin up by @p force: the pin presses on the bore at −90°. */
  contact::ContactLoad
  load_up(const double force)
  {
    contact::ContactLoad load;
    load.force         = {{0.0, force}};
    load.normal_force  = force;
    load.contact_angle = -pi / 2;
    load.eccentricity  = {{0.0, -(R1 - R2)}};
    return load;
  }

  class WearingState : public ::testing::TestWithParam<std::string>
  {
  };
} // namespace

TEST_P(WearingState, StiffLimitIsTheRigidImprint)
{
  const auto geometry = steel_pair(360);
  auto       model    = create(GetParam());
  model->update_geometry(geometry);
  // A 30 µm imprint holds a volume of about (4/3) a √(2a/c_r) R L = 1.66e-9 m³, i.e.
  // c F with c ≈ 1.66e-12 m/Pa at 1 kN: c k ≈ 230 for the 1 mm winkler layer, more
  // for fe; the bore and the pin each wear half.
  const double             force = 1000, c = 1.66e-12, c_r = R1 - R2;
  contact::SurfacePressure p;
  model->evaluate_wearing(load_up(force), {0.5 * c, 0.5 * c}, p);
  // The worn depth of both surfaces at each bore area (frames aligned: the pin area
  // facing bore area k is area k).
  // The pressure still carries the load: its resultant on each surface is the 1 kN
  // (each area's force at its centre normal: to 2e-3 over 1° areas).
  std::vector<double> depth(360);
  double              bore_y = 0, pin_y = 0;
  for (unsigned int k = 0; k < 360; ++k)
    {
      depth[k]         = c * p.bore[k];
      const double psi = 2 * pi * k / 360;
      bore_y += p.bore[k] * L * R1 * 2 * pi / 360 * std::sin(psi);
      pin_y += p.pin[k] * L * R2 * 2 * pi / 360 * std::sin(psi);
    }
  EXPECT_NEAR(bore_y, -force, 2e-3 * force) << GetParam();
  EXPECT_NEAR(pin_y, -force, 2e-3 * force) << GetParam();
  const double a = *std::max_element(depth.begin(), depth.end());
  ASSERT_GT(a, 10e-6);
  ASSERT_LT(a, 60e-6);
  for (unsigned int k = 0; k < 360; ++k)
    {
      const double delta   = 2 * pi * k / 360 + pi / 2; // from the load direction −90°
      const double imprint = std::max(0.0, (c_r + a) * std::cos(delta) - c_r);
      EXPECT_NEAR(depth[k], imprint, 0.05 * a) << GetParam() << ", area " << k;
    }

  // The explicit step of the same state: a trench within the Hertz strip (b ≈ 0.5 mm,
  // ±2.5°), several times deeper than the imprint.
  model->update_geometry(geometry);
  model->evaluate(load_up(force), p);
  double explicit_depth = 0;
  for (const double x : p.bore)
    explicit_depth = std::max(explicit_depth, c * x);
  EXPECT_GT(explicit_depth, 3 * a) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(Models, WearingState, ::testing::Values("winkler", "fe"));
