// SPDX-License-Identifier: LGPL-2.1-or-later
// The first look of `wearlink run` (workflows/run/first_look.h) on the Flores slider-crank,
// one crank revolution (12 ms at 5000 rpm): the orbit of its clearance joint B, the
// contact forces and the slider's acceleration (the default plot body: the body on the
// translational joint) are written as PNGs; the printed summary carries the numbers of
// summary.json (to its 6 printed digits); Output/Plots = false writes no PNG; without
// gnuplot on PATH the run warns and succeeds.
#include "base/json.h"
#include "io/plot.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <regex>

namespace wl = wearlink::testing;

namespace
{
  const std::vector<std::string> one_revolution = {"--set", "Simulation/End time=0.012", "--quiet"};

  wl::ProgramResult
  run_flores(const std::string &dir, const std::vector<std::string> &extra = {})
  {
    std::vector<std::string> args{"run", wl::source_path("params/slider_crank_flores.prm"), "--output", dir};
    args.insert(args.end(), one_revolution.begin(), one_revolution.end());
    args.insert(args.end(), extra.begin(), extra.end());
    return wl::run_wearlink(args);
  }

  bool
  is_png(const std::string &path)
  {
    const std::string content = wl::file_content(path);
    return content.size() > 1000 && content.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0;
  }

  /** The number printed after @p label in @p text (NaN if absent). */
  double
  printed(const std::string &text, const std::string &label)
  {
    std::smatch m;
    if (!std::regex_search(text, m, std::regex(label + " ([-+0-9.eE]+)")))
      return std::nan("");
    return std::stod(m[1]);
  }

  void
  expect_printed(const std::string &text, const std::string &label, const wearlink::Json &value)
  {
    const double v = wearlink::json_number(value);
    EXPECT_NEAR(printed(text, label), v, 1e-5 * std::abs(v) + 1e-300) << label << "\n" << text;
  }
} // namespace

TEST(FirstLook, RunWritesPngsAndASummaryWithTheNumbersOfSummaryJson)
{
  if (!wearlink::io::gnuplot_available())
    GTEST_SKIP() << "gnuplot is not installed";
  const std::string dir = wl::fresh_directory("first_look");
  const auto        r   = run_flores(dir);
  ASSERT_EQ(r.exit_status, 0) << r.output;
  for (const char *png : {"orbit_B.png", "contact_forces.png", "accelerations.png"})
    {
      EXPECT_TRUE(is_png(dir + "/" + png)) << png;
      EXPECT_NE(r.output.find(dir + "/" + png), std::string::npos) << "not listed: " << png << "\n" << r.output;
    }
  for (const char *file : {"summary.json", "time_series.csv", "parameters.prm"})
    EXPECT_NE(r.output.find(dir + "/" + file), std::string::npos) << "not listed: " << file << "\n" << r.output;

  const auto  summary = wearlink::Json::parse(wl::file_content(dir + "/summary.json"));
  const auto &b       = summary.at("clearance_joints").at("B");
  expect_printed(r.output, "joint B: contact fraction", b.at("fraction_in_contact"));
  expect_printed(r.output, "peak normal force", b.at("max_normal_force_N"));
  expect_printed(r.output, "peak friction force", b.at("max_friction_force_N"));
  expect_printed(r.output, "impacts", b.at("impacts"));
  const auto &slider = summary.at("bodies").at("slider");
  expect_printed(r.output, "body slider: peak acceleration \\|a_x\\|", slider.at("max_abs_ax_m_s2"));
  expect_printed(r.output, "m/s², \\|a_y\\|", slider.at("max_abs_ay_m_s2"));
  EXPECT_GT(wearlink::json_number(b.at("max_normal_force_N")), 0); // the joint does hit
}

TEST(FirstLook, PlotsFalseWritesNoPngButStillTheSummary)
{
  const std::string dir = wl::fresh_directory("first_look_off");
  const auto        r   = run_flores(dir, {"--set", "Output/Plots=false"});
  ASSERT_EQ(r.exit_status, 0) << r.output;
  for (const auto &f : wl::files_in(dir))
    EXPECT_EQ(f.find(".png"), std::string::npos) << f;
  EXPECT_NE(r.output.find("joint B: contact fraction"), std::string::npos) << r.output;
}

TEST(FirstLook, AnUnknownPlotBodyIsRefused)
{
  const std::string dir = wl::fresh_directory("first_look_bad_body");
  const auto        r   = run_flores(dir, {"--set", "Output/Plot bodies=crank, piston"});
  EXPECT_EQ(r.exit_status, 2) << r.output;
  EXPECT_NE(r.output.find("'piston' is not a moving body"), std::string::npos) << r.output;
}

TEST(FirstLook, WithoutGnuplotTheRunWarnsAndSucceeds)
{
  const std::string dir = wl::fresh_directory("first_look_no_gnuplot");
  const std::string cmd = "env PATH=/nonexistent '" + std::string(WEARLINK_BINARY) + "' run '" +
                          wl::source_path("params/slider_crank_flores.prm") + "' --output '" + dir +
                          "' --set 'Simulation/End time=0.012' --quiet 2>&1";
  FILE       *pipe = ::popen(cmd.c_str(), "r");
  std::string out;
  char        buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, pipe)) > 0;)
    out.append(buf, n);
  const int status = ::pclose(pipe);
  EXPECT_EQ(WEXITSTATUS(status), 0) << out;
  EXPECT_NE(out.find("gnuplot is not installed"), std::string::npos) << out;
  for (const auto &f : wl::files_in(dir))
    EXPECT_EQ(f.find(".png"), std::string::npos) << f;
}
