// SPDX-License-Identifier: LGPL-2.1-or-later
// Validity warnings of wear runs (base/validity_warnings.h):
//  - the hertz-strip pressure model warns, once per joint with the worst value and the
//    limit, when its Hertz strip is wider than half the pin (half-angle past 90°). Here
//    provoked by an axial length of 1 µm on the nine-bar (the line load of a ~100 N
//    contact is then ~1e8 N/m and b = √(4 P R*/(π E*)) ≈ 18 mm > π/2 · 11.5 mm); the
//    shipped params/nine_bar_wear.prm (10 mm, b ≈ 0.2 mm, half-angle ≈ 1°) does not warn;
//  - a wear run stopped after its first iteration and resumed from the checkpoint
//    reports the same `warnings` list as an uninterrupted run: the warnings raised
//    before the checkpoint are kept in it (format version 6);
//  - an adaptive run that ends at its Number of iterations short of its Target
//    revolutions warns, one that reaches the target does not;
//  - entries valid one by one but implausible are warned about when the scene is read,
//    and the warning reaches a run's summary.json and stderr: a friction coefficient
//    above 1 (dry metal pairs 0.1 … 0.8), a Wear/Cycle period that is no whole number of
//    the 0.5 s driving period (0.37 s, 1e-9 s); 1 s (two periods) and the shipped
//    values are not warned about;
//  - the iterations' dynamics warnings are named as theirs (the summary's dynamics
//    figures are the response run's after wear).
#include "io/json_file.h"
#include "scene_support.h"
#include "wear/wear_state.h"
#include "workflows/wear/wear_run.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace wearlink;

namespace
{
  const std::vector<std::string> warning_wear = {"Wear/Cycles per iteration=0.5",
                                                 "Wear/Response cycles=0.1",
                                                 "Wear/Number of iterations=3",
                                                 "Wear/Extrapolation factor=2000"};

  /** Joints A and B 1 µm long: the Hertz strip of every contact is wider than half the pin. */
  const std::vector<std::string> knife_edge_joints = {"Joint A/Clearance/Axial length=1e-6",
                                                      "Joint B/Clearance/Axial length=1e-6",
                                                      "Wear/Cycles per iteration=0.5",
                                                      "Wear/Response cycles=0.1",
                                                      "Wear/Number of iterations=3",
                                                      "Wear/Extrapolation factor=1"};

  std::vector<std::string>
  warnings_of(const Json &summary)
  {
    std::vector<std::string> out;
    for (const auto &w : summary.at("warnings"))
      out.push_back(w.get<std::string>());
    return out;
  }

  std::vector<std::string>
  containing(const std::vector<std::string> &list, const std::string &text)
  {
    std::vector<std::string> out;
    std::copy_if(list.begin(), list.end(), std::back_inserter(out), [&](const std::string &w) {
      return w.find(text) != std::string::npos;
    });
    return out;
  }

  workflows::WearRunResult
  run_wear(const std::vector<std::string> &overrides, workflows::WearRunOptions o)
  {
    auto s = wearlink::testing::scene("params/nine_bar_wear.prm", overrides);
    return workflows::run_wear(s, o);
  }
} // namespace

TEST(WearWarnings, HertzStripHalfAnglePast90IsWarnedOncePerJoint)
{
  workflows::WearRunOptions o;
  o.progress         = false;
  o.output_directory = wearlink::testing::fresh_directory("wear_knife_edge");
  ::testing::internal::CaptureStderr();
  const auto        r   = run_wear(knife_edge_joints, o);
  const std::string log = ::testing::internal::GetCapturedStderr();
  const auto        all = warnings_of(r.summary);
  for (const std::string joint : {"A", "B"})
    {
      const auto w = containing(all, "joint " + joint + ": hertz-strip contact half-angle ");
      ASSERT_EQ(w.size(), 1u) << r.summary.at("warnings").dump(1);
      EXPECT_NE(w[0].find(" deg exceeds its limit 90 deg (a contact wider than half the pin; the worst at the "
                          "normal force "),
                std::string::npos)
        << w[0];
      EXPECT_NE(w[0].find("outside its validity"), std::string::npos) << w[0];
      EXPECT_NE(log.find("[wearlink] warning: " + w[0]), std::string::npos) << log;
    }
  const auto on_disk = warnings_of(io::read_json_file(o.output_directory + "/summary.json"));
  EXPECT_EQ(on_disk, all);
}

