// SPDX-License-Identifier: LGPL-2.1-or-later
// `wearlink compare-contact` on the nine-bar (coarse FE surfaces, 100 µm, to keep it at
// seconds): the sphere-law column is the closed form K δ^1.5, the FE column passes
// through the FE load levels, the deviations are those of the columns, and the effect
// runs report every dynamics law.
#include "contact/clearance_joint.h"
#include "io/csv.h"
#include "scene_support.h"
#include "workflows/contact_comparison.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

using namespace wearlink;

TEST(ContactComparison, ColumnsAreTheLawsAndEffectsCoverEveryDynamicsLaw)
{
  ::setenv("WEARLINK_CACHE_DIR", wearlink::testing::fresh_directory("contact_comparison_cache").c_str(), 1);
  workflows::ContactComparisonRequest r;
  r.scene_file = wearlink::testing::source_path("params/nine_bar_clearance.prm");
  r.overrides  = ParameterOverrides(
    {"Joint A/Clearance/fe/Surface element size=1e-4", "Joint B/Clearance/fe/Surface element size=1e-4"});
  r.cycles     = 2;
  r.progress   = false;
  const auto c = workflows::compare_contact(r);
  ::unsetenv("WEARLINK_CACHE_DIR");

  io::Scene    scene = wearlink::testing::scene("params/nine_bar_clearance.prm");
  const double K     = scene.clearance_joints.at(0)->stiffness();
  ASSERT_EQ(c.joints, (std::vector<std::string>{"A", "B"}));
  bool saw_sphere = false, saw_fe = false;
  for (const auto &fc : c.curves)
    {
      ASSERT_EQ(fc.force.size(), c.approach.size());
      if (fc.joint == "A" && fc.law == "lankarani-nikravesh")
        {
          saw_sphere = true;
          for (std::size_t i = 0; i < c.approach.size(); ++i)
            EXPECT_DOUBLE_EQ(fc.force[i], K * std::pow(c.approach[i], 1.5));
        }
      if (fc.joint == "A" && fc.law == "fe")
        {
          saw_fe = true;
          // The grid starts at the FE approach of the smallest level (10 N) and ends at the largest (100 kN).
          EXPECT_NEAR(fc.force.front() / 10.0, 1.0, 1e-6);
          EXPECT_NEAR(fc.force.back() / 1e5, 1.0, 1e-6);
        }
    }
  EXPECT_TRUE(saw_sphere && saw_fe);
  for (const auto &d : c.deviations)
    if (d.law == "fe" && d.state == "fresh")
      for (const double x : d.ratio)
        EXPECT_NEAR(x, 1.0, 1e-6);
    else if (d.law == "lankarani-nikravesh")
      EXPECT_LT(d.ratio[0], 0.5) << "the sphere law is far more compliant than FE at 100 N";

  ASSERT_EQ(c.effects.size(), 4u);
  for (const auto &e : c.effects)
    for (std::size_t k = 0; k < 2; ++k)
      {
        EXPECT_GT(e.contact_fraction[k], 0.0) << e.law;
        EXPECT_LE(e.contact_fraction[k], 1.0) << e.law;
        EXPECT_GT(e.peak_force[k], 0.0) << e.law;
      }
  EXPECT_EQ(c.effects.back().law, "fe");
  EXPECT_GT(c.effects.back().table_setup_time, 0.0);

  const std::string dir = wearlink::testing::fresh_directory("contact_comparison") + "/out";
  workflows::write_contact_comparison(dir, c);
  const auto table = io::CsvTable::read(dir + "/force_approach.csv", "force-approach file");
  EXPECT_EQ(table.columns().front(), "approach_m");
  EXPECT_NE(table.find("force_N_fe_fresh_A"), io::CsvTable::npos);
  EXPECT_EQ(table.n_rows(), c.approach.size());
}
