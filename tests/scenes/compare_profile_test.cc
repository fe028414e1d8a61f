// SPDX-License-Identifier: LGPL-2.1-or-later
// `wearlink compare-profile` end to end on a run folder the tool writes itself: the
// nine-bar wear scene shortened as in the wear tests (one iteration of half a cycle from
// the assembly, no settling, extrapolated by the scene's factor) wears joint A's bore by
// a few micrometres. The
// "measured" trace is that worn bore, sampled at 1000 unevenly spaced angles on the
// run's own interpolant and turned by a known −40°: measured(a) = bore(a + θ) with
// θ = −40°. The command must
//  - find θ to 0.1° — a tenth of the run's 1° sample spacing: the measured points lie
//    on the predicted interpolant, so only the measured trace's chords across its kinks
//    (≪ the pocket's micrometres) pull the minimum;
//  - report the run's own deepest bore wear (summary.json) to rounding, and a worn area
//    that, times the joint's length, is the run's worn bushing volume to 1e-3 (they
//    differ by O(h/R) ≈ 1e-4 and the polygon's sin h/h ≈ 1 − 5e-5);
//  - refuse bad input with exit status 2 and write nothing, in its folder or the run's.
#include "base/json.h"
#include "base/numbers.h"
#include "contact/clearance_joint.h"
#include "io/plot.h"
#include "io/profile_file.h"
#include "scene_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>

namespace wl = wearlink::testing;
using wearlink::Json;
using wearlink::json_number;
using wearlink::numbers::pi;
using wearlink::numbers::two_pi;

namespace
{
  const std::vector<std::string> short_wear_arguments = {"--set",
                                                         "Wear/Settling cycles=0",
                                                         "--set",
                                                         "Wear/Cycles per iteration=0.5",
                                                         "--set",
                                                         "Wear/Response cycles=0.1",
                                                         "--set",
                                                         "Wear/Number of iterations=1",
                                                         "--quiet"};

  /** The run folder, written once for the tests below. */
  const std::string &
  run_folder()
  {
    static const std::string dir = [] {
      const std::string out = wl::fresh_directory("compare_profile_run");
      auto args = std::vector<std::string>{"run", wl::source_path("params/nine_bar_wear.prm"), "--output", out};
      args.insert(args.end(), short_wear_arguments.begin(), short_wear_arguments.end());
      const auto r = wl::run_wearlink(args);
      EXPECT_EQ(r.exit_status, 0) << r.output;
      return out;
    }();
    return dir;
  }

  /** The run's worn bore of joint A at 1000 uneven angles a_i, turned: radius bore(a_i + θ). */
  std::string
  turned_measurement(const double theta, const std::string &file)
  {
    const auto    bore = wearlink::io::read_profile_csv(run_folder() + "/bore_A.csv");
    std::ofstream out(file);
    out << "# the run's worn bore, turned\nangle_rad,radius_m\n" << std::setprecision(17);
    const int n = 1000;
    for (int i = 0; i < n; ++i)
      {
        const double a = two_pi * (i + 0.3 + 0.4 * std::sin(1.7 * i)) / n;
        out << a << "," << bore.radius(a + theta) << "\n";
      }
    return file;
  }

  std::vector<std::string>
  compare(const std::string &measured, const std::string &out, std::vector<std::string> more = {})
  {
    std::vector<std::string> args = {"compare-profile", run_folder(), measured, "--output", out, "--quiet"};
    args.insert(args.end(), more.begin(), more.end());
    return args;
  }
} // namespace

