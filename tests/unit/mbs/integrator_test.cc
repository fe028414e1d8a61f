// SPDX-License-Identifier: LGPL-2.1-or-later
// Integrators on the harmonic oscillator y'' = −y, y(0) = 1, y'(0) = 0 (exact cos t):
//  - rk4 is 4th order: halving the step divides the error at t = 2π by 2⁴ = 16
//    (asymptotically; accepted between 14 and 18 at these steps);
//  - dopri5 meets its tolerance: the global error at t = 2π follows the tolerance
//    (ratio of errors for tolerances 1e-6 and 1e-9 at least 100, i.e. error ∝ tol^≥⅔);
//  - the dense outputs are accurate between steps: rk4's cubic Hermite to O(h⁴) and
//    dopri5's 4th-order continuous extension to within 10× the step tolerance;
//  - dop853 is 8th order: at a fixed step (tolerance so loose that every step is
//    accepted at the maximum step) halving the step divides the error by 2⁸ = 256
//    (accepted 180 … 360), it meets its tolerance like dopri5, its 7th-order dense output
//    is as accurate as its steps, and after a dense output the system was last evaluated
//    at the accepted state (observers read the system's workspace after a step).
#include "base/exceptions.h"
#include "mbs/integrator.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <iostream>

using namespace wearlink::mbs;

namespace
{
  class Oscillator : public OdeSystem
  {
  public:
    unsigned int
    size() const override
    {
      return 2;
    }
    void
    rhs(double, const double *y, double *f) override
    {
      f[0] = y[1];
      f[1] = -y[0];
    }
  };

  constexpr double two_pi = 6.283185307179586;

  /** The oscillator that remembers the last point it was evaluated at. */
  class RecordingOscillator : public Oscillator
  {
  public:
    void
    rhs(double t, const double *y, double *f) override
    {
      last_t = t;
      last_y = {y[0], y[1]};
      Oscillator::rhs(t, y, f);
    }
    double                last_t = -1;
    std::array<double, 2> last_y{0, 0};
  };

  /** Integrate to 2π; return the final error and the worst dense-output error. */
  std::pair<double, double>
  run(IntegratorSettings s)
  {
    Oscillator osc;
    s.absolute_tolerance = {s.relative_tolerance, s.relative_tolerance};
    auto integ           = make_integrator(osc, s);
    integ->reset(0, Eigen::Vector2d(1, 0));
    double dense_error = 0;
    double y[2];
    while (integ->time() < two_pi)
      {
        integ->step(two_pi);
        for (double f : {0.25, 0.5, 0.75})
          {
            const double t = integ->previous_time() + f * (integ->time() - integ->previous_time());
            integ->dense_output(t, y);
            dense_error = std::max(dense_error, std::abs(y[0] - std::cos(t)));
          }
      }
    // The state error: at t = 2π the position error alone is second order in the phase
    // error, the velocity error (−sin) first order.
    return {std::hypot(integ->state()[0] - 1.0, integ->state()[1]), dense_error};
  }
  /**
   * Global error at 1e-6 and at @p tight: the tight one below @p max_error (dense
   * output below @p max_dense_error), and at least 100 × smaller than the loose one.
   */
  void
  expect_follows_tolerance(IntegratorType type, double tight, double max_error, double max_dense_error)
  {
    IntegratorSettings s;
    s.type               = type;
    s.max_step           = 1.0;
    s.relative_tolerance = 1e-6;
    const auto loose     = run(s);
    s.relative_tolerance = tight;
    const auto fine      = run(s);
    EXPECT_LT(fine.first, max_error);
    EXPECT_GT(loose.first / fine.first, 100.0);
    EXPECT_LT(fine.second, max_dense_error);
  }
} // namespace

TEST(Integrators, Rk4IsFourthOrder)
{
  IntegratorSettings s;
  s.type             = IntegratorType::rk4;
  s.time_step        = two_pi / 100;
  const auto e1      = run(s);
  s.time_step        = two_pi / 200;
  const auto   e2    = run(s);
  const double ratio = e1.first / e2.first;
  EXPECT_GT(ratio, 14.0);
  EXPECT_LT(ratio, 18.0);
  // Cubic Hermite dense output: O(h⁴) with a constant ~1/384 · max|y''''| h⁴.
  EXPECT_LT(e2.second, std::pow(two_pi / 200, 4));
}

TEST(Integrators, Dopri5FollowsItsTolerance)
{
  expect_follows_tolerance(IntegratorType::dopri5, 1e-9, 1e-7, 1e-8);
}

TEST(Integrators, Dop853IsEighthOrder)
{
  IntegratorSettings s;
  s.type               = IntegratorType::dop853;
  s.relative_tolerance = 1.0; // every step accepted at the maximum step
  s.max_step           = two_pi / 12;
  const auto coarse    = run(s);
  s.max_step           = two_pi / 24;
  const auto   fine    = run(s);
  const double ratio   = coarse.first / fine.first;
  std::cout << "dop853 at h = 2π/12: error " << coarse.first << ", at 2π/24: " << fine.first << ", ratio " << ratio
            << " (8th order: 256)\n";
  EXPECT_GT(ratio, 180.0);
  EXPECT_LT(ratio, 360.0);
  // The 7th-order continuous extension stays near the step's own accuracy.
  EXPECT_LT(fine.second, 1e-7);
}

TEST(Integrators, Dop853FollowsItsTolerance)
{
  expect_follows_tolerance(IntegratorType::dop853, 1e-10, 1e-8, 1e-8);
}

TEST(Integrators, Dop853LeavesTheSystemAtTheAcceptedStateAfterDenseOutput)
{
  RecordingOscillator osc;
  IntegratorSettings  s;
  s.type               = IntegratorType::dop853;
  s.relative_tolerance = 1e-8;
  s.absolute_tolerance = {1e-8, 1e-8};
  auto integ           = make_integrator(osc, s);
  integ->reset(0, Eigen::Vector2d(1, 0));
  integ->step(1.0);
  const long before = integ->n_evaluations;
  double     y[2];
  integ->dense_output(0.5 * (integ->previous_time() + integ->time()), y);
  // Three extra stages, then the accepted state again; a second read costs nothing.
  EXPECT_EQ(integ->n_evaluations - before, 4);
  integ->dense_output(integ->previous_time() + 0.25 * (integ->time() - integ->previous_time()), y);
  EXPECT_EQ(integ->n_evaluations - before, 4);
  EXPECT_EQ(osc.last_t, integ->time());
  EXPECT_EQ(osc.last_y[0], integ->state()[0]);
  EXPECT_EQ(osc.last_y[1], integ->state()[1]);
}

TEST(Integrators, UnknownNameIsAnInputError)
{
  EXPECT_THROW(parse_integrator_type("euler"), wearlink::InputError);
}
