// SPDX-License-Identifier: LGPL-2.1-or-later
#include "analysis/richardson.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace wearlink::analysis;

namespace
{
  /** f(h) = f0 + C h^p at h = 1, 1/2, 1/4, each with standard error se. */
  RefinementTriple
  power_law(const double f0, const double c, const double p, const double se = 0)
  {
    RefinementTriple t;
    for (int l = 0; l < 3; ++l)
      {
        t.value[l]          = f0 + c * std::pow(0.5, p * l);
        t.standard_error[l] = se;
      }
    return t;
  }
} // namespace

TEST(Richardson, RecoversOrderAndLimitOfAPowerLaw)
{
  for (const double p : {1.0, 2.0, 1.5})
    {
      const auto e = richardson(power_law(30, -3, p));
      ASSERT_TRUE(e.determinable) << e.reason;
      EXPECT_NEAR(e.order, p, 1e-12);
      EXPECT_NEAR(e.extrapolated, 30, 1e-12);
      EXPECT_NEAR(e.error[0], -3 / 30.0, 1e-12) << "the coarse level's error is C/f0";
      EXPECT_NEAR(e.error[2], -3 * std::pow(0.25, p) / 30, 1e-12);
    }
}

TEST(Richardson, DifferencesWithinTheNoiseAreNotExtrapolated)
{
  // The fine difference is 0.75 at p = 1; a standard error of 0.3 per level makes its
  // noise 0.42, twice that 0.85 > 0.75: not determinable.
  const auto e = richardson(power_law(30, -3, 1, 0.3));
  EXPECT_FALSE(e.determinable);
  EXPECT_TRUE(std::isnan(e.extrapolated));
  EXPECT_FALSE(e.reason.empty());
  EXPECT_TRUE(richardson(power_law(30, -3, 1, 0.2)).determinable);
}

TEST(Richardson, NonMonotoneLevelsAreNotExtrapolated)
{
  RefinementTriple t;
  t.value[0]   = 29;
  t.value[1]   = 31;
  t.value[2]   = 30;
  const auto e = richardson(t);
  EXPECT_FALSE(e.determinable);
  EXPECT_NE(e.reason.find("monoton"), std::string::npos);
}

TEST(Richardson, DivergingOrSlowLevelsAreNotExtrapolated)
{
  RefinementTriple t; // differences 0.1 then 1: growing, order −3.3
  t.value[0] = 20;
  t.value[1] = 20.1;
  t.value[2] = 21.1;
  auto e     = richardson(t);
  EXPECT_FALSE(e.determinable);
  EXPECT_NEAR(e.order, -std::log2(10), 1e-12);
  t.value[2] = 20.1 + 0.1 / std::sqrt(2.0) * 1.01; // order just below 0.5
  e          = richardson(t);
  EXPECT_FALSE(e.determinable);
  EXPECT_LT(e.order, 0.5);
  t.value[2] = 20.1 + 0.1 / std::sqrt(2.0) * 0.99; // just above
  EXPECT_TRUE(richardson(t).determinable);
  RefinementTriple none;
  EXPECT_EQ(richardson(none).reason, "no wear at any level");
}

TEST(Richardson, AnOrderAboveTheAsymptoticRangeIsClampedAndSaid)
{
  // Differences 4 and 0.1: p = log2(40) = 5.3, clamped to 4.
  RefinementTriple t;
  t.value[0]   = 20;
  t.value[1]   = 24;
  t.value[2]   = 24.1;
  const auto e = richardson(t);
  ASSERT_TRUE(e.determinable);
  EXPECT_NEAR(e.order, std::log2(40), 1e-12);
  EXPECT_NEAR(e.extrapolated, 24.1 + 0.1 / 15, 1e-12);
  EXPECT_FALSE(e.reason.empty());
}
