// SPDX-License-Identifier: LGPL-2.1-or-later
// A sliced joint's pin as an Euler–Bernoulli beam (contact/elastic_pin.h, doc/models.md
// §1.8), on the steel pair of the nine-bar (R1 = 12 mm, c = 0.5 mm, L = 10 mm):
//  - the flexibility at the slices is the beam tables' (simply supported, built in,
//    cantilever) and symmetric;
//  - on linear slices (K δ: a Winkler foundation along the pin) the bent pin's pressure is
//    Hetényi's beam on an elastic foundation, EI y'''' + k y = 0 with the supports'
//    conditions, converging as 1/n² with the slices;
//  - inside the mechanism the slices see the bent pin: their forces are the pin's, and the
//    force is the gradient of the potential energy with the beam's strain energy in it.
#include "contact/axial_slices.h"
#include "contact/clearance_joint.h"
#include "contact/elastic_pin.h"
#include "contact/normal_force_law.h"
#include "plugin_support.h"
#include "steel_pair.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <memory>
#include <vector>

using namespace wearlink;
using namespace wearlink::contact;

namespace elastic_pin_test
{
  constexpr double c = 0.5e-3, L = 0.01;

  struct BentPin
  {
    std::vector<std::unique_ptr<ClearanceJoint>> owned;
    std::vector<const ClearanceJoint *>          slices;
    std::shared_ptr<ElasticPin>                  pin;
  };

  /** The steel pair cut into @p n linear (K δ) slices on a pin bending as @p bending says. */
  BentPin
  bent_pin(const unsigned int n, const PinBending &bending)
  {
    ClearanceJointDescription d;
    d.name     = "J";
    d.geometry = contact::testing::steel_pair();
    d.pin_body = 0;
    SliceLayout layout;
    layout.count   = n;
    layout.bending = bending;
    BentPin b;
    b.pin = make_elastic_pin(d, layout);
    for (unsigned int i = 0; i < n; ++i)
      {
        auto s              = slice_of(d, layout, i);
        s.slice.elastic_pin = b.pin;
        b.owned.push_back(std::make_unique<ClearanceJoint>(
          s,
          contact::testing::make_plugin(normal_force_laws(), "hertz", {{"Exponent", "1"}}),
          nullptr));
        b.slices.push_back(b.owned.back().get());
      }
    b.pin->attach(b.slices);
    return b;
  }

  /**
   * Hetényi's beam on an elastic foundation: the approach y(z) of a pin held at its
   * supports (z = ±L/2) with the rigid approach δ₀ there, solving EI y'''' + k y = 0,
   * y = Σ a_m φ_m with φ = e^{±βz} (cos βz, sin βz), β = (k/4EI)^¼.
   */
  class Hetenyi
  {
  public:
    Hetenyi(const PinSupport support, const double beta, const double delta0)
      : beta(beta)
    {
      // The rows: y = δ₀ at a support (v = 0), and y' = 0 (clamped), y'' = 0 (pinned, free
      // end), y''' = 0 (free end).
      Eigen::Matrix4d a;
      Eigen::Vector4d b;
      const double    lo = -L / 2, hi = L / 2;
      const auto      row = [&](int r, double z, int order, double value) {
        for (int m = 0; m < 4; ++m)
          a(r, m) = basis(m, z, order);
        b[r] = value;
      };
      row(0, lo, 0, delta0);
      switch (support)
        {
          case PinSupport::pinned:
            row(1, lo, 2, 0), row(2, hi, 0, delta0), row(3, hi, 2, 0);
            break;
          case PinSupport::clamped:
            row(1, lo, 1, 0), row(2, hi, 0, delta0), row(3, hi, 1, 0);
            break;
          default: // the cantilever's root at −L/2, its free end at L/2
            row(1, lo, 1, 0), row(2, hi, 2, 0), row(3, hi, 3, 0);
        }
      coefficients = a.fullPivLu().solve(b);
    }

    double
    operator()(const double z) const
    {
      double y = 0;
      for (int m = 0; m < 4; ++m)
        y += coefficients[m] * basis(m, z, 0);
      return y;
    }

  private:
    /** The @p order-th derivative of φ_m at @p z: Re or Im of λᵏ e^{λz}, λ = β(±1 + i). */
    double
    basis(const int m, const double z, const int order) const
    {
      const std::complex<double> lambda(m < 2 ? beta : -beta, beta);
      const auto                 value = std::pow(lambda, order) * std::exp(lambda * z);
      return m % 2 == 0 ? value.real() : value.imag();
    }

    double          beta;
    Eigen::Vector4d coefficients;
  };

  /** The largest difference of the slices' pressure and Hetényi's, over the mean. */
  double
  hetenyi_error(const unsigned int n, const PinSupport support, const double ei, double &edge_to_middle)
  {
    const auto   b      = bent_pin(n, {support, ei, 0});
    const double delta0 = 1e-6;
    const auto  &f      = b.pin->forces(mbs::Vec2(0, -(c + delta0)), 0.0);
    const double k      = b.slices[0]->stiffness() / (L / n); // the foundation [N/m²]
    const double beta   = std::pow(k / (4 * ei), 0.25);
    Hetenyi      y(support, beta, delta0);
    double       mean = 0, error = 0;
    for (unsigned int i = 0; i < n; ++i)
      mean += f[i].y() / L; // Σ f / L [N/m]
    for (unsigned int i = 0; i < n; ++i)
      {
        const double z = b.slices[i]->get_description().slice.position;
        EXPECT_GT(y(z), 0) << "every slice must touch for the linear law to hold";
        EXPECT_NEAR(f[i].x(), 0, 1e-12 * std::abs(f[i].y()));
        error = std::max(error, std::abs(f[i].y() / (L / n) - k * y(z)) / mean);
      }
    edge_to_middle = f[0].y() / f[n / 2].y(); // the −z end: supported, or the cantilever's root
    EXPECT_EQ(b.pin->n_failures(), 0);
    return error;
  }
} // namespace elastic_pin_test


