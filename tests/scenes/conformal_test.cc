// SPDX-License-Identifier: LGPL-2.1-or-later
// A worn joint as a conformal contact (doc/models.md §1.7), on tests/scenes/journal_pocket.prm:
// a 100 kg rotor turning at 300 rpm in a ground bearing of R1 = 10 mm, c = 50 µm, μ = 0.1,
// whose bore alone wears (k_D = 2e-15 m³/(N m)). The load W = m g acts in one direction;
// friction turns the contact by atan μ against the rotation, and the normal force is
// N = W/√(1 + μ²) = 976.12 N. Checked, for every pressure model where the wear is:
//  - while the contact is narrow (a Hertz half-angle of 8.5°), Archard's global balance
//    V = k N s (the pressure over a narrow arc carries N: ∫p dA = κ N with κ − 1 = ε²/8 =
//    0.3 %, and the iterations carry N from one to the next instead of dropping the pin
//    into the pocket its extrapolated wear deepened);
//  - once the bore is worn into a pocket it is the journal's imprint
//    h(θ) = (c + d₀) cos(θ − θ_c) − c about the friction-turned load direction θ_c, to
//    within the pressure model's elastic approach, and its wear rate is local Archard's on
//    that conformal arc: dV/ds = κ(θ_m) k N, κ = 2 sin θ_m / (θ_m + sin θ_m cos θ_m) the
//    ratio of ∫p dA to |∫p n dA| for the pressure p ∝ cos θ that wears an imprint
//    uniformly (θ_m = acos(c/(c + d₀)) its half-arc);
//  - at rest in the pocket the contact force stays within 1 % of N and its direction
//    steady (the pressure over the whole pocket, the sideways motion damped), compliant
//    and held;
//  - a round pair is unchanged (the point law, bit for bit), and a worn pocket closes its
//    energy balance (the field is the gradient of its energy).
#include "base/json.h"
#include "base/numbers.h"
#include "contact/clearance_joint.h"
#include "io/csv.h"
#include "io/json_file.h"
#include "scene_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

using namespace wearlink;
using namespace wearlink::testing;

namespace
{
  using numbers::pi;
  using numbers::two_pi;

  constexpr const char *scene_file = "tests/scenes/journal_pocket.prm";

  /** "x,y" to the last bit, for an --set of a point [m]. */
  std::string
  point(const double x, const double y)
  {
    std::ostringstream os;
    os << std::setprecision(17) << x << ',' << y;
    return os.str();
  }
  constexpr double c = 50e-6, R1 = 0.010, R2 = R1 - c, k_bore = 2e-15, mu = 0.1;
  const double     normal_force = 100 * 9.81 / std::sqrt(1 + mu * mu);
  /** Where the pin presses the bore (the rotor turns counter-clockwise, friction turns it clockwise). */
  const double contact_direction = -pi / 2 - std::atan(mu);

  /** ∫p dA / |∫p n dA| of a pressure ∝ cos θ over ±θ_m. */
  double
  kappa(const double half_arc)
  {
    return 2 * std::sin(half_arc) / (half_arc + std::sin(half_arc) * std::cos(half_arc));
  }

  /** A wear run of the scene: its history (per iteration) and the bore's depth after each. */
  struct Worn
  {
    std::vector<double>              revolutions, volume, sliding, force; ///< [-], m³, m, N
    std::vector<double>              angle;                               ///< bore areas [rad]
    std::vector<std::vector<double>> depth;                               ///< per iteration, per area [m]
  };

  Worn
  wear_run(const std::string &model, const std::vector<std::string> &sets)
  {
    const std::string        dir  = fresh_directory("journal_pocket_" + model);
    std::vector<std::string> args = {"run",
                                     source_path(scene_file),
                                     "--output",
                                     dir,
                                     "--quiet",
                                     "--set",
                                     "Joint O/Clearance/Pressure model=" + model};
    for (const auto &s : sets)
      args.insert(args.end(), {"--set", s});
    const auto r = run_wearlink(args);
    EXPECT_EQ(r.exit_status, 0) << r.output;
    Worn       w;
    const auto h  = io::CsvTable::read(dir + "/wear_history.csv", "wear history");
    w.revolutions = h.numbers(h.find("revolutions"));
    w.volume      = h.numbers(h.find("O_volume_bushing_mm3"));
    for (auto &v : w.volume)
      v *= 1e-9;
    w.sliding    = h.numbers(h.find("O_sliding_distance_m"));
    w.force      = h.numbers(h.find("O_mean_normal_force_N"));
    const auto d = io::CsvTable::read(dir + "/wear_depth_O.csv", "wear depths");
    for (const double a : d.numbers(0))
      w.angle.push_back(a * pi / 180);
    for (std::size_t i = 1; i <= w.revolutions.size(); ++i)
      w.depth.push_back(d.numbers(d.find("bushing_it" + std::to_string(i) + "_m")));
    return w;
  }

