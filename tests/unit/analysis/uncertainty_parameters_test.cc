// SPDX-License-Identifier: LGPL-2.1-or-later
// A scene's `subsection Uncertainty` (io/uncertainty_parameters.h): the four
// distributions in their documented parametrisation, the entry checks (a declared,
// numeric entry in a part the scene uses, listed once) and the messages of bad input
// (file, entry, what is allowed).
#include "analysis/uncertainty_parameters.h"
#include "base/exceptions.h"
#include "io/scene.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace wearlink;
using wearlink::testing::source_path;

namespace
{
  /** The message of the InputError reading nine_bar_wear.prm with Uncertainty/Inputs = @p inputs throws. */
  std::string
  error_of(const std::string &inputs)
  {
    try
      {
        io::read_scene(source_path("params/nine_bar_wear.prm"), {"Uncertainty/Inputs=" + inputs});
      }
    catch (const InputError &e)
      {
        return e.message();
      }
    return "";
  }
} // namespace

TEST(UncertaintyParameters, DistributionsInTheirDocumentedParametrisation)
{
  const auto n = analysis::parse_distribution("normal(0.15, 0.02)");
  EXPECT_EQ(n.kind, analysis::DistributionKind::normal);
  EXPECT_DOUBLE_EQ(n.quantile(0.5), 0.15);
  const auto l = analysis::parse_distribution("lognormal(4.6e-14, 0.3)");
  EXPECT_DOUBLE_EQ(l.quantile(0.5), 4.6e-14) << "the first parameter is the median";
  EXPECT_NEAR(l.quantile(0.8413447460685429), 4.6e-14 * std::exp(0.3), 1e-26) << "the second the σ of ln x";
  const auto u = analysis::parse_distribution("uniform( 0.8 , 0.95 )");
  EXPECT_DOUBLE_EQ(u.quantile(0.25), 0.8375);
  const auto t = analysis::parse_distribution("truncated normal(2e-4, 1e-5, 1.95e-4, 2e-4)");
  EXPECT_EQ(t.kind, analysis::DistributionKind::truncated_normal);
  EXPECT_LE(t.quantile(0.999999), 2e-4);
  EXPECT_GE(t.quantile(1e-6), 1.95e-4);
  for (const char *bad : {"gauss(1, 2)",
                          "normal(1)",
                          "normal(1, 0)",
                          "normal(1, -1)",
                          "normal(1, nan)",
                          "normal(1, 2",
                          "lognormal(0, 0.3)",
                          "uniform(2, 1)",
                          "uniform(1, 1)",
                          "truncated normal(0, 1, 1, 0)",
                          "uniform(a, 1)"})
    EXPECT_THROW(analysis::parse_distribution(bad), InputError) << bad;
}

TEST(UncertaintyParameters, TheSceneReadsItsUncertainInputs)
{
  const auto scene =
    io::read_scene(source_path("params/nine_bar_wear.prm"),
                   {"Uncertainty/Inputs=Joint A/Clearance/archard/Pin wear coefficient: lognormal(4.6e-14, 0.3);"
                    " Joint A / Clearance / modified-coulomb / Friction coefficient : uniform(0.1, 0.2)",
                    "Uncertainty/Seed=9"});
  ASSERT_EQ(scene.uncertainty.inputs.size(), 2u);
  EXPECT_EQ(scene.uncertainty.inputs[1].entry, "Joint A/Clearance/modified-coulomb/Friction coefficient");
  EXPECT_EQ(scene.uncertainty.seed, 9u);
  EXPECT_TRUE(io::read_scene(source_path("params/nine_bar_wear.prm")).uncertainty.inputs.empty());
}

TEST(UncertaintyParameters, BadInputsNameTheFileTheEntryAndWhatIsAllowed)
{
  const std::string unknown = error_of("Joint A/Clearance/Radial clarance: uniform(1e-4, 2e-4)");
  EXPECT_NE(unknown.find("nine_bar_wear.prm"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("no entry 'Radial clarance'"), std::string::npos) << unknown;
  EXPECT_NE(error_of("Joint Z/Mass: uniform(1, 2)").find("no subsection 'Joint Z'"), std::string::npos);
  EXPECT_NE(error_of("Joint A/Model: uniform(1, 2)").find("is not a number"), std::string::npos);
  EXPECT_NE(error_of("Joint A/Clearance/coulomb/Friction coefficient: uniform(0.1, 0.2)").find("does not use"),
            std::string::npos);
  const std::string twice = error_of("Body rod2/Mass: uniform(1, 2); Body rod2/Mass: normal(1.5, 0.1)");
  EXPECT_NE(twice.find("twice"), std::string::npos) << twice;
  const std::string bad = error_of("Body rod2/Mass: uniform(2, 1)");
  EXPECT_NE(bad.find("'Body rod2/Mass'"), std::string::npos) << bad;
  EXPECT_NE(bad.find("lower < upper"), std::string::npos) << bad;
  EXPECT_NE(error_of("Body rod2/Mass uniform(1, 2)").find("without ':'"), std::string::npos);
}
