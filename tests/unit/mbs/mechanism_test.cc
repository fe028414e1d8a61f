// SPDX-License-Identifier: LGPL-2.1-or-later
// The equations of motion and the assembly:
//  - compound pendulum (a rod pinned at one end): small-amplitude period
//    T = 2π √((J + m d²)/(m g d)), d = L/2, and exact energy conservation;
//  - the Schur-complement solve equals a direct solve of the full saddle-point system
//    [M Φqᵀ; Φq 0] (independent path through Eigen's LU) on the nine-bar;
//  - assembly picks the branch nearest the guess and reports an impossible mechanism;
//  - the body angles' cos and sin (libmvec) against the scalar library.
#include "base/exceptions.h"
#include "io/scene.h"
#include "mbs/assembly.h"
#include "mbs/body_trig.h"
#include "mbs/mechanism.h"
#include "mbs/simulation.h"
#include "support/test_support.h"
#include "workflows/run/run.h"

#include <Eigen/LU>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace wearlink;
using namespace wearlink::mbs;


TEST(Mechanism, CompoundPendulumPeriodAndEnergy)
{
  const double m = 0.5, L = 0.4, J = m * L * L / 12, g = 9.81, d = L / 2;
  const double theta0 = 0.01; // amplitude [rad]; the finite-amplitude correction θ0²/16 ≈ 6e-6
  Mechanism    mech;
  Body         rod;
  rod.name             = "rod";
  rod.mass             = m;
  rod.inertia          = J;
  const double phi0    = -M_PI / 2 + theta0; // rod hanging down, released at +θ0
  rod.initial_position = Vec2(d * std::cos(phi0), d * std::sin(phi0));
  rod.initial_angle    = phi0;
  mech.add_body(rod);
  mech.add_constraint(make_revolute("pivot", ground, Vec2(0, 0), 0, Vec2(-d, 0)));
  mech.set_gravity(Vec2(0, -g));
  mech.finalize();

  Eigen::VectorXd q, v;
  assemble(mech, 0, {}, {}, q, v);
  SimulationSettings s;
  s.integrator.relative_tolerance = 1e-11;
  s.integrator.absolute_tolerance = {1e-13, 1e-11};
  s.integrator.max_step           = 1e-2;
  Simulation sim(mech, s);
  // θ + π/2 crosses zero where the rod passes the vertical (dense output, bisection).
  sim.initialize(0, q, v);
  class Crossings : public StepObserver
  {
  public:
    void
    on_step(const StepContext &c) override
    {
      auto f = [&](double t) {
        Eigen::VectorXd y;
        c.simulation.state_at(t, y);
        return y[2] + M_PI / 2;
      };
      if (f(c.t_previous) < 0 && f(c.t) >= 0)
        {
          double lo = c.t_previous, hi = c.t;
          for (int i = 0; i < 60; ++i)
            {
              const double mid       = 0.5 * (lo + hi);
              (f(mid) < 0 ? lo : hi) = mid;
            }
          times.push_back(hi);
        }
    }
    std::vector<double> times;
  } crossings;
  const double period = 2 * M_PI * std::sqrt((J + m * d * d) / (m * g * d));
  sim.run(3.2 * period, {&crossings});
  ASSERT_GE(crossings.times.size(), 3u);
  const double measured = crossings.times[2] - crossings.times[1];
  EXPECT_NEAR(measured / period, 1.0, 2e-5) << "measured " << measured << " s, linear theory " << period << " s";

  const auto  &y     = sim.state();
  const double e0    = mech.kinetic_energy(v.data()) + mech.potential_energy(q.data(), v.data());
  const double e1    = mech.kinetic_energy(y.data() + 3) + mech.potential_energy(y.data(), y.data() + 3);
  const double swing = m * g * d * (1 - std::cos(theta0)); // energy scale of the motion
  EXPECT_NEAR(e1, e0, 1e-6 * swing);
}

TEST(Mechanism, SchurComplementEqualsSaddlePointSolve)
{
  io::Scene       scene = io::read_scene(wearlink::testing::source_path("params/nine_bar_ideal.prm"));
  auto           &mech  = *scene.mechanism;
  Eigen::VectorXd q, v;
  workflows::assemble_scene(scene, q, v);
  // Perturb the state off the constraint manifold so that Baumgarte terms matter too.
  q[4] += 1e-4;
  v[7] += 0.1;

  Eigen::VectorXd a(mech.n_coordinates());
  PowerTerms      p;
  mech.accelerations(0.1, q.data(), v.data(), a.data(), p);

  Eigen::VectorXd phi, phit, gamma;
  Eigen::MatrixXd J;
  mech.evaluate_constraints(0.1, q.data(), v.data(), phi, J, phit, gamma);
  const unsigned int n = mech.n_coordinates(), m = mech.n_constraint_equations();
  Eigen::MatrixXd    K = Eigen::MatrixXd::Zero(n + m, n + m);
  Eigen::VectorXd    b = Eigen::VectorXd::Zero(n + m);
  for (unsigned int i = 0; i < mech.n_bodies(); ++i)
    {
      const auto &body = mech.get_bodies()[i];
      K(3 * i, 3 * i) = K(3 * i + 1, 3 * i + 1) = body.mass;
      K(3 * i + 2, 3 * i + 2)                   = body.inertia;
      b[3 * i]                                  = body.mass * mech.get_gravity().x();
      b[3 * i + 1]                              = body.mass * mech.get_gravity().y();
    }
  K.block(0, n, n, m) = J.transpose();
  K.block(n, 0, m, n) = J;
  const double alpha = 5, beta = 5; // the scene's Baumgarte parameters (defaults)
  b.tail(m)               = gamma - 2 * alpha * (J * v + phit) - beta * beta * phi;
  const Eigen::VectorXd x = K.fullPivLu().solve(b);
  EXPECT_LT((x.head(n) - a).norm(), 1e-9 * x.head(n).norm());
  EXPECT_LT((x.tail(m) - mech.multipliers()).norm(), 1e-9 * x.tail(m).norm());
}

