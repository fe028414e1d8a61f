// SPDX-License-Identifier: LGPL-2.1-or-later
// Scene-selected nonlinear-dynamics analyses (workflows/run/analyses.h) on the nine-bar press:
//  - ideal joints: the mechanism has zero degrees of freedom (24 coordinates, 20
//    revolute + 2 translational + 2 driver equations), so its state is a function of
//    time alone, periodic with the drivers' period T = 2π/(4π rad/s) = 0.5 s. Every
//    Poincaré point is the same state: the section collapses to one point, up to the
//    integration error and the constraint drift;
//  - the section is taken at the exact section times from the dense output: the crank
//    angle there equals the driver's θ1 = θ0 − ω t_k to the constraint tolerance, with
//    t_k off the 1 ms output grid (a nearest sample would be 0.4 ms = 5 mrad off);
//  - with clearance joints the journal rattles in its bore: the section does not
//    collapse (spread of the order of the clearance), which shows the collapse test
//    above can fail;
//  - analyses not listed are not built and record nothing (effect ledger), and files
//    appear only for what was listed.
#include "analysis/channels.h"
#include "io/json_file.h"
#include "io/plot.h"
#include "io/recorded_run_files.h"
#include "scene_support.h"
#include "workflows/run/analyses.h"

#include <deal.II/base/utilities.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace wearlink;
namespace wl = wearlink::testing;

namespace
{
  constexpr double two_pi = 6.28318530717958647692;

  /** Spread of channel @p name in the summary's Poincaré section [unit of the channel]. */
  double
  spread(const Json &summary, const std::string &name)
  {
    return json_number(summary.at("analyses").at("poincare").at("spread").at(name));
  }
} // namespace

TEST(Analyses, IdealNineBarPoincareSectionCollapsesToOnePoint)
{
  // Six sections at t_k = 0.1234 s + k 0.5 s. Tolerances from the scene's integrator
  // settings (params/nine_bar_ideal.prm: position tolerance 1e-11 m, velocity 1e-8 m/s,
  // relative 1e-8): over a few hundred steps the accumulated error of a 0-DOF motion
  // stays within 100 times the per-step position tolerance, 1e-9 m; velocities are
  // held to their tolerance 1e-8 m/s (rad/s for angular ones), and angles like
  // positions, 1e-9 rad. For scale: within one period the slider moves 0.12 m at up to
  // 1 m/s, so any point taken off the periodic orbit would show up at the 1e-4 level.
  auto        scene = wl::scene("params/nine_bar_ideal.prm",
                         {"Simulation/End time=3.0",
                                 "Analyses/List of analyses=poincare",
                                 "Analyses/Section phase=0.1234",
                                 "Output/Time series=false"});
  const Json  s     = wl::run(scene);
  const Json &p     = s.at("analyses").at("poincare");
  EXPECT_DOUBLE_EQ(json_number(p.at("period_s")), 0.5);
  ASSERT_EQ(json_number(p.at("n_points")), 6);
  EXPECT_LT(json_number(s.at("max_constraint_violation_m")), 1e-9);
  for (const auto &[name, value] : p.at("spread").items())
    {
      const double bound =
        name.find("_v") != std::string::npos || name.find("_omega") != std::string::npos ? 1e-8 : 1e-9;
      EXPECT_LT(json_number(value), bound) << name;
    }
}

TEST(Analyses, PoincarePointsAreAtTheExactSectionTimes)
{
  // Driver drive1: θ_crank1 = θ0 + ω t with the scene's θ0 = 5.7645 rad, ω = −4π rad/s.
  // The recorded crank angle at t_k must match to 1e-9 rad (the driver constraint holds
  // to the reported violation, < 1e-9); t_k = 0.1234 + 0.5 k s are 0.4 ms off the 1 ms
  // output grid, so the nearest time-series sample would be 5e-3 rad off.
  auto                     scene = wl::scene("params/nine_bar_ideal.prm",
                         {"Simulation/End time=2.0",
                                              "Analyses/List of analyses=poincare",
                                              "Analyses/Section phase=0.1234",
                                              "Output/Time series=false"});
  workflows::SceneAnalyses analyses(scene);
  workflows::RunOptions    options;
  options.observers = analyses.observers();
  scene.analyses    = {}; // the run's own copy would record the same thing twice
  workflows::run_scene(scene, options);
  const analysis::RecordedRun run = analyses.recorded_run();
  const auto                 &pts = run.section.points;
  ASSERT_EQ(pts.n_samples(), 4u);
  scene.parameters->enter_subsection("Joint drive1");
  const double theta0 = scene.parameters->get_double("Angle offset");
  const double omega  = scene.parameters->get_double("Angular velocity");
  scene.parameters->leave_subsection();
  const std::size_t c = pts.index("crank1_theta_rad");
  for (std::size_t k = 0; k < pts.n_samples(); ++k)
    {
      EXPECT_NEAR(pts.time[k], 0.1234 + 0.5 * k, 1e-12) << "section " << k;
      const double expected = std::remainder(theta0 + omega * pts.time[k], two_pi);
      EXPECT_NEAR(std::remainder(pts.values[c][k] - expected, two_pi), 0.0, 1e-9) << "section " << k;
    }
}

