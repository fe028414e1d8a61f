// SPDX-License-Identifier: LGPL-2.1-or-later
// Ensembles: `wearlink run SCENE --ensemble N --seed S` of a wear scene
// (params/nine_bar_wear.prm cut to 1 wear iteration of 1 cycle × 500, hertz-strip, so
// that a member takes about a second).
//  - Independent of the rank count and reproducible: the same seed on 1 and on 2 MPI
//    ranks gives the same statistics to the last bit (a member's perturbation depends on
//    the seed and its index only, and its run on nothing else); a member's figures are
//    those of its own summary.json.
//  - The perturbation reaches the chaos: the members' worn volumes differ (a standard
//    deviation > 0.1 % of the mean; measured 1–4 %), and another seed gives other
//    statistics.
//  - The statistics are the textbook ones: mean of the members, sample standard
//    deviation, 95 % interval of the mean with Student's t for 3 members,
//    t(0.975, 2) = 4.303 (table value, to its 3 decimals); P05 / P50 / P95 of the
//    members' figures by type-7 interpolation, identical on 1 and 2 ranks.
//  - A life ensemble (`life --ensemble 4` of tests/scenes/life_journal.prm, ~1 s a member)
//    gives the same `ensemble_life` on 1 and 2 ranks; its percentiles are those of the
//    members' own summaries (type 7: P10 = x₁ + 0.3 (x₂ − x₁) for 4 members), its life is
//    the pin's mass loss at the analytic revolutions, and life.png is drawn.
#include "base/json.h"
#include "base/output_directory.h"
#include "io/json_file.h"
#include "support/test_support.h"
#include "workflows/ensemble/ensemble.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <unistd.h>

using namespace wearlink;
using namespace wearlink::testing;

namespace
{
  std::vector<std::string>
  ensemble_args(const std::string &dir, const std::string &seed)
  {
    return {"run",
            source_path("params/nine_bar_wear.prm"),
            "--ensemble",
            "3",
            "--seed",
            seed,
            "--output",
            dir,
            "--quiet",
            "--set",
            "Wear/Number of iterations=1",
            "--set",
            "Wear/Cycles per iteration=1",
            "--set",
            "Wear/Response cycles=1"};
  }
} // namespace

TEST(Ensemble, SeededStatisticsAreReproducibleAndIndependentOfTheRankCount)
{
  if (std::string(WEARLINK_MPIEXEC).empty())
    GTEST_SKIP() << "no mpiexec";
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  const std::string serial = fresh_directory("ensemble_serial"), parallel = fresh_directory("ensemble_mpi"),
                    other = fresh_directory("ensemble_other_seed");
  const auto r1           = run_wearlink(ensemble_args(serial, "11"));
  ASSERT_EQ(r1.exit_status, 0) << r1.output;
  const auto r2 = run_wearlink_mpi(2, ensemble_args(parallel, "11"));
  ASSERT_EQ(r2.exit_status, 0) << r2.output;
  const auto r3 = run_wearlink(ensemble_args(other, "12"));
  ASSERT_EQ(r3.exit_status, 0) << r3.output;

  const Json a = io::read_json_file(serial + "/summary.json"), b = io::read_json_file(parallel + "/summary.json"),
             c = io::read_json_file(other + "/summary.json");
  EXPECT_EQ(json_number(b.at("mpi_ranks")), 2);
  EXPECT_EQ(json_number(b.at("members")[1].at("rank")), 1) << "member 1 ran on rank 1";
  EXPECT_EQ(a.at("ensemble"), b.at("ensemble")) << "1 rank and 2 ranks disagree";
  EXPECT_EQ(file_content(serial + "/member_01/summary.json").empty(), false);

  const std::string volume = "A_wear_volume_bushing_m3";
  const Json       &f      = a.at("ensemble").at(volume);
  ASSERT_EQ(json_number(f.at("members")), 3);
  std::vector<double> v;
  for (const char *m : {"member_00", "member_01", "member_02"})
    v.push_back(json_number(io::read_json_file(serial + "/" + m + "/summary.json")
                              .at("clearance_joints")
                              .at("A")
                              .at("wear_volume_bushing_m3")));
  const double mean = (v[0] + v[1] + v[2]) / 3;
  const double s =
    std::sqrt(((v[0] - mean) * (v[0] - mean) + (v[1] - mean) * (v[1] - mean) + (v[2] - mean) * (v[2] - mean)) / 2);
  EXPECT_NEAR(json_number(f.at("mean")), mean, 1e-14 * mean);
  std::sort(v.begin(), v.end()); // 3 members: P05 = x₁ + 0.1 (x₂ − x₁), P50 = x₂, P95 = x₂ + 0.9 (x₃ − x₂)
  EXPECT_DOUBLE_EQ(json_number(f.at("p05")), v[0] + 0.1 * (v[1] - v[0]));
  EXPECT_DOUBLE_EQ(json_number(f.at("p50")), v[1]);
  EXPECT_DOUBLE_EQ(json_number(f.at("p95")), v[1] + 0.9 * (v[2] - v[1]));
  EXPECT_NEAR(json_number(f.at("std")), s, 1e-12 * mean);
  EXPECT_NEAR(json_number(f.at("ci95_high")) - mean, 4.303 * s / std::sqrt(3.0), 5e-4 * s / std::sqrt(3.0));
  EXPECT_GT(s, 1e-3 * mean) << "the members did not part: the perturbation does not reach the dynamics";
  EXPECT_NE(json_number(c.at("ensemble").at(volume).at("mean")), mean) << "another seed, the same members";
}

