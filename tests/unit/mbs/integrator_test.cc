// SPDX-License-Identifier: LGPL-2.1-or-later
// Integrators on the harmonic oscillator y'' = −y, y(0) = 1, y'(0) = 0 (exact cos t):
//  - rk4 is 4th order: halving the step divides the error at t = 2π by 2⁴ = 16
//    (asymptotically; accepted between 14 and 18 at these steps);
//  - dopri5 meets its tolerance: the global error at t = 2π follows the tolerance
//    (ratio of errors for tolerances 1e-6 and 1e-9 at least 100, i.e. error ∝ tol^≥⅔);
//  - the dense outputs are accurate between steps: rk4's cubic Hermite to O(h⁴) and
//    dopri5's 4th-order continuous extension to within 10× the step tolerance.
#include "base/exceptions.h"
#include "mbs/integrator.h"

#include <gtest/gtest.h>

#include <cmath>

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
  IntegratorSettings s;
  s.type               = IntegratorType::dopri5;
  s.max_step           = 1.0;
  s.relative_tolerance = 1e-6;
  const auto loose     = run(s);
  s.relative_tolerance = 1e-9;
  const auto tight     = run(s);
  EXPECT_LT(tight.first, 1e-7);
  EXPECT_GT(loose.first / tight.first, 100.0);
  EXPECT_LT(tight.second, 1e-8);
}

TEST(Integrators, UnknownNameIsAnInputError)
{
  EXPECT_THROW(parse_integrator_type("euler"), wearlink::InputError);
}
