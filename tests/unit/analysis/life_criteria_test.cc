// SPDX-License-Identifier: LGPL-2.1-or-later
// The stop criteria of a life run (analysis/life_criteria.h) on hand-made wear states:
// the factor at which a criterion reaches its limit (the depths h + f Δh and volumes
// V + f ΔV are known before the step), the envelope depth the depth criteria use, the
// approach to a crossing within the tolerance, and the interpolated crossing with its
// bracket. The trend criterion on synthetic measurements (no simulation): the coverage
// of its 95 % crossing interval, and that pure noise or too few points are never the
// life (trend_criterion_test.cc).
#include "analysis/life_criteria.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace wearlink;
using namespace wearlink::analysis;

namespace
{
  /**
   * One joint: pin depths {1, 3, 2} µm growing by {2, 0, 1} µm per unit factor, bore
   * depths {0, 5, 0} µm growing by {1, 1, 1} µm; volumes pin 1e-9 + f 1e-10 m³, bore
   * 2e-9 + f 4e-10 m³.
   */
  wear::StepPreview
  preview()
  {
    wear::StepPreview        p;
    wear::StepPreview::Joint j;
    j.depth_pin             = {1e-6, 3e-6, 2e-6};
    j.pin_increment         = {2e-6, 0, 1e-6};
    j.depth_bore            = {0, 5e-6, 0};
    j.bore_increment        = {1e-6, 1e-6, 1e-6};
    j.volume_pin            = 1e-9;
    j.pin_volume_increment  = 1e-10;
    j.volume_bore           = 2e-9;
    j.bore_volume_increment = 4e-10;
    p.joints.push_back(j);
    p.revolutions = 1000;
    p.cycles      = 10;
    p.factor      = 100;
    return p;
  }
} // namespace

TEST(LifeCriteria, FactorToReachEachWearCriterion)
{
  const auto                        p         = preview();
  const std::vector<JointDensities> densities = {{2700, 7850, ""}};
  // Deepest wear: bore 5 + f µm reaches 8 µm at f = 3 (the pin, max(1 + 2f, 3, 2 + f),
  // only at f = 3.5).
  CriterionSpec depth{Criterion::wear_depth, "wear_depth", "Maximum wear depth", "m", 8e-6};
  EXPECT_NEAR(factor_to_reach(depth, p, densities, 100), 3, 3e-12);
  // Clearance growth: max pin + max bore = max(1 + 2f, 3) + 5 + f: 3 + 5 + f up to f = 1,
  // then 6 + 3f: 12 µm at f = 2.
  CriterionSpec growth{Criterion::clearance_growth, "clearance_growth", "Radial clearance growth", "m", 12e-6};
  EXPECT_NEAR(factor_to_reach(growth, p, densities, 100), 2, 2e-12);
  // Pin mass: (1e-9 + f 1e-10) m³ × 2700 kg/m³ = 2.7 + 0.27 f mg: 5.4 mg at f = 10.
  CriterionSpec pin{Criterion::pin_mass_loss, "pin_mass_loss", "Pin mass loss", "mg", 5.4};
  EXPECT_NEAR(factor_to_reach(pin, p, densities, 100), 10, 1e-11);
  // Beyond the loop's own factor: no limit from this criterion.
  EXPECT_TRUE(std::isinf(factor_to_reach(pin, p, densities, 5)));
  // Already reached: 0.
  CriterionSpec bushing{Criterion::bushing_mass_loss, "bushing_mass_loss", "Bushing mass loss", "mg", 1};
  EXPECT_EQ(factor_to_reach(bushing, p, densities, 100), 0);
}

TEST(LifeCriteria, ApproachLeavesAShortLastStepAndOvershootsWithIt)
{
  // 10 cycles per iteration at 1000 revolutions, tolerance 2 %. A crossing 10 factors
  // away is 100 revolutions: more than 0.9 × 2 % of 1100 = 19.8, so stop half of that,
  // 9.9 revolutions, short of it.
  EXPECT_NEAR(approach_factor(10, 10, 1000, 0.02), (100 - 9.9) / 10.0, 1e-12);
  // A crossing 1 factor away (10 rev ≤ 0.9 × 2 % of 1010 = 18.18): take that whole last
  // step, which brackets the crossing within the tolerance.
  EXPECT_NEAR(approach_factor(1, 10, 1000, 0.02), 1.818, 1e-12);
  EXPECT_LE(approach_factor(1, 10, 1000, 0.02) * 10, 0.02 * 1010);
  // From the start (0 revolutions): stop 0.9 % short, then overshoot by 0.9 %.
  const double first = approach_factor(50, 10, 0, 0.02);
  EXPECT_NEAR(first, 50 * (1 - 0.009), 1e-12);
  const double last = approach_factor(50 - first, 10, first * 10, 0.02);
  EXPECT_GT(last, 50 - first);
  EXPECT_NEAR(last * 10, 0.018 * 500, 1e-9);
  EXPECT_TRUE(std::isinf(approach_factor(INFINITY, 10, 0, 0.02)));
}

