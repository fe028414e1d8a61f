// SPDX-License-Identifier: LGPL-2.1-or-later
// The wear step (Wear/Wear integration; wear/wear_step.h), on ordinary differential equations
// in revolutions whose solutions are known:
//  - a rate that changes linearly with the revolutions is integrated exactly by the
//    Adams–Bashforth step after its first (Euler) step, with steps of changing factor;
//  - a rate that grows with the depth (the worn pocket drawing the contact,
//    dh/dN = λ h) converges at order 2 (Adams–Bashforth) and 1 (Euler) under halving
//    of the step, and Adams–Bashforth is the more accurate at the coarsest step;
//  - an area the contact left is not restored (no negative increment), the volumes
//    combine like the depths, and rates of different sizes are refused;
//  - the change of rate is taken over the contact width: a saw-tooth between
//    neighbouring areas (chaotic samples) is not extrapolated, a trend is, and the
//    change keeps its sum.
#include "base/exceptions.h"
#include "wear/wear_step.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using wearlink::wear::step_rate;
using wearlink::wear::WearRate;
using wearlink::wear::WearStep;

namespace
{
  /** A rate of one pin and one bore area, both @p value, and a volume rate 10 × it. */
  WearRate
  rate_of(const double value)
  {
    WearRate r;
    r.depth_pin   = {value};
    r.depth_bore  = {value};
    r.volume_pin  = 10 * value;
    r.volume_bore = 10 * value;
    return r;
  }

  /**
   * Integrate dh/dN = g(N, h) from N = 0, h = h0 with the given factors (steps in N),
   * the rate of each step taken at its start, as the wear loop does.
   */
  template <typename Rate>
  double
  integrate(const Rate &g, const double h0, const std::vector<double> &factors, const WearStep scheme)
  {
    double   h = h0, N = 0, f_before = 0;
    WearRate before;
    for (const double f : factors)
      {
        const WearRate now     = rate_of(g(N, h));
        const WearRate applied = step_rate(now, before, f, f_before, scheme);
        h += f * applied.depth_bore[0];
        N += f;
        before   = now;
        f_before = f;
      }
    return h;
  }

  /** The error of integrating dh/dN = λ h to N = 1 in n equal steps. */
  double
  growth_error(const unsigned int n, const WearStep scheme)
  {
    const double lambda = 2;
    const double h =
      integrate([&](double, double h) { return lambda * h; }, 1.0, std::vector<double>(n, 1.0 / n), scheme);
    return std::abs(h - std::exp(lambda));
  }
} // namespace

TEST(WearStep, EulerAndTheFirstIterationApplyTheOwnRate)
{
  const WearRate now = rate_of(3), before = rate_of(1);
  EXPECT_EQ(step_rate(now, before, 1, 1, WearStep::euler).depth_bore[0], 3);
  EXPECT_EQ(step_rate(now, WearRate(), 1, 0, WearStep::adams_bashforth).depth_bore[0], 3);
  EXPECT_EQ(step_rate(now, before, 1, 0, WearStep::adams_bashforth).depth_bore[0], 3); // after a step of factor 0
}

TEST(WearStep, ALinearRateIsExactAfterTheFirstStepWithChangingFactors)
{
  const double a = 2e-9, b = 3e-13; // dh/dN = a + b N [m per revolution]
  const auto   g = [&](double N, double) {
    return a + b * N;
  };
  const std::vector<double> factors = {500, 1000, 1500, 750, 1500, 3000, 300}; // ω = 2, 1.5, 0.5, 2, 2, 0.1
  double                    N       = 0;
  for (const double f : factors)
    N += f;
  const double exact       = a * N + b * N * N / 2;
  const double first_error = -b * factors[0] * factors[0] / 2; // the Euler start
  const double h           = integrate(g, 0.0, factors, WearStep::adams_bashforth);
  EXPECT_NEAR(h, exact + first_error, 1e-12 * exact);
  // Euler lags by half a step's change of rate on every step.
  double euler_error = 0;
  for (const double f : factors)
    euler_error -= b * f * f / 2;
  EXPECT_NEAR(integrate(g, 0.0, factors, WearStep::euler), exact + euler_error, 1e-12 * exact);
}

