// SPDX-License-Identifier: LGPL-2.1-or-later
// `wearlink calibrate` (workflows/wear/calibration.h) on synthetic measurements whose
// coefficients are known. The scene: params/slider_crank_wear.prm cut to 3 fixed wear
// iterations of 1 cycle × 1000 (3000 revolutions), so that a forward run takes about
// 0.1 s (measured: 0.09 s each; the recovery test 1.8 s, the 12 coverage cases 2.7 s).
//  - Recovery: the measurements are the tool's own prediction with the pin coefficient
//    halved and the bushing's doubled (2.3e-14 and 9.2e-14 against the scene's 4.6e-14),
//    given with a 2 % (1σ) uncertainty; `calibrate --ensemble 3` from the scene's
//    coefficients finds both inside their 95 % intervals, writes calibration.json,
//    calibrated.prm (a scene that validates and holds the calibrated values) and
//    calibration.png, and counts its forward runs (secant runs + members + the profile
//    run). The rig's worn pin and bore (pin_B.csv, bore_B.csv of its run) given as
//    measured profiles with 0.1 µm per point agree with the run at the calibrated
//    coefficients (RMS below 3σ, worn areas within 2 %).
//  - Two joints measured after different revolutions (params/nine_bar_wear.prm cut to 2
//    iterations of 1 cycle, ~0.4 s a run, chaotic: single runs scatter by a few per
//    cent): joint A's pin after 1000 and joint B's bushing after 2000 revolutions take
//    one run per count in every step; both true coefficients (the tool's own runs at
//    each count, perturbed as an ensemble member of another seed) are inside their
//    intervals (5 % measurement σ and the chaotic scatter of 3 members).
//  - MPI: the same calibration on 1 and on 2 ranks (the members spread over them) gives
//    the same calibration.json joints to the last bit.
//  - Coverage: 12 seeded cases whose measured mass losses are the truth's prediction with
//    a normal error of known σ (3 %, drawn with analysis::member_normals): the 95 %
//    intervals cover the true coefficient in ≥ 20 of the 12 cases' 24 coefficients (the
//    expected count is 22.8; a binomial (24, 0.95) falls below 20 with probability
//    0.6 %; measured: 22); the cases run in-process without ensemble (members = 1).
#include "analysis/ensemble_statistics.h"
#include "base/parameters.h"
#include "io/json_file.h"
#include "io/scene.h"
#include "support/test_support.h"
#include "workflows/ensemble/ensemble.h"
#include "workflows/wear/calibration.h"
#include "workflows/wear/wear_run.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>

using namespace wearlink;
using namespace wearlink::testing;

namespace
{
  const std::vector<std::string> cut      = {"Wear/Extrapolation=fixed",
                                             "Wear/Number of iterations=3",
                                             "Wear/Cycles per iteration=1",
                                             "Wear/Extrapolation factor=1000",
                                             "Wear/Response cycles=1",
                                             "Output/Plots=false"};
  constexpr double               true_pin = 2.3e-14, true_bushing = 9.2e-14; // [m³/(N m)]

  /** The pin's and the bushing's mass loss [mg] of the cut scene with the true coefficients. */
  std::pair<double, double>
  true_mass_losses()
  {
    ParameterOverrides o(cut);
    o.set("Joint B/Clearance/archard/Pin wear coefficient", true_pin);
    o.set("Joint B/Clearance/archard/Bushing wear coefficient", true_bushing);
    io::Scene                 scene = io::read_scene(source_path("params/slider_crank_wear.prm"), o);
    workflows::WearRunOptions w;
    w.progress      = false;
    w.final_outputs = false;
    const auto  r   = workflows::run_wear(scene, w);
    const auto &h   = r.state.joints.at(0).history.back();
    const auto &a   = scene.wear.at(0)->archard;
    return {h.volume_pin * a.pin_density * 1e6, h.volume_bore * a.bushing_density * 1e6};
  }

