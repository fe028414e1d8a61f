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
//    at the accepted state (observers read the system's workspace after a step);
//  - a step size that collapses (y' = y² towards its blow-up at t = 1) is a
//    NumericalError whose advice fits the tolerance: loosen it where there is room.
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
      last_y = {{y[0], y[1]}};
      Oscillator::rhs(t, y, f);
    }
    double                last_t = -1;
    std::array<double, 2> last_y{{0, 0}};
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

namespace
{
  /**
   * q'' = −k q − c(t) q' as a second-order system y = [q | q'] (n = 1), c(t) = c inside
   * [t_on, t_off) and 0 outside, with both terms offered as stiff directions (w = 1)
   * when @p with_directions.
   */
  class DampedOscillator : public OdeSystem
  {
  public:
    DampedOscillator(double k, double c, bool with_directions, double t_on = -1e300, double t_off = 1e300)
      : k(k)
      , c(c)
      , with_directions(with_directions)
      , t_on(t_on)
      , t_off(t_off)
    {
    }
    double
    damping(double t) const
    {
      return t >= t_on && t < t_off ? c : 0.0;
    }
    unsigned int
    size() const override
    {
      return 2;
    }
    unsigned int
    n_second_order() const override
    {
      return 1;
    }
    void
    rhs(double t, const double *y, double *f) override
    {
      f[0] = y[1];
      f[1] = -k * y[0] - damping(t) * y[1];
    }
    void
    stiff_directions(double, const double *, std::vector<StiffDirection> &out) override
    {
      out.clear();
      if (!with_directions)
        return;
      StiffDirection d;
      d.w             = Eigen::VectorXd::Ones(1);
      d.position      = true;
      d.velocity      = true;
      d.position_step = 1e-7;
      d.velocity_step = 1e-7;
      out.push_back(d);
    }
    const double k, c;
    const bool   with_directions;
    const double t_on, t_off;
  };

  /** The exact state at t0 + τ of q'' = −k q − c q' (constant c) from @p y0. */
  Eigen::Vector2d
  exact_damped(double k, double c, const Eigen::Vector2d &y0, double tau)
  {
    if (c == 0)
      {
        const double w = std::sqrt(k);
        return {y0[0] * std::cos(w * tau) + y0[1] / w * std::sin(w * tau),
                -y0[0] * w * std::sin(w * tau) + y0[1] * std::cos(w * tau)};
      }
    // Overdamped (c² > 4k): modes e^{λ τ}, λ = (−c ± √(c² − 4k))/2; the slow one written
    // as 2k/(−c − √…) to keep its digits.
    const double root = std::sqrt(c * c - 4 * k);
    const double l1 = 2 * k / (-c - root), l2 = 0.5 * (-c - root);
    const double a2 = (y0[1] - l1 * y0[0]) / (l2 - l1), a1 = y0[0] - a2;
    return {a1 * std::exp(l1 * tau) + a2 * std::exp(l2 * tau),
            a1 * l1 * std::exp(l1 * tau) + a2 * l2 * std::exp(l2 * tau)};
  }

  /** Error at t = 2π of q'' = −q from (1, 0) at a fixed step (every step accepted). */
  double
  fixed_step_error(IntegratorType type, double h, bool with_directions)
  {
    DampedOscillator   osc(1, 0, with_directions);
    IntegratorSettings s;
    s.type               = type;
    s.relative_tolerance = 1e3;
    s.absolute_tolerance = {1, 1};
    s.max_step           = h;
    auto integ           = make_integrator(osc, s);
    integ->reset(0, Eigen::Vector2d(1, 0));
    while (integ->time() < two_pi)
      integ->step(two_pi);
    return std::hypot(integ->state()[0] - 1.0, integ->state()[1]);
  }
} // namespace

TEST(Integrators, Ros34pw2IsThirdOrderWithAnyW)
{
  for (bool exact : {true, false})
    {
      const double coarse = fixed_step_error(IntegratorType::ros34pw2, two_pi / 50, exact);
      const double fine   = fixed_step_error(IntegratorType::ros34pw2, two_pi / 100, exact);
      std::cout << (exact ? "exact W" : "W without stiff directions") << ": error " << coarse << " → " << fine
                << ", ratio " << coarse / fine << " (3rd order: 8)\n";
      EXPECT_GT(coarse / fine, 6.5);
      EXPECT_LT(coarse / fine, 10.0);
    }
}

// A stiff damper: q'' = −q − 10⁴ q' from (1, 0), overdamped with modes −1e-4 and −1e4.
// dopri5 would need ~3·10⁴ steps for 1 s (stability, h < 3.3e-4); ROS34PW2 with the
// exact W is L-stable and follows the slow mode at steps set by its accuracy. Asserted:
// the state at t = 1 within 1e-6 of the exact one (tolerance 1e-8 over a slow mode of
// unit size: the global error stays within ~100 × the local tolerance), in fewer than
// 200 steps.
TEST(Integrators, Ros34pw2FollowsAStiffDamperAtLargeSteps)
{
  DampedOscillator   osc(1, 1e4, true);
  IntegratorSettings s;
  s.type               = IntegratorType::ros34pw2;
  s.relative_tolerance = 1e-8;
  s.absolute_tolerance = {1e-8, 1e-8};
  s.max_step           = 1.0;
  auto integ           = make_integrator(osc, s);
  integ->reset(0, Eigen::Vector2d(1, 0));
  while (integ->time() < 1.0)
    integ->step(1.0);
  const Eigen::Vector2d exact = exact_damped(1, 1e4, Eigen::Vector2d(1, 0), 1.0);
  std::cout << "ros34pw2 on the stiff damper: " << integ->n_accepted << " steps, " << integ->n_rejected
            << " rejected; q(1) = " << integ->state()[0] << " (exact " << exact[0] << ")\n";
  EXPECT_NEAR(integ->state()[0], exact[0], 1e-6);
  EXPECT_NEAR(integ->state()[1], exact[1], 1e-6);
  EXPECT_LT(integ->n_accepted, 200);
}