TEST(WearStep, AGrowingPocketConvergesAtOrderTwo)
{
  for (const auto scheme : {WearStep::adams_bashforth, WearStep::euler})
    {
      const double e10 = growth_error(10, scheme), e20 = growth_error(20, scheme), e40 = growth_error(40, scheme);
      const double order = std::log2(e20 / e40);
      SCOPED_TRACE(scheme == WearStep::euler ? "euler" : "adams-bashforth");
      EXPECT_GT(e10 / e20, 1.6);
      if (scheme == WearStep::adams_bashforth)
        EXPECT_NEAR(order, 2.0, 0.15);
      else
        EXPECT_NEAR(order, 1.0, 0.1);
    }
  // At the coarsest step (10 iterations, the shipped scenes') the second-order step is
  // the more accurate by more than 3× (its Euler start included).
  EXPECT_LT(3 * growth_error(10, WearStep::adams_bashforth), growth_error(10, WearStep::euler));
}

TEST(WearStep, AnAreaTheContactLeftIsNotRestoredAndVolumesCombineLikeDepths)
{
  WearRate now = rate_of(1), before = rate_of(1);
  now.depth_bore    = {1.0, 0.1};
  before.depth_bore = {1.0, 1.0};
  now.depth_pin     = {2.0};
  before.depth_pin  = {1.0};
  const WearRate r  = step_rate(now, before, 1, 1, WearStep::adams_bashforth);
  EXPECT_DOUBLE_EQ(r.depth_bore[0], 1.0);
  EXPECT_EQ(r.depth_bore[1], 0.0); // 1.5 · 0.1 − 0.5 · 1 < 0: cut, not restored
  EXPECT_DOUBLE_EQ(r.depth_pin[0], 2.5);
  EXPECT_DOUBLE_EQ(r.volume_pin, 10.0);
  // ω is at most 2: a factor grown tenfold extrapolates as a doubled one.
  EXPECT_DOUBLE_EQ(step_rate(now, before, 10, 1, WearStep::adams_bashforth).depth_pin[0], 3.0);
}

TEST(WearStep, RatesOfDifferentSizesAreRefused)
{
  WearRate now = rate_of(1), before = rate_of(1);
  before.depth_bore = {1.0, 1.0};
  EXPECT_THROW(step_rate(now, before, 1, 1, WearStep::adams_bashforth), wearlink::NumericalError);
}

TEST(WearStep, TheChangeOfRateIsTakenOverTheContactWidth)
{
  // 360 areas of a 12 mm bore (0.21 mm each), a contact 1.5 mm wide.
  const unsigned int                    n = 360;
  const wearlink::wear::RateChangeScale scale{1.5e-3, 0.0115, 0.012};
  WearRate                              now, before;
  now.depth_pin.assign(n, 1.0);
  before.depth_pin.assign(n, 1.0);
  before.depth_bore.assign(n, 1.0);
  now.depth_bore.resize(n);
  for (unsigned int k = 0; k < n; ++k)
    now.depth_bore[k] = 1.0 + 0.5 * (k % 2 == 0 ? 1 : -1) + 0.2 * std::sin(2 * M_PI * k / n); // saw-tooth + a trend
  const WearRate r      = step_rate(now, before, 1, 1, WearStep::adams_bashforth, scale);
  double         change = 0, expected_change = 0;
  for (unsigned int k = 0; k < n; ++k)
    {
      // The saw-tooth of neighbouring areas is not extrapolated, the trend is (by half).
      EXPECT_NEAR(r.depth_bore[k] - now.depth_bore[k], 0.1 * std::sin(2 * M_PI * k / n), 2e-3) << k;
      change += r.depth_bore[k] - now.depth_bore[k];
      expected_change += 0.5 * (now.depth_bore[k] - before.depth_bore[k]);
    }
  EXPECT_NEAR(change, expected_change, 1e-9); // the change's sum is kept
  EXPECT_EQ(r.depth_pin, now.depth_pin);      // no change of rate, none applied
}