TEST(WearWarnings, ShippedNineBarWearHasNoHertzHalfAngleWarning)
{
  workflows::WearRunOptions o;
  o.progress      = false;
  o.final_outputs = true;
  const auto r    = run_wear(warning_wear, o);
  EXPECT_TRUE(containing(warnings_of(r.summary), "half-angle").empty()) << r.summary.at("warnings").dump(1);
}

TEST(WearWarnings, WarningsSurviveAResume)
{
  workflows::WearRunOptions o;
  o.progress          = false;
  o.output_directory  = wearlink::testing::fresh_directory("wear_warnings_straight");
  const auto straight = warnings_of(run_wear(knife_edge_joints, o).summary);
  ASSERT_FALSE(straight.empty());

  o.output_directory = wearlink::testing::fresh_directory("wear_warnings_resumed");
  o.stop_after       = 1; // the process ends after iteration 1 and its checkpoint
  run_wear(knife_edge_joints, o);
  const auto at_checkpoint = wear::WearState::read(o.output_directory + "/checkpoint.json").warnings;
  ASSERT_FALSE(at_checkpoint.empty()) << "the checkpoint keeps the warnings of iteration 1";
  for (const auto &w : at_checkpoint.warnings())
    EXPECT_FALSE(containing(straight, w.quantity + " ").empty()) << w.text();

  o.stop_after       = 0;
  o.resume           = true;
  const auto resumed = warnings_of(run_wear(knife_edge_joints, o).summary);
  EXPECT_EQ(resumed, straight);
}

TEST(WearWarnings, AnAdaptiveRunShortOfItsTargetSaysSo)
{
  const std::vector<std::string> adaptive = {"Wear/Cycles per iteration=0.5",
                                             "Wear/Response cycles=0.1",
                                             "Wear/Extrapolation=adaptive",
                                             "Wear/Maximum depth increment=1e-6",
                                             "Wear/Maximum extrapolation factor=100"};
  workflows::WearRunOptions      o;
  o.progress = false;
  // Two iterations of at most 100 × 0.5 cycles cannot represent 1e30 revolutions.
  auto       short_of = adaptive;
  const auto capped   = {"Wear/Number of iterations=2", "Wear/Target revolutions=1e30"};
  short_of.insert(short_of.end(), capped.begin(), capped.end());
  const auto w = containing(warnings_of(run_wear(short_of, o).summary), "revolutions short of Wear/Target revolutions");
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("the run ended at its Number of iterations (2)"), std::string::npos) << w[0];
  // One that reaches its target (25 revolutions, within the first iteration's 50) does not warn.
  auto reached = adaptive;
  reached.insert(reached.end(), {"Wear/Number of iterations=2", "Wear/Target revolutions=25"});
  EXPECT_TRUE(containing(warnings_of(run_wear(reached, o).summary), "Target revolutions").empty());
}

TEST(SceneWarnings, ImplausibleEntriesAreWarnedAboutWhenTheSceneIsRead)
{
  const auto warned = [](const std::vector<std::string> &overrides, const std::string &text) {
    const auto               s = wearlink::testing::scene("params/nine_bar_wear.prm", overrides);
    std::vector<std::string> texts;
    for (const auto &w : s.warnings.warnings())
      texts.push_back(w.text());
    return containing(texts, text);
  };
  EXPECT_TRUE(warned({}, "").empty()) << "the shipped scene is plausible";
  const auto mu = warned({"Joint A/Clearance/modified-coulomb/Friction coefficient=10"}, "friction coefficient");
  ASSERT_EQ(mu.size(), 1u);
  EXPECT_NE(mu[0].find("joint A: Clearance friction coefficient 10 exceeds its limit 1 (dry metal pairs"),
            std::string::npos)
    << mu[0];
  EXPECT_TRUE(warned({"Joint A/Clearance/modified-coulomb/Friction coefficient=0.8"}, "friction").empty());

  const std::string cycle = "Wear/Cycle period: distance from a whole number of driving periods";
  const auto        part  = warned({"Wear/Cycle period=0.37"}, cycle);
  ASSERT_EQ(part.size(), 1u);
  EXPECT_NE(part[0].find("0.26 periods exceeds its limit 0.001 periods (Cycle period 0.37 s is 0.74 driving "
                         "periods of 0.5 s)"),
            std::string::npos)
    << part[0];
  EXPECT_EQ(warned({"Wear/Cycle period=1e-9"}, cycle).size(), 1u) << "a cycle of no time at all";
  EXPECT_TRUE(warned({"Wear/Cycle period=1"}, cycle).empty()) << "two whole revolutions";
}

