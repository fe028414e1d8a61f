// SPDX-License-Identifier: LGPL-2.1-or-later
// `wearlink compare-contact` on the nine-bar (coarse FE surfaces, 50 µm, few cycles, to
// keep it at seconds): the sphere-law column is the closed form K δ^1.5, the FE column
// passes through the FE load levels, the deviations are those of the columns, and the
// effect runs report every dynamics law. The pressure distributions carry their load,
// hertz-strip's is the Hertz strip of that load and winkler's the closed form of a
// linear layer on round profiles; a wear scene's effect runs wear pin and bushing by
// Archard's k_D ∫ F_n |v_t| dt.
#include "base/numbers.h"
#include "contact/clearance_joint.h"
#include "io/csv.h"
#include "io/plot.h"
#include "io/profile_file.h"
#include "scene_support.h"
#include "workflows/compare/contact_comparison.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <sstream>

using namespace wearlink;
using numbers::pi;

namespace
{
  /** The coarse FE surfaces of both joints (50 µm instead of 25 µm). */
  std::vector<std::string>
  coarse_fe()
  {
    return {"Joint A/Clearance/fe/Surface element size=5e-5", "Joint B/Clearance/fe/Surface element size=5e-5"};
  }

  /**
   * The resultant of curve @p c's pressure along its load direction,
   * Σ_k p_k L R_k Δψ cos(ψ_k − ψ0) [N] (R_k the radius of bore area k).
   */
  double
  carried_load(const workflows::PressureCurve &c, const std::vector<double> &angle, const contact::JointGeometry &g)
  {
    const double width = 2 * pi / angle.size();
    double       f     = 0;
    for (std::size_t k = 0; k < angle.size(); ++k)
      f += c.pressure[k] * g.axial_length * g.bore.radius(angle[k]) * width * std::cos(angle[k] - c.direction);
    return f;
  }

  /** Hertz line contact of load @p force on the round pair @p g: half-width b [m], peak p0 [Pa]. */
  std::pair<double, double>
  hertz(const double force, const contact::JointGeometry &g)
  {
    const auto compliance = [](const contact::Material &m) {
      return (1 - m.poisson_ratio * m.poisson_ratio) / m.youngs_modulus;
    };
    const double e_star = 1 / (compliance(g.bushing) + compliance(g.pin_material));
    const double r1 = g.bore.mean_radius(), r2 = g.pin.mean_radius();
    const double line_load = force / g.axial_length;
    const double b         = std::sqrt(4 * line_load * (r1 * r2 / (r1 - r2)) / (pi * e_star));
    return {b, 2 * line_load / (pi * b)};
  }

  /** The column name of curve @p c (doc/tutorials/fe_contact.md: whole newtons from 100 N on). */
  std::string
  column(const workflows::PressureCurve &c)
  {
    std::ostringstream load;
    if (c.load >= 100)
      load << std::llround(c.load);
    else
      load << std::setprecision(3) << c.load;
    return "pressure_Pa_" + c.model + "_" + c.state + "_" + c.joint + "_" + load.str() + "N";
  }

  /** Every curve's load carried to within @p tolerance, its column present in @p dir/pressure.csv. */
  void
  expect_pressure_file_and_loads(const workflows::ContactComparison &c,
                                 const std::string                  &dir,
                                 const contact::JointGeometry       &fresh,
                                 const contact::JointGeometry       &worn,
                                 const double                        tolerance)
  {
    const auto table = io::CsvTable::read(dir + "/pressure.csv", "pressure file");
    EXPECT_EQ(table.columns().front(), "bore_angle_rad");
    EXPECT_EQ(table.n_rows(), c.pressures.bore_angle.size());
    EXPECT_EQ(table.n_columns(), c.pressures.curves.size() + 1);
    for (const auto &p : c.pressures.curves)
      {
        EXPECT_TRUE(p.failure.empty()) << column(p) << ": " << p.failure;
        EXPECT_NE(table.find(column(p)), io::CsvTable::npos) << column(p);
        const double carried = carried_load(p, c.pressures.bore_angle, p.state == "worn" ? worn : fresh);
        EXPECT_NEAR(carried / p.load, 1.0, tolerance) << column(p);
      }
  }
} // namespace