TEST(LifeCriteria, FirstCrossingIsInterpolatedInItsBracket)
{
  // Values 0, 4, 8, 12 at 0, 100, 200, 300 rev: the limit 10 is crossed halfway
  // between 200 and 300.
  const auto x = first_crossing({0, 100, 200, 300}, {0, 4, 8, 12}, 10);
  ASSERT_TRUE(x.reached);
  EXPECT_DOUBLE_EQ(x.revolutions, 250);
  EXPECT_EQ(x.low, 200);
  EXPECT_EQ(x.high, 300);
  EXPECT_EQ(x.iteration, 3u);
  // A landing a rounding below the limit counts as reached there.
  EXPECT_TRUE(first_crossing({0, 100}, {0, 10 * (1 - 1e-12)}, 10).reached);
  EXPECT_FALSE(first_crossing({0, 100}, {0, 9.9}, 10).reached);
}

TEST(LifeCriteria, TheResponseTrendIsTheLeastSquaresLine)
{
  // 100, 110, 100, 110 m/s² at 0, 1000, 2000, 3000 rev: the line 102 + 0.002 N
  // (slope Σ(x − x̄)(y − ȳ)/Σ(x − x̄)² = 10000/5e6), so 6 % above its fresh value at
  // 3000 rev, while the last measurement over the first says +10 %.
  const ResponseModels m({0, 1000, 2000, 3000}, {100, 110, 100, 110}, 4);
  const auto          &t = m.model(TrendFamily::line);
  EXPECT_EQ(m.points(), 4u);
  EXPECT_NEAR(t.fit.beta, 0.002, 1e-15);
  EXPECT_NEAR(t.fit.a, 102, 1e-12);
  EXPECT_NEAR(t.rise(3000), 100 * 6 / 102.0, 1e-12);
  // Residuals ±(−2, 6, −6, 2): s = √(80 / 2).
  EXPECT_NEAR(m.residual_std(TrendFamily::line), std::sqrt(40.0), 1e-12);
  EXPECT_EQ(ResponseModels({0, 1000}, {100, 120}, 1).model(TrendFamily::line).rise(1000), 0)
    << "one point has no trend";
}

namespace
{
  /**
   * A joint of 36 areas on radii 10 mm (bore) and 9.95 mm (pin) whose contact width,
   * 8.7 mm, spans 5 areas of 1.745 mm (wear::window_areas rounds 4.99 to 5): the depth
   * criteria take the running median over 5 areas.
   */
  wear::JointWearState
  joint_of_five_area_contact()
  {
    wear::JointWearState js;
    js.name          = "A";
    js.initial_bore  = Profile::round(0.010, 36);
    js.initial_pin   = Profile::round(0.00995, 36);
    js.bore          = js.initial_bore;
    js.pin           = js.initial_pin;
    js.contact_width = 8.7e-3;
    return js;
  }
} // namespace

// The envelope, not the raw deepest area: a one-area spike of 60 µm growing by 10 µm per
// unit factor never reaches a 50 µm limit (the median over the 5 areas of the contact
// stays at the 0 of its neighbours), while a pocket of 7 areas — wider than the contact —
// at 40 µm growing by 5 µm per unit factor reaches it at f = 2, as its raw depth does.
TEST(LifeCriteria, TheDepthCriteriaUseTheEnvelopeOverTheContactWidth)
{
  const auto                        js        = joint_of_five_area_contact();
  const std::vector<JointDensities> densities = {{7850, 7850, ""}};
  CriterionSpec                     depth{Criterion::wear_depth, "wear_depth", "Maximum wear depth", "m", 50e-6};
  CriterionSpec growth{Criterion::clearance_growth, "clearance_growth", "Radial clearance growth", "m", 50e-6};

  wear::StepPreview        spike;
  wear::StepPreview::Joint j;
  j.state              = &js;
  j.depth_pin          = std::vector<double>(36, 0.0);
  j.pin_increment      = std::vector<double>(36, 0.0);
  j.depth_bore         = std::vector<double>(36, 0.0);
  j.bore_increment     = std::vector<double>(36, 0.0);
  j.depth_bore[10]     = 60e-6;
  j.bore_increment[10] = 10e-6;
  spike.joints.push_back(j);
  spike.cycles = 10;
  EXPECT_EQ(wear_criterion_value(depth, spike, densities, 0).value, 0) << "the raw depth would be 60 µm";
  EXPECT_TRUE(std::isinf(factor_to_reach(depth, spike, densities, 1000))) << "a spike is no depth the contact meets";
  EXPECT_TRUE(std::isinf(factor_to_reach(growth, spike, densities, 1000)));

  wear::StepPreview pocket = spike;
  auto             &p      = pocket.joints[0];
  for (int k = 20; k < 27; ++k)
    {
      p.depth_bore[k]     = 40e-6;
      p.bore_increment[k] = 5e-6;
    }
  EXPECT_NEAR(wear_criterion_value(depth, pocket, densities, 0).value, 40e-6, 1e-18);
  EXPECT_NEAR(factor_to_reach(depth, pocket, densities, 1000), 2, 2e-12);
  // Clearance growth: the pin's envelope adds to the bore's. A pin pocket of 5 areas at
  // 4 µm (+1 µm per unit factor): 40 + 5 f + 4 + f = 50 µm at f = 1.
  for (int k = 0; k < 5; ++k)
    {
      p.depth_pin[k]     = 4e-6;
      p.pin_increment[k] = 1e-6;
    }
  EXPECT_NEAR(factor_to_reach(growth, pocket, densities, 1000), 1, 1e-12);
  EXPECT_EQ(wear_criterion_value(growth, pocket, densities, 0).joint, "A");
}