namespace
{
  struct SwitchingRun
  {
    Eigen::Vector2d at_off, at_end;
    long            evaluations_stiff = 0, evaluations_after = 0;
  };

  /** dopri5 or dopri5-stiff on the oscillator damped by 10⁴ during [1, 2); evaluations per phase. */
  SwitchingRun
  damped_phase_run(IntegratorType type)
  {
    DampedOscillator   osc(1, 1e4, true, 1.0, 2.0);
    IntegratorSettings s;
    s.type               = type;
    s.relative_tolerance = 1e-8;
    s.absolute_tolerance = {1e-8, 1e-8};
    s.max_step           = 0.1;
    auto integ           = make_integrator(osc, s);
    integ->reset(0, Eigen::Vector2d(1, 0));
    SwitchingRun r;
    for (const double t_limit : {1.0, 2.0, 12.0})
      {
        const long before = integ->n_evaluations;
        while (integ->time() < t_limit)
          integ->step(t_limit);
        if (t_limit == 2.0)
          {
            r.evaluations_stiff = integ->n_evaluations - before;
            r.at_off            = integ->state();
          }
        if (t_limit == 12.0)
          r.evaluations_after = integ->n_evaluations - before;
      }
    r.at_end = integ->state();
    return r;
  }
} // namespace

// dopri5-stiff on an oscillator damped stiffly during [1, 2) only: it must hand over to
// ROS34PW2 in the damped phase (there: under a tenth of dopri5's right-hand sides, which
// are ~3·10⁴ × 6 for the stability limit) and back to dopri5 afterwards (over the ten
// undamped seconds: within 1.3× dopri5's evaluations; ROS34PW2 alone, third order, would
// need several times more there). Both states against the exact piecewise solution to
// 1e-6 (tolerance 1e-8, a few hundred steps).
TEST(Integrators, Dopri5StiffHandsOverInTheStiffPhaseAndBack)
{
  const SwitchingRun    explicit_run = damped_phase_run(IntegratorType::dopri5);
  const SwitchingRun    switching    = damped_phase_run(IntegratorType::dopri5_stiff);
  const Eigen::Vector2d at_on        = exact_damped(1, 0, Eigen::Vector2d(1, 0), 1.0);
  const Eigen::Vector2d at_off       = exact_damped(1, 1e4, at_on, 1.0);
  const Eigen::Vector2d at_end       = exact_damped(1, 0, at_off, 10.0);
  std::cout << "damped phase: dopri5 " << explicit_run.evaluations_stiff << " evaluations, dopri5-stiff "
            << switching.evaluations_stiff << "; undamped after it: " << explicit_run.evaluations_after << " vs "
            << switching.evaluations_after << "\n";
  EXPECT_LT(switching.evaluations_stiff, explicit_run.evaluations_stiff / 10);
  EXPECT_LT(switching.evaluations_after, 1.3 * explicit_run.evaluations_after);
  EXPECT_NEAR(switching.at_off[0], at_off[0], 1e-6);
  EXPECT_NEAR(switching.at_end[0], at_end[0], 1e-6);
  EXPECT_NEAR(switching.at_end[1], at_end[1], 1e-6);
}

namespace
{
  /** y' = y², y(0) = 1: y = 1/(1 − t) blows up at t = 1, where no step meets any tolerance. */
  class BlowUp : public OdeSystem
  {
  public:
    unsigned int
    size() const override
    {
      return 1;
    }
    void
    rhs(double, const double *y, double *f) override
    {
      f[0] = y[0] * y[0];
    }
  };

  /** The message of the NumericalError that dopri5 throws before t = 1 at @p relative_tolerance. */
  std::string
  blow_up_message(const double relative_tolerance)
  {
    BlowUp             ode;
    IntegratorSettings s;
    s.relative_tolerance = relative_tolerance;
    s.absolute_tolerance = {1.0};
    s.min_step           = 1e-3; // reached when 1 − t is about a millisecond
    auto integ           = make_integrator(ode, s);
    integ->reset(0, Eigen::VectorXd::Ones(1));
    try
      {
        while (integ->time() < 2.0)
          integ->step(2.0);
      }
    catch (const wearlink::NumericalError &e)
      {
        return e.message();
      }
    return "(no NumericalError)";
  }
} // namespace

// When the step size collapses, the message advises loosening the relative tolerance
// only where there is room to: at 1 (the entry's maximum) it says that loosening will
// not help and names what may.
TEST(Integrators, StepSizeCollapseAdvisesWhatCanHelp)
{
  const std::string tight = blow_up_message(1e-6);
  EXPECT_NE(tight.find("the step size fell to"), std::string::npos) << tight;
  EXPECT_NE(tight.find("Loosen Integrator/Relative tolerance (now 1e-06)"), std::string::npos) << tight;
  const std::string loose = blow_up_message(1.0);
  EXPECT_NE(loose.find("the step size fell to"), std::string::npos) << loose;
  EXPECT_EQ(loose.find("Loosen Integrator/Relative tolerance"), std::string::npos) << loose;
  EXPECT_NE(loose.find("Integrator/Relative tolerance is 1 already, so loosening it will not help"), std::string::npos)
    << loose;
}