TEST(ContactComparison, ColumnsAreTheLawsAndEffectsCoverEveryDynamicsLaw)
{
  ::setenv("WEARLINK_CACHE_DIR", wearlink::testing::fresh_directory("contact_comparison_cache").c_str(), 1);
  workflows::ContactComparisonRequest r;
  r.scene_file = wearlink::testing::source_path("params/nine_bar_clearance.prm");
  r.overrides  = ParameterOverrides(coarse_fe());
  r.cycles     = 2;
  r.progress   = false;
  const auto c = workflows::compare_contact(r);
  ::unsetenv("WEARLINK_CACHE_DIR");

  io::Scene    scene = wearlink::testing::scene("params/nine_bar_clearance.prm");
  const double K     = scene.clearance_joints.at(0)->stiffness();
  ASSERT_EQ(c.joints, (std::vector<std::string>{"A", "B"}));
  bool saw_sphere = false, saw_fe = false;
  for (const auto &fc : c.curves)
    {
      ASSERT_EQ(fc.force.size(), c.approach.size());
      if (fc.joint == "A" && fc.law == "lankarani-nikravesh")
        {
          saw_sphere = true;
          for (std::size_t i = 0; i < c.approach.size(); ++i)
            EXPECT_DOUBLE_EQ(fc.force[i], K * std::pow(c.approach[i], 1.5));
        }
      if (fc.joint == "A" && fc.law == "fe")
        {
          saw_fe = true;
          // The grid starts at the FE approach of the smallest level (10 N) and ends at the largest (100 kN).
          EXPECT_NEAR(fc.force.front() / 10.0, 1.0, 1e-6);
          EXPECT_NEAR(fc.force.back() / 1e5, 1.0, 1e-6);
        }
    }
  EXPECT_TRUE(saw_sphere && saw_fe);
  for (const auto &d : c.deviations)
    {
      if (d.law == "fe" && d.state == "fresh")
        {
          for (const double x : d.ratio)
            EXPECT_NEAR(x, 1.0, 1e-6);
        }
      else if (d.law == "lankarani-nikravesh")
        {
          EXPECT_LT(d.ratio[0], 0.5) << "the sphere law is far more compliant than FE at 100 N";
        }
    }

  ASSERT_EQ(c.effects.size(), 4u);
  for (const auto &e : c.effects)
    for (std::size_t k = 0; k < 2; ++k)
      {
        EXPECT_GT(e.contact_fraction[k], 0.0) << e.law;
        EXPECT_LE(e.contact_fraction[k], 1.0) << e.law;
        EXPECT_GT(e.peak_force[k], 0.0) << e.law;
        EXPECT_GT(e.mean_contact_force[k], 0.0) << e.law;
        EXPECT_LT(e.mean_contact_force[k], e.peak_force[k]) << e.law;
        EXPECT_TRUE(e.wear_volume_pin.empty()) << "no wear law, no wear iteration";
      }
  EXPECT_EQ(c.effects.back().law, "fe");
  EXPECT_GT(c.effects.back().table_setup_time, 0.0);
  EXPECT_TRUE(c.wear_joints.empty());

  const std::string dir = wearlink::testing::fresh_directory("contact_comparison") + "/out";
  workflows::write_contact_comparison(dir, c);
  const auto table = io::CsvTable::read(dir + "/force_approach.csv", "force-approach file");
  EXPECT_EQ(table.columns().front(), "approach_m");
  EXPECT_NE(table.find("force_N_fe_fresh_A"), io::CsvTable::npos);
  EXPECT_EQ(table.n_rows(), c.approach.size());
  const auto effects = io::CsvTable::read(dir + "/effects.csv", "effects file");
  for (const auto &name : effects.columns())
    EXPECT_EQ(name.find("wear"), std::string::npos) << name << ": a scene without wear has no wear columns";
}