namespace
{
  std::vector<std::string>
  life_ensemble_args(const std::string &dir)
  {
    return {"life",
            source_path("tests/scenes/life_journal.prm"),
            "--ensemble",
            "4",
            "--seed",
            "5",
            "--output",
            dir,
            "--quiet"};
  }

  using wearlink::testing::type7;
} // namespace

TEST(Ensemble, LifeStatisticsAreTheSameOnOneAndTwoRanks)
{
  if (std::string(WEARLINK_MPIEXEC).empty())
    GTEST_SKIP() << "no mpiexec";
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  const std::string serial = fresh_directory("life_ensemble_serial"), parallel = fresh_directory("life_ensemble_mpi");
  const auto        r1 = run_wearlink(life_ensemble_args(serial));
  ASSERT_EQ(r1.exit_status, 0) << r1.output;
  const auto r2 = run_wearlink_mpi(2, life_ensemble_args(parallel));
  ASSERT_EQ(r2.exit_status, 0) << r2.output;
  const Json a = io::read_json_file(serial + "/summary.json"), b = io::read_json_file(parallel + "/summary.json");
  EXPECT_EQ(json_number(b.at("mpi_ranks")), 2);
  EXPECT_EQ(a.at("ensemble_life"), b.at("ensemble_life")) << "1 rank and 2 ranks disagree";
  EXPECT_EQ(a.at("ensemble"), b.at("ensemble"));

  const Json &life = a.at("ensemble_life");
  ASSERT_EQ(life.at("criterion").get<std::string>(), "pin_mass_loss") << life.at("reason");
  EXPECT_EQ(json_number(life.at("members_decided")), 4);
  std::vector<double> n;
  for (int k = 0; k < 4; ++k)
    n.push_back(json_number(io::read_json_file(serial + "/member_0" + std::to_string(k) + "/summary.json")
                              .at("life")
                              .at("criteria")
                              .at("pin_mass_loss")
                              .at("revolutions")));
  EXPECT_DOUBLE_EQ(json_number(life.at("p10_revolutions")), type7(n, 0.1));
  EXPECT_DOUBLE_EQ(json_number(life.at("p50_revolutions")), type7(n, 0.5));
  EXPECT_DOUBLE_EQ(json_number(life.at("p90_revolutions")), type7(n, 0.9));
  EXPECT_NEAR(json_number(life.at("p10_hours")), type7(n, 0.1) * 0.2 / 3600, 1e-12) << "T = 0.2 s per revolution";
  // The analytic life of the pin's 10 mg (the scene's header), within its 1 % tolerance.
  const double analytic = 1e-5 / (7850 * 2e-13 * 98.1 * 2 * 3.14159265358979 * 0.00995);
  EXPECT_NEAR(json_number(life.at("p50_revolutions")), analytic, 0.01 * analytic);
  const Json &bushing = life.at("criteria").at("bushing_mass_loss");
  EXPECT_LE(json_number(bushing.at("revolutions").at("p10")), json_number(bushing.at("revolutions").at("p90")));
  EXPECT_TRUE(std::filesystem::exists(serial + "/life.png")) << "the ensemble's band of the criteria";
  EXPECT_TRUE(std::filesystem::exists(serial + "/life_cdf.png")) << "the CDF of the decided criteria's revolutions";
  const Json &pin = life.at("criteria").at("pin_mass_loss").at("revolutions");
  EXPECT_DOUBLE_EQ(json_number(pin.at("p05")), type7(n, 0.05));
  EXPECT_DOUBLE_EQ(json_number(pin.at("p95")), type7(n, 0.95));
  EXPECT_NE(r1.output.find("ensemble life: pin_mass_loss, P10"), std::string::npos) << r1.output;
}

