// SPDX-License-Identifier: LGPL-2.1-or-later
// `wearlink lyapunov` end to end: it reads a CSV column, takes dt from a time column,
// prints the exponent with its units and the embedding, writes the plot data, summary
// and plot; bad input exits with status 2, a message naming the file/option and the
// allowed values, and leaves no output files.
#include "base/json.h"
#include "io/json_file.h"
#include "io/plot.h"
#include "support/test_support.h"
#include "unit/analysis/reference_series.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <regex>

namespace ref = wearlink::testing;
using wearlink::testing::files_in;
using wearlink::testing::fresh_directory;
using wearlink::testing::run_wearlink;

namespace
{
  /** Write @p columns (name, values) as CSV into @p file. */
  void
  write_csv(const std::string &file, const std::vector<std::pair<std::string, std::vector<double>>> &columns)
  {
    std::ofstream out(file);
    out << std::setprecision(17);
    for (std::size_t c = 0; c < columns.size(); ++c)
      out << (c ? "," : "") << columns[c].first;
    out << "\n";
    for (std::size_t i = 0; i < columns[0].second.size(); ++i)
      {
        for (std::size_t c = 0; c < columns.size(); ++c)
          out << (c ? "," : "") << columns[c].second[i];
        out << "\n";
      }
  }

  std::vector<double>
  times(const std::size_t n, const double dt)
  {
    std::vector<double> t(n);
    for (std::size_t i = 0; i < n; ++i)
      t[i] = i * dt;
    return t;
  }

  /** The number after "largest Lyapunov exponent" in the report. */
  double
  reported_exponent(const std::string &output)
  {
    std::smatch m;
    if (!std::regex_search(output, m, std::regex("largest Lyapunov exponent ([-0-9.e+]+)")))
      return std::nan("");
    return std::stod(m[1]);
  }
} // namespace

