// SPDX-License-Identifier: LGPL-2.1-or-later
// A clearance joint cut into slices along its pin (doc/models.md §1.8), on the steel pair
// of the nine-bar (R1 = 12 mm, c = 0.5 mm, L = 10 mm):
//  - aligned, n slices carry the joint's force to round-off, round and worn;
//  - a rigid pin tilted against its bore on linear slices (K δ, a Winkler foundation
//    along the pin) carries the linear law's closed forms: while every slice touches,
//    p(z) = p̄ (1 + 12 e z / L²), p_max = p̄ (1 + 6e/L) with e = M/F; beyond e = L/6
//    the contact is a = 3(L/2 − e) long and p_max = 2F/a (a triangle);
//  - a circular crown takes its drop off each slice's approach.
#include "contact/clearance_joint.h"
#include "contact/normal_force_law.h"
#include "plugin_support.h"
#include "steel_pair.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

using namespace wearlink;
using namespace wearlink::contact;

namespace slices_test
{
  constexpr double R1 = 0.012, c = 0.5e-3, L = 0.01;

  ClearanceJointDescription
  joint(const JointGeometry &g)
  {
    ClearanceJointDescription d;
    d.name     = "J";
    d.geometry = g;
    d.pin_body = 0;
    return d;
  }

  std::unique_ptr<ClearanceJoint>
  make(const ClearanceJointDescription &d, const std::string &exponent)
  {
    return std::make_unique<ClearanceJoint>(d,
                                            contact::testing::make_plugin(normal_force_laws(),
                                                                          "hertz",
                                                                          {{"Exponent", exponent}}),
                                            nullptr);
  }

  struct Sliced
  {
    std::vector<std::unique_ptr<ClearanceJoint>> owned;
    std::vector<const ClearanceJoint *>          slices;
  };

  Sliced
  sliced(const JointGeometry &g, const SliceLayout &layout, const std::string &exponent = "1.5")
  {
    Sliced s;
    for (unsigned int i = 0; i < layout.count; ++i)
      {
        s.owned.push_back(make(slice_of(joint(g), layout, i), exponent));
        s.slices.push_back(s.owned.back().get());
      }
    return s;
  }


  /** Per slice, the force per unit length [N/m] along +y with the pin carrying @p force up. */
  std::vector<double>
  pressures(const Sliced &s, const double force, double &e_first)
  {
    bool            converged = false;
    const mbs::Vec2 e = eccentricity_carrying(s.slices, mbs::Vec2(0, force), 0.0, mbs::Vec2(0, -c - 1e-8), converged);
    EXPECT_TRUE(converged);
    e_first = e.y();
    std::vector<double> p;
    const auto          o0 = s.slices.front()->get_description().slice.bore_offset;
    for (const auto *j : s.slices)
      {
        const auto &d = j->get_description();
        p.push_back(j->elastic_force(e + o0 - d.slice.bore_offset, 0.0).y() / d.geometry.axial_length);
      }
    return p;
  }
} // namespace slices_test


TEST(Slices, AlignedSlicesCarryTheJointsForce)
{
  for (const auto &g : {contact::testing::steel_pair(), contact::testing::worn_steel_pair()})
    {
      const auto whole = slices_test::make(slices_test::joint(g), "1.5");
      for (const unsigned int n : {2u, 7u, 10u})
        {
          SliceLayout layout;
          layout.count = n;
          const auto s = slices_test::sliced(g, layout);
          for (const double depth : {1e-8, 1e-6, 1e-5})
            for (const double angle : {-2.0, -1.5708, -1.0, 0.3})
              {
                const mbs::Vec2 e   = (slices_test::c + depth) * mbs::Vec2(std::cos(angle), std::sin(angle));
                const mbs::Vec2 f   = whole->elastic_force(e, 0.2);
                const mbs::Vec2 sum = slices_elastic_force(s.slices, e, 0.2);
                EXPECT_LE((sum - f).norm(), 1e-12 * f.norm()) << n << " slices, " << depth << " m, " << angle;
              }
        }
    }
}

