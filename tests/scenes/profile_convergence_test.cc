// SPDX-License-Identifier: LGPL-2.1-or-later
// Worn profiles that converge (the scenes in params/):
//  - params/nine_bar_wear.prm cut to one iteration of 10 cycles × 5,000 (50,000
//    revolutions, the bores ~30 µm deep): at 360 and at 1440 discrete areas the depth
//    profiles of every surface agree within 2 % point by point (relative L2 on the 360
//    areas, each the mean of the four 1440 areas it holds) and in the largest and the
//    envelope depth (measured: 0.1–0.3 %; the required bound is 5 %). One iteration, so
//    that both see the same load history (the profiles are round while it is simulated,
//    and a round profile's radius does not depend on its sample count) and the
//    difference is the discretization's alone; with more iterations the worn profiles
//    differ in the last bits, the chaotic dynamics part, and the difference is the chaos
//    floor, which `wearlink study convergence` measures with ensembles;
//  - every shipped scene with wear settings of its own (nine_bar_wear, its life variant,
//    nine_bar_wear_fe, nine_bar_experiment, slider_crank_wear; nine_bar_wear_dynamics
//    wears as nine_bar_wear does, at a tenth of its integrator tolerance, which the
//    accuracy study covers), run through (its wear only: no before/after analyses): the
//    roughness of every worn surface (wear/depth_measures.h) is at most 5 % (measured
//    0.7–1.7 %; the seed's simultaneous update gave 25–48 % on the bores). Not cut
//    short: a few thousand revolutions of a chaotic load history extrapolated stamp
//    single impacts' marks on a pin (5–8 % after 15,000 revolutions), which later
//    iterations, other impacts, even out;
//  - `wearlink study convergence` on the journals of tests/scenes/life_journal.prm (a
//    constant wear rate, about a second): three levels of two members, the finest level
//    its own reference, the worn volume independent of the level (a constant rate makes
//    it exact to the sequential update's round-off; measured 0.1–0.2 %), and the
//    Richardson block the same as analysis/richardson.h computes from the levels' figures.
#include "analysis/richardson.h"
#include "base/json.h"
#include "io/json_file.h"
#include "scene_support.h"
#include "support/test_support.h"
#include "wear/depth_measures.h"
#include "workflows/wear/wear_run.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

using namespace wearlink;

namespace
{
  /** The final depth profiles and measures of a wear run of @p file under @p overrides. */
  wear::WearState
  worn(const std::string &file, const std::vector<std::string> &overrides)
  {
    auto                      scene = wearlink::testing::scene(file, overrides);
    workflows::WearRunOptions o;
    o.progress      = false;
    o.final_outputs = false;
    return workflows::run_wear(scene, o).state;
  }

  /**
   * @p fine (m areas) on the n areas of a coarser profile: coarse area k spans the fine
   * areas k r − r/2 … k r + r/2 (r = m/n even: the two end ones half inside).
   */
  std::vector<double>
  on_coarse(const std::vector<double> &fine, const std::size_t n)
  {
    const long          m = static_cast<long>(fine.size()), r = m / static_cast<long>(n);
    std::vector<double> out(n, 0.0);
    for (long k = 0; k < static_cast<long>(n); ++k)
      for (long d = -r / 2; d <= r / 2; ++d)
        out[k] += (std::abs(d) == r / 2 ? 0.5 : 1.0) * fine[((k * r + d) % m + m) % m] / r;
    return out;
  }

  /** ‖a − b‖/‖b‖. */
  double
  l2(const std::vector<double> &a, const std::vector<double> &b)
  {
    double d = 0, r = 0;
    for (std::size_t k = 0; k < b.size(); ++k)
      {
        d += (a[k] - b[k]) * (a[k] - b[k]);
        r += b[k] * b[k];
      }
    return std::sqrt(d / r);
  }

  double
  largest(const std::vector<double> &v)
  {
    return *std::max_element(v.begin(), v.end());
  }
} // namespace