TEST(Analyses, ClearanceSectionDoesNotCollapse)
{
  // The same mechanism with 0.5 mm clearance at A and B: between sections the journal
  // of A travels across its bore (impacts, free flight), so the section points scatter.
  // Bound: a spread of e_x above 5 % of the radial clearance (2.5e-5 m); measured about
  // 2e-4 m over 8 sections after a 1 s transient.
  auto       scene = wl::scene("params/nine_bar_clearance.prm",
                         {"Simulation/End time=5.0",
                                "Analyses/List of analyses=poincare",
                                "Analyses/Transient=1.0",
                                "Output/Time series=false"});
  const Json s     = wl::run(scene);
  EXPECT_GE(json_number(s.at("analyses").at("poincare").at("n_points")), 8);
  EXPECT_GT(spread(s, "A_ex_m"), 0.05 * 0.5e-3);
  EXPECT_GT(spread(s, "B_ex_m"), 0.05 * 0.5e-3);
}

TEST(Analyses, UnlistedAnalysesAreNotBuiltAndRecordNothing)
{
  auto &ledger = EffectLedger::instance();
  {
    // Nothing listed: no analysis constructed, no channel recorded, no "analyses" key.
    auto       scene = wl::scene("params/nine_bar_clearance.prm", {"Simulation/End time=0.2"});
    const Json s     = wl::run(scene);
    EXPECT_EQ(ledger.constructions("analysis"), 0);
    EXPECT_EQ(ledger.resources("analysis channels"), 0);
    EXPECT_EQ(ledger.calls("analysis samples"), 0);
    EXPECT_EQ(ledger.calls("poincare points"), 0);
    EXPECT_FALSE(s.contains("analyses"));
  }
  {
    // Only poincare: no series recorder (0 samples), the whole state per section point:
    // 6 channels for each of 8 bodies + 4 for each of 2 clearance joints = 56.
    auto scene =
      wl::scene("params/nine_bar_clearance.prm", {"Simulation/End time=1.2", "Analyses/List of analyses=poincare"});
    const Json s = wl::run(scene);
    EXPECT_EQ(ledger.constructions("analysis", "poincare"), 1);
    EXPECT_EQ(ledger.constructions("analysis", "phase-portrait"), 0);
    EXPECT_EQ(ledger.constructions("analysis", "lyapunov"), 0);
    EXPECT_EQ(ledger.resources("analysis channels"), 56);
    EXPECT_EQ(ledger.calls("analysis samples"), 0);
    EXPECT_EQ(ledger.calls("poincare points"), 3); // t = 0, 0.5, 1.0 s
    EXPECT_EQ(ledger.calls("lyapunov estimates"), 0);
    EXPECT_FALSE(s.at("analyses").contains("lyapunov"));
    // The summary prints the same ledger.
    EXPECT_EQ(json_number(s.at("effect_ledger").at("constructed").at("analysis/poincare")), 1);
  }
  {
    // Only the phase portrait of joint A: its 4 channels, sampled every 2 ms from the
    // end of a 0.2 s transient to 1.2 s: 501 samples; no section.
    auto       scene = wl::scene("params/nine_bar_clearance.prm",
                           {"Simulation/End time=1.2",
                                  "Analyses/List of analyses=phase-portrait",
                                  "Analyses/Joints=A",
                                  "Analyses/Transient=0.2",
                                  "Analyses/Sample interval=2e-3"});
    const Json s     = wl::run(scene);
    EXPECT_EQ(ledger.constructions("analysis", "phase-portrait"), 1);
    EXPECT_EQ(ledger.constructions("analysis", "poincare"), 0);
    EXPECT_EQ(ledger.resources("analysis channels"), 4);
    EXPECT_EQ(ledger.calls("analysis samples"), 501);
    EXPECT_EQ(ledger.calls("poincare points"), 0);
  }
}

