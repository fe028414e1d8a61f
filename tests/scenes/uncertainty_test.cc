// SPDX-License-Identifier: LGPL-2.1-or-later
// Ensembles with uncertain inputs (workflows/ensemble/uncertain_inputs.h): `wearlink run
// nine_bar_wear.prm --ensemble 8` cut to 1 wear iteration of 1 cycle (about a second a
// member) with two uncertain inputs: joint A's pin wear coefficient, lognormal with
// median 4.6e-14 m³/(N m) and σ_ln = 0.5 (a factor 1.65 per σ), and joint B's bushing
// density, uniform(7800, 7900) kg/m³, which cannot change joint A's worn volume.
//  - The worn volume of A's pin is proportional to its wear coefficient (Archard, one
//    iteration), up to the chaos of the members' perturbations (a few %): its rank
//    correlation with the coefficient is > 0.8 and its 95 % interval excludes 0;
//    summary.json says the method (rank correlations: no Saltelli design).
//  - Member k's inputs are analysis::member_inputs(seed, k); ensemble.csv has a column
//    per input; the worn volume's P05 / P50 / P95 are the type-7 percentiles of the
//    members' volumes.
//  - On 2 MPI ranks the members' inputs, the statistics with their P05 / P50 / P95 and
//    the sensitivities are identical to 1 rank's.
#include "analysis/input_distributions.h"
#include "base/json.h"
#include "io/json_file.h"
#include "io/plot.h"
#include "support/test_support.h"
#include "workflows/ensemble/uncertain_inputs.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>

using namespace wearlink;
using namespace wearlink::testing;

namespace
{
  const char *const wear_coefficient = "Joint A/Clearance/archard/Pin wear coefficient";
  const char *const density          = "Joint B/Clearance/archard/Bushing density";

  std::vector<std::string>
  uncertain_args(const std::string &dir)
  {
    return {"run",
            source_path("params/nine_bar_wear.prm"),
            "--ensemble",
            "8",
            "--output",
            dir,
            "--quiet",
            "--set",
            "Wear/Number of iterations=1",
            "--set",
            "Wear/Cycles per iteration=1",
            "--set",
            "Wear/Response cycles=1",
            "--set",
            std::string("Uncertainty/Inputs=") + wear_coefficient + ": lognormal(4.6e-14, 0.5); " + density +
              ": uniform(7800, 7900)",
            "--set",
            "Uncertainty/Seed=5"};
  }

  using wearlink::testing::type7;
} // namespace

TEST(UncertainEnsemble, TheWearCoefficientDrivesTheWornVolumeOnAnyRankCount)
{
  if (std::string(WEARLINK_MPIEXEC).empty())
    GTEST_SKIP() << "no mpiexec";
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  const std::string serial = fresh_directory("uncertain_serial"), parallel = fresh_directory("uncertain_mpi");
  const auto        r1 = run_wearlink(uncertain_args(serial));
  ASSERT_EQ(r1.exit_status, 0) << r1.output;
  const auto r2 = run_wearlink_mpi(2, uncertain_args(parallel));
  ASSERT_EQ(r2.exit_status, 0) << r2.output;
  const Json a = io::read_json_file(serial + "/summary.json"), b = io::read_json_file(parallel + "/summary.json");

  const Json &s = a.at("sensitivity");
  EXPECT_EQ(s.at("method").get<std::string>(), "rank-correlation");
  const Json &rho = s.at("figures").at("A_wear_volume_pin_m3").at("inputs").at(wear_coefficient).at("rank_correlation");
  EXPECT_GT(json_number(rho.at("value")), 0.8) << s.dump(2);
  EXPECT_GT(json_number(rho.at("ci95_low")), 0) << "the interval excludes 0";
  EXPECT_TRUE(s.at("figures").at("A_wear_volume_pin_m3").at("inputs").contains(density));

  // The members' inputs: the sampler's, in their own scenes, in ensemble.csv.
  analysis::UncertaintySettings u;
  u.seed   = 5;
  u.inputs = {{wear_coefficient, analysis::InputDistribution::lognormal(4.6e-14, 0.5)},
              {density, analysis::InputDistribution::uniform(7800, 7900)}};
  std::vector<double> volumes;
  for (unsigned int k = 0; k < 8; ++k)
    {
      const Json &m = a.at("members")[k];
      const auto  x = analysis::member_inputs(u, analysis::InputSampling::sobol, 8, k);
      EXPECT_DOUBLE_EQ(json_number(m.at("inputs").at(wear_coefficient)), x[0]) << "member " << k;
      EXPECT_DOUBLE_EQ(json_number(m.at("inputs").at(density)), x[1]) << "member " << k;
      volumes.push_back(json_number(m.at("figures").at("A_wear_volume_pin_m3")));
    }
  const Json &v = a.at("ensemble").at("A_wear_volume_pin_m3");
  EXPECT_DOUBLE_EQ(json_number(v.at("p05")), type7(volumes, 0.05));
  EXPECT_DOUBLE_EQ(json_number(v.at("p50")), type7(volumes, 0.5));
  EXPECT_DOUBLE_EQ(json_number(v.at("p95")), type7(volumes, 0.95));
  const std::string csv = file_content(serial + "/ensemble.csv");
  EXPECT_NE(csv.find(std::string(",") + wear_coefficient + "," + density + ","), std::string::npos) << csv;
  if (io::gnuplot_available())
    {
      EXPECT_TRUE(std::filesystem::exists(serial + "/sensitivity.png"));
    }

  // 1 rank and 2 ranks: the same members, statistics and sensitivities.
  EXPECT_EQ(json_number(b.at("mpi_ranks")), 2);
  for (unsigned int k = 0; k < 8; ++k)
    EXPECT_EQ(a.at("members")[k].at("inputs"), b.at("members")[k].at("inputs")) << "member " << k;
  EXPECT_EQ(a.at("ensemble"), b.at("ensemble"));
  EXPECT_EQ(a.at("sensitivity"), b.at("sensitivity"));
  EXPECT_EQ(a.at("uncertainty"), b.at("uncertainty"));
}

