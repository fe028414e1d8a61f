// SPDX-License-Identifier: LGPL-2.1-or-later
// Ensembles (issue 15): `wearlink run SCENE --ensemble N --seed S` of a wear scene
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
//    t(0.975, 2) = 4.303 (table value, to its 3 decimals).
#include "base/json.h"
#include "base/output_directory.h"
#include "io/json_file.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

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
  EXPECT_NEAR(json_number(f.at("std")), s, 1e-12 * mean);
  EXPECT_NEAR(json_number(f.at("ci95_high")) - mean, 4.303 * s / std::sqrt(3.0), 5e-4 * s / std::sqrt(3.0));
  EXPECT_GT(s, 1e-3 * mean) << "the members did not part: the perturbation does not reach the dynamics";
  EXPECT_NE(json_number(c.at("ensemble").at(volume).at("mean")), mean) << "another seed, the same members";
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