TEST(SceneWarnings, AnImplausibleEntryReachesTheRunsSummaryAndStderr)
{
  const std::string dir = wearlink::testing::fresh_directory("scene_warning_run");
  const auto        r   = wearlink::testing::run_wearlink({"run",
                                                           wearlink::testing::source_path("params/nine_bar_clearance.prm"),
                                                           "--output",
                                                           dir,
                                                           "--quiet",
                                                           "--set",
                                                           "Simulation/End time=0.01",
                                                           "--set",
                                                           "Joint B/Clearance/modified-coulomb/Friction coefficient=10"});
  ASSERT_EQ(r.exit_status, 0) << r.output;
  const auto w = containing(warnings_of(io::read_json_file(dir + "/summary.json")), "joint B: Clearance friction");
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(r.output.find("[wearlink] warning: " + w[0]), std::string::npos) << r.output;
}

// `contact` under displacement control with an eccentricity equal to the radial
// clearance (0.5 mm): the pin does not touch the bore, every force is 0. It ran and
// reported 0 N without a word; now the load state is warned about, and the one that
// pushes 10 µm into the bore is not.
TEST(SceneWarnings, ContactEccentricityWithinTheClearanceIsWarned)
{
  const std::string dir = wearlink::testing::fresh_directory("contact_gap_warning");
  const auto        r   = wearlink::testing::run_wearlink({"contact",
                                                           wearlink::testing::source_path("params/pin_bushing.prm"),
                                                           "--output",
                                                           dir,
                                                           "--set",
                                                           "Loads/Control=displacement",
                                                           "--set",
                                                           "Loads/Eccentricities=0.5e-3, 0.51e-3",
                                                           "--set",
                                                           "FE model/Surface element size=1e-4",
                                                           "--set",
                                                           "FE model/Solvers=condensed",
                                                           "--set",
                                                           "Output/Write VTU=false"});
  ASSERT_EQ(r.exit_status, 0) << r.output;
  const auto all = warnings_of(io::read_json_file(dir + "/summary.json"));
  const auto gap = containing(all, "radial clearance left");
  ASSERT_EQ(gap.size(), 1u) << io::read_json_file(dir + "/summary.json").at("warnings").dump(1);
  EXPECT_NE(gap[0].find("load state 0 (eccentricity 0.0005 m): radial clearance left 0 m exceeds its limit"),
            std::string::npos)
    << gap[0];
  EXPECT_NE(gap[0].find("the pin does not touch the bore: the contact force is 0"), std::string::npos) << gap[0];
  EXPECT_NE(r.output.find("[wearlink] warning: " + gap[0]), std::string::npos) << r.output;
}

// The warnings of a wear run's iterations name them: the summary's dynamics figures
// (max_constraint_violation_m, …) are those of the response run after wear, and an
// iteration beyond a limit must not read as if that run were. The getting-started
// four-bar worn 2000-fold per iteration, in two long iterations of 20 cycles: they drift
// 1.8 µm off the joints (limit 1 µm; the carry onto the worn profiles puts the bodies back
// on their joints between iterations), the response run after wear of one cycle stays
// at 0.02 µm.
TEST(WearWarnings, TheIterationsWarningsAreNamedAsTheirs)
{
  const std::string        dir = wearlink::testing::fresh_directory("wear_iteration_warnings");
  std::vector<std::string> args{"run",
                                wearlink::testing::source_path("params/getting_started.prm"),
                                "--output",
                                dir,
                                "--quiet"};
  for (const std::string set : {"Joint B/Clearance/Wear law=archard",
                                "Joint B/Clearance/Pressure model=hertz-strip",
                                "Joint B/Clearance/archard/Bushing density=8900",
                                "Joint B/Clearance/archard/Pin density=7850",
                                "Joint B/Clearance/archard/Pin wear coefficient=5e-14",
                                "Joint B/Clearance/archard/Bushing wear coefficient=5e-14",
                                "Wear/Number of iterations=2",
                                "Wear/Extrapolation factor=2000",
                                "Wear/Cycles per iteration=20",
                                "Output/Plots=false"})
    args.insert(args.end(), {"--set", set});
  const auto r = wearlink::testing::run_wearlink(args);
  ASSERT_EQ(r.exit_status, 0) << r.output;
  const Json summary = io::read_json_file(dir + "/summary.json");
  const auto all     = warnings_of(summary);
  const auto drift   = containing(all, "largest constraint violation");
  ASSERT_EQ(drift.size(), 1u) << summary.at("warnings").dump(1);
  EXPECT_EQ(drift[0].rfind("wear iterations' dynamics: largest constraint violation ", 0), 0u) << drift[0];
  EXPECT_LT(json_number(summary.at("max_constraint_violation_m")), 1e-6) << "the response run after wear";
}