TEST(Assembly, FindsTheBranchNearestTheGuessAndReportsImpossibleMechanisms)
{
  // Four-bar O2 (0,0) – crank 0.1 – coupler 0.35 – rocker 0.3 – O4 (0.38, 0), crank at
  // 90°: the two assembly branches have the coupler–rocker hinge at
  // (0.2953, 0.2878) (elbow up) and (0.1646, -0.2089) (elbow down); each guess is the
  // other branch's mirror image, perturbed by a few millimetres and degrees.
  struct Guess
  {
    Vec2   coupler;
    double coupler_angle;
    Vec2   rocker;
    double rocker_angle;
  };
  const Guess up{Vec2(0.15, 0.19), 0.6, Vec2(0.34, 0.14), 1.8};
  const Guess down{Vec2(0.08, -0.05), -1.05, Vec2(0.27, -0.10), -2.4};
  auto        build = [](double rocker_length, const Guess &g) {
    auto mech = std::make_unique<Mechanism>();
    mech->add_body(Body{"crank", 0.1, 1e-4, Vec2(0, 0.05), M_PI / 2});
    mech->add_body(Body{"coupler", 0.3, 3e-3, g.coupler, g.coupler_angle});
    mech->add_body(Body{"rocker", 0.25, 2e-3, g.rocker, g.rocker_angle});
    mech->add_constraint(make_revolute("O2", ground, Vec2(0, 0), 0, Vec2(-0.05, 0)));
    mech->add_constraint(make_revolute("A", 0, Vec2(0.05, 0), 1, Vec2(-0.175, 0)));
    mech->add_constraint(make_revolute("B", 1, Vec2(0.175, 0), 2, Vec2(rocker_length / 2, 0)));
    mech->add_constraint(make_revolute("O4", ground, Vec2(0.38, 0), 2, Vec2(-rocker_length / 2, 0)));
    mech->add_constraint(make_angle_driver("drive", ground, 0, M_PI / 2, 1.0));
    mech->finalize();
    return mech;
  };
  Eigen::VectorXd q, v;
  {
    auto m = build(0.30, up);
    assemble(*m, 0, {}, {}, q, v);
    EXPECT_NEAR(2 * q[7], 0.287808, 1e-5) << "hinge height (twice the rocker's centre), elbow up";
  }
  {
    auto m = build(0.30, down);
    assemble(*m, 0, {}, {}, q, v);
    EXPECT_NEAR(2 * q[7], -0.208857, 1e-5) << "hinge height (twice the rocker's centre), elbow down";
  }
  {
    // The crank–rocker-pivot distance is 0.393 m; a 0.35 m coupler and a 2 cm rocker
    // cannot close the loop.
    auto impossible = build(0.02, up);
    try
      {
        assemble(*impossible, 0, {}, {}, q, v);
        FAIL() << "an impossible mechanism assembled";
      }
    catch (const InputError &e)
      {
        EXPECT_NE(e.message().find("cannot be assembled"), std::string::npos) << e.message();
        EXPECT_NE(e.message().find("joint '"), std::string::npos) << e.message();
      }
  }
}

// The body angles' cos and sin (mbs/body_trig.h, libmvec on x86-64): every body count
// from 1 to 9 (whole vectors and the padded remainders of 2 and 4 lanes), angles up to
// the 700 rad of a 100-cycle run at 120 rpm and a negative one, each within libmvec's
// stated 4 ulp of std::cos / std::sin (4.5e-16 for values ≤ 1; 2 ulp measured), and
// only the 2n entries of n bodies written.
TEST(Mechanism, BodyAnglesCosAndSinMatchTheScalarLibrary)
{
  for (unsigned int n = 1; n <= 9; ++n)
    {
      std::vector<double> q(3 * n), trig(2 * n + 2, 42.0);
      for (unsigned int b = 0; b < n; ++b)
        {
          q[3 * b]     = 1e3; // positions: never read
          q[3 * b + 1] = -1e3;
          q[3 * b + 2] = b % 3 == 0 ? -0.3 - b : 77.7 * b + 0.123;
        }
      body_trig(q.data(), n, trig.data());
      for (unsigned int b = 0; b < n; ++b)
        {
          EXPECT_NEAR(trig[2 * b], std::cos(q[3 * b + 2]), 4.5e-16) << n << " bodies, body " << b;
          EXPECT_NEAR(trig[2 * b + 1], std::sin(q[3 * b + 2]), 4.5e-16) << n << " bodies, body " << b;
        }
      EXPECT_EQ(trig[2 * n], 42.0) << "written past the last body";
      EXPECT_EQ(trig[2 * n + 1], 42.0) << "written past the last body";
    }
}