  /** The fe pressure model on a coarse mesh kept over the run (Remesh depth: one element, 100 µm). */
  std::vector<std::string>
  model_settings(const std::string &model)
  {
    if (model != "fe")
      return {};
    return {"Joint O/Clearance/fe/Remesh depth=1",
            "Wear/Pressure evaluation=samples per cycle",
            "Wear/Load samples per cycle=20"};
  }

  class SteadyLoad : public ::testing::TestWithParam<std::string>
  {
  };
} // namespace

// Two iterations × 100: the bore wears 0.5 µm, the arc stays the Hertz strip's (±8.5°).
// Tolerance 1 %: κ − 1 = 0.3 % over the Hertz arc, the mean force within 0.2 % of N
// (the friction ramp of the modified Coulomb law and the start of each iteration).
TEST_P(SteadyLoad, ArchardGlobalBalanceWhileTheContactIsNarrow)
{
  auto sets = model_settings(GetParam());
  sets.insert(sets.end(), {"Wear/Number of iterations=2", "Wear/Extrapolation factor=100"});
  const Worn   w         = wear_run(GetParam(), sets);
  const double sliding   = two_pi * R2 * w.revolutions.back(); // the pin turns past the bore
  const double archard_v = k_bore * normal_force * sliding;
  EXPECT_NEAR(w.volume.back() / archard_v, 1.0, 0.01);
  EXPECT_NEAR(w.sliding.back() / sliding, 1.0, 1e-3);
  for (const double f : w.force)
    EXPECT_NEAR(f / normal_force, 1.0, 2e-3) << "every iteration carries N";
}

// Ten iterations × 4000: 40,000 revolutions, d₀ ≈ 41 µm, a pocket of ±57°.
//  - its centre is the friction-turned load direction to 0.05° (one area is 1°);
//  - the worn bore is the imprint of its deepest depth to within the model's elastic
//    approach under N: winkler's layer 0.05 µm (N/(k_f L R (θ_m + sin θ_m cos θ_m)) with
//    k_f = E_c/h), fe's a line contact's, 1.5 µm (Johnson's approach of the round pair);
//  - the last iteration's volume rate is κ k N at its mean half-arc, to 1 % (the rate
//    changes by 0.5 % over an iteration).
// hertz-strip is Hertz's narrow strip, not a conformal pressure: its semi-elliptic
// pressure of one width cannot wear the imprint's increment cos θ over ±θ_m, whose flanks
// keep wearing. It is held to what it is: the pocket's centre as above, the shape within
// 12 % of d₀ (measured 9.9 %: the flanks 4.4 µm short of a 44 µm imprint), the rate
// within 3 % of κ k N (measured −1.7 %: Σ p A = F ε/(2 J1(ε)) of its strip against κ of
// the cos pressure).
TEST_P(SteadyLoad, WornBoreConvergesToTheJournalImprint)
{
  auto sets = model_settings(GetParam());
  sets.insert(sets.end(), {"Wear/Number of iterations=10", "Wear/Extrapolation factor=4000"});
  const Worn  w  = wear_run(GetParam(), sets);
  const auto &h  = w.depth.back();
  double      sx = 0, sy = 0;
  for (std::size_t k = 0; k < h.size(); ++k)
    sx += h[k] * std::cos(w.angle[k]), sy += h[k] * std::sin(w.angle[k]);
  const double centre = std::atan2(sy, sx);
  EXPECT_NEAR(centre, contact_direction, 0.05 * pi / 180);
  const double d0        = *std::max_element(h.begin(), h.end());
  const bool   narrow    = GetParam() == "hertz-strip";
  const double tolerance = GetParam() == "winkler" ? 0.05e-6 : narrow ? 0.12 * d0 : 1.5e-6;
  double       worst     = 0;
  for (std::size_t k = 0; k < h.size(); ++k)
    worst = std::max(worst, std::abs(h[k] - std::max(0.0, (c + d0) * std::cos(w.angle[k] - centre) - c)));
  EXPECT_LT(worst, tolerance) << "the worn bore against the imprint of d₀ = " << d0;
  // The last iteration's rate against κ at its mean half-arc.
  const auto   n        = w.depth.size();
  const auto  &before   = w.depth[n - 2];
  const double d_before = *std::max_element(before.begin(), before.end());
  const double half_arc = std::acos(c / (c + 0.5 * (d0 + d_before)));
  const double rate     = (w.volume[n - 1] - w.volume[n - 2]) / (w.sliding[n - 1] - w.sliding[n - 2]);
  EXPECT_NEAR(rate / (kappa(half_arc) * k_bore * normal_force), 1.0, narrow ? 0.03 : 0.01);
}

