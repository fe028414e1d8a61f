// SPDX-License-Identifier: LGPL-2.1-or-later
// Kill and resume: a short wear run of params/slider_crank_wear.prm is killed with SIGKILL
// at WEARLINK_KILL_INSTANTS seeded random instants (reproducible: the seed is fixed), each
// time resumed from what the killed process left (--resume if a checkpoint exists, else
// a fresh start), and finally run to its end. Its outputs must equal an uninterrupted
// run's: the summary's wear figures, effect ledger, warnings and the response before and
// after wear (with its ratios), wear_history.csv byte for byte,
// and no temporary file left anywhere. Built twice (tests/scenes/CMakeLists.txt): three
// instants in the default suite, twenty under the label `fuzz` (WEARLINK_LONG_TESTS).
#include "io/json_file.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <random>
#include <thread>

#ifndef WEARLINK_KILL_INSTANTS
#  define WEARLINK_KILL_INSTANTS 3
#  define WEARLINK_KILL_SUITE KillResume
#else
#  define WEARLINK_KILL_SUITE KillResumeFuzz
#endif

using namespace wearlink;
namespace fs = std::filesystem;

namespace
{
  std::vector<std::string>
  arguments(const std::vector<std::string> &directory)
  {
    std::vector<std::string> a = {"run",
                                  wearlink::testing::source_path("params/slider_crank_wear.prm"),
                                  "--quiet",
                                  "--set",
                                  "Wear/Number of iterations=4",
                                  "--set",
                                  "Wear/Response cycles=0.25"};
    a.insert(a.end(), directory.begin(), directory.end());
    return a;
  }

  /** The outputs that must not depend on interruptions. */
  Json
  wear_figures(const std::string &dir)
  {
    const Json s            = io::read_json_file(dir + "/summary.json");
    Json       out          = Json::object();
    out["clearance_joints"] = s.at("clearance_joints");
    out["wear_iterations"]  = s.at("wear_iterations");
    out["wear_revolutions"] = s.at("wear_revolutions");
    out["effect_ledger"]    = s.at("effect_ledger");
    out["warnings"]         = s.at("warnings");
    out["response"]         = s.at("response"); // before wear too: it is in the checkpoint
    if (!s.at("response").contains("peak_acceleration_ratio"))
      ADD_FAILURE() << dir << ": summary.json has no response before wear";
    return out;
  }

  /** Start the run in @p dir: resume it if it has a checkpoint, else start it afresh. */
  int
  start(const std::string &dir, const std::string &log)
  {
    if (fs::exists(dir + "/checkpoint.json"))
      return wearlink::testing::start_wearlink(arguments({"--resume", dir}), log);
    return wearlink::testing::start_wearlink(arguments({"--output", dir, "--overwrite"}), log);
  }
} // namespace

TEST(WEARLINK_KILL_SUITE, KilledAtRandomInstantsEndsAsAnUninterruptedRun)
{
  const std::string straight = wearlink::testing::fresh_directory("kill_resume_straight");
  const auto        t0       = std::chrono::steady_clock::now();
  const auto        r        = wearlink::testing::run_wearlink(arguments({"--output", straight}));
  ASSERT_EQ(r.exit_status, 0) << r.output;
  const double duration = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  const std::string                      dir = wearlink::testing::fresh_directory("kill_resume_killed");
  std::mt19937                           random(20240614);
  std::uniform_real_distribution<double> instant(0.0, duration);
  int                                    killed = 0, resumed = 0;
  for (int k = 0; k < WEARLINK_KILL_INSTANTS; ++k)
    {
      const double t = instant(random);
      resumed += fs::exists(dir + "/checkpoint.json");
      const int pid = start(dir, dir + ".log");
      std::this_thread::sleep_for(std::chrono::duration<double>(t));
      ::kill(pid, SIGKILL);
      const int status = wearlink::testing::wait_for(pid);
      killed += status == 128 + SIGKILL;
      EXPECT_TRUE(status == 0 || status == 128 + SIGKILL) << "instant " << k << " (" << t << " s): " << status << "\n"
                                                          << wearlink::testing::file_content(dir + ".log");
    }
  const int pid = start(dir, dir + ".log");
  ASSERT_EQ(wearlink::testing::wait_for(pid), 0) << wearlink::testing::file_content(dir + ".log");
  std::cout << killed << " of " << WEARLINK_KILL_INSTANTS << " runs killed; " << resumed
            << " runs resumed from a checkpoint (uninterrupted run: " << duration << " s)\n";

  EXPECT_EQ(wear_figures(dir), wear_figures(straight));
  EXPECT_EQ(wearlink::testing::file_content(dir + "/wear_history.csv"),
            wearlink::testing::file_content(straight + "/wear_history.csv"));
  EXPECT_TRUE(wearlink::testing::partial_files_in(dir).empty());
  for (const auto &f : wearlink::testing::files_in(straight))
    EXPECT_TRUE(fs::exists(dir + "/" + fs::relative(f, straight).string())) << f;
}
