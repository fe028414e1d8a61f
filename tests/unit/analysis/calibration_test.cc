// SPDX-License-Identifier: LGPL-2.1-or-later
// The calibration's root finding and interval (analysis/calibration.h) on synthetic
// forward models whose answer is known:
//  - a power law m = a k^p (p = 0.8 and 1.3): the least-squares slope of log m on log k
//    is p, and the secant recovers the k of a measured m from a prior a factor 5 off to
//    the tolerance; exactly proportional wear (p = 1) takes 2 runs (the first step is
//    the linear rescale k0 m / m(k0));
//  - two surfaces that couple weakly (each prediction depends a little on the other
//    coefficient) are solved together;
//  - a bracketed root: a step that would leave the bracket bisects it;
//  - a noisy model (a chaotic scatter of 2 % on top of the power law) stops at the run
//    limit or once the root is bracketed within the tolerance, and keeps the run with the
//    smallest residual; the bracket's width by hand;
//  - the interval: σ_log k = sqrt((σ_m/m)² + (σ_c/m̄)²) / |S| by hand, and the
//    correction k (m / m̄)^(1/S).
#include "analysis/calibration.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace wearlink::analysis;

namespace
{
  /** m = a k^p of one surface. */
  ForwardModel
  power_law(const double a, const double p)
  {
    return [a, p](const std::vector<double> &k) {
      return std::vector<double>{a * std::pow(k[0], p)};
    };
  }
} // namespace

TEST(Calibration, LeastSquaresSlopeOfAPowerLawIsItsExponent)
{
  SecantSettings           s;
  std::vector<SecantPoint> points;
  for (const double k : {1e-14, 3e-14, 8e-14})
    points.push_back({std::log(k), std::log(2e13 * std::pow(k, 0.8) / 5.0)});
  EXPECT_NEAR(log_slope(points, s), 0.8, 1e-12);
  EXPECT_EQ(log_slope({points[0]}, s), 1) << "one run: slope 1 (Archard)";
  EXPECT_EQ(log_slope({{0, 1}, {1, 0}}, s), 1) << "a falling mass loss is not a slope";
  EXPECT_EQ(log_slope({{0, 0}, {1, 100}}, s), s.max_slope);
}

TEST(Calibration, SecantRecoversThePowerLawCoefficient)
{
  for (const double p : {0.8, 1.3})
    {
      const double   a = 1e14, truth = 2.3e-14;
      const double   measured = a * std::pow(truth, p);
      SecantSettings s;
      s.tolerance    = 1e-6;
      const auto fit = fit_coefficients(power_law(a, p), {5 * truth}, {measured}, s);
      EXPECT_TRUE(fit.converged) << p;
      EXPECT_NEAR(fit.k[0] / truth, 1, 2e-6) << p;
      EXPECT_LE(fit.runs, 6u) << p;
      EXPECT_NEAR(fit.slope[0], p, 1e-9) << p;
      EXPECT_NEAR(fit.history[0][1].log_k, std::log(5 * truth * measured / (a * std::pow(5 * truth, p))), 1e-12)
        << "the first step is the linear rescale";
    }
  const auto linear = fit_coefficients(power_law(1e14, 1), {1e-13}, {3.0}, SecantSettings());
  EXPECT_EQ(linear.runs, 2u);
  EXPECT_NEAR(linear.k[0], 3e-14, 1e-26);
}

TEST(Calibration, TwoWeaklyCoupledSurfacesAreSolvedTogether)
{
  // Pin and bushing: m_s = a_s k_s^p_s (1 + 0.05 log(k_other / 1e-14)).
  const ForwardModel model = [](const std::vector<double> &k) {
    return std::vector<double>{2e14 * std::pow(k[0], 0.9) * (1 + 0.05 * std::log(k[1] / 1e-14)),
                               1e14 * std::pow(k[1], 1.1) * (1 + 0.05 * std::log(k[0] / 1e-14))};
  };
  const std::vector<double> truth = {2.3e-14, 9.2e-14};
  const auto                m     = model(truth);
  const auto                fit   = fit_coefficients(model, {4.6e-14, 4.6e-14}, m, SecantSettings());
  ASSERT_TRUE(fit.converged);
  for (std::size_t s = 0; s < 2; ++s)
    EXPECT_NEAR(fit.k[s] / truth[s], 1, 5e-3) << s;
  EXPECT_LE(fit.runs, 8u);
}

