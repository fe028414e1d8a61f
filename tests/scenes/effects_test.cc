// SPDX-License-Identifier: LGPL-2.1-or-later
// Effects are switched on by the scene and cost nothing when off (doc/architecture.md §4):
// the effect ledger of a run proves what was constructed and evaluated.
//  - all joints ideal: no clearance joint, no normal/friction law constructed, zero
//    contact-law evaluations;
//  - clearance with Friction law = none: the normal law is constructed, no friction law,
//    and the friction dissipation is exactly zero;
//  - clearance with friction: both laws constructed once per joint.
#include "scene_support.h"

#include <gtest/gtest.h>

using namespace wearlink;

TEST(Effects, IdealJointsConstructNoContactCode)
{
  auto       scene  = wearlink::testing::scene("params/nine_bar_ideal.prm", {"Simulation/End time=0.05"});
  const Json s      = wearlink::testing::run(scene);
  auto      &ledger = EffectLedger::instance();
  EXPECT_EQ(ledger.constructions("joint model", "clearance"), 0);
  EXPECT_EQ(ledger.constructions("joint model", "ideal"), 10);
  EXPECT_EQ(ledger.constructions("normal force law"), 0);
  EXPECT_EQ(ledger.constructions("friction law"), 0);
  EXPECT_EQ(ledger.calls("contact law evaluations"), 0);
  EXPECT_EQ(s.at("clearance_joints").size(), 0u);
  EXPECT_EQ(ledger.resources("gmsh sessions"), 0);
  EXPECT_EQ(ledger.resources("triangulations"), 0);
}

TEST(Effects, FrictionNoneConstructsNoFrictionLaw)
{
  auto       scene  = wearlink::testing::scene("params/nine_bar_clearance.prm",
                                        {"Simulation/End time=0.05",
                                                "Joint A/Clearance/Friction law=none",
                                                "Joint B/Clearance/Friction law=none"});
  const Json s      = wearlink::testing::run(scene);
  auto      &ledger = EffectLedger::instance();
  EXPECT_EQ(ledger.constructions("joint model", "clearance"), 2);
  EXPECT_EQ(ledger.constructions("normal force law", "lankarani-nikravesh"), 2);
  EXPECT_EQ(ledger.constructions("friction law"), 0);
  EXPECT_GT(ledger.calls("contact law evaluations"), 0);
  EXPECT_EQ(json_number(s.at("energy").at("friction_dissipation_J")), 0.0);
  EXPECT_EQ(ledger.resources("gmsh sessions"), 0);
}

TEST(Effects, ClearanceWithFrictionConstructsBothLaws)
{
  auto scene = wearlink::testing::scene("params/nine_bar_clearance.prm", {"Simulation/End time=0.05"});
  wearlink::testing::run(scene);
  auto &ledger = EffectLedger::instance();
  EXPECT_EQ(ledger.constructions("normal force law", "lankarani-nikravesh"), 2);
  EXPECT_EQ(ledger.constructions("friction law", "modified-coulomb"), 2);
  EXPECT_EQ(ledger.constructions("normal force law", "hertz"), 0);
}