TEST(Analyses, PhasePortraitOfTheJournalFillsTheClearanceCircle)
{
  // The journal centre relative to the bushing (channels A_ex_m, A_ey_m) moves inside
  // the clearance circle |e| ≤ c and, in contact, beyond it by the penetration only:
  // max |e| ≤ c + max penetration (both from the run's summary), to the series'
  // 12-digit CSV rounding. The journal of the nine-bar touches the bore (hundreds of
  // impacts per second), so max |e| ≥ c. Its eccentricity rate is bounded by the
  // relative speed of crank and rod pins: a few m/s at most for cranks at 120 rpm
  // with link lengths of tenths of a metre (seed Table 1), so |ė| < 10 m/s.
  const std::string     dir   = wl::fresh_directory("analyses_phase_extent");
  auto                  scene = wl::scene("params/nine_bar_clearance.prm",
                         {"Simulation/End time=0.6",
                                           "Analyses/List of analyses=phase-portrait",
                                           "Analyses/Joints=A",
                                           "Analyses/Transient=0.1",
                                           "Analyses/Sample interval=1e-4"});
  workflows::RunOptions options;
  options.output_directory = dir;
  const Json   s           = workflows::run_scene(scene, options);
  const auto   run         = io::read_recorded_run(dir);
  const double c           = json_number(s.at("clearance_joints").at("A").at("radial_clearance_m"));
  const double pen         = json_number(s.at("clearance_joints").at("A").at("max_penetration_m"));
  const auto  &ch          = run.series;
  auto         column      = [&](const std::string &name) -> const std::vector<double>              &{
    for (std::size_t k = 0; k < ch.names.size(); ++k)
      if (ch.names[k] == name)
        return ch.values[k];
    throw std::runtime_error("no channel " + name);
  };
  const auto &ex = column("A_ex_m"), &ey = column("A_ey_m");
  const auto &vx = column("A_vex_m_s"), &vy = column("A_vey_m_s");
  ASSERT_EQ(ex.size(), 5001u);
  double e_max = 0, v_max = 0;
  for (std::size_t k = 0; k < ex.size(); ++k)
    {
      e_max = std::max(e_max, std::hypot(ex[k], ey[k]));
      v_max = std::max(v_max, std::hypot(vx[k], vy[k]));
    }
  EXPECT_LE(e_max, c + pen + 1e-12 * c);
  EXPECT_GE(e_max, c);
  EXPECT_GT(pen, 0.0);
  EXPECT_LT(pen, 0.05 * c) << "Hertzian approach of microns in a 0.5 mm clearance";
  EXPECT_GT(v_max, 0.0);
  EXPECT_LT(v_max, 10.0);
}

TEST(Analyses, OutputFilesOnlyForListedAnalyses)
{
  // A run with poincare and lyapunov on joint A writes the section CSV, its plots and
  // the Lyapunov curves, and no phase-portrait file; summary.json gives every exponent
  // with its unit.
  const std::string     dir   = wl::fresh_directory("analyses_outputs");
  auto                  scene = wl::scene("params/nine_bar_clearance.prm",
                         {"Simulation/End time=3.0",
                                           "Analyses/List of analyses=poincare, lyapunov",
                                           "Analyses/Joints=A",
                                           "Analyses/Transient=0.5",
                                           "Analyses/Lyapunov/Methods=rosenstein"});
  workflows::RunOptions options;
  options.output_directory = dir;
  const Json s             = workflows::run_scene(scene, options);
  EXPECT_TRUE(std::filesystem::exists(dir + "/poincare_section.csv"));
  EXPECT_TRUE(std::filesystem::exists(dir + "/lyapunov_A_ex_m_rosenstein.csv"));
  EXPECT_TRUE(std::filesystem::exists(dir + "/analysis_series.csv")); // the Lyapunov series
  EXPECT_FALSE(std::filesystem::exists(dir + "/phase_portrait_A_ex_m.png"));
  EXPECT_FALSE(std::filesystem::exists(dir + "/lyapunov_B_ex_m_rosenstein.csv"));
  const Json &l = s.at("analyses").at("lyapunov");
  ASSERT_EQ(l.size(), 1u);
  EXPECT_EQ(l[0].at("channel").get<std::string>(), "A_ex_m");
  EXPECT_EQ(l[0].at("unit").get<std::string>(), "1/s (natural log)");
  EXPECT_NEAR(json_number(l[0].at("exponent_per_s")) * 1e-3, json_number(l[0].at("exponent_per_sample")), 1e-15);
  for (const auto &f : wl::files_in(dir))
    EXPECT_EQ(f.find(".partial-"), std::string::npos) << f; // no temporary left behind
}