  /** The "test rig": `wearlink run` of the cut scene with the true coefficients into DIR/truth. */
  ::testing::AssertionResult
  run_truth(const std::string &dir, const std::vector<std::string> &more = {})
  {
    std::vector<std::string> args = {"run",
                                     source_path("params/slider_crank_wear.prm"),
                                     "--output",
                                     dir + "/truth",
                                     "--quiet",
                                     "--set",
                                     "Joint B/Clearance/archard/Pin wear coefficient=2.3e-14",
                                     "--set",
                                     "Joint B/Clearance/archard/Bushing wear coefficient=9.2e-14"};
    for (const auto &c : cut)
      args.insert(args.end(), {"--set", c});
    for (const auto &c : more)
      args.insert(args.end(), {"--set", c});
    const auto r = run_wearlink(args);
    if (r.exit_status != 0)
      return ::testing::AssertionFailure() << r.output;
    return ::testing::AssertionSuccess();
  }

  /** A measurements file of joint B after 3000 revolutions. */
  std::string
  measurements(const std::string &dir,
               const double       pin,
               const double       s_pin,
               const double       bushing,
               const double       s_b,
               const std::string &more = "")
  {
    const std::string path = dir + "/measurements.prm";
    std::ofstream     out(path);
    out.precision(17);
    out << "subsection Joint B\n  set Revolutions = 3000\n  set Pin mass loss = " << pin
        << "\n  set Pin mass loss uncertainty = " << s_pin << "\n  set Bushing mass loss = " << bushing
        << "\n  set Bushing mass loss uncertainty = " << s_b << "\n"
        << more << "end\n";
    return path;
  }

  /** Whether calibration.json @p r's interval of @p surface covers @p truth. */
  bool
  covers(const Json &r, const std::string &surface, const double truth)
  {
    const Json &k = r.at("joints").at("B").at(surface + "_wear_coefficient");
    return json_number(k.at("ci95_low")) <= truth && truth <= json_number(k.at("ci95_high"));
  }
} // namespace

TEST(CalibrateCommand, RecoversKnownCoefficientsFromTheToolsOwnPrediction)
{
  // The "test rig": a wear run with the true coefficients, its mass losses and worn surfaces.
  const std::string dir = fresh_directory("calibration_recovery");
  ASSERT_TRUE(run_truth(dir));
  const Json   summary = io::read_json_file(dir + "/truth/summary.json");
  const Json  &b       = summary.at("clearance_joints").at("B");
  const double pin = json_number(b.at("mass_loss_pin_mg")), bushing = json_number(b.at("mass_loss_bushing_mg"));
  const auto [p2, b2] = true_mass_losses();
  EXPECT_EQ(pin, p2) << "the in-process run is the command's";
  EXPECT_EQ(bushing, b2);
  // The worn surfaces too (paths relative to the measurements file).
  const std::string meas =
    measurements(dir,
                 pin,
                 0.02 * pin,
                 bushing,
                 0.02 * bushing,
                 "  set Pin profile file = truth/pin_B.csv\n  set Bore profile file = truth/bore_B.csv\n"
                 "  set Profile uncertainty = 1e-7\n  set Profile angle search = 10\n");
  std::vector<std::string> args = {"calibrate",
                                   source_path("params/slider_crank_wear.prm"),
                                   "--measurements",
                                   meas,
                                   "--ensemble",
                                   "3",
                                   "--seed",
                                   "5",
                                   "--output",
                                   dir + "/out",
                                   "--quiet"};
  for (const auto &c : cut)
    args.insert(args.end(), {"--set", c});
  const auto run = run_wearlink(args);
  ASSERT_EQ(run.exit_status, 0) << run.output;
  const Json r = io::read_json_file(dir + "/out/calibration.json");
  EXPECT_TRUE(covers(r, "pin", true_pin)) << r.dump(1);
  EXPECT_TRUE(covers(r, "bushing", true_bushing)) << r.dump(1);
  const Json &k = r.at("joints").at("B").at("pin_wear_coefficient");
  EXPECT_EQ(json_number(k.at("prior")), 4.6e-14);
  EXPECT_NEAR(json_number(k.at("value")) / true_pin, 1, 0.02);
  EXPECT_EQ(r.at("joints").at("B").at("bushing_mass_loss_mg").at("predicted_members").size(), 3u);
  EXPECT_EQ(json_number(r.at("forward_runs")), json_number(r.at("iterations")) + 3 + 1) << "secant, members, profiles";
  EXPECT_TRUE(r.at("secant").at("converged").get<bool>());
  EXPECT_NE(file_content(dir + "/out/calibration.png"), "");
  // The worn surfaces at the calibrated coefficients are the rig's within the points' 1σ
  // (measured: 0.3 and 1.5 × 0.1 µm, worn areas within 0.03 %).
  for (const std::string surface : {"pin", "bore"})
    {
      const Json &p = r.at("joints").at("B").at(surface + "_profile");
      EXPECT_LT(json_number(p.at("rms_over_uncertainty")), 3) << p.dump(1);
      EXPECT_NEAR(json_number(p.at("worn_area_predicted_m2")) / json_number(p.at("worn_area_measured_m2")), 1, 0.02);
    }
  // calibrated.prm stands alone: it validates and holds the calibrated coefficient.
  const std::string prm = file_content(dir + "/out/calibrated.prm");
  EXPECT_NE(prm.find(format_number(json_number(k.at("value")))), std::string::npos);
  const auto check = run_wearlink({"run", "--validate", dir + "/out/calibrated.prm"});
  EXPECT_EQ(check.exit_status, 0) << check.output;
}