// The Saltelli layout (--sensitivity saltelli) from the members' records, no run: 64 base
// rows of 2 inputs (256 members, member k = design point k) and a figure
// y = x₁ + 0.1 x₂ with x₁, x₂ ~ U(0, 1), whose variance shares are 1 / 1.01 = 0.990 and
// 0.01 / 1.01 = 0.0099 (first order = total: no interaction). The same members without
// the layout give rank correlations; a failed member is left out (its base row dropped).
TEST(UncertainEnsemble, ASaltelliLayoutGivesSobolIndices)
{
  analysis::UncertaintySettings u;
  u.inputs = {{"Body crank1/Mass", analysis::InputDistribution::uniform(0, 1)},
              {"Body rod2/Mass", analysis::InputDistribution::uniform(0, 1)}};
  workflows::EnsembleRequest request;
  request.members  = 256;
  request.saltelli = true;
  std::vector<Json> members;
  for (unsigned int k = 0; k < request.members; ++k)
    {
      const auto x = analysis::member_inputs(u, analysis::InputSampling::saltelli, request.members, k);
      members.push_back({{"status", k == 17 ? "failed" : "ok"},
                         {"inputs", {{u.inputs[0].entry, x[0]}, {u.inputs[1].entry, x[1]}}},
                         {"figures", {{"A_wear_volume_pin_m3", x[0] + 0.1 * x[1]}}}});
    }
  const Json statistics = {{"A_wear_volume_pin_m3", Json::object()}, {"A_sliding_distance_m", Json::object()}};
  const Json s          = workflows::ensemble_sensitivity(u, request, statistics, members);
  ASSERT_EQ(s.at("method").get<std::string>(), "sobol-indices") << s.dump(2);
  EXPECT_FALSE(s.at("figures").contains("A_sliding_distance_m")) << "not a headline figure";
  const Json &f = s.at("figures").at("A_wear_volume_pin_m3");
  EXPECT_EQ(json_number(f.at("dropped")), 1);
  const Json &x1 = f.at("inputs").at("Body crank1/Mass"), &x2 = f.at("inputs").at("Body rod2/Mass");
  EXPECT_NEAR(json_number(x1.at("first_order").at("value")), 0.990, 0.05);
  EXPECT_NEAR(json_number(x1.at("total").at("value")), 0.990, 0.05);
  EXPECT_NEAR(json_number(x2.at("total").at("value")), 0.0099, 0.005);
  EXPECT_LT(json_number(x2.at("first_order").at("ci95_low")), 0.0099);
  EXPECT_GT(json_number(x1.at("first_order").at("ci95_high")), json_number(x1.at("first_order").at("ci95_low")));

  request.saltelli = false; // the same values as plain members: rank correlations
  const Json r     = workflows::ensemble_sensitivity(u, request, statistics, members);
  EXPECT_EQ(r.at("method").get<std::string>(), "rank-correlation");
  EXPECT_GT(json_number(r.at("figures")
                          .at("A_wear_volume_pin_m3")
                          .at("inputs")
                          .at("Body crank1/Mass")
                          .at("rank_correlation")
                          .at("value")),
            0.9);
}