TEST(Analyses, IdealMechanismHasZeroLyapunovExponent)
{
  // The ideal nine-bar's motion is exactly periodic (0 DOF): rod 2's x has LLE 0. The
  // sampled orbit repeats itself every 500 samples up to integration drift (~1e-13 m),
  // so a neighbour can be the same state one period later; such recurrences must not be
  // taken as neighbours (they were, through the interpolation of Rosenstein's
  // neighbours, which gave 1.7 1/s from the slow growth of the drift). Bound as for the
  // periodic signals of tests/unit/analysis/lyapunov_test.cc: |λ| T < 0.05 per driving
  // period T = 0.5 s.
  auto        scene = wl::scene("params/nine_bar_ideal.prm",
                         {"Simulation/End time=10.5",
                                 "Analyses/List of analyses=lyapunov",
                                 "Analyses/Bodies=rod2",
                                 "Analyses/Transient=0.5",
                                 "Output/Time series=false"});
  const Json  s     = wl::run(scene);
  const Json &l     = s.at("analyses").at("lyapunov");
  ASSERT_EQ(l.size(), 2u);
  for (std::size_t k = 0; k < l.size(); ++k)
    EXPECT_NEAR(json_number(l[k].at("exponent_per_s")) * 0.5, 0.0, 0.05) << l[k].at("method").get<std::string>();
}

TEST(Analyses, RecordedRunReadsBackFromItsOutputs)
{
  // A run's analyses can be redone later from its output directory (for comparisons of
  // runs made at different times, e.g. before and after wear): read_recorded_run() gives
  // back the series and the section, and analysing them again reproduces the summary's
  // Poincaré spread and Lyapunov exponent. Tolerances: the files hold 12 significant
  // digits, so a spread agrees to 1e-11 of the channel's magnitude; the exponent, a mean over thousands of
  // neighbour pairs whose distances (~1e-6 m) are perturbed by ~1e-15 m, to 1e-6.
  const std::string     dir   = wl::fresh_directory("analyses_read_back");
  auto                  scene = wl::scene("params/nine_bar_clearance.prm",
                         {"Simulation/End time=3.0",
                                           "Analyses/List of analyses=poincare, lyapunov",
                                           "Analyses/Joints=A",
                                           "Analyses/Transient=0.5",
                                           "Analyses/Lyapunov/Methods=rosenstein",
                                           "Output/Time series=false"});
  workflows::RunOptions options;
  options.output_directory = dir;
  const Json  s            = workflows::run_scene(scene, options);
  const Json &original     = s.at("analyses");

  const analysis::RecordedRun run = io::read_recorded_run(dir, "read back");
  EXPECT_EQ(run.series.n_samples(), 2501u); // 0.5 .. 3.0 s every 1 ms
  EXPECT_EQ(run.series.names.size(), 4u);   // A_ex_m, A_ey_m, A_vex_m_s, A_vey_m_s
  EXPECT_EQ(run.series.units[2], "m/s");
  EXPECT_EQ(run.section.points.n_samples(), 6u);
  EXPECT_DOUBLE_EQ(run.driving_period, 0.5);

  const Json again = workflows::analyse_recorded_run(run, scene.analyses, "");
  for (const char *c : {"A_ex_m", "A_vey_m_s", "rod2_y_m"})
    {
      // Each value is rounded to 5e-12 of itself, so a difference of two moves by at
      // most 1e-11 of the largest magnitude.
      double largest = 0.0;
      for (const double v : run.section.points.values[run.section.points.index(c)])
        largest = std::max(largest, std::abs(v));
      EXPECT_NEAR(json_number(again.at("poincare").at("spread").at(c)),
                  json_number(original.at("poincare").at("spread").at(c)),
                  1e-11 * largest)
        << c;
    }
  const double l0 = json_number(original.at("lyapunov")[0].at("exponent_per_s"));
  EXPECT_NEAR(json_number(again.at("lyapunov")[0].at("exponent_per_s")), l0, 1e-6 * std::abs(l0));

  // A run that recorded no analyses has nothing to read back.
  const std::string     plain = wl::fresh_directory("analyses_read_back_none");
  auto                  none  = wl::scene("params/nine_bar_ideal.prm", {"Simulation/End time=0.1"});
  workflows::RunOptions o2;
  o2.output_directory = plain;
  workflows::run_scene(none, o2);
  EXPECT_THROW(io::read_recorded_run(plain), InputError);
}

