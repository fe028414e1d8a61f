// SPDX-License-Identifier: LGPL-2.1-or-later
// The before/after comparison of workflows/compare/dynamics_comparison.h on series whose answer is
// known:
//  - the Lorenz flow run twice as fast (the same orbit, time stamps halved) has twice
//    the exponent per second, so after/before must come out near 2 for both methods
//    when the common delay is given in seconds (the faster run gets the same delay in
//    seconds, i.e. half the flow time);
//  - the same flow recorded at two sample intervals has the same exponent per second
//    (after/before near 1): the common delay is converted to each run's samples;
//  - a run compared with itself gives exactly 1 everywhere and writes the files;
//  - a channel missing from one run is an InputError before anything is written.
#include "analysis/analyses_parameters.h"
#include "base/exceptions.h"
#include "io/plot.h"
#include "support/test_support.h"
#include "unit/analysis/reference_series.h"
#include "workflows/compare/dynamics_comparison.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>

namespace ref = wearlink::testing;
using wearlink::InputError;
using wearlink::analysis::LyapunovMethod;
using wearlink::analysis::RecordedRun;
using namespace wearlink::workflows;
using wearlink::json_number;

namespace
{
  /** A run whose joint "A" has the series @p x as its e_x channel, sampled every dt. */
  ComparedRun
  run_of(const std::vector<double> &x, const double dt, const std::string &label)
  {
    ComparedRun r;
    r.run.label           = label;
    r.run.sample_interval = dt;
    r.run.series.names    = {"A_ex_m"};
    r.run.series.units    = {"m"};
    r.run.series.values   = {x};
    for (std::size_t i = 0; i < x.size(); ++i)
      r.run.series.time.push_back(i * dt);
    return r;
  }

  DynamicsComparisonSettings
  lorenz_settings()
  {
    DynamicsComparisonSettings s;
    s.joints     = {"A"};
    s.directions = {"x"};
    s.methods    = {LyapunovMethod::wolf, LyapunovMethod::rosenstein};
    s.delay      = 0.1; // [s]: 10 samples of Lorenz at dt 0.01, near its mutual-information delay
    s.dimension  = 3;
    return s;
  }

  constexpr double lorenz_exponent = 0.906; // per time unit (doc/models.md §6.3)
} // namespace

TEST(DynamicsComparison, LorenzRunTwiceAsFastHasTwiceTheExponentPerSecond)
{
  const auto before = run_of(ref::lorenz_x(30000, 0.01), 0.01, "Lorenz");
  // 0.02 time units of the flow between samples, stamped 0.01 s apart: twice as fast.
  const auto  after = run_of(ref::lorenz_x(30000, 0.02), 0.01, "Lorenz twice as fast");
  const auto  c     = compare_dynamics(before, after, lorenz_settings(), "");
  const auto &l     = c.json.at("lyapunov");
  ASSERT_EQ(l.size(), 2u);
  for (std::size_t k = 0; k < l.size(); ++k)
    {
      const double b = json_number(l[k].at("before_per_s")), a = json_number(l[k].at("after_per_s"));
      SCOPED_TRACE(l[k].at("method").get<std::string>());
      std::cout << "  " << l[k].at("method").get<std::string>() << ": before " << b << " 1/s, after " << a
                << " 1/s, after/before " << a / b << " (expected 2)\n";
      // Each estimate is within 10 % of the reference on Lorenz (lyapunov_test.cc), so the
      // ratio is within about 20 % of 2.
      EXPECT_NEAR(b, lorenz_exponent, 0.15 * lorenz_exponent);
      EXPECT_NEAR(a / b, 2.0, 0.4);
      EXPECT_DOUBLE_EQ(json_number(l[k].at("delay_s")), 0.1);
      EXPECT_TRUE(l[k].at("before_resolved").get<bool>());
      EXPECT_TRUE(l[k].at("after_resolved").get<bool>());
    }
}

TEST(DynamicsComparison, SameFlowAtTwoSampleIntervalsGivesTheSameExponentPerSecond)
{
  const auto  before = run_of(ref::lorenz_x(30000, 0.01), 0.01, "dt 0.01");
  const auto  after  = run_of(ref::lorenz_x(60000, 0.005), 0.005, "dt 0.005");
  const auto  c      = compare_dynamics(before, after, lorenz_settings(), "");
  const auto &l      = c.json.at("lyapunov");
  ASSERT_EQ(l.size(), 2u);
  for (std::size_t k = 0; k < l.size(); ++k)
    {
      SCOPED_TRACE(l[k].at("method").get<std::string>());
      std::cout << "  " << l[k].at("method").get<std::string>() << ": after/before "
                << json_number(l[k].at("after_per_s")) / json_number(l[k].at("before_per_s")) << " (expected 1)\n";
      EXPECT_NEAR(json_number(l[k].at("after_per_s")) / json_number(l[k].at("before_per_s")), 1.0, 0.2);
      // Per sample, the finer run's exponent is half the coarser one's.
      EXPECT_NEAR(json_number(l[k].at("after_per_sample")) / json_number(l[k].at("before_per_sample")), 0.5, 0.1);
    }
}