TEST(LyapunovCommand, HenonPerIterationWithOutputs)
{
  // Hénon x_n without a time column: the exponent is per sample (= per iteration);
  // 0.420 within 10 % (see lyapunov_test.cc), and the delay/dimension are printed.
  const std::string dir = fresh_directory("lyapunov_command_henon");
  write_csv(dir + "/henon.csv", {{"x", ref::henon_x(10000)}});
  const auto r = run_wearlink({"lyapunov", dir + "/henon.csv", "--column", "x", "--output", dir + "/out"});
  ASSERT_EQ(r.exit_status, 0) << r.output;
  EXPECT_NEAR(reported_exponent(r.output), 0.420, 0.042) << r.output;
  EXPECT_NE(r.output.find("1/sample (natural log, per sample = per iteration"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("delay tau            1 samples"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("embedding dimension  2"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("fit region"), std::string::npos) << r.output;
  EXPECT_TRUE(std::filesystem::exists(dir + "/out/lyapunov_x_rosenstein.csv"));
  const wearlink::Json summary = wearlink::io::read_json_file(dir + "/out/lyapunov_x_rosenstein.json");
  EXPECT_EQ(summary.at("exponent_unit").get<std::string>(), "1/sample (natural log)");
  EXPECT_EQ(wearlink::json_number(summary.at("embedding_dimension")), 2);
  if (wearlink::io::gnuplot_available())
    {
      EXPECT_TRUE(std::filesystem::exists(dir + "/out/lyapunov_x_rosenstein.png"));
    }
}

TEST(LyapunovCommand, TimeColumnGivesPerSecond)
{
  // Lorenz x with a column t (dt = 0.01 s) and given delay/dimension (18, 3): the Wolf
  // exponent is reported per second, with dt taken from t. 3e4 samples keep the test
  // fast; Wolf's bias at that density is about +10 %, so the bound here is 25 %: the
  // test checks the units and plumbing (a per-sample value would be 100x smaller),
  // accuracy is tested in lyapunov_test.cc.
  const std::string dir = fresh_directory("lyapunov_command_lorenz");
  write_csv(dir + "/lorenz.csv", {{"t", times(30000, 0.01)}, {"x", ref::lorenz_x(30000, 0.01)}});
  const auto r = run_wearlink({"lyapunov",
                               dir + "/lorenz.csv",
                               "--column",
                               "x",
                               "--method",
                               "wolf",
                               "--delay",
                               "18",
                               "--embedding",
                               "3",
                               "--output",
                               dir + "/out"});
  ASSERT_EQ(r.exit_status, 0) << r.output;
  EXPECT_NEAR(reported_exponent(r.output), 0.906, 0.25 * 0.906) << r.output;
  EXPECT_NE(r.output.find("1/s (natural log"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("column 't'"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("given by --delay"), std::string::npos) << r.output;
  std::ifstream csv(dir + "/out/lyapunov_x_wolf.csv");
  std::string   header;
  std::getline(csv, header);
  EXPECT_EQ(header, "evolution_time_s,running_exponent_per_s");
}

TEST(LyapunovCommand, BadInputIsAnInputErrorWithoutOutputs)
{
  // Each case: exit status 2, a message that names the file or option and what is
  // allowed, and an empty output directory (nothing half-written).
  const std::string dir = fresh_directory("lyapunov_command_bad");
  write_csv(dir + "/good.csv", {{"t", times(2000, 0.1)}, {"x", ref::henon_x(2000)}});
  write_csv(dir + "/short.csv", {{"x", ref::henon_x(50)}});
  {
    std::ofstream nan(dir + "/nan.csv");
    nan << "x\n";
    for (int i = 0; i < 500; ++i)
      nan << (i == 321 ? std::string("nan") : std::to_string(std::sin(0.1 * i))) << "\n";
  }
  {
    std::ofstream uneven(dir + "/uneven.csv");
    uneven << "time_s,x\n";
    for (int i = 0; i < 500; ++i)
      uneven << (i < 250 ? 0.01 * i : 0.02 * i) << "," << std::sin(0.1 * i) << "\n";
  }
  struct Case
  {
    std::vector<std::string> args;
    std::string              expected; ///< regex the message must contain
  };
  const std::string       out   = dir + "/out";
  const std::vector<Case> cases = {
    {{"lyapunov", dir + "/missing.csv", "--column", "x"}, "Cannot open the series file '.*missing.csv'"},
    {{"lyapunov", dir + "/good.csv", "--column", "y"}, "has no column 'y'. Its columns are: t, x"},
    {{"lyapunov", dir + "/good.csv"}, "needs --column NAME"},
    {{"lyapunov", dir + "/good.csv", "--column", "x", "--method", "lyap"},
     "Unknown --method 'lyap'. The methods are: rosenstein, wolf"},
    {{"lyapunov", dir + "/short.csv", "--column", "x"}, "has 50 samples; the Lyapunov exponent needs at least 100"},
    {{"lyapunov", dir + "/nan.csv", "--column", "x"}, "line 323, column 'x' is 'nan', not a finite number"},
    {{"lyapunov", dir + "/uneven.csv", "--column", "x"}, "time column 'time_s' is not uniformly sampled"},
    {{"lyapunov", dir + "/good.csv", "--column", "x", "--dt", "-1"}, "--dt .* must be > 0"},
    {{"lyapunov", dir + "/good.csv", "--column", "x", "--embedding", "two"}, "--embedding needs a whole number >= 1"},
    {{"lyapunov", dir + "/good.csv", "--column", "x", "--delay", "0"}, "--delay needs a whole number >= 1"},
    {{"lyapunov", dir + "/good.csv", "--column", "x", "--embedding", "40", "--delay", "60"},
     "Column 'x' of '.*good.csv': .*needs at least"},
  };
  for (const Case &c : cases)
    {
      std::vector<std::string> args = c.args;
      args.insert(args.end(), {"--output", out});
      const auto r = run_wearlink(args);
      EXPECT_EQ(r.exit_status, 2) << r.output;
      EXPECT_TRUE(std::regex_search(r.output, std::regex(c.expected)))
        << "expected /" << c.expected << "/ in: " << r.output;
      EXPECT_TRUE(files_in(out).empty()) << r.output;
    }
}

TEST(LyapunovCommand, HelpExplainsMethodsDefaultsAndUnits)
{
  const auto r = run_wearlink({"lyapunov", "--help"});
  ASSERT_EQ(r.exit_status, 0);
  for (const char *text : {"rosenstein",
                           "wolf",
                           "first minimum of the average mutual",
                           "false nearest neighbours",
                           "Theiler window",
                           "natural-log",
                           "per second",
                           "per sample"})
    EXPECT_NE(r.output.find(text), std::string::npos) << text;
}
