// SPDX-License-Identifier: LGPL-2.1-or-later
// Every command that writes an output folder holds it like `wearlink run` does
// (app/output_claim.h; the run command's own tests are in run_robustness_test.cc):
//  - a folder locked by another process (this test process holds the lock) is refused
//    with exit status 2, naming the holder's pid, and nothing in it is touched: sweep,
//    study accuracy, contact, compare-pressure, compare-contact, compare-dynamics,
//    lyapunov, and sweep on 2 MPI ranks (both ranks stop; none waits for the other);
//  - a folder holding a file of the command's earlier run is refused with exit status 2
//    unless --overwrite, which replaces the command's files and keeps the user's
//    (lyapunov keeps earlier files: its default folder is the current directory);
//  - a folder the command created is gone again when a bad input stops it.
#include "base/output_directory.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace wearlink;
namespace fs = std::filesystem;

namespace
{
  /** A command's arguments writing into the folder DIR (the placeholder is replaced). */
  struct Invocation
  {
    std::string              name;
    std::vector<std::string> args;
    std::string              earlier_file; ///< a file name the command writes ("": keeps earlier files)
  };

  std::vector<std::string>
  into(std::vector<std::string> args, const std::string &dir)
  {
    for (auto &a : args)
      if (a == "DIR")
        a = dir;
    return args;
  }

  /** Valid invocations (cheap up to the claim), one per command that writes a folder. */
  std::vector<Invocation>
  invocations()
  {
    const auto p = [](const std::string &f) {
      return wearlink::testing::source_path(f);
    };
    return {
      {"sweep",
       {"sweep",
        p("params/four_bar.prm"),
        "--parameter",
        "Joint A/Clearance/Radial clearance",
        "--values",
        "2e-4:2e-4:1",
        "--set",
        "Simulation/End time=0.5",
        "--quiet",
        "--output",
        "DIR"},
       "sweep.json"},
      {"study accuracy",
       {"study", "accuracy", p("params/nine_bar_clearance.prm"), "--quick", "--quiet", "--output", "DIR"},
       "accuracy.md"},
      {"contact", {"contact", p("params/pin_bushing.prm"), "--output", "DIR"}, "summary.json"},
      {"compare-pressure",
       {"compare-pressure", p("params/nine_bar_wear.prm"), "--models", "hertz-strip", "--output", "DIR"},
       "compare_pressure.csv"},
      {"compare-contact",
       {"compare-contact", p("params/nine_bar_clearance.prm"), "--no-effects", "--output", "DIR"},
       "deviations.csv"},
      {"compare-dynamics", {"compare-dynamics", "before_run", "after_run", "--output", "DIR"}, "before_after.md"},
      {"lyapunov", {"lyapunov", "series.csv", "--column", "x", "--output", "DIR"}, ""},
      {"compare-signal",
       {"compare-signal", p("params/nine_bar_experiment.prm"), "measured.csv", "--channel", "x", "--output", "DIR"},
       "signal_comparison.json"},
      {"compare-profile",
       {"compare-profile", "run_dir", "measured.csv", "--surface", "bore", "--joint", "A", "--output", "DIR"},
       "profile_comparison.json"},
      {"calibrate",
       {"calibrate",
        p("params/nine_bar_experiment.prm"),
        "--measurements",
        p("params/nine_bar_experiment_measurements.prm"),
        "--output",
        "DIR"},
       "calibration.json"}};
  }

  std::string
  holder_message()
  {
    return "is in use by another wearlink run (pid " + std::to_string(::getpid()) + ";";
  }
} // namespace

TEST(OutputFolders, EveryCommandRefusesALockedFolder)
{
  for (const auto &c : invocations())
    {
      const std::string dir = wearlink::testing::fresh_directory("locked_" + c.args[0]);
      std::ofstream(dir + "/notes.txt") << "mine";
      OutputDirectory held(dir, EarlierRun::resume, {}, "");
      const auto      before = wearlink::testing::directory_snapshot(dir);
      const auto      r      = wearlink::testing::run_wearlink(into(c.args, dir));
      EXPECT_EQ(r.exit_status, 2) << c.name << ": " << r.output;
      EXPECT_NE(r.output.find("The output directory '" + dir + "' " + holder_message()), std::string::npos)
        << c.name << ": " << r.output;
      EXPECT_EQ(wearlink::testing::directory_snapshot(dir), before) << c.name << ": the folder was touched";
    }
}

