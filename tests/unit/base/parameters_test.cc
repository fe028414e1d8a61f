// SPDX-License-Identifier: LGPL-2.1-or-later
// .prm reading: includes resolved relative to the including file, typos and values
// outside their pattern rejected with the file named, required entries enforced,
// command-line overrides checked against the declared tree.
#include "base/exceptions.h"
#include "base/parameters.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>

using namespace wearlink;

namespace
{
  void
  declare(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Joint");
    wearlink::declare(prm, "Radial clearance", "0.5e-3", dealii::Patterns::Double(0), "Gap.", "m");
    declare_required(prm, "Youngs modulus", dealii::Patterns::Double(0), "E.", "Pa");
    prm.leave_subsection();
  }

} // namespace

TEST(Parameters, IncludeIsRelativeToIncludingFile)
{
  const std::string dir = wearlink::testing::fresh_directory("prm_include");
  std::filesystem::create_directories(dir + "/sub");
  std::ofstream(dir + "/sub/part.prm") << "subsection Joint\n set Radial clearance = 0.25e-3\nend\n";
  std::ofstream(dir + "/scene.prm") << "include sub/part.prm\nsubsection Joint\n set Youngs modulus = 2e11\nend\n";
  dealii::ParameterHandler prm;
  declare(prm);
  read_prm_file(prm, dir + "/scene.prm");
  check_required_entries(prm, dir + "/scene.prm");
  prm.enter_subsection("Joint");
  EXPECT_DOUBLE_EQ(prm.get_double("Radial clearance"), 0.25e-3);
  EXPECT_DOUBLE_EQ(prm.get_double("Youngs modulus"), 2e11);
}

TEST(Parameters, ErrorsNameFileEntryAndRange)
{
  const std::string dir = wearlink::testing::fresh_directory("prm_errors");
  std::ofstream(dir + "/typo.prm") << "subsection Joint\n set Radial clearence = 1\nend\n";
  std::ofstream(dir + "/negative.prm") << "subsection Joint\n set Radial clearance = -1\nend\n";
  std::ofstream(dir + "/missing.prm") << "subsection Joint\n set Radial clearance = 1\nend\n";

  dealii::ParameterHandler prm;
  declare(prm);
  const auto typo = wearlink::testing::input_error_message([&] { read_prm_file(prm, dir + "/typo.prm"); });
  EXPECT_NE(typo.find("typo.prm"), std::string::npos) << typo;
  EXPECT_NE(typo.find("Radial clearence"), std::string::npos) << typo;

  dealii::ParameterHandler prm2;
  declare(prm2);
  const auto neg = wearlink::testing::input_error_message([&] { read_prm_file(prm2, dir + "/negative.prm"); });
  EXPECT_NE(neg.find("negative.prm"), std::string::npos) << neg;
  EXPECT_NE(neg.find("Radial clearance"), std::string::npos) << neg;

  dealii::ParameterHandler prm3;
  declare(prm3);
  read_prm_file(prm3, dir + "/missing.prm");
  const auto missing =
    wearlink::testing::input_error_message([&] { check_required_entries(prm3, dir + "/missing.prm"); });
  EXPECT_NE(missing.find("Joint/Youngs modulus"), std::string::npos) << missing;

  EXPECT_NE(wearlink::testing::input_error_message([&] { read_prm_file(prm3, dir + "/nope.prm"); }).find("nope.prm"),
            std::string::npos);
}

TEST(Parameters, OverridesAreChecked)
{
  dealii::ParameterHandler prm;
  declare(prm);
  apply_overrides(prm, {"Joint/Radial clearance=1e-4"});
  prm.enter_subsection("Joint");
  EXPECT_DOUBLE_EQ(prm.get_double("Radial clearance"), 1e-4);
  prm.leave_subsection();
  EXPECT_THROW(apply_overrides(prm, {"Joint/Radial clearance=-3"}), InputError);
  EXPECT_THROW(apply_overrides(prm, {"Joint/Nope=1"}), InputError);
  EXPECT_THROW(apply_overrides(prm, {"Nope/Radial clearance=1"}), InputError);
  EXPECT_THROW(apply_overrides(prm, {"Joint/Radial clearance"}), InputError);
}

// Settings made by the program go through one typed builder: numbers to 17 significant
// digits (they read back exactly), later settings win, and a path the user sets removes
// the program's own setting of it.
TEST(Parameters, OverridesBuilderFormatsNumbersOnceAndLetsTheUserWin)
{
  wearlink::ParameterOverrides o;
  o.set("Simulation/End time", 0.1 + 0.2).set("Output/Time series", "false");
  EXPECT_EQ(o.settings().front(), "Simulation/End time=0.30000000000000004");
  EXPECT_EQ(std::stod(o.settings().front().substr(o.settings().front().find('=') + 1)), 0.1 + 0.2);
  EXPECT_TRUE(o.sets(" Simulation/End time "));
  const wearlink::ParameterOverrides user{"Simulation/End time = 2"};
  o.remove_paths_set_in(user).append(user);
  ASSERT_EQ(o.settings().size(), 2u);
  EXPECT_EQ(o.settings().back(), "Simulation/End time = 2");
  EXPECT_EQ(wearlink::ParameterOverrides::path_of(o.settings().back()), "Simulation/End time");
}