// The ensemble's life from its members' records (workflows::ensemble_life, no run): the
// response rise crosses early in 3 members (10, 20, 30 rev) but one left it undecided, so
// it is not a life of the ensemble; the wear depth, decided by all 4 at 100, 110, 120, 130
// rev, is: P10 = 100 + 0.3 × 10 = 103, P50 = 115, P90 = 127 (type 7), mean 115 with the
// 95 % interval 115 ± t(0.975, 3) s/2, s = √(500/3). A failed member does not count.
TEST(Ensemble, AnUndecidedCriterionIsNotTheLifeOfTheEnsemble)
{
  std::vector<Json> members;
  const double      depth[] = {100, 110, 120, 130}, response[] = {10, 20, 30, NAN};
  for (int k = 0; k < 4; ++k)
    {
      const bool decided = std::isfinite(response[k]);
      Json       life    = {{"criteria",
                             {{"wear_depth", {{"status", "decided"}, {"revolutions", depth[k]}, {"hours", depth[k] / 7200}}},
                              {"response_rise",
                               {{"status", decided ? "decided" : "undecided"},
                                {"revolutions", decided ? Json(response[k]) : Json()},
                                {"hours", decided ? Json(response[k] / 7200) : Json()}}}}},
                            {"headline", decided ? "response_rise" : "wear_depth"}};
      members.push_back({{"status", "ok"}, {"life", life}});
    }
  members.push_back({{"status", "failed"}});
  const Json e = workflows::ensemble_life(members);
  EXPECT_EQ(json_number(e.at("members")), 4);
  ASSERT_EQ(e.at("criterion").get<std::string>(), "wear_depth") << e.at("reason");
  EXPECT_DOUBLE_EQ(json_number(e.at("p10_revolutions")), 103);
  EXPECT_DOUBLE_EQ(json_number(e.at("p50_revolutions")), 115);
  EXPECT_DOUBLE_EQ(json_number(e.at("p90_revolutions")), 127);
  EXPECT_DOUBLE_EQ(json_number(e.at("p10_hours")), 103.0 / 7200);
  EXPECT_NEAR(json_number(e.at("ci95_mean_revolutions")[1]) - 115, 3.182446 * std::sqrt(500.0 / 3) / 2, 1e-4);
  const Json &r = e.at("criteria").at("response_rise");
  EXPECT_EQ(json_number(r.at("members_decided")), 3);
  EXPECT_EQ(json_number(r.at("members_undecided")), 1);
  EXPECT_DOUBLE_EQ(json_number(r.at("revolutions").at("p10")), 12) << "over the members that decided it";
  EXPECT_NE(e.at("reason").get<std::string>().find("response_rise was decided by 3 of 4"), std::string::npos)
    << e.at("reason");
}

namespace
{
  /**
   * Four members' life records whose response measure steps from 600 to 900 m/s² (+50 %,
   * the limit 25 %) between 20,000 and 25,000 rev, each with its own scatter of ±150 m/s²
   * (members leave the criterion undecided one by one), measured every 5,000 rev up to
   * 75,000 and once more at a revolutions of its own; the wear depth decided at @p wear.
   */
  std::vector<Json>
  stepping_members(const double wear)
  {
    std::vector<Json> members;
    for (int k = 0; k < 4; ++k)
      {
        Json rev = Json::array(), measure = Json::array();
        for (int i = 0; i <= 16; ++i)
          {
            const double at = i < 16 ? 5000.0 * i : 76000 + 100 * k;
            rev.push_back(at);
            measure.push_back((at < 22500 ? 600 : 900) + 150 * std::sin(12.9898 * (i + 1) * (k + 1)));
          }
        Json life = {{"criteria",
                      {{"wear_depth",
                        {{"status", "decided"}, {"revolutions", wear + 1000 * k}, {"hours", wear / 7200}}},
                       {"response_rise",
                        {{"status", "undecided"},
                         {"revolutions", Json()},
                         {"hours", Json()},
                         {"located_by", "trend"},
                         {"limit", 25.0},
                         {"response_tolerance", 0.5}}}}},
                     {"headline", "wear_depth"},
                     {"response", {{"revolutions", rev}, {"measures_m_s2", measure}}}};
        members.push_back({{"status", "ok"}, {"life", life}});
      }
    return members;
  }
} // namespace