// While every slice touches: the linear law's p(z) = p̄ (1 + 12 e z/L²) at the slices'
// centres. The discrete moment Σ z_i² L/n = L³/12 (1 − 1/n²) puts 1/n² of e off the
// continuous one: 1e-4 of p̄ at n = 100; the test allows 1e-3.
TEST(Slices, TiltedRigidPinOnLinearSlicesWhileEveryOneTouches)
{
  SliceLayout layout;
  layout.count        = 100;
  layout.misalignment = 1e-6; // e ≈ L/15
  const auto   s      = slices_test::sliced(contact::testing::steel_pair(), layout, "1");
  const double F      = 1000;
  double       e_y    = 0;
  const auto   p      = slices_test::pressures(s, F, e_y);
  double       sum = 0, moment = 0, largest = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    {
      const double z = s.slices[i]->get_description().slice.position;
      sum += p[i] * slices_test::L / 100;
      moment += z * p[i] * slices_test::L / 100;
      largest = std::max(largest, p[i]);
    }
  EXPECT_NEAR(sum / F, 1.0, 1e-9);
  const double e = moment / F, mean = F / slices_test::L;
  ASSERT_GT(std::abs(e), slices_test::L / 30);
  ASSERT_LT(std::abs(e), slices_test::L / 6);
  for (std::size_t i = 0; i < p.size(); ++i)
    {
      const double z = s.slices[i]->get_description().slice.position;
      EXPECT_NEAR(p[i] / mean, 1 + 12 * e * z / (slices_test::L * slices_test::L), 1e-3) << "slice " << i;
    }
  // The edge: p_max = p̄ (1 + 6|e|/L), the outer slice L/(2n) inside it.
  const double edge = mean * (1 + 6 * std::abs(e) / slices_test::L);
  EXPECT_NEAR(largest / edge,
              1 - 6 * std::abs(e) / slices_test::L / 100 / (1 + 6 * std::abs(e) / slices_test::L),
              1e-3);
}

// Beyond e = L/6 the pin lifts off: the touching length a = 3(L/2 − e) and the triangle
// p(z) = (2F/a) (1 − (edge − z)/a) from the loaded edge. With n = 200 a slice is L/200:
// the length is resolved to one slice, the pressure to 2 % of p_max.
TEST(Slices, TiltedRigidPinOnLinearSlicesLiftsOffBeyondASixth)
{
  SliceLayout layout;
  layout.count        = 200;
  layout.misalignment = 3e-5;
  const auto   s      = slices_test::sliced(contact::testing::steel_pair(), layout, "1");
  const double F      = 1000;
  double       e_y    = 0;
  const auto   p      = slices_test::pressures(s, F, e_y);
  double       moment = 0, touching = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    {
      moment += s.slices[i]->get_description().slice.position * p[i] * slices_test::L / 200;
      touching += p[i] > 0 ? slices_test::L / 200 : 0.0;
    }
  const double e = std::abs(moment / F);
  ASSERT_GT(e, slices_test::L / 6);
  const double a = 3 * (slices_test::L / 2 - e), peak = 2 * F / a;
  EXPECT_NEAR(touching, a, slices_test::L / 200 + 1e-12);
  const double edge = moment > 0 ? slices_test::L / 2 : -slices_test::L / 2; // the loaded end
  for (std::size_t i = 0; i < p.size(); ++i)
    {
      const double from_edge = std::abs(edge - s.slices[i]->get_description().slice.position);
      EXPECT_NEAR(p[i] / peak, std::max(0.0, 1 - from_edge / a), 0.02) << "slice " << i;
    }
}

// A circular crown: each slice's approach falls by c_e (2z/L)², so on linear slices
// under an aligned load p(z) = k (δ₀ − c_e (2z/L)²).
TEST(Slices, CircularCrownTakesItsDropOffTheApproach)
{
  SliceLayout layout;
  layout.count          = 20;
  layout.crown          = PinCrown::circular;
  layout.crown_drop     = 5e-9;
  const auto   s        = slices_test::sliced(contact::testing::steel_pair(), layout, "1");
  double       e_y      = 0;
  const auto   p        = slices_test::pressures(s, 2000, e_y);
  const double k        = s.slices[0]->stiffness() / (slices_test::L / 20); // per unit length [N/m²]
  const double approach = -e_y - slices_test::c;                            // at the straight pin's centre
  for (std::size_t i = 0; i < p.size(); ++i)
    {
      const double z = s.slices[i]->get_description().slice.position;
      EXPECT_NEAR(p[i], k * (approach - 5e-9 * std::pow(2 * z / slices_test::L, 2)), 1e-9 * k * approach)
        << "slice " << i;
    }
}