// A surface that was not weighed but traced: the bore's worn profile alone (bore_B.csv of
// the true run, 0.1 µm per point) gives the bushing's mass loss through its worn area ×
// length × density (the weighed loss to 0.1 %: the two differ by terms of order depth /
// radius), and the bushing's coefficient is recovered inside its interval; the pin, not
// measured, keeps no coefficient.
TEST(CalibrateCommand, RecoversTheBushingCoefficientFromAWornBoreProfileAlone)
{
  const std::string dir = fresh_directory("calibration_profile");
  ASSERT_TRUE(run_truth(dir));
  const double weighed = json_number(
    io::read_json_file(dir + "/truth/summary.json").at("clearance_joints").at("B").at("mass_loss_bushing_mg"));
  {
    std::ofstream out(dir + "/measurements.prm");
    out << "subsection Joint B\n  set Revolutions = 3000\n  set Bore profile file = truth/bore_B.csv\n"
           "  set Profile uncertainty = 1e-7\n  set Profile angle search = 10\nend\n";
  }
  std::vector<std::string> args = {"calibrate",
                                   source_path("params/slider_crank_wear.prm"),
                                   "--measurements",
                                   dir + "/measurements.prm",
                                   "--ensemble",
                                   "3",
                                   "--output",
                                   dir + "/out",
                                   "--quiet"};
  for (const auto &c : cut)
    args.insert(args.end(), {"--set", c});
  const auto run = run_wearlink(args);
  ASSERT_EQ(run.exit_status, 0) << run.output;
  const Json  r = io::read_json_file(dir + "/out/calibration.json");
  const Json &m = r.at("joints").at("B").at("bushing_mass_loss_mg");
  EXPECT_NEAR(json_number(m.at("measured")) / weighed, 1, 1e-3) << m.dump(1);
  EXPECT_GT(json_number(m.at("measured_uncertainty")), 0);
  EXPECT_NE(m.at("measured_by").get<std::string>().find("bore_B.csv"), std::string::npos);
  EXPECT_TRUE(covers(r, "bushing", true_bushing)) << r.dump(1);
  EXPECT_FALSE(r.at("joints").at("B").contains("pin_wear_coefficient"));
}

TEST(CalibrateCommand, SerialAndTwoRanksAgree)
{
  if (std::string(WEARLINK_MPIEXEC).empty())
    GTEST_SKIP() << "no mpiexec";
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  const auto [pin, bushing] = true_mass_losses();
  const std::string dir     = fresh_directory("calibration_mpi");
  const std::string meas    = measurements(dir, pin, 0.02 * pin, bushing, 0.02 * bushing);
  const auto        args    = [&](const std::string &out) {
    std::vector<std::string> a = {"calibrate",
                                  source_path("params/slider_crank_wear.prm"),
                                  "--measurements",
                                  meas,
                                  "--ensemble",
                                  "3",
                                  "--output",
                                  dir + "/" + out,
                                  "--quiet"};
    for (const auto &c : cut)
      a.insert(a.end(), {"--set", c});
    return a;
  };
  const auto serial = run_wearlink(args("serial"));
  ASSERT_EQ(serial.exit_status, 0) << serial.output;
  const auto parallel = run_wearlink_mpi(2, args("mpi"));
  ASSERT_EQ(parallel.exit_status, 0) << parallel.output;
  const Json a = io::read_json_file(dir + "/serial/calibration.json"),
             b = io::read_json_file(dir + "/mpi/calibration.json");
  EXPECT_EQ(json_number(b.at("ensemble").at("mpi_ranks")), 2);
  EXPECT_EQ(a.at("joints"), b.at("joints"));
}

