// SPDX-License-Identifier: LGPL-2.1-or-later
// `wearlink compare-signal` end to end on the Flores slider-crank (two crank
// revolutions, 24 ms, sampled every 10 µs). The "measured" signal is the simulation's own
// slider acceleration delayed by a known 0.37 ms (37 samples): measured(t) =
// simulated(t − 0.37 ms). The comparison must find that lag (to one sample), the same
// dominant frequency in both blocks (to a bin) and nearly the same RMS (the comparison
// starts at 0.37 ms, where the delayed copy still holds the run's first impact). Bad input is refused with exit
// status 2, a message naming the file and column, and no output.
#include "base/json.h"
#include "io/plot.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace wl = wearlink::testing;
using wearlink::Json;
using wearlink::json_number;

namespace
{
  constexpr double               lag             = 0.37e-3; // s
  constexpr double               dt              = 1e-5;    // the scene's Time series interval
  const std::string              channel         = "slider_ax_m_s2";
  const std::string              flores_scene    = wl::source_path("params/slider_crank_flores.prm");
  const std::vector<std::string> two_revolutions = {"--set", "Simulation/End time=0.024", "--quiet"};

  std::vector<std::string>
  with_scene_settings(std::vector<std::string> args)
  {
    args.insert(args.end(), two_revolutions.begin(), two_revolutions.end());
    return args;
  }

  /** The run's channel, delayed by `lag`, as a measured file (time_s, accel). */
  std::string
  delayed_measurement(const std::string &run_dir, const std::string &file)
  {
    std::ifstream in(run_dir + "/time_series.csv");
    std::string   line;
    std::getline(in, line);
    std::size_t column = 0;
    for (std::size_t start = 0, k = 0;; ++k)
      {
        const auto comma = line.find(',', start);
        if (line.substr(start, comma - start) == channel)
          column = k;
        if (comma == std::string::npos)
          break;
        start = comma + 1;
      }
    std::ofstream out(file);
    out << "time_s,accel\n" << std::setprecision(12);
    while (std::getline(in, line))
      {
        std::stringstream fields(line);
        std::string       field;
        double            t = 0, v = 0;
        for (std::size_t k = 0; std::getline(fields, field, ','); ++k)
          {
            if (k == 0)
              t = std::stod(field);
            if (k == column)
              v = std::stod(field);
          }
        out << t + lag << "," << v << "\n";
      }
    return file;
  }

  void
  expect_recovered_lag(const std::string &out)
  {
    const Json j = Json::parse(wl::file_content(out + "/signal_comparison.json"));
    EXPECT_NEAR(json_number(j.at("lag_s")), lag, dt);
    EXPECT_GT(json_number(j.at("correlation_at_lag")), 0.9);
    const Json &s = j.at("simulated"), &m = j.at("measured");
    for (const char *key : {"dominant_frequency_Hz", "peak_per_cycle", "rms"})
      {
        EXPECT_TRUE(s.contains(key)) << key;
        EXPECT_TRUE(m.contains(key)) << key;
      }
    const double bin = 1 / (json_number(j.at("grid").at("dt_s")) * json_number(j.at("grid").at("samples")));
    EXPECT_NEAR(json_number(m.at("dominant_frequency_Hz")), json_number(s.at("dominant_frequency_Hz")), bin);
    // The copy starts 0.37 ms late: on the common grid it holds the run's first impact
    // (-3e5 m/s² at 0.2 ms), the simulated signal does not (measured: 9 % more RMS).
    EXPECT_NEAR(json_number(m.at("rms")), json_number(s.at("rms")), 0.25 * json_number(s.at("rms")));
    EXPECT_EQ(s.at("peak_per_cycle").size(), 1u); // 24 ms − 0.37 ms hold one whole 12 ms cycle
    if (wearlink::io::gnuplot_available())
      {
        for (const char *png : {"signal_overlay.png", "signal_spectrum.png"})
          EXPECT_EQ(wl::file_content(out + "/" + png).compare(0, 4, "\x89PNG"), 0) << png;
      }
  }
} // namespace

