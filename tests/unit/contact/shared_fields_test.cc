// SPDX-License-Identifier: LGPL-2.1-or-later
// Slices of equal geometry share their conformal field (contact/shared_fields.h) on the
// nine-bar's steel pair with a worn pocket: the pool hands out one field per distinct set
// of profiles (one for aligned slices, one per pair of a symmetric crown), and a shared
// field answers every question exactly as a field of its own would — bit for bit, also
// when the questions alternate between pin centres, motions and the stored energy.
#include "contact/clearance_joint.h"
#include "contact/normal_force_law.h"
#include "contact/shared_fields.h"
#include "plugin_support.h"
#include "steel_pair.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

using namespace wearlink;
using namespace wearlink::contact;

namespace shared_fields_test
{
  constexpr double c = 0.5e-3;


  /** The slices of the worn joint cut as @p layout says, sharing @p pool (nullptr: each its own field). */
  std::vector<std::unique_ptr<ClearanceJoint>>
  slices(const SliceLayout &layout, const std::shared_ptr<FieldPool> &pool)
  {
    ClearanceJointDescription d;
    d.name     = "J";
    d.geometry = contact::testing::worn_steel_pair();
    d.pin_body = 0;
    std::vector<std::unique_ptr<ClearanceJoint>> out;
    for (unsigned int i = 0; i < layout.count; ++i)
      {
        auto s             = slice_of(d, layout, i);
        s.slice.field_pool = pool;
        out.push_back(std::make_unique<ClearanceJoint>(
          s,
          contact::testing::make_plugin(normal_force_laws(), "hertz", {{"Exponent", "1.5"}}),
          nullptr));
      }
    return out;
  }

  /** Pin centres in the pocket, visited in an order that alternates between them. */
  std::vector<mbs::Vec2>
  centres()
  {
    std::vector<mbs::Vec2> e;
    for (const double depth : {2e-6, 1.5e-5, 2e-6, 3e-5})
      for (const double angle : {-1.5708, -1.2, -1.5708})
        e.push_back((c + depth) * mbs::Vec2(std::cos(angle), std::sin(angle)));
    return e;
  }
} // namespace shared_fields_test

TEST(SharedFields, SlicesShareOneFieldPerDistinctGeometry)
{
  SliceLayout aligned;
  aligned.count = 4;
  auto pool     = std::make_shared<FieldPool>();
  auto a        = shared_fields_test::slices(aligned, pool);
  EXPECT_EQ(pool->n_fields(), 1u) << "aligned slices: one field";
  EXPECT_EQ(a[0]->conformal_field(), a[3]->conformal_field());

  SliceLayout crowned = aligned;
  crowned.crown       = PinCrown::circular;
  crowned.crown_drop  = 2e-6;
  auto crown_pool     = std::make_shared<FieldPool>();
  auto b              = shared_fields_test::slices(crowned, crown_pool);
  EXPECT_EQ(crown_pool->n_fields(), 2u) << "a symmetric crown: one field per pair of slices at ±z";
  EXPECT_EQ(b[0]->conformal_field(), b[3]->conformal_field());
  EXPECT_EQ(b[1]->conformal_field(), b[2]->conformal_field());
  EXPECT_NE(b[0]->conformal_field(), b[1]->conformal_field());

  b.clear();
  EXPECT_EQ(crown_pool->n_fields(), 0u) << "a field lives as long as a slice holds it";
}

TEST(SharedFields, ASharedFieldAnswersAsAFieldOfItsOwn)
{
  SliceLayout tilted;
  tilted.count        = 4;
  tilted.misalignment = 2e-3; // the slices' pin centres differ; their profiles do not
  const auto shared   = shared_fields_test::slices(tilted, std::make_shared<FieldPool>());
  const auto own      = shared_fields_test::slices(tilted, nullptr);
  for (const auto &e : shared_fields_test::centres())
    for (std::size_t i = 0; i < shared.size(); ++i)
      {
        const auto &o = shared[i]->get_description().slice.bore_offset;
        const auto  f = shared[i]->elastic_force(e - o, 0.01);
        const auto  g = own[i]->elastic_force(e - o, 0.01);
        EXPECT_EQ(f.x(), g.x()) << "slice " << i;
        EXPECT_EQ(f.y(), g.y()) << "slice " << i;
        EXPECT_EQ(shared[i]->overlap(e - o, 0.01), own[i]->overlap(e - o, 0.01)) << "slice " << i;
      }

  // The field itself, with motions and the stored energy asked for in turn.
  const auto        g = contact::testing::worn_steel_pair();
  const Foundation  f = foundation_of_power_law(1e10, 1.5, shared_fields_test::c, 0.012, g.axial_length);
  OverlapFoundation bare(g.bore, g.pin, g.axial_length, 0.012, f, 4);
  FieldPool         pool;
  const auto        field =
    pool.field(g.bore, g.pin, FieldKey{"hertz", 1e10, 1.5, shared_fields_test::c, 0.012, 0.01, 4}, [&] {
      return std::make_unique<OverlapFoundation>(g.bore, g.pin, g.axial_length, 0.012, f, 4);
    });
  ConformalMotion slow, fast;
  slow.velocity = {0.01, -0.02};
  slow.factor   = 0.5;
  fast          = slow;
  fast.velocity = {0.01, -0.5};
  const std::vector<const ConformalMotion *> motions{nullptr, &slow, &fast, &slow, nullptr};
  for (const auto &e : shared_fields_test::centres())
    for (const auto *m : motions)
      for (const bool potential : {false, true, false})
        {
          ConformalForce a, b;
          field->evaluate(e, 0.01, m, potential, a);
          bare.evaluate(e, 0.01, m, potential, b);
          EXPECT_EQ(a.force.x(), b.force.x());
          EXPECT_EQ(a.damped.y(), b.damped.y());
          EXPECT_EQ(a.pin_torque, b.pin_torque);
          EXPECT_EQ(a.damping_power, b.damping_power);
          EXPECT_EQ(a.potential, b.potential);
          EXPECT_EQ(a.overlap, b.overlap);
        }
}