TEST(CalibrateCommand, IntervalsCoverTheTruthOverSeededNoisyMeasurements)
{
  const auto [pin, bushing] = true_mass_losses();
  const double sigma        = 0.03; // relative 1σ of the synthetic measurements
  unsigned     covered = 0, cases = 0;
  for (unsigned int c = 0; c < 12; ++c)
    {
      const auto                    z   = analysis::member_normals(2026, c, 2);
      const std::string             dir = fresh_directory("calibration_coverage_" + std::to_string(c));
      workflows::CalibrationOptions o;
      o.scene_file = source_path("params/slider_crank_wear.prm");
      o.measurements_file =
        measurements(dir, pin * (1 + sigma * z[0]), sigma * pin, bushing * (1 + sigma * z[1]), sigma * bushing);
      o.overrides        = ParameterOverrides(cut);
      o.members          = 1;
      o.progress         = false;
      auto       problem = workflows::load_calibration(o);
      const Json r       = workflows::calibrate(problem, o);
      covered += covers(r, "pin", true_pin) + covers(r, "bushing", true_bushing);
      cases += 2;
    }
  EXPECT_GE(covered, 20u) << "of " << cases;
  std::cout << "95 % intervals covering the truth: " << covered << " of " << cases << "\n";
}

TEST(CalibrateCommand, TwoJointsMeasuredAfterDifferentRevolutions)
{
  const std::vector<std::string> nine = {"Wear/Number of iterations=2",
                                         "Wear/Cycles per iteration=1",
                                         "Wear/Response cycles=1",
                                         "Output/Plots=false"};
  const double                   k_a = 2.3e-14, k_b = 9.2e-14; // A's pin, B's bushing [m³/(N m)]
  // The truth: the scene with both coefficients, stretched to 1000 and to 2000 revolutions.
  const auto truth = [&](const double revolutions, const std::string &joint, const bool pin) {
    ParameterOverrides o(nine);
    o.set("Joint A/Clearance/archard/Pin wear coefficient", k_a);
    o.set("Joint B/Clearance/archard/Bushing wear coefficient", k_b);
    o.set("Wear/Extrapolation factor", revolutions / 2);
    // The "test" is one sample of the chaotic wear: a perturbed run as an ensemble's member
    // (the unperturbed scene happens to lie 8 % above all of 8 perturbed members here).
    const io::Scene base = io::read_scene(source_path("params/nine_bar_wear.prm"), o);
    io::Scene       scene =
      io::read_scene(source_path("params/nine_bar_wear.prm"), workflows::member_overrides(base, o, {2, 99, 1e-9}, 0));
    workflows::WearRunOptions w;
    w.progress      = false;
    w.final_outputs = false;
    const auto r    = workflows::run_wear(scene, w);
    for (std::size_t j = 0; j < r.state.joints.size(); ++j)
      if (r.state.joints[j].name == joint)
        {
          const auto &h = r.state.joints[j].history.back();
          const auto &a = scene.wear[j]->archard;
          return (pin ? h.volume_pin * a.pin_density : h.volume_bore * a.bushing_density) * 1e6;
        }
    return 0.0;
  };
  const double      m_a = truth(1000, "A", true), m_b = truth(2000, "B", false);
  const std::string dir  = fresh_directory("calibration_two_joints");
  const std::string meas = dir + "/measurements.prm";
  {
    std::ofstream out(meas);
    out.precision(17);
    out << "subsection Joint A\n  set Revolutions = 1000\n  set Pin mass loss = " << m_a
        << "\n  set Pin mass loss uncertainty = " << 0.05 * m_a
        << "\nend\nsubsection Joint B\n  set Revolutions = 2000\n"
        << "  set Bushing mass loss = " << m_b << "\n  set Bushing mass loss uncertainty = " << 0.05 * m_b << "\nend\n";
  }
  std::vector<std::string> args = {"calibrate",
                                   source_path("params/nine_bar_wear.prm"),
                                   "--measurements",
                                   meas,
                                   "--ensemble",
                                   "3",
                                   "--output",
                                   dir + "/out",
                                   "--quiet"};
  for (const auto &c : nine)
    args.insert(args.end(), {"--set", c});
  const auto run = run_wearlink(args);
  ASSERT_EQ(run.exit_status, 0) << run.output;
  const Json r = io::read_json_file(dir + "/out/calibration.json");
  EXPECT_EQ(json_number(r.at("forward_runs")), 2 * (json_number(r.at("iterations")) + 3));
  EXPECT_EQ(json_number(r.at("joints").at("A").at("revolutions")), 1000);
  EXPECT_EQ(json_number(r.at("joints").at("B").at("revolutions")), 2000);
  EXPECT_FALSE(r.at("joints").at("A").contains("bushing_wear_coefficient"));
  const Json &a = r.at("joints").at("A").at("pin_wear_coefficient");
  const Json &b = r.at("joints").at("B").at("bushing_wear_coefficient");
  EXPECT_LE(json_number(a.at("ci95_low")), k_a) << a.dump(1);
  EXPECT_GE(json_number(a.at("ci95_high")), k_a) << a.dump(1);
  EXPECT_LE(json_number(b.at("ci95_low")), k_b) << b.dump(1);
  EXPECT_GE(json_number(b.at("ci95_high")), k_b) << b.dump(1);
}