// A trend criterion no member decides alone is decided on the trend of the members' mean
// response (the scatter falls by √4): here the step between 20,000 and 25,000 rev, whose
// interval ends long before the wear depth's P10 (100,300 rev), so it is the ensemble's
// life; the members' own counts stay as they were.
TEST(Ensemble, TheMembersMeanResponseDecidesWhatNoMemberCanAlone)
{
  const Json e = workflows::ensemble_life(stepping_members(100000));
  ASSERT_EQ(e.at("criterion").get<std::string>(), "response_rise") << e.at("reason");
  EXPECT_EQ(e.at("located_by").get<std::string>(), "trend of the members' mean response");
  const double at = json_number(e.at("revolutions"));
  EXPECT_GE(at, 20000);
  EXPECT_LE(at, 25000);
  const Json &i = e.at("interval_revolutions");
  ASSERT_TRUE(i.is_array());
  EXPECT_LE(json_number(i[0]), at);
  EXPECT_GE(json_number(i[1]), at);
  EXPECT_LT(json_number(i[1]), 100000);
  EXPECT_EQ(json_number(e.at("members_decided")), 0);
  EXPECT_EQ(json_number(e.at("criteria").at("response_rise").at("trend_of_the_mean").at("measurements")), 16)
    << "the revolutions every member measured";
}

// The same members worn out at 10,000 rev: the mean's rise comes after the wear depth's
// P10, so the wear depth stays the ensemble's life; the mean's trend is reported.
TEST(Ensemble, TheMembersMeanResponseAfterTheWearLifeIsNotTheLife)
{
  const Json e = workflows::ensemble_life(stepping_members(10000));
  ASSERT_EQ(e.at("criterion").get<std::string>(), "wear_depth") << e.at("reason");
  EXPECT_DOUBLE_EQ(json_number(e.at("p10_revolutions")), 10300);
  EXPECT_FALSE(e.at("criteria").at("response_rise").at("trend_of_the_mean").is_null());
}

// An ensemble on 2 ranks into a folder locked by another process: rank 0 is refused,
// rank 1 receives the refusal, both stop with exit status 2 (none waits for the other)
// and no member runs.
TEST(Ensemble, OnTwoRanksALockedFolderStopsEveryRank)
{
  if (std::string(WEARLINK_MPIEXEC).empty())
    GTEST_SKIP() << "no mpiexec";
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  const std::string dir = fresh_directory("ensemble_locked");
  OutputDirectory   held(dir, EarlierRun::resume, {}, "");
  const auto        r = run_wearlink_mpi(2, ensemble_args(dir, "1"));
  EXPECT_EQ(r.exit_status, 2) << r.output;
  EXPECT_NE(r.output.find("is in use by another wearlink run (pid " + std::to_string(::getpid())), std::string::npos)
    << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir + "/member_00"));
}

// A plain run (no --ensemble) started on 2 ranks: every rank would run the same scene
// into the same folder (rank 1 was refused "in use" by rank 0's lock, a message about a
// folder, not about the launch). Each rank says at once that the command is serial; no
// folder is written.
TEST(Ensemble, APlainRunOnTwoRanksIsRefusedAsSerial)
{
  if (std::string(WEARLINK_MPIEXEC).empty())
    GTEST_SKIP() << "no mpiexec";
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  const std::string dir = fresh_directory("plain_run_on_two_ranks") + "/out";
  const auto        r   = run_wearlink_mpi(
    2,
    {"run", source_path("params/nine_bar_ideal.prm"), "--output", dir, "--quiet", "--set", "Simulation/End time=0.01"});
  EXPECT_EQ(r.exit_status, 2) << r.output;
  EXPECT_NE(r.output.find("`wearlink run` without `--ensemble` runs serially, but it was started on 2 MPI ranks"),
            std::string::npos)
    << r.output;
  EXPECT_EQ(r.output.find("in use"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir));
}
