// SPDX-License-Identifier: LGPL-2.1-or-later
// The wear loop on the nine-bar (params/nine_bar_wear.prm, shortened):
//  - Bookkeeping: after a wear iteration the volume removed from each surface,
//    Σ_k h_k A_k, equals the integrated Archard volume k_D ∫ F_n |v_t| dt, where the
//    integral is taken here by an independent observer (trapezoidal rule over the
//    accepted steps, from the joint diagnostics). hertz-strip carries F_n as the
//    resultant of its strip (contact/pressure_model.h), so Σ p A = F_n ε/(2 J1(ε)) on
//    each surface, ε = b/R the Hertz strip's half-angle there (b from the round pair's
//    R* and E*, J1 from std::cyl_bessel_j): the observer integrates that too, and only
//    rounding separates them: 1e-9 relative (plus the sequential update's h/R below).
//    The worn profiles carry the same volume: L (A_enclosed(before) − A_enclosed(after))
//    differs from Σ h A only by the second-order term h²/2 per area and the linear
//    interpolation between samples, O(h/R) ≈ 1e-4 relative here; we ask 1e-3.
//  - Resume: a run stopped after 1 iteration and resumed to 3 ends with exactly the
//    profiles, state and volumes of an uninterrupted 3-iteration run: the checkpoint
//    holds everything the next iteration depends on, written in hexadecimal floating
//    point, so the two runs do the same arithmetic (bitwise equality is asserted).
//  - Effects: wear off → no wear law, no pressure model, no wear buffers, no gmsh;
//    wear on with hertz-strip → only that pressure model, still no gmsh.
#include "contact/clearance_joint.h"
#include "scene_support.h"
#include "workflows/compare/pressure_comparison.h"
#include "workflows/wear/wear_run.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>

using namespace wearlink;

namespace
{
  /**
   * k_D-free ∫ F_n |v_t| dt per joint by the trapezoidal rule over accepted steps, and
   * ∫ F_n ε/(2 J1(ε)) |v_t| dt with the Hertz strip's half-angle ε on the bore and on
   * the pin of the joint's round pair (the file comment).
   */
  class FrictionWorkObserver : public mbs::StepObserver
  {
  public:
    explicit FrictionWorkObserver(std::vector<contact::ClearanceJoint *> j)
      : joints(std::move(j))
      , integral(joints.size(), 0.0)
      , bore_integral(joints.size(), 0.0)
      , pin_integral(joints.size(), 0.0)
      , last(3 * joints.size(), 0.0)
    {
    }
    void
    on_start(const mbs::StepContext &c) override
    {
      t_last = c.t;
      eval(c, last);
    }
    void
    on_step(const mbs::StepContext &c) override
    {
      std::vector<double> now(last.size());
      eval(c, now);
      for (unsigned i = 0; i < joints.size(); ++i)
        {
          integral[i] += 0.5 * (c.t - t_last) * (now[3 * i] + last[3 * i]);
          bore_integral[i] += 0.5 * (c.t - t_last) * (now[3 * i + 1] + last[3 * i + 1]);
          pin_integral[i] += 0.5 * (c.t - t_last) * (now[3 * i + 2] + last[3 * i + 2]);
        }
      last   = now;
      t_last = c.t;
    }
    std::vector<contact::ClearanceJoint *> joints;
    std::vector<double>                    integral, bore_integral, pin_integral, last;
    double                                 t_last = 0;

  private:
    void
    eval(const mbs::StepContext &c, std::vector<double> &out)
    {
      const auto n = c.simulation.get_mechanism().n_coordinates();
      for (unsigned i = 0; i < joints.size(); ++i)
        {
          const auto   d     = joints[i]->diagnostics(mbs::StateView(c.y.data(), c.y.data() + n));
          const double power = d.normal_force * std::abs(d.sliding_velocity);
          const auto  &g     = joints[i]->get_description().geometry;
          const double r1 = g.bore[0], r2 = g.pin[0];
          const double e_star = 1 / (g.bushing.compliance() + g.pin_material.compliance());
          const double b      = std::sqrt(4 * d.normal_force / g.axial_length * r1 * r2 / (r1 - r2) / (M_PI * e_star));
          const auto   scale  = [](const double epsilon) {
            return epsilon > 0 ? epsilon / (2 * std::cyl_bessel_j(1.0, epsilon)) : 1.0;
          };
          out[3 * i]     = power;
          out[3 * i + 1] = power * scale(b / r1);
          out[3 * i + 2] = power * scale(b / r2);
        }
    }
  };

