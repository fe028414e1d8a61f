// SPDX-License-Identifier: LGPL-2.1-or-later
// Nothing crashes, nothing is silently lost, on real scenes:
//  - a checkpoint with a changed byte, cut short, with a state of another length or one
//    edited off the mechanism's joints behind a valid checksum, or written for another
//    Title is refused with a message naming what is wrong (both values of a changed
//    entry), and the output directory is left exactly as it was;
//  - a resumed run reports the whole run: its effect ledger equals the uninterrupted
//    run's, its timings include the killed run's up to the checkpoint;
//  - the program: a second run into a locked directory is refused naming the holder's
//    pid; a directory with an earlier run's files needs --overwrite (the user's own
//    files stay); SIGTERM ends a run with 143 and no temporary files; the temporary
//    files of a run killed with SIGKILL are removed by the next run.
#include "base/output_directory.h"
#include "scene_support.h"
#include "wear/wear_state.h"
#include "workflows/wear/wear_run.h"

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <thread>

using namespace wearlink;
namespace fs = std::filesystem;

namespace
{
  const std::vector<std::string> short_wear = {"Wear/Cycles per iteration=0.5",
                                               "Wear/Response cycles=0.1",
                                               "Wear/Number of iterations=3",
                                               "Wear/Extrapolation factor=2000"};

  using wearlink::testing::with;

  /** Wait until a temporary file appears in @p dir (the run has started writing). */
  bool
  wait_for_partial(const std::string &dir)
  {
    for (int k = 0; k < 3000; ++k)
      {
        if (!wearlink::testing::partial_files_in(dir).empty())
          return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
      }
    return false;
  }

  /** A plain scene that runs long enough to be stopped while it writes time_series.csv. */
  std::vector<std::string>
  long_run(const std::string &dir)
  {
    return {"run",
            wearlink::testing::source_path("params/nine_bar_clearance.prm"),
            "--output",
            dir,
            "--quiet",
            "--set",
            "Simulation/End time=1000"};
  }
} // namespace

TEST(Wear, DamagedOrMismatchedCheckpointIsRefusedOutputsUntouched)
{
  workflows::WearRunOptions o;
  o.progress         = false;
  o.final_outputs    = false;
  o.output_directory = wearlink::testing::fresh_directory("wear_refused_checkpoint");
  o.stop_after       = 1;
  {
    auto s = wearlink::testing::scene("params/nine_bar_wear.prm", short_wear);
    workflows::run_wear(s, o);
  }
  const std::string checkpoint = o.output_directory + "/checkpoint.json";
  const std::string original   = wearlink::testing::file_content(checkpoint);
  const auto        before     = wearlink::testing::directory_snapshot(o.output_directory);
  const auto        n_state    = std::to_string(wear::WearState::read(checkpoint).state.size());
  ASSERT_TRUE(before.count("wear_history.csv"));
  o.stop_after = 0;
  o.resume     = true;

  std::string flipped = original;
  flipped[original.size() / 2] ^= 0x04;
  std::string longer = original;
  longer.replace(longer.find("\"state\": ["), 10, "\"state\": [0.5, ");
  // The first coordinate (crank1's x) edited to 1e300, the checksum made to match.
  std::string far_away  = original;
  const auto  first     = far_away.find("\"state\": [") + 10;
  const auto  first_end = far_away.find_first_of(",]", first);
  far_away.replace(first, first_end - first, "1e300");
  struct Case
  {
    std::string              text;
    std::vector<std::string> overrides;
    std::string              expected;
  };
  const std::vector<Case> cases = {
    {flipped, {}, "is damaged: its checksum does not match its content"},
    {original.substr(0, 2 * original.size() / 3), {}, "is damaged: it is truncated"},
    {wearlink::testing::reseal_checkpoint(longer),
     {},
     "entries, the mechanism of the scene needs " + n_state + ". Resume with the scene"},
    {wearlink::testing::reseal_checkpoint(far_away),
     {},
     "its state puts the bodies 1e+300 off their joints (constraint row "},
    {original,
     {"Title=Another title"},
     "'Title' is 'Nine-bar press, wearing clearance joints A and B (seed §4.2.1)' in the checkpoint and "
     "'Another title' now"}};
  for (const auto &c : cases)
    {
      std::ofstream(checkpoint, std::ios::binary) << c.text;
      const auto  on_disk = wearlink::testing::directory_snapshot(o.output_directory);
      auto        s       = wearlink::testing::scene("params/nine_bar_wear.prm", with(short_wear, c.overrides));
      std::string m       = wearlink::testing::input_error_message([&] { workflows::run_wear(s, o); });
      EXPECT_NE(m.find(c.expected), std::string::npos) << m;
      EXPECT_NE(m.find(checkpoint), std::string::npos) << m;
      EXPECT_EQ(wearlink::testing::directory_snapshot(o.output_directory), on_disk) << "outputs touched: " << m;
    }
  std::ofstream(checkpoint, std::ios::binary) << original;
  EXPECT_EQ(wearlink::testing::directory_snapshot(o.output_directory), before);
}