// After an iteration the criteria read the wear loop's own envelope depths of the
// record, not its raw deepest area.
TEST(LifeCriteria, AfterAnIterationTheCriteriaReadTheRecordedEnvelope)
{
  wear::WearState       state;
  auto                  js = joint_of_five_area_contact();
  wear::IterationRecord r;
  r.max_depth_bore      = 70e-6; // a spike
  r.envelope_depth_bore = 45e-6;
  r.max_depth_pin       = 12e-6;
  r.envelope_depth_pin  = 10e-6;
  js.history.push_back(r);
  state.joints.push_back(js);
  const std::vector<JointDensities> densities = {{7850, 7850, ""}};
  CriterionSpec                     depth{Criterion::wear_depth, "wear_depth", "Maximum wear depth", "m", 50e-6};
  CriterionSpec growth{Criterion::clearance_growth, "clearance_growth", "Radial clearance growth", "m", 75e-6};
  EXPECT_DOUBLE_EQ(wear_criterion_value(depth, state, densities).value, 45e-6);
  EXPECT_DOUBLE_EQ(wear_criterion_value(growth, state, densities).value, 55e-6);
}

// A joint cut into slices along its pin: its slices are wearing joints of their own. The
// depth criteria take the deepest slice (and name it); the mass criteria weigh the whole
// pin and bushing, the slices' masses summed, and name the joint. Two slices of B at
// 3 and 4 mg of pin (7 mg together) against A's 5 mg: B's pin is the heavier loss.
TEST(LifeCriteria, ASlicedJointsDepthIsItsDeepestSliceAndItsMassTheSum)
{
  wear::WearState state;
  const double    rho = 7850;
  const auto      add = [&](const std::string &name, const double depth, const double mg) {
    auto                  js = joint_of_five_area_contact();
    wear::IterationRecord r;
    js.name               = name;
    r.envelope_depth_bore = depth;
    r.volume_pin          = mg * 1e-6 / rho;
    js.history.push_back(r);
    state.joints.push_back(js);
  };
  add("A", 30e-6, 5);
  add("B.s01", 40e-6, 3);
  add("B.s02", 20e-6, 4);
  const std::vector<JointDensities> densities = {{rho, rho, ""}, {rho, rho, "B"}, {rho, rho, "B"}};
  CriterionSpec                     depth{Criterion::wear_depth, "wear_depth", "Maximum wear depth", "m", 50e-6};
  CriterionSpec                     mass{Criterion::pin_mass_loss, "pin_mass_loss", "Pin mass loss", "mg", 10};
  const auto                        deepest = wear_criterion_value(depth, state, densities);
  EXPECT_DOUBLE_EQ(deepest.value, 40e-6);
  EXPECT_EQ(deepest.joint, "B.s01");
  const auto heaviest = wear_criterion_value(mass, state, densities);
  EXPECT_NEAR(heaviest.value, 7, 1e-12);
  EXPECT_EQ(heaviest.joint, "B");
  // Without the grouping the largest slice (4 mg) would lose to A's 5 mg.
  const std::vector<JointDensities> ungrouped = {{rho, rho, ""}, {rho, rho, ""}, {rho, rho, ""}};
  EXPECT_EQ(wear_criterion_value(mass, state, ungrouped).joint, "A");
}
