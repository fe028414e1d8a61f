// SPDX-License-Identifier: LGPL-2.1-or-later
// The `fe` pressure model as the contact layer sees it: registered by name, constructed
// without meshing anything (gmsh and deal.II are touched only by update_geometry()),
// returning per-area pressures on both profiles, each in its own body frame, that
// balance the joint force.
#include "base/effect_ledger.h"
#include "fe_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <unistd.h>

using namespace wearlink;
using namespace wearlink::fe::testing;

namespace
{
  /** The fe pressure model at @p surface_size [m]; @p max_iterations: its default if 0. */
  std::unique_ptr<contact::PressureModel>
  create_fe_model(double surface_size, unsigned int max_iterations = 0)
  {
    dealii::ParameterHandler prm;
    contact::pressure_models().declare_all(prm);
    prm.enter_subsection("fe");
    prm.set("Surface element size", std::to_string(surface_size));
    prm.set("Refined layer thickness", "0");
    if (max_iterations > 0)
      prm.set("Maximum active-set iterations", std::to_string(max_iterations));
    prm.leave_subsection();
    ParameterReader reader(prm, "test");
    return contact::pressure_models().create("fe", reader, "Pressure model");
  }

  /** L Σ p_k ΔA_k n_k over a profile (outward radial normals at the samples) [N]. */
  std::array<double, 2>
  resultant(const Profile &profile, const std::vector<double> &p, double frame_angle)
  {
    std::array<double, 2> f{};
    const double          da = 2 * pi / profile.n_points();
    for (unsigned int k = 0; k < profile.n_points(); ++k)
      {
        const double a = profile.angle(k) + frame_angle;
        f[0] += p[k] * L * profile[k] * da * std::cos(a);
        f[1] += p[k] * L * profile[k] * da * std::sin(a);
      }
    return f;
  }
} // namespace


TEST(FePlugin, RegisteredAndBuildsNothingUntilGeometry)
{
  ASSERT_TRUE(contact::pressure_models().has("fe"));
  auto      &ledger   = EffectLedger::instance();
  const long sessions = ledger.resources("gmsh sessions");
  const long trias    = ledger.resources("triangulations");
  auto       model    = create_fe_model(1e-4);
  EXPECT_NE(model->fe_hooks(), nullptr) << "the fe model meshes: it has the FE hooks";
  EXPECT_EQ(ledger.resources("gmsh sessions"), sessions) << "constructing must not mesh";
  EXPECT_EQ(ledger.resources("triangulations"), trias);
  model->update_geometry(steel_pair(72));
  EXPECT_EQ(ledger.resources("gmsh sessions"), sessions + 1);
  EXPECT_EQ(ledger.resources("triangulations"), trias + 1);
}


TEST(FePlugin, PressurePerAreaBalancesLoadInBodyFrames)
{
  // Bushing turned by −20°, pin by +30°; the bushing pushes the pin up with 1 kN, so the
  // pin is pressed down (−y) and touches the bore at the global angle −90°: sample
  // −90° − θ of each profile in its own frame (5° areas, N = 72).
  auto model    = create_fe_model(1e-4);
  auto geometry = steel_pair(72);
  model->update_geometry(geometry);
  contact::ContactLoad load;
  load.bushing_angle = -20 * pi / 180;
  load.pin_angle     = 30 * pi / 180;
  load.force         = {{0.0, 1000.0}};
  contact::SurfacePressure out;
  model->evaluate(load, out);
  ASSERT_EQ(out.pin.size(), 72u);
  ASSERT_EQ(out.bore.size(), 72u);

  auto peak = [](const std::vector<double> &p) {
    return static_cast<int>(std::max_element(p.begin(), p.end()) - p.begin());
  };
  auto expected_sample = [](double angle_deg) {
    return static_cast<int>(std::lround(std::remainder(angle_deg, 360.0) / 5 + 72)) % 72;
  };
  EXPECT_NEAR(peak(out.pin), expected_sample(-90 - 30), 1) << "pin pressure in the pin frame";
  EXPECT_NEAR(peak(out.bore), expected_sample(-90 + 20), 1) << "bore pressure in the bushing frame";

  // Equilibrium of the per-area pressures: the pin is pushed along −y by 1 kN and the
  // bore carries the same force. Each area's force is attributed to its centre normal
  // while it spreads over ±2.5°, so the balance holds to ~1 − cos 2.5° ≈ 1e-3.
  const auto fp = resultant(geometry.pin, out.pin, load.pin_angle);
  const auto fb = resultant(geometry.bore, out.bore, load.bushing_angle);
  EXPECT_NEAR(fp[0], 0.0, 2e-3 * 1000);
  EXPECT_NEAR(fp[1], -1000.0, 2e-3 * 1000);
  EXPECT_NEAR(fb[0], 0.0, 2e-3 * 1000);
  EXPECT_NEAR(fb[1], -1000.0, 2e-3 * 1000);

  // No load, no pressure.
  load.force = {{0.0, 0.0}};
  model->evaluate(load, out);
  EXPECT_EQ(*std::max_element(out.pin.begin(), out.pin.end()), 0.0);
}