// The beam tables: simply supported over S, a load P at a from one end deflects under
// itself by P a² b²/(3 EI S); built in at both ends, by P a³ b³/(3 EI S³); a cantilever
// of root-to-load a, by P a³/(3 EI).
TEST(ElasticPin, FlexibilityIsTheBeamTables)
{
  const double              ei = 500, d = 0.004, span = elastic_pin_test::L + 2 * d;
  const std::vector<double> z{-0.004, -0.001, 0.0015, 0.0045};
  for (const auto support : {PinSupport::pinned, PinSupport::clamped, PinSupport::cantilever})
    {
      const auto c = pin_flexibility({support, ei, d}, elastic_pin_test::L, z);
      ASSERT_EQ(c.rows(), 4);
      for (int i = 0; i < 4; ++i)
        {
          const double a = z[static_cast<std::size_t>(i)] + span / 2, b = span - a;
          const double own = support == PinSupport::pinned  ? a * a * b * b / (3 * ei * span) :
                             support == PinSupport::clamped ? std::pow(a * b, 3) / (3 * ei * std::pow(span, 3)) :
                                                              a * a * a / (3 * ei);
          EXPECT_NEAR(c(i, i) / own, 1, 1e-9) << "support " << static_cast<int>(support) << ", load " << i;
          for (int j = 0; j < 4; ++j)
            EXPECT_NEAR(c(i, j), c(j, i), 1e-12 * c.maxCoeff());
        }
    }
  // The simply supported beam away from the load: P b x (S² − b² − x²)/(6 EI S), x ≤ a.
  const auto   c = pin_flexibility({PinSupport::pinned, ei, d}, elastic_pin_test::L, z);
  const double x = z[0] + span / 2, a = z[2] + span / 2, b = span - a;
  EXPECT_NEAR(c(0, 2) / (b * x * (span * span - b * b - x * x) / (6 * ei * span)), 1, 1e-9);
}

// βL = 3 between supports, 1.5 for the cantilever (whose free end would lift off at 3;
// EI of a hollow pin): the supported end carries 1.5 (cantilever), 2 (clamped) and 27
// (pinned) times the middle. The slices are springs at their centres standing for the
// continuous foundation: the midpoint rule's error falls as 1/n² (measured: 16× from
// n = 50 to 200); at n = 200 it is 2e-5 of the mean pressure or less.
TEST(ElasticPin, PinOnWinklerSlicesFollowsHetenyi)
{
  // k = K/L of the steel pair's linear law; EI from β L.
  const auto   probe = elastic_pin_test::bent_pin(2, {PinSupport::pinned, 1.0, 0});
  const double k     = probe.slices[0]->stiffness() / (elastic_pin_test::L / 2);
  for (const auto support : {PinSupport::pinned, PinSupport::clamped, PinSupport::cantilever})
    {
      const double beta         = (support == PinSupport::cantilever ? 1.5 : 3.0) / elastic_pin_test::L;
      const double ei           = k / (4 * std::pow(beta, 4));
      double       coarse_ratio = 0, fine_ratio = 0;
      const double coarse = elastic_pin_test::hetenyi_error(50, support, ei, coarse_ratio);
      const double fine   = elastic_pin_test::hetenyi_error(200, support, ei, fine_ratio);
      const int    which  = static_cast<int>(support);
      EXPECT_LT(fine, 5e-5) << "support " << which;
      EXPECT_LT(fine, coarse / 8) << "support " << which << ": the error must fall as 1/n²";
      EXPECT_GT(fine_ratio, 1.1) << "support " << which << ": the bent pin loads its supported end";
    }
}

// The mechanism's view: a pin body at e (bushing on the ground); the slices' forces on the
// pin are the bent pin's, and −∂U/∂y of the total potential energy (slices plus beam)
// is their sum (the deflection is at equilibrium: the energy is stationary in it).
TEST(ElasticPin, SlicesInTheMechanismSeeTheBentPin)
{
  const auto b        = elastic_pin_test::bent_pin(10, {PinSupport::pinned, 200, 0.002});
  const auto state_at = [](const double y) {
    return std::vector<double>{0.2e-6, y, 0.01, 0, 0, 0};
  };
  const double         y0 = -(elastic_pin_test::c + 2e-6);
  auto                 q  = state_at(y0);
  const mbs::StateView s(q.data(), q.data() + 3);
  mbs::Vec2            sum(0, 0), pin_sum(0, 0);
  for (const auto *j : b.slices)
    sum += j->diagnostics(s).force_on_pin;
  for (const auto &f : b.pin->forces(mbs::Vec2(0.2e-6, y0), 0.01))
    pin_sum += f;
  ASSERT_GT(sum.norm(), 0);
  EXPECT_LE((sum - pin_sum).norm(), 1e-12 * sum.norm());
  const auto energy = [&](const double y) {
    auto                 qq = state_at(y);
    const mbs::StateView ss(qq.data(), qq.data() + 3);
    double               u = 0;
    for (const auto *j : b.slices)
      u += j->potential_energy(ss);
    return u;
  };
  const double h = 1e-10;
  EXPECT_NEAR(-(energy(y0 + h) - energy(y0 - h)) / (2 * h) / sum.y(), 1, 1e-5);
  EXPECT_EQ(b.pin->n_failures(), 0);
}