TEST(ProfileConvergence, HertzStripAt360And1440AreasAgree)
{
  const std::vector<std::string> cut        = {"Wear/Number of iterations=1",
                                               "Wear/Cycles per iteration=10",
                                               "Wear/Extrapolation factor=5000",
                                               "Wear/Response cycles=0.1"};
  auto                           with_areas = [&](const int n) {
    auto o = cut;
    for (const char *j : {"A", "B"})
      o.push_back(std::string("Joint ") + j + "/Clearance/Number of discrete areas=" + std::to_string(n));
    return worn("params/nine_bar_wear.prm", o);
  };
  const auto coarse = with_areas(360), fine = with_areas(1440);
  ASSERT_EQ(coarse.joints.size(), 2u);
  for (std::size_t j = 0; j < 2; ++j)
    {
      const auto &c = coarse.joints[j].history.back(), &f = fine.joints[j].history.back();
      const auto  name = coarse.joints[j].name;
      ASSERT_GT(c.max_depth_bore, 10e-6) << name << ": a pocket deep enough to say something";
      EXPECT_NEAR(c.archard_bore, f.archard_bore, 1e-12 * f.archard_bore) << name << ": the same load history";
      const auto bore = on_coarse(f.depth_bore, 360), pin = on_coarse(f.depth_pin, 360);
      EXPECT_LT(l2(c.depth_bore, bore), 0.02) << name << " bore";
      EXPECT_LT(l2(c.depth_pin, pin), 0.02) << name << " pin";
      EXPECT_NEAR(c.max_depth_bore, largest(bore), 0.02 * largest(bore)) << name;
      EXPECT_NEAR(c.max_depth_pin, largest(pin), 0.02 * largest(pin)) << name;
      EXPECT_NEAR(c.envelope_depth_bore, f.envelope_depth_bore, 0.02 * f.envelope_depth_bore) << name;
      EXPECT_NEAR(c.volume_bore, f.volume_bore, 2e-3 * f.volume_bore) << name << ": the local volume";
    }
}

namespace
{
  class ShippedWearScene : public ::testing::TestWithParam<const char *>
  {
  };
} // namespace

TEST_P(ShippedWearScene, WornProfilesAreSmooth)
{
  const auto st = worn(std::string("params/") + GetParam() + ".prm", {"Wear/Response cycles=0.1"});
  for (const auto &js : st.joints)
    {
      const auto &r = js.history.back();
      EXPECT_LE(r.roughness_bore, wear::roughness_limit) << GetParam() << " joint " << js.name << " bore";
      EXPECT_LE(r.roughness_pin, wear::roughness_limit) << GetParam() << " joint " << js.name << " pin";
      EXPECT_GT(r.max_depth_bore + r.max_depth_pin, 0) << GetParam() << " joint " << js.name << " wears";
    }
}

INSTANTIATE_TEST_SUITE_P(
  Scenes,
  ShippedWearScene,
  ::testing::Values("nine_bar_wear", "nine_bar_life", "nine_bar_wear_fe", "nine_bar_experiment", "slider_crank_wear"));

TEST(ConvergenceStudy, LevelsOfAConstantWearRateAndTheirExtrapolation)
{
  const std::string dir = wearlink::testing::fresh_directory("convergence_journal");
  const auto        r   = wearlink::testing::run_wearlink({"study",
                                                           "convergence",
                                                           wearlink::testing::source_path("tests/scenes/life_journal.prm"),
                                                           "--output",
                                                           dir,
                                                           "--ensemble",
                                                           "2",
                                                           "--quiet"});
  ASSERT_EQ(r.exit_status, 0) << r.output;
  for (const char *f : {"convergence.md", "convergence.csv", "convergence.json", "convergence_O1_pin.png"})
    EXPECT_TRUE(std::filesystem::exists(dir + "/" + f)) << f;
  const Json study = io::read_json_file(dir + "/convergence.json");
  ASSERT_EQ(study.at("levels").size(), 3u);
  for (const char *surface : {"O1 pin", "O2 bushing"})
    {
      EXPECT_EQ(json_number(study.at("levels")[2].at("surfaces").at(surface).at("l2_to_finest")), 0) << surface;
      for (int l = 0; l < 2; ++l)
        EXPECT_LT(std::abs(json_number(study.at("levels")[l].at("surfaces").at(surface).at("volume_change"))), 5e-3)
          << surface << " level " << l << ": a constant wear rate wears the same volume at every level";
    }
  const Json &e = study.at("extrapolation");
  EXPECT_EQ(e.at("levels"), Json::array({1.0, 2.0, 4.0}));
  for (const auto &[surface, block] : e.at("surfaces").items())
    {
      analysis::RefinementTriple t;
      t.ratio = 2;
      for (int l = 0; l < 3; ++l)
        {
          const Json &x       = study.at("levels")[l].at("surfaces").at(surface);
          t.value[l]          = json_number(x.at("largest_depth_m"));
          t.standard_error[l] = json_number(x.at("largest_depth_standard_error_m"));
        }
      const auto expected = analysis::richardson(t);
      EXPECT_EQ(block.at("largest_depth").at("determinable").get<bool>(), expected.determinable) << surface;
      EXPECT_EQ(block.at("largest_depth").at("note").get<std::string>(), expected.reason) << surface;
    }
  EXPECT_NE(r.output.find("Extrapolated depths"), std::string::npos) << r.output;
}