TEST(Wear, ResumedRunContinuesLedgerAndTimings)
{
  workflows::WearRunOptions o;
  o.progress          = false;
  o.final_outputs     = false;
  auto straight_scene = wearlink::testing::scene("params/nine_bar_wear.prm", short_wear);
  o.output_directory  = wearlink::testing::fresh_directory("wear_ledger_straight");
  const auto straight = workflows::run_wear(straight_scene, o);
  const auto ledger   = EffectLedger::instance().snapshot();
  ASSERT_EQ(EffectLedger::instance().calls("wear iterations"), 3);

  o.output_directory = wearlink::testing::fresh_directory("wear_ledger_resumed");
  {
    auto s       = wearlink::testing::scene("params/nine_bar_wear.prm", short_wear);
    o.stop_after = 1;
    workflows::run_wear(s, o);
  }
  const auto at_checkpoint = wear::WearState::read(o.output_directory + "/checkpoint.json").timings;
  auto       s2            = wearlink::testing::scene("params/nine_bar_wear.prm", short_wear);
  o.stop_after             = 0;
  o.resume                 = true;
  const auto resumed       = workflows::run_wear(s2, o);
  EXPECT_EQ(EffectLedger::instance().snapshot(), ledger) << "the ledger counts the whole run, once";
  EXPECT_GT(at_checkpoint.dynamics, 0);
  EXPECT_GT(resumed.timings.dynamics, at_checkpoint.dynamics);
  EXPECT_GT(resumed.timings.total, at_checkpoint.total + resumed.timings.dynamics - at_checkpoint.dynamics - 1e-9);
  // Wall time varies with the machine's load: the sums agree within a factor, not exactly.
  EXPECT_GT(resumed.timings.dynamics, 0.3 * straight.timings.dynamics);
  EXPECT_LT(resumed.timings.dynamics, 3.0 * straight.timings.dynamics);
}

TEST(Run, SecondRunIntoLockedDirectoryIsRefused)
{
  const std::string dir = wearlink::testing::fresh_directory("run_locked");
  OutputDirectory   held(dir, EarlierRun::refuse, {}, "");
  const auto        r = wearlink::testing::run_wearlink({"run",
                                                         wearlink::testing::source_path("params/nine_bar_ideal.prm"),
                                                         "--output",
                                                         dir,
                                                         "--quiet",
                                                         "--set",
                                                         "Simulation/End time=0.05"});
  EXPECT_EQ(r.exit_status, 2) << r.output;
  EXPECT_NE(r.output.find("is in use by another wearlink run (pid " + std::to_string(::getpid()) + ";"),
            std::string::npos)
    << r.output;
  EXPECT_FALSE(fs::exists(dir + "/summary.json"));
}