TEST(OutputFolders, SweepOnTwoRanksRefusesALockedFolderOnEveryRank)
{
  if (std::string(WEARLINK_MPIEXEC).empty())
    GTEST_SKIP() << "no mpiexec";
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  const std::string dir = wearlink::testing::fresh_directory("locked_sweep_mpi");
  OutputDirectory   held(dir, EarlierRun::resume, {}, "");
  const auto        r = wearlink::testing::run_wearlink_mpi(2, into(invocations()[0].args, dir));
  EXPECT_NE(r.exit_status, 0) << r.output;
  EXPECT_NE(r.output.find(holder_message()), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir + "/bifurcation.csv"));
}

TEST(OutputFolders, EarlierFilesAreRefusedUnlessOverwrite)
{
  for (const auto &c : invocations())
    {
      if (c.earlier_file.empty())
        continue;
      const std::string dir = wearlink::testing::fresh_directory("earlier_" + c.args[0]);
      std::ofstream(dir + "/" + c.earlier_file) << "earlier";
      const auto before = wearlink::testing::directory_snapshot(dir);
      const auto r      = wearlink::testing::run_wearlink(into(c.args, dir));
      EXPECT_EQ(r.exit_status, 2) << c.name << ": " << r.output;
      EXPECT_NE(r.output.find("The output directory '" + dir + "' holds the files of an earlier run (" +
                              c.earlier_file +
                              "). Add --overwrite to replace them, or choose another --output directory."),
                std::string::npos)
        << c.name << ": " << r.output;
      EXPECT_EQ(wearlink::testing::directory_snapshot(dir), before) << c.name << ": the folder was touched";
    }
}

TEST(OutputFolders, OverwriteReplacesTheCommandsFilesOnly)
{
  const auto        sweep = invocations()[0];
  const std::string dir   = wearlink::testing::fresh_directory("earlier_sweep_overwrite");
  std::ofstream(dir + "/sweep.json") << "earlier";
  std::ofstream(dir + "/bifurcation.png") << "earlier"; // gone even if gnuplot is missing
  std::ofstream(dir + "/notes.txt") << "mine";
  auto args = into(sweep.args, dir);
  args.push_back("--overwrite");
  const auto r = wearlink::testing::run_wearlink(args);
  ASSERT_EQ(r.exit_status, 0) << r.output;
  EXPECT_NE(wearlink::testing::file_content(dir + "/sweep.json"), "earlier");
  EXPECT_NE(wearlink::testing::file_content(dir + "/bifurcation.png"), "earlier");
  EXPECT_TRUE(fs::exists(dir + "/members.csv"));
  EXPECT_EQ(wearlink::testing::file_content(dir + "/notes.txt"), "mine");
  EXPECT_FALSE(fs::exists(dir + "/" + OutputDirectory::lock_file_name)) << "released";
}

TEST(OutputFolders, LyapunovKeepsEarlierFilesAndReleasesTheFolder)
{
  const std::string dir = wearlink::testing::fresh_directory("lyapunov_folder");
  {
    std::ofstream series(dir + "/series.csv");
    series << "x\n";
    double x = 0.3;
    for (int i = 0; i < 3000; ++i, x = 3.9 * x * (1 - x))
      series << x << "\n";
  }
  std::ofstream(dir + "/out_lyapunov_note.txt") << "mine";
  std::ofstream(dir + "/lyapunov_y_wolf.csv") << "an earlier analysis";
  const auto r = wearlink::testing::run_wearlink(
    {"lyapunov", dir + "/series.csv", "--column", "x", "--method", "rosenstein", "--output", dir});
  ASSERT_EQ(r.exit_status, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir + "/lyapunov_x_rosenstein.json"));
  EXPECT_EQ(wearlink::testing::file_content(dir + "/lyapunov_y_wolf.csv"), "an earlier analysis");
  EXPECT_FALSE(fs::exists(dir + "/" + OutputDirectory::lock_file_name)) << "released";
}

TEST(OutputFolders, AFolderCreatedForABadInputIsRemovedAgain)
{
  const std::string dir = wearlink::testing::fresh_directory("bad_input_folder") + "/new";
  const auto        r =
    wearlink::testing::run_wearlink({"compare-dynamics", "/nonexistent/before", "/nonexistent/after", "--output", dir});
  EXPECT_EQ(r.exit_status, 2) << r.output;
  EXPECT_FALSE(fs::exists(dir)) << r.output;
}