  const std::vector<std::string> short_run = {"Wear/Cycles per iteration=0.5", "Wear/Response cycles=0.1"};

  using wearlink::testing::with;
} // namespace

TEST(Wear, VolumeBookkeepingMatchesIntegratedArchard)
{
  // One iteration of half a cycle, factor 1: the summary's volumes are one iteration's.
  auto scene2 =
    wearlink::testing::scene("params/nine_bar_wear.prm",
                             with(short_run, {"Wear/Number of iterations=1", "Wear/Extrapolation factor=1"}));
  FrictionWorkObserver      work(scene2.clearance_joints);
  workflows::WearRunOptions o;
  o.progress      = false;
  o.final_outputs = false;
  o.observers     = {&work};
  const auto r    = workflows::run_wear(scene2, o);
  ASSERT_EQ(r.state.joints.size(), 2u);
  for (unsigned i = 0; i < 2; ++i)
    {
      const auto  &js            = r.state.joints[i];
      const auto  &w             = *scene2.wear[i];
      const auto  &h             = js.history.back();
      const double expected_pin  = w.archard.pin_coefficient * work.pin_integral[i];
      const double expected_bore = w.archard.bushing_coefficient * work.bore_integral[i];
      ASSERT_GT(expected_pin, 0) << js.name;
      // The sequential update wears the surfaces state by state, so a strip spread on
      // surfaces already worn by h carries F_n over areas whose radii differ from the
      // start's by up to h: the local volume is the expected one to h/R (and to 1e-9).
      const double worn = std::max(h.max_depth_pin / js.pin.min_radius(), h.max_depth_bore / js.bore.min_radius());
      EXPECT_NEAR(h.volume_pin, expected_pin, (1e-9 + worn) * expected_pin) << js.name;
      EXPECT_NEAR(h.volume_bore, expected_bore, (1e-9 + worn) * expected_bore) << js.name;
      // Σ depth × area from the stored depths (areas of the profiles the wear was
      // accumulated on: the initial ones).
      const double length  = scene2.clearance_joints[i]->get_description().geometry.axial_length;
      const double dpsi    = 2 * M_PI / js.pin.n_points();
      double       sum_pin = 0, sum_bore = 0;
      for (unsigned k = 0; k < js.pin.n_points(); ++k)
        {
          sum_pin += h.depth_pin[k] * length * js.initial_pin[k] * dpsi;
          sum_bore += h.depth_bore[k] * length * js.initial_bore[k] * dpsi;
        }
      // The stored depth is a difference of radii, R* − R, so each area carries a
      // rounding error of up to 2 ε R: the sum may be off by 2 ε R (2π R L).
      const double eps        = std::numeric_limits<double>::epsilon();
      const double round_pin  = 2 * eps * js.initial_pin[0] * 2 * M_PI * js.initial_pin[0] * length;
      const double round_bore = 2 * eps * js.initial_bore[0] * 2 * M_PI * js.initial_bore[0] * length;
      EXPECT_NEAR(sum_pin, expected_pin, (1e-9 + worn) * expected_pin + round_pin) << js.name;
      EXPECT_NEAR(sum_bore, expected_bore, (1e-9 + worn) * expected_bore + round_bore) << js.name;
      // The profiles: enclosed-area change × L.
      const double v_pin  = length * (js.initial_pin.enclosed_area() - js.pin.enclosed_area());
      const double v_bore = length * (js.bore.enclosed_area() - js.initial_bore.enclosed_area());
      EXPECT_NEAR(v_pin, expected_pin, 1e-3 * expected_pin) << js.name;
      EXPECT_NEAR(v_bore, expected_bore, 1e-3 * expected_bore) << js.name;
    }
}