TEST(Analyses, TwoTrajectoryExponentOfTheSimulation)
{
  // The exponent from the simulation itself (workflows/run/shadow_trajectory.h), two checks with
  // independent expectations:
  //  - ideal nine-bar: 0 DOF, so every displacement of the shadow violates the
  //    constraints and Baumgarte's γ − 2αΦ̇ − β²Φ with α = β = 5 1/s (a critically
  //    damped double root at −5 1/s) pulls it back: λ = −5 1/s at most, a little less in
  //    magnitude because of the double root's secular factor t e^(−5t) between
  //    renormalizations (measured −4.5). Accepted: −5.0 … −4.0 1/s.
  //  - clearance nine-bar: nearby trajectories separate, λ T > 1 per driving period (as
  //    for Wolf and Rosenstein). Its value depends on d0 and on the integration tolerance
  //    (82–238 1/s measured), which is why only the sign and scale are asserted.
  {
    auto        scene = wl::scene("params/nine_bar_ideal.prm",
                           {"Simulation/End time=5.5",
                                   "Analyses/List of analyses=lyapunov",
                                   "Analyses/Transient=0.5",
                                   "Analyses/Lyapunov/Methods=two-trajectory",
                                   "Output/Time series=false"});
    const Json  s     = wl::run(scene);
    const Json &l     = s.at("analyses").at("lyapunov");
    ASSERT_EQ(l.size(), 1u);
    EXPECT_EQ(l[0].at("method").get<std::string>(), "two-trajectory");
    EXPECT_EQ(json_number(l[0].at("renormalizations")), 250); // 5 s / 0.02 s
    EXPECT_GE(json_number(l[0].at("exponent_per_s")), -5.0);
    EXPECT_LE(json_number(l[0].at("exponent_per_s")), -4.0);
  }
  {
    auto       scene = wl::scene("params/nine_bar_clearance.prm",
                           {"Simulation/End time=3.5",
                                  "Analyses/List of analyses=lyapunov",
                                  "Analyses/Transient=0.5",
                                  "Analyses/Lyapunov/Methods=two-trajectory",
                                  "Output/Time series=false"});
    const Json s     = wl::run(scene);
    EXPECT_GT(json_number(s.at("analyses").at("lyapunov")[0].at("exponent_per_s")) * 0.5, 1.0);
  }
}

