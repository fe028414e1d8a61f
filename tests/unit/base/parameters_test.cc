// SPDX-License-Identifier: LGPL-2.1-or-later
// .prm reading: includes resolved relative to the including file, typos and values
// outside their pattern rejected with the file named, required entries enforced,
// command-line overrides checked against the declared tree.
#include "base/exceptions.h"
#include "base/parameters.h"
#include "base/text.h"
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

// Malformed overrides are input errors with the form to use, never a crash: "=1" once
// read past the end of an empty path (SIGSEGV).
TEST(Parameters, MalformedOverridesNameTheProblem)
{
  dealii::ParameterHandler prm;
  declare(prm);
  for (const char *bad : {"=1", " = 1", "/Radial clearance=1", "Joint/=1", "Joint//Radial clearance=1", "Joint/"})
    {
      const auto m = wearlink::testing::input_error_message([&] { apply_overrides(prm, {bad}); });
      EXPECT_NE(m.find(std::string("'--set ") + bad + "'"), std::string::npos) << m;
      EXPECT_NE(m.find("Section/Sub/Entry=value"), std::string::npos) << m;
    }
  // The tree is left as it was (no subsection left entered).
  apply_overrides(prm, {"Joint/Radial clearance=2e-4"});
  prm.enter_subsection("Joint");
  EXPECT_DOUBLE_EQ(prm.get_double("Radial clearance"), 2e-4);
}

// Some editors start a UTF-8 file with a byte-order mark; the first line is read as if
// it were not there (deal.II would otherwise see an unknown line "\xEF\xBB\xBFsubsection").
TEST(Parameters, ByteOrderMarkIsSkipped)
{
  const std::string dir = wearlink::testing::fresh_directory("prm_bom");
  std::ofstream(dir + "/part.prm") << "\xEF\xBB\xBFsubsection Joint\n set Radial clearance = 0.3e-3\nend\n";
  std::ofstream(dir + "/scene.prm") << "\xEF\xBB\xBF# a comment first\ninclude part.prm\nsubsection Joint\n set Youngs "
                                       "modulus = 2e11\nend\n";
  dealii::ParameterHandler prm;
  declare(prm);
  read_prm_file(prm, dir + "/scene.prm");
  check_required_entries(prm, dir + "/scene.prm");
  prm.enter_subsection("Joint");
  EXPECT_DOUBLE_EQ(prm.get_double("Radial clearance"), 0.3e-3);
  EXPECT_DOUBLE_EQ(prm.get_double("Youngs modulus"), 2e11);
}