TEST(Wear, ResumedRunEqualsUninterruptedRun)
{
  const auto                base = with(short_run, {"Wear/Number of iterations=3", "Wear/Extrapolation factor=2000"});
  workflows::WearRunOptions o;
  o.progress      = false;
  o.final_outputs = false;

  auto straight_scene = wearlink::testing::scene("params/nine_bar_wear.prm", base);
  o.output_directory  = wearlink::testing::fresh_directory("wear_straight");
  const auto straight = workflows::run_wear(straight_scene, o);
  ASSERT_EQ(straight.state.iterations_done, 3u);

  // "Killed" after one iteration of three, then resumed by a fresh process state.
  o.output_directory = wearlink::testing::fresh_directory("wear_resumed");
  {
    auto s       = wearlink::testing::scene("params/nine_bar_wear.prm", base);
    o.stop_after = 1;
    const auto k = workflows::run_wear(s, o);
    EXPECT_FALSE(k.finished);
    EXPECT_EQ(k.state.iterations_done, 1u);
  }
  auto s2            = wearlink::testing::scene("params/nine_bar_wear.prm", base);
  o.stop_after       = 0;
  o.resume           = true;
  const auto resumed = workflows::run_wear(s2, o);
  ASSERT_TRUE(resumed.finished);
  ASSERT_EQ(resumed.state.iterations_done, 3u);
  EXPECT_EQ(resumed.state.revolutions, straight.state.revolutions);
  EXPECT_EQ(resumed.state.time, straight.state.time);
  for (unsigned i = 0; i < straight.state.joints.size(); ++i)
    {
      const auto &a = straight.state.joints[i];
      const auto &b = resumed.state.joints[i];
      EXPECT_EQ(a.pin.samples(), b.pin.samples()) << a.name;
      EXPECT_EQ(a.bore.samples(), b.bore.samples()) << a.name;
      EXPECT_EQ(a.history.back().volume_pin, b.history.back().volume_pin) << a.name;
      // The wear is real, not zero (else equality would be trivial).
      EXPECT_GT(a.history.back().max_depth_pin, 1e-8) << a.name;
      EXPECT_GT(a.history.back().max_depth_bore, 1e-8) << a.name;
    }
  for (int k = 0; k < straight.state.state.size(); ++k)
    EXPECT_EQ(straight.state.state[k], resumed.state.state[k]) << "state component " << k;
}

TEST(Wear, ResumeRefusesAnotherScene)
{
  workflows::WearRunOptions o;
  o.progress         = false;
  o.final_outputs    = false;
  o.output_directory = wearlink::testing::fresh_directory("wear_other_scene");
  o.stop_after       = 1;
  {
    auto s = wearlink::testing::scene("params/nine_bar_wear.prm", with(short_run, {"Wear/Number of iterations=2"}));
    workflows::run_wear(s, o);
  }
  auto s = wearlink::testing::scene(
    "params/nine_bar_wear.prm",
    with(short_run, {"Wear/Number of iterations=2", "Joint A/Clearance/archard/Pin wear coefficient=1e-12"}));
  o.stop_after = 0;
  o.resume     = true;
  EXPECT_THROW(workflows::run_wear(s, o), InputError);
}

TEST(Effects, WearOffConstructsNoWearCode)
{
  auto scene = wearlink::testing::scene("params/nine_bar_clearance.prm", {"Simulation/End time=0.05"});
  EXPECT_FALSE(workflows::has_wear(scene));
  wearlink::testing::run(scene);
  auto &ledger = EffectLedger::instance();
  EXPECT_EQ(ledger.constructions("wear law"), 0);
  EXPECT_EQ(ledger.constructions("pressure model"), 0);
  EXPECT_EQ(ledger.resources("wear buffers"), 0);
  EXPECT_EQ(ledger.resources("gmsh sessions"), 0);
  EXPECT_EQ(ledger.resources("triangulations"), 0);
}