TEST(CompareSignal, RecoversTheLagOfTheSimulationsOwnSignalDelayed)
{
  const std::string dir = wl::fresh_directory("compare_signal");
  const auto        run = wl::run_wearlink(
    with_scene_settings({"run", flores_scene, "--output", dir + "/run", "--set", "Output/Plots=false"}));
  ASSERT_EQ(run.exit_status, 0) << run.output;
  const std::string measured = delayed_measurement(dir + "/run", dir + "/measured.csv");

  // From the finished run (--simulated).
  const auto read = wl::run_wearlink(with_scene_settings({"compare-signal",
                                                          flores_scene,
                                                          measured,
                                                          "--channel",
                                                          channel,
                                                          "--simulated",
                                                          dir + "/run",
                                                          "--output",
                                                          dir + "/read"}));
  ASSERT_EQ(read.exit_status, 0) << read.output;
  EXPECT_NE(read.output.find("dominant frequency [Hz]"), std::string::npos) << read.output;
  expect_recovered_lag(dir + "/read");

  // Running the scene itself (into OUTPUT/simulated/).
  const auto ran = wl::run_wearlink(
    with_scene_settings({"compare-signal", flores_scene, measured, "--channel", channel, "--output", dir + "/ran"}));
  ASSERT_EQ(ran.exit_status, 0) << ran.output;
  EXPECT_TRUE(std::filesystem::exists(dir + "/ran/simulated/time_series.csv"));
  expect_recovered_lag(dir + "/ran");

  // The folder of an earlier comparison is refused (exit 2, nothing replaced) unless
  // --overwrite, which removes the command's files (also the simulated/ folder).
  const std::vector<std::string>
             again{"compare-signal", flores_scene, measured, "--channel", channel, "--output", dir + "/ran"};
  const auto refused = wl::run_wearlink(with_scene_settings(again));
  EXPECT_EQ(refused.exit_status, 2) << refused.output;
  EXPECT_NE(refused.output.find("signal_comparison.json"), std::string::npos) << refused.output;
  auto overwrite = again;
  overwrite.push_back("--overwrite");
  const auto replaced = wl::run_wearlink(with_scene_settings(overwrite));
  ASSERT_EQ(replaced.exit_status, 0) << replaced.output;
  expect_recovered_lag(dir + "/ran");
}

TEST(CompareSignal, BadInputIsRefusedBeforeAnythingIsWritten)
{
  const std::string dir  = wl::fresh_directory("compare_signal_bad");
  const std::string good = dir + "/good.csv", back = dir + "/back_in_time.csv", nan = dir + "/nan.csv";
  {
    std::ofstream g(good), b(back), n(nan);
    g << "time_s,accel\n";
    b << "time_s,accel\n";
    n << "time_s,accel\n";
    for (int i = 0; i < 100; ++i)
      {
        g << i * 1e-4 << "," << i << "\n";
        b << (i == 50 ? 1e-4 : i * 1e-4) << "," << i << "\n";
        n << i * 1e-4 << "," << (i == 70 ? "NaN" : std::to_string(i)) << "\n";
      }
  }
  struct Case
  {
    std::vector<std::string> args;
    std::vector<std::string> expected;
  };
  const std::vector<Case> cases = {
    {{dir + "/missing.csv", "--channel", channel}, {dir + "/missing.csv"}},
    {{good, "--channel", channel, "--column", "force"}, {good, "'force'"}},
    {{good, "--channel", "slider_jerk"}, {"--channel 'slider_jerk'", "slider_ax_m_s2"}},
    {{back, "--channel", channel}, {back, "'time_s'", "line 52"}},
    {{nan, "--channel", channel}, {nan, "column 'accel'", "line 72"}},
    {{good, "--channel", channel, "--simulated", dir + "/no_run"}, {dir + "/no_run"}},
  };
  for (std::size_t k = 0; k < cases.size(); ++k)
    {
      const std::string        out = dir + "/out" + std::to_string(k);
      std::vector<std::string> args{"compare-signal", flores_scene};
      args.insert(args.end(), cases[k].args.begin(), cases[k].args.end());
      args.insert(args.end(), {"--output", out});
      const auto r = wl::run_wearlink(with_scene_settings(args));
      EXPECT_EQ(r.exit_status, 2) << k << ": " << r.output;
      for (const auto &e : cases[k].expected)
        EXPECT_NE(r.output.find(e), std::string::npos) << k << ": expected '" << e << "' in " << r.output;
      EXPECT_FALSE(std::filesystem::exists(out)) << k << ": " << out << " was created";
    }
}