// A joint cut into slices along its pin (doc/models.md §1.8) is measured as a whole: its
// mass losses are its slices' sums, and the coefficients (one per joint, shared by the
// slices) are recovered as for the two-dimensional joint. A profile trace of a sliced
// joint is refused: its slices' surfaces differ along the pin.
TEST(CalibrateCommand, ASlicedJointIsWeighedAsAWhole)
{
  const std::string dir    = fresh_directory("calibration_sliced");
  const std::string slices = "Joint B/Clearance/Slices/Axial slices=4";
  ASSERT_TRUE(run_truth(dir, {slices}));
  const Json summary = io::read_json_file(dir + "/truth/summary.json");
  double     pin = 0, bushing = 0;
  for (const std::string s : {"B.s01", "B.s02", "B.s03", "B.s04"})
    {
      pin += json_number(summary.at("clearance_joints").at(s).at("mass_loss_pin_mg"));
      bushing += json_number(summary.at("clearance_joints").at(s).at("mass_loss_bushing_mg"));
    }
  const auto calibrate = [&](const std::string &meas, const std::string &out) {
    std::vector<std::string> args = {"calibrate",
                                     source_path("params/slider_crank_wear.prm"),
                                     "--measurements",
                                     meas,
                                     "--output",
                                     dir + "/" + out,
                                     "--quiet",
                                     "--set",
                                     slices};
    for (const auto &c : cut)
      args.insert(args.end(), {"--set", c});
    return run_wearlink(args);
  };
  const auto run = calibrate(measurements(dir, pin, 0.02 * pin, bushing, 0.02 * bushing), "out");
  ASSERT_EQ(run.exit_status, 0) << run.output;
  const Json r = io::read_json_file(dir + "/out/calibration.json");
  EXPECT_TRUE(covers(r, "pin", true_pin)) << r.dump(1);
  EXPECT_TRUE(covers(r, "bushing", true_bushing)) << r.dump(1);
  EXPECT_NEAR(json_number(r.at("joints").at("B").at("pin_wear_coefficient").at("value")) / true_pin, 1, 0.02);
  const auto traced =
    calibrate(measurements(dir,
                           pin,
                           0.02 * pin,
                           bushing,
                           0.02 * bushing,
                           "  set Pin profile file = truth/pin_B.s01.csv\n  set Profile uncertainty = 1e-7\n"),
              "traced");
  EXPECT_EQ(traced.exit_status, 2) << traced.output;
  EXPECT_NE(traced.output.find("cut into slices"), std::string::npos) << traced.output;
}