TEST(Effects, HertzStripWearConstructsOnlyItsPressureModel)
{
  auto scene = wearlink::testing::scene("params/nine_bar_wear.prm", with(short_run, {"Wear/Number of iterations=1"}));
  workflows::WearRunOptions o;
  o.progress      = false;
  o.final_outputs = false;
  workflows::run_wear(scene, o);
  auto &ledger = EffectLedger::instance();
  EXPECT_EQ(ledger.constructions("wear law", "archard"), 2);
  EXPECT_EQ(ledger.constructions("pressure model", "hertz-strip"), 2);
  EXPECT_EQ(ledger.constructions("pressure model", "winkler"), 0);
  EXPECT_EQ(ledger.constructions("pressure model", "fe"), 0);
  EXPECT_EQ(ledger.resources("wear buffers"), 2);
  EXPECT_EQ(ledger.resources("gmsh sessions"), 0);
  EXPECT_EQ(ledger.resources("triangulations"), 0);
}

// "Validating simplified contact": the same load history (a quarter cycle of the
// nine-bar, pressure shapes at 200 samples per cycle) through hertz-strip and winkler. Both conserve the force (winkler to its
// foundation's Σ p A / F − 1 = O(ε²) for the narrow arcs of a fresh joint), so the worn
// volumes agree within 2 %; the profiles differ (the Hertz strip is √F-wide, the
// foundation's arc follows the overlap), which the L2 column quantifies — asserted
// non-zero but not bounded, since that difference is the finding, not a defect.
TEST(Wear, PressureModelComparisonSameLoadsSimilarVolumes)
{
  auto scene =
    wearlink::testing::scene("params/nine_bar_wear.prm",
                             {"Wear/Pressure evaluation=samples per cycle", "Wear/Load samples per cycle=200"});
  const auto c = workflows::compare_pressure_models(scene, {"hertz-strip", "winkler"}, 0.25);
  std::cout << c.table();
  ASSERT_EQ(c.rows.size(), 4u); // 2 joints × 2 models
  for (unsigned j = 0; j < 2; ++j)
    {
      const auto &h = c.rows[2 * j];
      const auto &w = c.rows[2 * j + 1];
      ASSERT_EQ(h.model, "hertz-strip");
      ASSERT_GT(h.volume_pin, 0);
      EXPECT_NEAR(w.volume_pin, h.volume_pin, 0.02 * h.volume_pin) << h.joint;
      EXPECT_NEAR(w.volume_bore, h.volume_bore, 0.02 * h.volume_bore) << h.joint;
      EXPECT_GT(h.difference_pin, 0) << h.joint;
      EXPECT_EQ(w.difference_pin, 0) << "the last model is the reference";
    }
}

namespace
{
  /** Three iterations of nine_bar_wear.prm with joint A on a coarse fe model (0.2 mm), its loads sampled. */
  const std::vector<std::string> fe_files_run = with(short_run,
                                                     {"Wear/Number of iterations=3",
                                                      "Wear/Pressure evaluation=samples per cycle",
                                                      "Wear/Load samples per cycle=25",
                                                      "Joint A/Clearance/Pressure model=fe",
                                                      "Joint A/Clearance/fe/Surface element size=2e-4"});

  /** Run @p overrides of nine_bar_wear.prm into a fresh folder named @p name; returns the folder. */
  std::string
  wear_files_of(const std::vector<std::string> &overrides, const std::string &name)
  {
    workflows::WearRunOptions o;
    o.progress         = false;
    o.final_outputs    = false;
    o.output_directory = wearlink::testing::fresh_directory(name);
    auto scene         = wearlink::testing::scene("params/nine_bar_wear.prm", overrides);
    EXPECT_EQ(workflows::run_wear(scene, o).state.iterations_done, 3u);
    return o.output_directory;
  }
} // namespace