INSTANTIATE_TEST_SUITE_P(PressureModels,
                         SteadyLoad,
                         ::testing::Values("hertz-strip", "winkler", "fe"),
                         [](const auto &info) {
                           std::string n = info.param;
                           std::replace(n.begin(), n.end(), '-', '_');
                           return n;
                         });

namespace
{
  /**
   * The imprint of d₀ = 28 µm about the contact direction (a ±50° pocket), as a profile
   * file in @p dir.
   */
  std::string
  imprinted_bore(const std::string &dir)
  {
    const std::string file = dir + "/imprinted_bore.csv";
    std::ofstream     out(file);
    out << "angle_rad,radius_m\n" << std::setprecision(17);
    constexpr double d0 = 28e-6;
    for (int k = 0; k < 360; ++k)
      {
        const double psi = two_pi * k / 360;
        out << psi << ',' << R1 + std::max(0.0, (c + d0) * std::cos(psi - contact_direction) - c) << '\n';
      }
    return file;
  }

  /** A plain run of the rotor resting in the imprinted pocket, the force and its direction every 0.1 ms after 0.1 s. */
  struct Rest
  {
    std::vector<double> force, direction;
    Json                summary;
  };

  Rest
  rest(const std::vector<std::string> &sets)
  {
    const std::string        dir = fresh_directory("journal_pocket_rest");
    const double             e   = c + 28e-6 - 0.3e-6; // 0.3 µm above the pocket's bottom
    std::vector<std::string> o   = {"Joint O/Clearance/Bore profile file=" + imprinted_bore(dir),
                                    "Joint O/Clearance/Wear law=none",
                                    "Simulation/End time=0.5"};
    const std::string        at  = point(e * std::cos(contact_direction), e * std::sin(contact_direction));
    o.insert(o.end(), {"Joint O/Clearance/Initial eccentricity=" + at, "Body rotor/Initial position=" + at});
    o.insert(o.end(), sets.begin(), sets.end());
    auto                           s     = scene(scene_file, o);
    const contact::ClearanceJoint &joint = *s.clearance_joints.front();
    Sampler                        sample(1e-4, [&](double, const Eigen::VectorXd &y, mbs::Simulation &) {
      const auto n = (y.size() - mbs::MechanismOde::n_quadratures) / 2;
      const auto d = joint.diagnostics(mbs::StateView(y.data(), y.data() + n));
      return std::vector<double>{d.normal_force, d.contact_angle};
    });
    Rest                           r;
    r.summary = run(s, {&sample});
    for (std::size_t i = 0; i < sample.times.size(); ++i)
      if (sample.times[i] >= 0.1)
        {
          r.force.push_back(sample.values[i][0]);
          r.direction.push_back(sample.values[i][1]);
        }
    return r;
  }
} // namespace