TEST(DynamicsComparison, ARunComparedWithItselfGivesOneEverywhereAndWritesTheFiles)
{
  auto run = run_of(ref::lorenz_x(8000, 0.01), 0.01, "self");
  // Velocities for the phase portrait, and a summary for the indicators.
  std::vector<double> v(run.run.series.values[0].size());
  for (std::size_t i = 1; i + 1 < v.size(); ++i)
    v[i] = (run.run.series.values[0][i + 1] - run.run.series.values[0][i - 1]) / 0.02;
  run.run.series.names.push_back("A_vex_m_s");
  run.run.series.units.push_back("m/s");
  run.run.series.values.push_back(v);
  run.run.driving_period = 1.0;
  run.summary            = wearlink::Json::parse(
    R"({"simulated_time_s": 80, "clearance_joints": {"A": {"impacts": 400, "fraction_in_contact": 0.5,
        "max_normal_force_N": 1000}}})");
  auto s                = lorenz_settings();
  s.delay_scan          = {0.05, 0.1, 0.2};
  s.published           = wearlink::analysis::parse_published_exponents("A_ex_m: 0.041 0.076", "test");
  const std::string dir = wearlink::testing::fresh_directory("dynamics_comparison_self");
  const auto        c   = compare_dynamics(run, run, s, dir);
  const auto       &l   = c.json.at("lyapunov");
  for (std::size_t k = 0; k < l.size(); ++k)
    EXPECT_EQ(json_number(l[k].at("after_per_s")), json_number(l[k].at("before_per_s")));
  const auto &scan = c.json.at("delay_scan");
  EXPECT_EQ(scan.size(), 6u); // 3 delays x 2 methods
  for (std::size_t k = 0; k < scan.size(); ++k)
    EXPECT_EQ(json_number(scan[k].at("after_per_s")), json_number(scan[k].at("before_per_s")));
  EXPECT_DOUBLE_EQ(json_number(c.json.at("indicators").at("A_impacts_per_period").at("before")), 5.0);
  for (const char *f : {"before_after.md", "before_after_lyapunov.csv", "before_after_delay_scan.csv"})
    EXPECT_TRUE(std::filesystem::exists(dir + "/" + f)) << f;
  if (wearlink::io::gnuplot_available())
    {
      EXPECT_TRUE(std::filesystem::exists(dir + "/before_after_phase_A_x.png"));
      EXPECT_TRUE(std::filesystem::exists(dir + "/before_after_delay_scan.png"));
    }
  EXPECT_NE(c.report.find("0.076"), std::string::npos) << "published values printed";
}

TEST(DynamicsComparison, AChannelMissingFromOneRunIsAnErrorAndWritesNothing)
{
  const auto before      = run_of(ref::lorenz_x(5000, 0.01), 0.01, "before");
  auto       after       = before;
  after.run.series.names = {"B_ex_m"};
  const std::string dir  = wearlink::testing::fresh_directory("dynamics_comparison_missing") + "/out";
  EXPECT_THROW(compare_dynamics(before, after, lorenz_settings(), dir), InputError);
  EXPECT_FALSE(std::filesystem::exists(dir));
  // A common delay shorter than a sample interval cannot be embedded.
  auto s  = lorenz_settings();
  s.delay = 0.001;
  EXPECT_THROW(compare_dynamics(before, before, s, dir), InputError);
  EXPECT_FALSE(std::filesystem::exists(dir));
}

TEST(PublishedExponents, ParsesPairsAndRejectsMalformedText)
{
  const auto p = wearlink::analysis::parse_published_exponents("A_ex_m: 0.041 0.076, B_ex_m: 0.030 0.052", "x");
  ASSERT_EQ(p.size(), 2u);
  EXPECT_EQ(p[1].channel, "B_ex_m");
  EXPECT_DOUBLE_EQ(p[1].before, 0.030);
  EXPECT_DOUBLE_EQ(p[1].after, 0.052);
  EXPECT_TRUE(wearlink::analysis::parse_published_exponents("", "x").empty());
  for (const char *bad : {"A_ex_m 0.041 0.076", "A_ex_m: 0.041", "A_ex_m: 0.041 0.076 9", ": 1 2", "A: x y"})
    EXPECT_THROW(wearlink::analysis::parse_published_exponents(bad, "x"), InputError) << bad;
}