// FE files of a wear run with the fe pressure model (Wear/FE output, default on), with
// Wear/Output every iteration: the mesh in use after every iteration in which it changed
// (Remesh depth 0: a new mesh after every iteration), the fields at the peak load of
// every iteration, and every profile frame; nothing for the hertz-strip joint B.
TEST(Wear, FeWearRunWritesEveryIterationsFilesOnRequest)
{
  const std::string dir = wear_files_of(with(fe_files_run, {"Wear/Output every iteration=true"}), "wear_fe_files");
  const std::string fe  = dir + "/fe/";
  for (const char *f : {"mesh_A_1.msh",
                        "mesh_A_2.msh",
                        "mesh_A_3.msh",
                        "fields_A_iteration1.vtu",
                        "fields_A_iteration1_pressure.csv",
                        "fields_A_iteration2.vtu",
                        "fields_A_iteration3.vtu",
                        "fields_A_iteration3_pressure.csv"})
    EXPECT_TRUE(std::filesystem::exists(fe + f)) << f << ": every iteration's";
  EXPECT_TRUE(std::filesystem::exists(fe + "fields_A.pvd")) << "their ParaView series";
  EXPECT_TRUE(std::filesystem::exists(dir + "/profiles_A.pvd"));
  for (const char *f : {"profile_B_0.vtu", "profile_B_1.vtu", "profile_B_2.vtu", "profile_B_3.vtu"})
    EXPECT_TRUE(std::filesystem::exists(dir + "/profiles/" + f)) << f << ": every joint's profiles";
  EXPECT_FALSE(std::filesystem::exists(fe + "mesh_B_1.msh")) << "joint B is on hertz-strip";
}

// By default a wear run keeps the last iteration's files only: its mesh, its fields, the
// unworn and the last profile frames, each listed in its .pvd; a mesh kept across the
// iterations (Remesh depth 20 elements = 4 mm, far beyond three iterations' wear) is the
// one copied after the first. FE output off: no fe/ folder.
TEST(Wear, FeWearRunKeepsTheLastIterationsFilesByDefault)
{
  const std::string dir = wear_files_of(fe_files_run, "wear_fe_files_last");
  const std::string fe  = dir + "/fe/";
  for (const char *f : {"mesh_A_3.msh", "fields_A_iteration3.vtu", "fields_A_iteration3_pressure.csv"})
    EXPECT_TRUE(std::filesystem::exists(fe + f)) << f << ": the last iteration's";
  for (const char *f : {"mesh_A_1.msh",
                        "mesh_A_2.msh",
                        "fields_A_iteration1.vtu",
                        "fields_A_iteration2.vtu",
                        "fields_A_iteration2_pressure.csv"})
    EXPECT_FALSE(std::filesystem::exists(fe + f)) << f << ": replaced by the last iteration's";
  for (const char *f : {"profile_A_0.vtu", "profile_A_3.vtu", "profile_B_0.vtu", "profile_B_3.vtu"})
    EXPECT_TRUE(std::filesystem::exists(dir + "/profiles/" + f)) << f << ": unworn and last";
  for (const char *f : {"profile_A_1.vtu", "profile_A_2.vtu", "profile_B_2.vtu"})
    EXPECT_FALSE(std::filesystem::exists(dir + "/profiles/" + f)) << f;
  const std::string fields   = wearlink::testing::file_content(fe + "fields_A.pvd"),
                    profiles = wearlink::testing::file_content(dir + "/profiles_A.pvd");
  EXPECT_NE(fields.find("fields_A_iteration3.vtu"), std::string::npos) << fields;
  EXPECT_EQ(fields.find("fields_A_iteration2.vtu"), std::string::npos) << "the .pvd lists what is kept";
  EXPECT_NE(profiles.find("profile_A_0.vtu"), std::string::npos) << profiles;
  EXPECT_NE(profiles.find("profile_A_3.vtu"), std::string::npos) << profiles;
  EXPECT_EQ(profiles.find("profile_A_2.vtu"), std::string::npos) << "the .pvd lists what is kept";

  const std::string kept =
    wear_files_of(with(fe_files_run, {"Joint A/Clearance/fe/Remesh depth=20"}), "wear_fe_files_kept");
  EXPECT_TRUE(std::filesystem::exists(kept + "/fe/mesh_A_1.msh")) << "the mesh in use";
  EXPECT_FALSE(std::filesystem::exists(kept + "/fe/mesh_A_2.msh")) << "the mesh is kept";
  EXPECT_TRUE(std::filesystem::exists(kept + "/fe/fields_A_iteration3.vtu"));

  const std::string off = wear_files_of(with(fe_files_run, {"Wear/FE output=false"}), "wear_fe_files_off");
  EXPECT_FALSE(std::filesystem::exists(off + "/fe"));
}