// After 0.1 s the force stays within 1 % of N (the bar; measured ±0.1 %) and the
// direction within 0.05° of the friction-turned load (measured: its scatter below 0.01°),
// compliant and with the contact held as a constraint (doc/models.md §1.6).
TEST(ConformalJournal, RestsInItsWornPocket)
{
  for (const std::string mode : {"compliant", "held"})
    {
      const Rest r = rest({"Joint O/Clearance/Persistent contact=" + mode});
      ASSERT_GT(r.force.size(), 1000u);
      for (std::size_t i = 0; i < r.force.size(); ++i)
        {
          ASSERT_NEAR(r.force[i] / normal_force, 1.0, 0.01) << mode << ", sample " << i;
          ASSERT_NEAR(r.direction[i], contact_direction, 0.05 * pi / 180) << mode << ", sample " << i;
        }
      if (mode == "held")
        {
          EXPECT_GE(json_number(r.summary.at("clearance_joints").at("O").at("held_episodes")), 1);
        }
    }
}

// A worn pocket without friction and with a purely elastic law conserves energy: the
// field is the gradient of its energy, the couples of the profiles' slopes included. The
// pin, worn on one side (5 µm deep, ±17°), turns in the pocket: its worn side passes the
// contact every revolution, the driver works against the couple the slopes carry, and the
// balance ΔT + ΔV = W_driver must close. Measured: 1e-5 J against 6.8e-3 J of driver
// work (|W|, summed over the run); the round pin in the same pocket leaves 3e-6 J (the
// integrator's error at Relative tolerance 1e-6). Tolerance 1 % of |W|: a field without
// the couples would miss all of it.
TEST(ConformalJournal, WornPocketClosesItsEnergyBalance)
{
  const std::string dir = fresh_directory("journal_pocket_energy");
  const std::string pin = dir + "/worn_pin.csv";
  {
    std::ofstream out(pin);
    out << "angle_rad,radius_m\n" << std::setprecision(17);
    for (int k = 0; k < 360; ++k)
      {
        const double psi = two_pi * k / 360;
        out << psi << ',' << R2 - 5e-6 * std::exp(-std::pow((psi - 1.0) / 0.3, 2)) << '\n';
      }
  }
  const double      e      = c + 28e-6 - 3e-6;
  const double      side   = 2e-6; // along the pocket's tangent, clear of its flanks (they rise by tan 50° per µm)
  const std::string at     = point(e * std::cos(contact_direction) - side * std::sin(contact_direction),
                               e * std::sin(contact_direction) + side * std::cos(contact_direction));
  auto              s      = scene(scene_file,
                 {"Joint O/Clearance/Bore profile file=" + imprinted_bore(dir),
                                    "Joint O/Clearance/Pin profile file=" + pin,
                                    "Joint O/Clearance/Wear law=none",
                                    "Joint O/Clearance/Normal force law=hertz",
                                    "Joint O/Clearance/Friction law=none",
                                    "Integrator/Position tolerance=1e-12",
                                    "Integrator/Velocity tolerance=1e-8",
                                    "Simulation/End time=0.2",
                                    "Joint O/Clearance/Initial eccentricity=" + at,
                                    "Body rotor/Initial position=" + at});
  const Json        energy = run(s).at("energy");
  const double      work   = json_number(energy.at("reaction_work_abs_J"));
  EXPECT_GT(work, 1e-3) << "the driver works against the worn pin's couple";
  EXPECT_LT(json_number(energy.at("max_residual_J")), 0.01 * work);
}

// Round profiles never take the conformal path: the point law, bit for bit, whatever the
// clearance form (params/nine_bar_clearance.prm, 0.25 s).
TEST(ConformalJournal, RoundPairIsUnchanged)
{
  const auto run_form = [](const std::string &form) {
    auto s = scene("params/nine_bar_clearance.prm",
                   {"Simulation/End time=0.25", "Output/Time series=false", "Wear/Clearance model=" + form});
    return run(s);
  };
  const Json conformal = run_form("conformal"), point = run_form("deepest-point");
  for (const char *key : {"steps", "rhs_evaluations"})
    EXPECT_EQ(json_number(conformal.at(key)), json_number(point.at(key))) << key;
  for (const char *j : {"A", "B"})
    EXPECT_EQ(json_number(conformal.at("clearance_joints").at(j).at("max_normal_force_N")),
              json_number(point.at("clearance_joints").at(j).at("max_normal_force_N")))
      << j;
}