// Includes that come back to a file being read are a cycle (named file by file); a long
// chain without a cycle stops at the depth limit; a directory is not a parameter file.
TEST(Parameters, IncludeCyclesDepthAndDirectoriesAreInputErrors)
{
  const std::string dir = wearlink::testing::fresh_directory("prm_cycles");
  std::ofstream(dir + "/self.prm") << "# includes itself\ninclude self.prm\n";
  std::ofstream(dir + "/a.prm") << "include b.prm\n";
  std::ofstream(dir + "/b.prm") << "\n\ninclude ./a.prm\n";
  for (int k = 0; k < 20; ++k)
    std::ofstream(dir + "/chain" + std::to_string(k) + ".prm") << "include chain" << k + 1 << ".prm\n";
  std::ofstream(dir + "/chain20.prm") << "subsection Joint\n set Radial clearance = 1e-4\nend\n";

  dealii::ParameterHandler prm;
  declare(prm);
  const auto self = wearlink::testing::input_error_message([&] { read_prm_file(prm, dir + "/self.prm"); });
  EXPECT_NE(self.find("self.prm line 2"), std::string::npos) << self;
  EXPECT_NE(self.find("cycle of includes: '" + dir + "/self.prm' → '" + dir + "/self.prm'"), std::string::npos) << self;

  const auto cycle = wearlink::testing::input_error_message([&] { read_prm_file(prm, dir + "/a.prm"); });
  EXPECT_NE(cycle.find("b.prm line 3"), std::string::npos) << cycle;
  EXPECT_NE(cycle.find("'" + dir + "/a.prm' → '" + dir + "/b.prm' → '" + dir + "/./a.prm'"), std::string::npos)
    << cycle;

  const auto deep = wearlink::testing::input_error_message([&] { read_prm_file(prm, dir + "/chain0.prm"); });
  EXPECT_NE(deep.find("17 files deep; at most 16"), std::string::npos) << deep;
  // 16 files deep is allowed.
  read_prm_file(prm, dir + "/chain5.prm");
  prm.enter_subsection("Joint");
  EXPECT_DOUBLE_EQ(prm.get_double("Radial clearance"), 1e-4);
  prm.leave_subsection();

  const auto folder = wearlink::testing::input_error_message([&] { read_prm_file(prm, dir); });
  EXPECT_NE(folder.find("'" + dir + "' is a directory, not a parameter file"), std::string::npos) << folder;
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

// `--output ""` once ran and wrote into the root directory; every command that takes
// --output refuses an empty value (exit status 2) before it reads or writes anything.
TEST(CommandLine, EmptyOutputIsRefusedByEveryCommand)
{
  const std::string                           scene    = wearlink::testing::source_path("params/nine_bar_ideal.prm");
  const std::vector<std::vector<std::string>> commands = {{"run", scene},
                                                          {"contact",
                                                           wearlink::testing::source_path("params/pin_bushing.prm")},
                                                          {"compare-pressure", scene},
                                                          {"compare-contact", scene},
                                                          {"compare-dynamics", "before", "after"},
                                                          {"compare-signal", scene, "measured.csv"},
                                                          {"compare-profile", "run", "measured.csv"},
                                                          {"study", "accuracy", scene},
                                                          {"sweep", scene},
                                                          {"lyapunov", "series.csv"},
                                                          {"calibrate", scene, "--measurements", "m.prm"}};
  for (auto args : commands)
    {
      const std::string name = args[0] == "study" ? "study accuracy" : args[0];
      args.insert(args.end(), {"--output", ""});
      const auto r = wearlink::testing::run_wearlink(args);
      EXPECT_EQ(r.exit_status, 2) << name << ": " << r.output;
      EXPECT_NE(r.output.find("The option --output of `wearlink " + name + "` is given an empty value"),
                std::string::npos)
        << name << ": " << r.output;
    }
}

// Text that reaches summary.json must be UTF-8 (a Latin-1 title once ran a whole
// simulation and then failed in the JSON writer).
TEST(Text, Utf8ValidationAcceptsTextAndRefusesStrayBytes)
{
  EXPECT_TRUE(is_valid_utf8("plain ASCII"));
  EXPECT_TRUE(is_valid_utf8("Ambrósio, 5000 rpm, θ₂ − θ₁, 𝜋"));
  EXPECT_TRUE(is_valid_utf8(""));
  EXPECT_FALSE(is_valid_utf8("caf\xe9")); // Latin-1 é
  EXPECT_FALSE(is_valid_utf8("\x80 stray continuation"));
  EXPECT_FALSE(is_valid_utf8("truncated \xe2\x88"));      // the first two of three bytes
  EXPECT_FALSE(is_valid_utf8("overlong \xc0\xaf"));       // '/' in two bytes
  EXPECT_FALSE(is_valid_utf8("surrogate \xed\xa0\x80"));  // U+D800
  EXPECT_FALSE(is_valid_utf8("beyond \xf4\x90\x80\x80")); // U+110000
}

// A message echoes the user's value; a value of megabytes is cut to its start and its
// length, so that the message stays readable. Words up to the limit and multi-byte
// characters at the cut are kept whole.
TEST(Text, LongWordsAreShortenedInMessages)
{
  const std::string huge(10 * 1000 * 1000, '7');
  const std::string message = "In scene.prm, 'Simulation/End time' is '" + huge + "'; it must be a number.";
  const std::string shown   = shorten_long_words(message);
  EXPECT_LT(shown.size(), 300u);
  // The word is the value with its quotes and the ';': 10,000,003 characters, 80 kept.
  EXPECT_NE(shown.find("'Simulation/End time' is '" + std::string(79, '7') + "… [10000003 characters] it must be"),
            std::string::npos)
    << shown;
  const std::string ordinary = "a path /" + std::string(990, 'p') + " stays whole";
  EXPECT_EQ(shorten_long_words(ordinary), ordinary);
  // "é" is two bytes: a cut after 3 bytes of "éééé…" would split the second one.
  const std::string accents = shorten_long_words(std::string(2000, 'x').replace(0, 4, "éé"), 1000, 3);
  EXPECT_EQ(accents.substr(0, 2), "é") << "cut before the character it would split";
  EXPECT_TRUE(is_valid_utf8(accents));
}