// The FE scene's wear loop (fe pressure model and fe contact law on both joints, a kept
// mesh between re-meshes) resumed from a checkpoint: the resumed run meshes the geometry
// the killed one had meshed, takes the current profiles into its gaps, rebuilds the
// law's worn tables, and ends with the profiles, volumes and mechanism state of an
// uninterrupted run. Coarse (0.2 mm elements, Remesh depth 0.05 = 10 µm: the 1 µm of
// wear stays on the first mesh) and short. Equality is asserted to 1e-12 relative: the
// compliance columns are computed in blocks whose make-up depends on which columns a
// run asked for first, which may change the last bits of a column.
TEST(Wear, FeSceneResumedRunEqualsUninterruptedRun)
{
  std::vector<std::string> base = with(short_run, {"Wear/Number of iterations=3", "Wear/Extrapolation factor=1000"});
  for (const char *j : {"A", "B"})
    for (const char *e : {"fe/Surface element size=2e-4", "fe/Remesh depth=0.05"})
      base.push_back(std::string("Joint ") + j + "/Clearance/" + e);
  workflows::WearRunOptions o;
  o.progress      = false;
  o.final_outputs = false;

  auto straight_scene = wearlink::testing::scene("params/nine_bar_wear_fe.prm", base);
  o.output_directory  = wearlink::testing::fresh_directory("wear_fe_straight");
  const auto straight = workflows::run_wear(straight_scene, o);
  ASSERT_EQ(straight.state.iterations_done, 3u);

  o.output_directory = wearlink::testing::fresh_directory("wear_fe_resumed");
  {
    auto s       = wearlink::testing::scene("params/nine_bar_wear_fe.prm", base);
    o.stop_after = 1;
    workflows::run_wear(s, o);
  }
  auto s2            = wearlink::testing::scene("params/nine_bar_wear_fe.prm", base);
  o.stop_after       = 0;
  o.resume           = true;
  const auto resumed = workflows::run_wear(s2, o);
  ASSERT_EQ(resumed.state.iterations_done, 3u);
  for (unsigned i = 0; i < straight.state.joints.size(); ++i)
    {
      const auto &a = straight.state.joints[i];
      const auto &b = resumed.state.joints[i];
      std::cout << a.name << ": bore depth " << a.history.back().max_depth_bore << " m, meshed bore drift "
                << std::abs(a.meshed_bore.max_radius() - a.bore.max_radius()) << " m\n";
      EXPECT_GT(a.history.back().max_depth_bore, 1e-8) << a.name;
      for (unsigned k = 0; k < a.bore.n_points(); ++k)
        {
          ASSERT_NEAR(a.bore[k], b.bore[k], 1e-12 * a.bore[k]) << a.name << " bore sample " << k;
          ASSERT_NEAR(a.pin[k], b.pin[k], 1e-12 * a.pin[k]) << a.name << " pin sample " << k;
        }
      EXPECT_NEAR(a.history.back().volume_pin, b.history.back().volume_pin, 1e-12 * a.history.back().volume_pin);
      EXPECT_EQ(a.meshed_bore.samples(), b.meshed_bore.samples()) << a.name;
    }
  for (int k = 0; k < straight.state.state.size(); ++k)
    EXPECT_NEAR(straight.state.state[k], resumed.state.state[k], 1e-9 * (1 + std::abs(straight.state.state[k])))
      << "state component " << k;
}