TEST(Run, EarlierRunFilesNeedOverwrite)
{
  const std::string              dir  = wearlink::testing::fresh_directory("run_earlier");
  const std::vector<std::string> args = {"run",
                                         wearlink::testing::source_path("params/nine_bar_ideal.prm"),
                                         "--output",
                                         dir,
                                         "--quiet",
                                         "--set",
                                         "Simulation/End time=0.05"};
  ASSERT_EQ(wearlink::testing::run_wearlink(args).exit_status, 0);
  std::ofstream(dir + "/notes.txt") << "mine";
  const auto summary = wearlink::testing::file_content(dir + "/summary.json");
  const auto again   = wearlink::testing::run_wearlink(args);
  EXPECT_EQ(again.exit_status, 2) << again.output;
  // The nine-bar's slider9 gets its first-look accelerations.png (workflows/run/first_look.h).
  EXPECT_NE(again.output.find("holds the files of an earlier run (accelerations.png, parameters.prm, summary.json"),
            std::string::npos)
    << again.output;
  EXPECT_NE(again.output.find("Add --overwrite to replace them, or choose another --output directory."),
            std::string::npos)
    << again.output;
  EXPECT_EQ(wearlink::testing::file_content(dir + "/summary.json"), summary) << "refused: nothing changed";
  const auto overwritten = wearlink::testing::run_wearlink(with(args, {"--overwrite"}));
  EXPECT_EQ(overwritten.exit_status, 0) << overwritten.output;
  EXPECT_TRUE(fs::exists(dir + "/summary.json"));
  EXPECT_EQ(wearlink::testing::file_content(dir + "/notes.txt"), "mine");
  EXPECT_FALSE(fs::exists(dir + "/" + OutputDirectory::lock_file_name)) << "released";
}

TEST(Run, SigtermLeavesNoTemporaryFiles)
{
  const std::string dir = wearlink::testing::fresh_directory("run_sigterm");
  const int         pid = wearlink::testing::start_wearlink(long_run(dir), dir + ".log");
  ASSERT_TRUE(wait_for_partial(dir)) << wearlink::testing::file_content(dir + ".log");
  ::kill(pid, SIGTERM);
  EXPECT_EQ(wearlink::testing::wait_for(pid), 128 + SIGTERM);
  EXPECT_TRUE(wearlink::testing::partial_files_in(dir).empty());
  EXPECT_TRUE(wearlink::testing::files_in(dir).empty()) << "no half-written outputs, no lock file";
  EXPECT_NE(wearlink::testing::file_content(dir + ".log").find("interrupted: Stopped by SIGTERM"), std::string::npos)
    << wearlink::testing::file_content(dir + ".log");
}

TEST(Run, TemporaryFilesOfAKilledRunAreRemovedAtTheNextStart)
{
  const std::string dir = wearlink::testing::fresh_directory("run_sigkill");
  const int         pid = wearlink::testing::start_wearlink(long_run(dir), dir + ".log");
  ASSERT_TRUE(wait_for_partial(dir)) << wearlink::testing::file_content(dir + ".log");
  ::kill(pid, SIGKILL);
  EXPECT_EQ(wearlink::testing::wait_for(pid), 128 + SIGKILL);
  ASSERT_EQ(wearlink::testing::partial_files_in(dir).size(), 1u);
  const auto r = wearlink::testing::run_wearlink({"run",
                                                  wearlink::testing::source_path("params/nine_bar_ideal.prm"),
                                                  "--output",
                                                  dir,
                                                  "--set",
                                                  "Simulation/End time=0.05"});
  EXPECT_EQ(r.exit_status, 0) << r.output;
  EXPECT_NE(r.output.find("removed 1 temporary file(s) left in " + dir + " by a run that was killed"),
            std::string::npos)
    << r.output;
  EXPECT_TRUE(wearlink::testing::partial_files_in(dir).empty());
}