TEST(FePlugin, TemporaryMeshDirectoryGoesWithTheModel)
{
  // Without 'Mesh directory' the model meshes into a temporary directory of its own
  // (wearlink-fe-<pid>-…); a wear run re-meshes every iteration, so the directory must
  // not outlive the model.
  namespace fs             = std::filesystem;
  const std::string prefix = "wearlink-fe-" + std::to_string(::getpid()) + "-";
  auto              count  = [&] {
    unsigned int n = 0;
    for (const auto &e : fs::directory_iterator(fs::temp_directory_path()))
      if (e.path().filename().string().rfind(prefix, 0) == 0)
        ++n;
    return n;
  };
  const unsigned int before = count();
  auto               model  = create_fe_model(2e-4);
  model->update_geometry(steel_pair(72));
  model->update_geometry(steel_pair(72)); // a re-mesh
  EXPECT_EQ(count(), before + 1);
  model.reset();
  EXPECT_EQ(count(), before);
}


TEST(FePlugin, SmallLoadsInAnyDirectionCarryNoTensileForce)
{
  // Archard's worn volume is Σ_k h_k A_k = k_D s Σ_k p_k A_k, so the per-area pressures
  // must add up to the joint force: Σ p_k A_k = |F| (for the few-degree arcs of these
  // loads, the scalar sum and the resultant differ by 1 − cos(half-angle) < 1e-3). On a
  // coarse mesh (0.2 mm elements, 1° between candidates) a small load carried by two
  // candidates whose normals do not bracket its direction needs a tensile force on one
  // of them; dropping that negative force when collecting the areas had made the sum up
  // to 29× the load at 1.6 N, and worn volumes under `fe` up to 2× Archard's k_D F s.
  // Loads of 1 N and 10 N in 36 directions, none aligned with a candidate.
  auto model    = create_fe_model(2e-4);
  auto geometry = steel_pair(360);
  model->update_geometry(geometry);
  contact::SurfacePressure out;
  double                   worst = 0;
  for (const double magnitude : {1.0, 10.0})
    for (int k = 0; k < 36; ++k)
      {
        const double         angle = (7.3 + 10.0 * k) * pi / 180;
        contact::ContactLoad load;
        load.force = {{magnitude * std::cos(angle), magnitude * std::sin(angle)}};
        model->evaluate(load, out);
        double sum_pin = 0, sum_bore = 0;
        for (unsigned int i = 0; i < geometry.pin.n_points(); ++i)
          sum_pin += out.pin[i] * L * geometry.pin[i] * 2 * pi / geometry.pin.n_points();
        for (unsigned int i = 0; i < geometry.bore.n_points(); ++i)
          sum_bore += out.bore[i] * L * geometry.bore[i] * 2 * pi / geometry.bore.n_points();
        EXPECT_NEAR(sum_pin, magnitude, 1e-3 * magnitude) << magnitude << " N at " << angle * 180 / pi << "°";
        EXPECT_NEAR(sum_bore, magnitude, 1e-3 * magnitude) << magnitude << " N at " << angle * 180 / pi << "°";
        worst = std::max(worst, std::abs(sum_pin / magnitude - 1));
      }
  std::cout << "largest |Σ p A / |F| − 1| over 72 small loads: " << worst << "\n";
}

// A vanishing load (the joint force sampled as the pin leaves contact: 7e-11 N was met
// in a wear run) is carried too. The rigid translation that closes the initial gaps
// (~1e-8 m between neighbouring candidates of a 0.2 mm mesh) corresponds to line loads
// of ~1e3 N/m that the active solve cancels down to the load, so its balance holds to
// round-off of those, ~1e-7 of such a load: the solver had refused it as "out of
// equilibrium" against a bound of 1e-8 of the load alone. The pressures still add up
// to the load.
TEST(FePlugin, VanishingLoadsAreCarried)
{
  auto model    = create_fe_model(2e-4);
  auto geometry = steel_pair(360);
  model->update_geometry(geometry);
  contact::SurfacePressure out;
  for (const double magnitude : {1e-10, 1e-7, 1e-4})
    for (int k = 0; k < 8; ++k)
      {
        const double         angle = (3.1 + 45.0 * k) * pi / 180;
        contact::ContactLoad load;
        load.force = {{magnitude * std::cos(angle), magnitude * std::sin(angle)}};
        ASSERT_NO_THROW(model->evaluate(load, out)) << magnitude << " N at " << angle * 180 / pi << "°";
        double sum_pin = 0;
        for (unsigned int i = 0; i < geometry.pin.n_points(); ++i)
          sum_pin += out.pin[i] * L * geometry.pin[i] * 2 * pi / geometry.pin.n_points();
        EXPECT_NEAR(sum_pin, magnitude, 1e-3 * magnitude) << magnitude << " N at " << angle * 180 / pi << "°";
      }
}

// A load state the condensed solver cannot finish (here: one active-set iteration
// allowed, for a contact of hundreds of nodes) is named in the error in full, so that
// `wearlink contact` reproduces it: the force on the pin (the negated bushing force) and
// both body angles.
TEST(FePlugin, AFailedLoadStateIsNamedInTheError)
{
  auto model = create_fe_model(1e-4, 1);
  model->update_geometry(steel_pair(360));
  contact::ContactLoad load;
  load.force         = {{0.0, 1e5}};
  load.bushing_angle = 0.25;
  load.pin_angle     = -1.5;
  contact::SurfacePressure out;
  try
    {
      model->evaluate(load, out);
      FAIL() << "one active-set iteration cannot carry 100 kN";
    }
  catch (const NumericalError &e)
    {
      const std::string m = e.what();
      EXPECT_NE(m.find("force on the pin (0, -100000) N"), std::string::npos) << m;
      EXPECT_NE(m.find("bushing angle 0.25 rad, pin angle -1.5 rad"), std::string::npos) << m;
    }
}