TEST(ContactComparison, PressureDistributionsCarryTheLoadAndHertzStripIsTheHertzStrip)
{
  ::setenv("WEARLINK_CACHE_DIR", wearlink::testing::fresh_directory("contact_pressure_cache").c_str(), 1);
  workflows::ContactComparisonRequest r;
  r.scene_file        = wearlink::testing::source_path("params/nine_bar_clearance.prm");
  r.overrides         = ParameterOverrides(coarse_fe());
  r.effects           = false;
  r.load_range_cycles = 2;
  r.progress          = false;
  const auto c        = workflows::compare_contact(r);
  ::unsetenv("WEARLINK_CACHE_DIR");

  io::Scene   scene = wearlink::testing::scene("params/nine_bar_clearance.prm");
  const auto &g     = scene.clearance_joints.at(0)->get_description().geometry;
  // Two models (no winkler/Layer thickness in this scene), one state, four loads, two joints.
  ASSERT_EQ(c.pressures.curves.size(), 2u * 4u * 2u);
  const double width = 2 * pi / c.pressures.bore_angle.size(); // Δψ of the 360 areas
  for (const auto &p : c.pressures.curves)
    {
      EXPECT_EQ(p.state, "fresh");
      EXPECT_NEAR(p.direction, 1.5 * pi, 1e-12) << "the bushing's −y without worn profiles";
      if (p.model != "hertz-strip")
        continue;
      const auto [b, p0] = hertz(p.load, g);
      const double arc   = g.bore.mean_radius() * width;
      // The strip carries F_n as its resultant: its pressure is the Hertz one scaled by
      // ε/(2 J1(ε)), ε = b/R1 (contact/pressure_models/hertz_strip.cc; J1 here from
      // std::cyl_bessel_j). The peak area is centred on the contact (270° is an area
      // centre): its average of p0 √(1 − s²/b²) over |s| ≤ Δs/2 is below p0 by
      // Δs²/(24 b²) to leading order.
      const double epsilon = b / g.bore.mean_radius();
      const double peak    = p0 * epsilon / (2 * std::cyl_bessel_j(1.0, epsilon));
      EXPECT_LE(p.peak, peak * (1 + 1e-12)) << p.load;
      EXPECT_NEAR(p.peak / peak, 1.0, arc * arc / (12 * b * b)) << p.load << " N, b = " << b;
      // α_c is the Hertz half-angle b/R1 once the strip spans 2 areas (Sheppard's
      // correction of the area width leaves at most 2.8 % there, less beyond).
      if (b / g.bore.mean_radius() > 2 * width)
        {
          EXPECT_NEAR(p.half_angle / (b / g.bore.mean_radius()), 1.0, 0.03) << p.load;
        }
    }
  // The loads span the L-N run: increasing, the first its mean, the last its peak (3 digits).
  for (std::size_t k = 0; k + 1 < 4; ++k)
    EXPECT_LT(c.pressures.curves[k].load, c.pressures.curves[k + 1].load);

  const std::string dir = wearlink::testing::fresh_directory("contact_pressures") + "/out";
  workflows::write_contact_comparison(dir, c);
  // hertz-strip carries F_n as its resultant to the areas' direction quantization, the
  // fe model to its equilibrium tolerance and the nodal forces' radial direction: 1 %.
  expect_pressure_file_and_loads(c, dir, g, g, 0.01);
  EXPECT_TRUE(std::filesystem::exists(dir + "/pressure.png") || !io::gnuplot_available());
}

namespace
{
  /**
   * Worn profiles of joints A and B into @p dir (bore_<J>.csv, pin_<J>.csv, as a wear run
   * writes them): a smooth dent 10 µm deep and ±20° wide in the bore at 270° (bushing
   * frame) and 5 µm in the pin at 90° (pin frame).
   */
  void
  write_worn_profiles(const std::string &dir, const contact::JointGeometry &g)
  {
    const auto dent = [](const Profile &p, const double centre, const double depth) {
      std::vector<double> r = p.samples();
      for (unsigned int k = 0; k < p.n_points(); ++k)
        {
          const double x = std::remainder(p.angle(k) - centre, 2 * pi) / (20 * pi / 180);
          if (std::abs(x) < 1)
            r[k] += depth * 0.5 * (1 + std::cos(pi * x));
        }
      return Profile::from_samples(r);
    };
    for (const char *joint : {"A", "B"})
      {
        io::write_profile_csv(dent(g.bore, 1.5 * pi, 10e-6), dir + "/bore_" + joint + ".csv");
        io::write_profile_csv(dent(g.pin, 0.5 * pi, -5e-6), dir + "/pin_" + joint + ".csv");
      }
  }
} // namespace