TEST(Calibration, AStepOutsideTheBracketBisects)
{
  SecantSettings s;
  // Runs below the root (f < 0) at log k = 0, above it at 0.5 and, newest, at 3 with
  // nearly the same residual: the slope is clamped to 0.2 and the step from the newest
  // run (to 2.99) leaves the bracket (0, 0.5); its midpoint instead.
  const std::vector<SecantPoint> points = {{0, -0.01}, {0.5, 0.001}, {3, 0.002}};
  EXPECT_DOUBLE_EQ(next_log_k(points, s), 0.25);
  EXPECT_EQ(next_log_k({{0.5, 1e-5}}, s), 0.5) << "below the tolerance: unchanged";
  EXPECT_DOUBLE_EQ(bracket_width(points), 0.5);
  EXPECT_TRUE(std::isinf(bracket_width({{0, -0.1}, {1, -0.01}}))) << "no run above the root";
  EXPECT_TRUE(std::isinf(bracket_width({{0, 0.1}, {1, -0.1}}))) << "runs that contradict a rising m(k)";
}

TEST(Calibration, ANoisyModelStopsWithItsBestRun)
{
  // A 2 % scatter that changes with every k (as the chaotic dynamics do): the tolerance
  // 1e-4 is not reached; the best run is kept, within the scatter of the truth.
  const ForwardModel model = [](const std::vector<double> &k) {
    const double noise = 0.02 * std::sin(1e17 * k[0]);
    return std::vector<double>{1e14 * k[0] * (1 + noise)};
  };
  SecantSettings s;
  s.tolerance    = 1e-4;
  s.max_runs     = 6;
  const auto fit = fit_coefficients(model, {1e-13}, {2.0}, s);
  EXPECT_LE(fit.runs, 6u);
  EXPECT_FALSE(fit.converged);
  EXPECT_NEAR(fit.k[0] / 2e-14, 1, 0.03);
  double smallest = 1;
  for (const auto &p : fit.history[0])
    smallest = std::min(smallest, std::abs(std::expm1(p.residual)));
  EXPECT_NEAR(std::abs(fit.predicted[0] / 2.0 - 1), smallest, 1e-12) << "the kept run is the best one";
  EXPECT_NEAR(fit.slope[0], 1, 0.3);
}

TEST(Calibration, AScatterLargerThanTheToleranceEndsOnceTheRootIsBracketedWithinIt)
{
  // A deterministic ±3 % scatter (a hash of log k): the tolerance 1e-3 is reached by chance
  // at best; the loop stops once runs on both sides of the root lie within 1e-3 in log k
  // (located), well before the limit of 40 runs.
  const ForwardModel model = [](const std::vector<double> &k) {
    const double u = std::fmod(std::abs(std::sin(std::log(k[0]) * 12345.678)) * 1e4, 1.0);
    return std::vector<double>{1e14 * k[0] * (1 + 0.06 * (u - 0.5))};
  };
  SecantSettings s;
  s.max_runs     = 40;
  const auto fit = fit_coefficients(model, {1e-13}, {2.0}, s);
  EXPECT_TRUE(fit.located);
  EXPECT_LT(fit.runs, 40u);
  EXPECT_NEAR(fit.k[0] / 2e-14, 1, 0.04);
}

TEST(Calibration, IntervalAndCorrectionByHand)
{
  // σ_m/m = 0.3/10 = 0.03, σ_c/m̄ = 0.32/8 = 0.04 → sqrt(0.03² + 0.04²) = 0.05; slope 0.5 → 0.1.
  const auto ci = coefficient_interval(2e-14, 10, 0.3, 8, 0.32, 0.5);
  EXPECT_NEAR(ci.sigma_log_k, 0.1, 1e-15);
  EXPECT_NEAR(ci.low, 2e-14 * std::exp(-0.196), 1e-28);
  EXPECT_NEAR(ci.high, 2e-14 * std::exp(0.196), 1e-28);
  const auto exact = coefficient_interval(1, 10, 0, 10, 0, 1);
  EXPECT_EQ(exact.low, 1);
  EXPECT_EQ(exact.high, 1);
  EXPECT_NEAR(corrected_coefficient(2, 10, 8, 1), 2.5, 1e-15);
  EXPECT_NEAR(corrected_coefficient(2, 10, 8, 2), 2 * std::sqrt(1.25), 1e-15);
}

TEST(Calibration, ASurfaceWithoutWearIsRefused)
{
  const ForwardModel none = [](const std::vector<double> &) {
    return std::vector<double>{0.0};
  };
  EXPECT_THROW(fit_coefficients(none, {1e-14}, {1.0}, SecantSettings()), std::invalid_argument);
}