TEST(CompareProfile, RecoversTheTurnOfTheRunsOwnWornBore)
{
  const double theta    = -40 * pi / 180;
  const auto   measured = turned_measurement(theta, wl::fresh_directory("compare_profile_in") + "/bore.csv");
  const auto   before   = wl::directory_snapshot(run_folder());
  const auto   out      = wl::fresh_directory("compare_profile_out");
  const auto   r        = wl::run_wearlink(compare(measured, out, {"--surface", "bore", "--joint", "A"}));
  ASSERT_EQ(r.exit_status, 0) << r.output;
  std::cout << r.output;
  const Json j       = Json::parse(wl::file_content(out + "/profile_comparison.json"));
  const Json summary = Json::parse(wl::file_content(run_folder() + "/summary.json"));
  const Json joint   = summary.at("clearance_joints").at("A");
  EXPECT_NEAR(json_number(j.at("rotation_deg")), -40.0, 0.1);
  const double depth = json_number(joint.at("max_wear_depth_bushing_m"));
  ASSERT_GT(depth, 1e-7) << "the run wore the bore";
  EXPECT_LT(json_number(j.at("rms_difference_m")), 0.02 * depth) << "only chords across kinks remain";
  EXPECT_NEAR(json_number(j.at("max_depth_predicted_m")), depth, 1e-15);
  EXPECT_NEAR(json_number(j.at("max_depth_measured_m")), depth, 0.02 * depth);

  auto         scene  = wl::scene("params/nine_bar_wear.prm");
  const double length = scene.clearance_joints[0]->get_description().geometry.axial_length;
  ASSERT_EQ(scene.clearance_joints[0]->name(), "A");
  const double volume = json_number(joint.at("wear_volume_bushing_m3"));
  EXPECT_NEAR(json_number(j.at("worn_area_predicted_m2")) * length, volume, 1e-3 * volume);
  EXPECT_NEAR(json_number(j.at("worn_area_measured_m2")),
              json_number(j.at("worn_area_predicted_m2")),
              0.01 * volume / length);
  EXPECT_TRUE(std::filesystem::exists(out + "/profile_comparison.png") || !wearlink::io::gnuplot_available());
  EXPECT_EQ(wl::directory_snapshot(run_folder()), before) << "the run's folder is only read";

  // The same folder again: refused (exit 2) without --overwrite, replaced with it.
  const auto again = wl::run_wearlink(compare(measured, out, {"--surface", "bore", "--joint", "A"}));
  EXPECT_EQ(again.exit_status, 2) << again.output;
  EXPECT_NE(again.output.find("Add --overwrite"), std::string::npos) << again.output;
  EXPECT_EQ(wl::run_wearlink(compare(measured, out, {"--surface", "bore", "--joint", "A", "--overwrite"})).exit_status,
            0);
}

TEST(CompareProfile, AProfileAgainstItselfDiffersByNothing)
{
  const auto out = wl::fresh_directory("compare_profile_pin") + "/out";
  const auto r   = wl::run_wearlink(
    compare(run_folder() + "/pin_A.csv", out, {"--surface", "pin", "--joint", "A", "--angle-search", "0"}));
  ASSERT_EQ(r.exit_status, 0) << r.output;
  const Json j = Json::parse(wl::file_content(out + "/profile_comparison.json"));
  EXPECT_EQ(json_number(j.at("rotation_deg")), 0.0);
  EXPECT_EQ(json_number(j.at("rms_difference_m")), 0.0);
  EXPECT_EQ(json_number(j.at("worn_area_difference_m2")), 0.0);
  EXPECT_GT(json_number(j.at("worn_area_predicted_m2")), 0.0) << "the pin lost material";
}

TEST(CompareProfile, BadInputWritesNothing)
{
  const auto in  = wl::fresh_directory("compare_profile_bad");
  const auto out = in + "/out";
  std::ofstream(in + "/nan.csv") << "angle_rad,radius_m\n0,0.012\n1,0.012\n2,nan\n3,0.012\n4,0.012\n5,0.012\n"
                                    "5.5,0.012\n6,0.012\n";
  const auto before = wl::directory_snapshot(run_folder());
  const auto r      = wl::run_wearlink(compare(in + "/nan.csv", out, {"--surface", "bore", "--joint", "A"}));
  EXPECT_EQ(r.exit_status, 2) << r.output;
  EXPECT_NE(r.output.find("line 4, column 'radius_m' is 'nan'"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(out)) << "the folder the command created is removed again";
  const auto missing = wl::run_wearlink({"compare-profile", run_folder(), in + "/nan.csv", "--joint", "A"});
  EXPECT_EQ(missing.exit_status, 2) << missing.output;
  EXPECT_NE(missing.output.find("needs --surface bore|pin and --joint J"), std::string::npos) << missing.output;
  EXPECT_EQ(wl::directory_snapshot(run_folder()), before);
}