TEST(ContactComparison, WearSceneWearsEachLawAndWinklerIsItsClosedForm)
{
  ::setenv("WEARLINK_CACHE_DIR", wearlink::testing::fresh_directory("contact_wear_cache").c_str(), 1);
  io::Scene         scene = wearlink::testing::scene("params/nine_bar_wear.prm");
  const auto        g     = scene.clearance_joints.at(0)->get_description().geometry;
  const std::string worn  = wearlink::testing::fresh_directory("contact_wear_worn");
  write_worn_profiles(worn, g);
  workflows::ContactComparisonRequest r;
  r.scene_file = wearlink::testing::source_path("params/nine_bar_wear.prm");
  r.overrides  = ParameterOverrides(coarse_fe());
  r.overrides.set("Wear/Cycles per iteration", 1.0);
  r.cycles         = 1;
  r.worn_directory = worn;
  r.progress       = false;
  const auto c     = workflows::compare_contact(r);
  ::unsetenv("WEARLINK_CACHE_DIR");

  // One wear iteration per law: both joints wear, by Archard's volume k_D ∫ F_n |v_t| dt
  // times hertz-strip's Σ p A / F_n = ε/(2 J1(ε)) = 1 + ε²/8 + … (its strip carries F_n
  // as its resultant; ε = b/R the strip's half-angle, at most that of the run's peak
  // force, ~1e-4), and pin and bushing equally to that (same k_D, same force, same
  // sliding; ε differs between them by R2/R1). Round-off: 1e-9.
  ASSERT_EQ(c.wear_joints, (std::vector<std::string>{"A", "B"}));
  EXPECT_EQ(c.wear_cycles, 1.0);
  ASSERT_EQ(c.effects.size(), 4u);
  for (const auto &e : c.effects)
    for (std::size_t k = 0; k < 2; ++k)
      {
        const double widest = hertz(e.peak_force[k], g).first / g.pin.mean_radius();
        const double excess = widest * widest / 8 + 1e-9;
        EXPECT_GT(e.wear_volume_pin[k], 0.0) << e.law;
        EXPECT_NEAR(e.wear_volume_pin[k] / e.archard_volume_pin[k], 1.0 + excess / 2, excess / 2) << e.law;
        EXPECT_NEAR(e.wear_volume_bushing[k] / e.archard_volume_bushing[k], 1.0 + excess / 2, excess / 2) << e.law;
        EXPECT_NEAR(e.wear_volume_bushing[k] / e.wear_volume_pin[k], 1.0, excess) << e.law;
      }

  // Winkler on the fresh (round) profiles: a linear layer of E_c/h between the profiles,
  // d(φ) = e cos φ − c, carries F = (E_c L R1/h)[e(φ0 + sin φ0 cos φ0) − 2c sin φ0]
  // with cos φ0 = c/e (closed form solved here for e); area k's mean pressure is
  // (E_c/h)/Δψ ∫ (e cos φ − c) dφ over its part of [−φ0, φ0].
  const double h  = 1e-3; // winkler/Layer thickness of nine_bar_wear.prm
  const auto   ef = [](const contact::Material &m) {
    const double nu = m.poisson_ratio;
    return m.youngs_modulus * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
  };
  const double k  = 1 / (1 / ef(g.bushing) + 1 / ef(g.pin_material)) / h; // [Pa/m]
  const double r1 = g.bore.mean_radius(), cl = r1 - g.pin.mean_radius();
  const double dpsi    = 2 * pi / c.pressures.bore_angle.size();
  unsigned int checked = 0;
  for (const auto &p : c.pressures.curves)
    {
      if (p.model != "winkler" || p.state != "fresh")
        continue;
      const auto force = [&](const double e) {
        const double phi0 = std::acos(cl / e);
        return k * g.axial_length * r1 * (e * (phi0 + std::sin(phi0) * std::cos(phi0)) - 2 * cl * std::sin(phi0));
      };
      double lo = cl, hi = 2 * cl;
      for (int i = 0; i < 200; ++i)
        (force(0.5 * (lo + hi)) < p.load ? lo : hi) = 0.5 * (lo + hi);
      const double e = 0.5 * (lo + hi), phi0 = std::acos(cl / e);
      // The model integrates on 8 sub-samples per area: at the arc's edges an area's
      // mean is off by up to one sub-sample's share of the edge slope, k e sin φ0 Δψ/8.
      const double tolerance = k * e * std::sin(phi0) * dpsi / 8 + 1e-9 * p.peak;
      for (std::size_t i = 0; i < c.pressures.bore_angle.size(); ++i)
        {
          const double x = std::remainder(c.pressures.bore_angle[i] - p.direction, 2 * pi);
          const double a = std::max(x - dpsi / 2, -phi0), b = std::min(x + dpsi / 2, phi0);
          const double pk = b > a ? k * (e * (std::sin(b) - std::sin(a)) - cl * (b - a)) / dpsi : 0.0;
          EXPECT_NEAR(p.pressure[i], pk, tolerance) << p.joint << ' ' << p.load << " N, area " << i;
        }
      ++checked;
    }
  EXPECT_EQ(checked, 8u) << "winkler at four loads for A and B";

  // Every model in both states at four loads for both joints: 3 × 2 × 4 × 2 columns,
  // each carrying its load (the winkler and fe resultants are their force balance; on the
  // dent the pressure spreads wider, so the area mapping's share is larger: 2 %).
  EXPECT_EQ(c.pressures.curves.size(), 48u);
  const std::string dir = wearlink::testing::fresh_directory("contact_wear") + "/out";
  workflows::write_contact_comparison(dir, c);
  contact::JointGeometry worn_geometry = g;
  worn_geometry.bore                   = io::read_profile_csv(worn + "/bore_A.csv", g.bore.n_points());
  expect_pressure_file_and_loads(c, dir, g, worn_geometry, 0.02);
  const auto effects = io::CsvTable::read(dir + "/effects.csv", "effects file");
  for (const char *name :
       {"wear_volume_pin_m3_A", "wear_volume_bushing_m3_B", "archard_volume_pin_m3_A", "wear_cycles"})
    EXPECT_NE(effects.find(name), io::CsvTable::npos) << name;
}
