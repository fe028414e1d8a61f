// SPDX-License-Identifier: LGPL-2.1-or-later
// Persistent contact held as a constraint (Persistent contact = held, doc/models.md §1.6):
//  - a pin resting in a bore under gravity (tests/scenes/held_pin.prm): released 1 nm
//    above the bottom, the joint takes the contact up at the touch-down, and at rest
//    the held normal force is the weight m g (equilibrium, to 1e-6) and the penetration
//    its quasi-static value (m g / K)^(1/n) of the law (to 1e-3: Baumgarte's rate of
//    1000/s over 50 ms leaves e^-50 of the initial difference);
//  - worn profiles are not held (the compliant law integrates them; on
//    params/nine_bar_worn.prm a held row let peak forces grow tenfold): no held episode,
//    the same steps as the compliant run;
//  - the nine-bar with both joints held for a crank cycle: contacts are held and given
//    up, no held force pulls (the release is located in time), and the energy balance
//    closes within the scene's limit (1000 × the relative tolerance; measured 2e-5).
#include "contact/clearance_joint.h"
#include "contact/normal_force_law.h"
#include "scene_support.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace wearlink;

namespace
{
  /** The joints' diagnostics at the last accepted step, and the least held force met. */
  class HeldForces : public mbs::StepObserver
  {
  public:
    explicit HeldForces(io::Scene &scene)
      : scene(scene)
    {
    }
    void
    on_step(const mbs::StepContext &c) override
    {
      const unsigned int   n = c.simulation.get_mechanism().n_coordinates();
      const mbs::StateView s(c.y.data(), c.y.data() + n);
      last.clear();
      for (const auto &j : scene.clearance_joints)
        {
          last.push_back(j->diagnostics(s));
          if (j->holds_contact())
            least_held_force = std::min(least_held_force, last.back().normal_force);
        }
    }
    io::Scene                             &scene;
    std::vector<contact::JointDiagnostics> last;
    double                                 least_held_force = 1e300;
  };
} // namespace

TEST(HeldContact, ARestingPinCarriesItsWeight)
{
  auto       scene = wearlink::testing::scene("tests/scenes/held_pin.prm");
  HeldForces watch(scene);
  const Json s = wearlink::testing::run(scene, {&watch});
  ASSERT_EQ(scene.clearance_joints.size(), 1u);
  const auto  &joint  = *scene.clearance_joints[0];
  const double weight = 2.0 * 9.81;
  EXPECT_TRUE(joint.holds_contact()) << "the pin rests on the bore: the contact is held";
  EXPECT_GE(json_number(s.at("clearance_joints").at("P").at("held_episodes")), 1);
  ASSERT_EQ(watch.last.size(), 1u);
  EXPECT_NEAR(watch.last[0].normal_force, weight, 1e-6 * weight) << "equilibrium";
  const double quasi_static = std::pow(weight / joint.stiffness(), 1.0 / joint.normal_force_law().exponent());
  EXPECT_NEAR(watch.last[0].penetration, quasi_static, 1e-3 * quasi_static);
  EXPECT_NEAR(watch.last[0].friction_force, 0, 1e-12) << "at rest: no sliding, no friction";
}

TEST(HeldContact, NineBarHoldsAndGivesUpWithTheEnergyBalanceClosed)
{
  auto       scene = wearlink::testing::scene("params/nine_bar_clearance.prm",
                                        {"Simulation/End time=0.5",
                                               "Output/Time series=false",
                                               "Joint A/Clearance/Persistent contact=held",
                                               "Joint B/Clearance/Persistent contact=held"});
  HeldForces watch(scene);
  const Json s = wearlink::testing::run(scene, {&watch});
  for (const char *j : {"A", "B"})
    EXPECT_GE(json_number(s.at("clearance_joints").at(j).at("held_episodes")), 1) << j;
  // Given up where the held force falls to zero, located on the step's dense output:
  // the step is taken again to end there, a hair past it (measured −0.003 N against
  // peaks of ~2 kN).
  EXPECT_GT(watch.least_held_force, -0.1) << "a held contact is given up before it pulls";
  EXPECT_LT(json_number(s.at("energy_balance_relative_error")), 1e3 * 1e-6);
}

// Worn profiles are held as conformal contacts (the normal is the resultant's direction,
// given back where the compliant law would no longer carry the held force, 25 %): on the
// nine-bar's worn joints the held run stays within the force the compliant run reaches.
// Tolerance 1.5 ×: the peak force of joint A scatters by 4–8 % (sd) between equivalent
// runs (tests/regression/nine_bar_worn.ref) and held contact moves it by up to 13 %
// (measured over 2.5 s); a held row on the deepest point of a worn profile drove it ×10.
TEST(HeldContact, WornProfilesAreHeldAsConformalContacts)
{
  auto run = [](const std::string &mode) {
    auto scene = wearlink::testing::scene("params/nine_bar_worn.prm",
                                          {"Simulation/End time=0.5",
                                           "Output/Time series=false",
                                           "Joint A/Clearance/Persistent contact=" + mode,
                                           "Joint B/Clearance/Persistent contact=" + mode});
    return wearlink::testing::run(scene);
  };
  const Json held = run("held"), compliant = run("compliant");
  for (const char *j : {"A", "B"})
    {
      const auto &h = held.at("clearance_joints").at(j);
      EXPECT_GE(json_number(h.at("held_episodes")), 1) << j;
      EXPECT_LT(json_number(h.at("max_normal_force_N")),
                1.5 * json_number(compliant.at("clearance_joints").at(j).at("max_normal_force_N")))
        << j;
    }
  EXPECT_LT(json_number(held.at("energy_balance_relative_error")), 1e-4);
}