TEST(Analyses, WearSceneComparesTheDynamicsBeforeAndAfterWear)
{
  // params/nine_bar_wear_dynamics.prm, shortened: one wear iteration of 2 cycles (×500
  // = 1000 revolutions), then the dynamics from assembly to 2.5 s (0.5 s transient + 4
  // cycles) once with the fresh and once with the worn profiles, compared. (Each run's
  // own analyses get a given embedding: 2000 samples are too few for the automatic one.)
  //  - The before-wear run must be the plain clearance scene's run exactly (same steps,
  //    impacts, peak force): the fresh profiles are restored after the wear loop, the
  //    analyses do not perturb the integration, and each run counts its own impacts
  //    (the joint objects count over the whole wear run).
  //  - The after-wear run must differ (the worn profiles are used).
  //  - Exponents of A and B by both methods at the common delay, the seed's values
  //    printed beside them; the stand-alone command on the two run directories gives
  //    the same exponents (values read back with 12 digits: agreement to 1e-6, as in
  //    RecordedRunReadsBackFromItsOutputs).
  const std::string dir = wl::fresh_directory("before_after_wear");
  const auto        r   = wl::run_wearlink({"run",
                                            wl::source_path("params/nine_bar_wear_dynamics.prm"),
                                            "--output",
                                            dir,
                                            "--quiet",
                                            "--set",
                                            "Wear/Number of iterations=1",
                                            "--set",
                                            "Wear/Cycles per iteration=2",
                                            "--set",
                                            "Simulation/End time=2.5",
                                            "--set",
                                            "Analyses/Before-after wear/Delay scan=0.005, 0.01",
                                            "--set",
                                            "Analyses/Lyapunov/Delay=5",
                                            "--set",
                                            "Analyses/Lyapunov/Embedding dimension=4",
                                            "--set",
                                            "Analyses/Before-after wear/Two-trajectory cycles=1"});
  ASSERT_EQ(r.exit_status, 0) << r.output;
  EXPECT_NE(r.output.find("| A_ex_m | wolf | 0.005 |"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("0.076"), std::string::npos) << "the seed's value is printed";

  const std::string plain_dir = wl::fresh_directory("before_after_wear_plain");
  const auto        p         = wl::run_wearlink({"run",
                                                  wl::source_path("params/nine_bar_clearance.prm"),
                                                  "--output",
                                                  plain_dir,
                                                  "--quiet",
                                                  "--set",
                                                  "Integrator/Method=dopri5", // the wear scene's
                                                  "--set",
                                                  "Simulation/End time=2.5"});
  ASSERT_EQ(p.exit_status, 0) << p.output;
  const Json plain  = io::read_json_file(plain_dir + "/summary.json");
  const Json before = io::read_json_file(dir + "/dynamics_before/summary.json");
  const Json after  = io::read_json_file(dir + "/dynamics_after/summary.json");
  EXPECT_EQ(json_number(before.at("steps")), json_number(plain.at("steps")));
  EXPECT_NE(json_number(after.at("steps")), json_number(plain.at("steps")));
  for (const char *j : {"A", "B"})
    {
      const auto &pj = plain.at("clearance_joints").at(j);
      const auto &bj = before.at("clearance_joints").at(j);
      EXPECT_EQ(json_number(bj.at("impacts")), json_number(pj.at("impacts"))) << j;
      EXPECT_EQ(json_number(bj.at("max_normal_force_N")), json_number(pj.at("max_normal_force_N"))) << j;
    }

  const Json  summary = io::read_json_file(dir + "/summary.json");
  const auto &all     = summary.at("before_after").at("lyapunov");
  ASSERT_EQ(all.size(), 5u); // A, B × wolf, rosenstein, and the simulation's own exponent
  // The two-trajectory exponent runs: separate, at the tight tolerance, the worn one
  // reading the worn profiles back from the output directory.
  const auto &tt = all[4];
  EXPECT_EQ(tt.at("method").get<std::string>(), "two-trajectory");
  // The journal rattles in its bore: nearby trajectories of the simulated model
  // separate (measured 119 and 349 1/s at 1e-11 on the full scene, README). A value ≤ 0
  // would mean the shadow did not see the clearance dynamics.
  EXPECT_GT(json_number(tt.at("before_per_s")), 0.0);
  EXPECT_GT(json_number(tt.at("after_per_s")), 0.0);
  {
    std::ifstream     prm(dir + "/exponent_after/parameters.prm");
    std::stringstream text;
    text << prm.rdbuf();
    EXPECT_NE(text.str().find(dir + "/bore_A.csv"), std::string::npos) << "worn profiles read back";
    EXPECT_NE(text.str().find("1e-11"), std::string::npos) << "tight tolerance";
  }
  EXPECT_TRUE(before.at("analyses").at("lyapunov").size() == 4u) << "no shadow in the main runs";
  Json l = Json::array();
  for (std::size_t k = 0; k < 4; ++k)
    l.push_back(all[k]);
  for (std::size_t k = 0; k < l.size(); ++k)
    {
      EXPECT_DOUBLE_EQ(json_number(l[k].at("delay_s")), 0.005);
      // Time-delay exponents of the rattling journal at a 5 ms delay are positive and
      // of order 10–100 1/s (doc/tutorials/nonlinear_dynamics.md: ~50 1/s at 5 ms before and after wear); they are
      // bounded by ln(attractor extent / nearest-neighbour distance) per delay, which
      // for a 0.5 mm clearance sampled at 1 ms cannot reach 1e4 1/s. Outside (0, 1e4)
      // the comparison analysed something else than the journal motion.
      for (const char *state : {"before_per_s", "after_per_s"})
        {
          EXPECT_GT(json_number(l[k].at(state)), 0.0) << state;
          EXPECT_LT(json_number(l[k].at(state)), 1e4) << state;
        }
    }
  EXPECT_EQ(summary.at("before_after").at("delay_scan").size(), 8u);
  for (const char *f : {"before_after.md",
                        "before_after_lyapunov.csv",
                        "dynamics_before/analysis_series.csv",
                        "dynamics_after/poincare_section.csv"})
    EXPECT_TRUE(std::filesystem::exists(dir + "/" + f)) << f;
  if (io::gnuplot_available())
    {
      EXPECT_TRUE(std::filesystem::exists(dir + "/before_after_phase_B_x.png"));
    }

  const std::string again_dir = dir + "/again";
  const auto        c         = wl::run_wearlink(
    {"compare-dynamics", dir + "/dynamics_before", dir + "/dynamics_after", "--output", again_dir, "--scan", "none"});
  ASSERT_EQ(c.exit_status, 0) << c.output;
  std::ifstream csv(again_dir + "/before_after_lyapunov.csv");
  std::string   line;
  std::getline(csv, line);
  std::size_t k = 0;
  while (std::getline(csv, line) && k < l.size())
    {
      const auto f = dealii::Utilities::split_string_list(line, ',');
      ASSERT_GE(f.size(), 6u);
      EXPECT_EQ(f[0], l[k].at("channel").get<std::string>());
      const double b = json_number(l[k].at("before_per_s")), a = json_number(l[k].at("after_per_s"));
      EXPECT_NEAR(std::stod(f[4]), b, 1e-6 * std::abs(b)) << line;
      EXPECT_NEAR(std::stod(f[5]), a, 1e-6 * std::abs(a)) << line;
      ++k;
    }
  EXPECT_EQ(k, l.size());

  // A missing run directory: exit 2, nothing written.
  const auto bad =
    wl::run_wearlink({"compare-dynamics", dir + "/dynamics_before", dir + "/no_such_run", "--output", dir + "/bad"});
  EXPECT_EQ(bad.exit_status, 2) << bad.output;
  EXPECT_NE(bad.output.find("no_such_run"), std::string::npos) << bad.output;
  EXPECT_FALSE(std::filesystem::exists(dir + "/bad"));

  // A body that is not in the runs: refused (it was a row of NaN), nothing written.
  const auto nobody = wl::run_wearlink({"compare-dynamics",
                                        dir + "/dynamics_before",
                                        dir + "/dynamics_after",
                                        "--bodies",
                                        "nobody",
                                        "--output",
                                        dir + "/nobody"});
  EXPECT_EQ(nobody.exit_status, 2) << nobody.output;
  EXPECT_NE(nobody.output.find("--bodies: 'nobody' is not a body of the runs; their bodies are "), std::string::npos)
    << nobody.output;
  EXPECT_FALSE(std::filesystem::exists(dir + "/nobody"));

  // A run of another mechanism (the after run with its bodies renamed, as a slider-crank's
  // differ from the nine-bar's): refused, not compared joint by joint under shared names.
  const std::string other = dir + "/other_mechanism";
  std::filesystem::copy(dir + "/dynamics_after", other, std::filesystem::copy_options::recursive);
  Json renamed      = io::read_json_file(other + "/summary.json");
  Json bodies       = Json::object();
  bodies["crank"]   = renamed.at("bodies").begin().value();
  renamed["bodies"] = bodies;
  std::ofstream(other + "/summary.json") << renamed.dump(2);
  const auto mixed =
    wl::run_wearlink({"compare-dynamics", dir + "/dynamics_before", other, "--output", dir + "/mixed"});
  EXPECT_EQ(mixed.exit_status, 2) << mixed.output;
  EXPECT_NE(mixed.output.find("are of different mechanisms"), std::string::npos) << mixed.output;
  EXPECT_FALSE(std::filesystem::exists(dir + "/mixed"));
}
