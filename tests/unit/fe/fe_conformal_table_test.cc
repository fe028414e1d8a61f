// SPDX-License-Identifier: LGPL-2.1-or-later
// The fe law's conformal field (fe/fe_conformal_table.h): the FE resultant as a function
// of the pin's displacement vector, tabulated under displacement control.
//
// Set-up: the steel pair of fe_test_support.h (R1 = 12 mm, c = 0.5 mm, L = 10 mm) with the
// bore imprinted by the pin pressed 30 µm deep along −y: h(ψ) = (c + d₀) cos(ψ + π/2) − c
// where positive (a pocket of ±19.4°, the pin's own shape), the pin round (so the table
// has one relative angle). Mesh: 100 µm surface elements (the pocket's arc is 8 mm long:
// 80 elements), so that a table of 24 directions × 6 levels builds in about a second;
// the comparisons are between the table and FE solves on the same mesh, so the mesh
// error cancels. Expected:
//  - at its nodes the field is the FE solve it was built from (the same solver on the
//    same model: to round-off, asserted 1e-9);
//  - between nodes in the pocket it follows direct FE solves within the interpolation
//    error (measured and stated at the test);
//  - a round pair tabulated this way has the force of the round force–approach table
//    along e (both are the same FE model, reached by displacement and by force control);
//  - overlap > 0 exactly where the force is > 0; the force is continuous at the table's
//    smallest overlap and across its directions;
//  - the hysteresis is the L-N law along the normal of a round pair, resists pressing
//    in, eases leaving, resists a pin sliding sideways in the pocket, and never gives
//    energy back (damping power ≥ 0).
#include "base/numbers.h"
#include "contact/clearance_joint.h"
#include "contact/gap.h"
#include "fe/fe_conformal_table.h"
#include "fe/fe_normal_force_law.h"
#include "fe/model_pool.h"
#include "fe_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

using namespace wearlink;
using namespace wearlink::fe;
using namespace wearlink::fe::testing;

namespace
{
  using numbers::two_pi;

  constexpr double clearance  = R1 - R2; ///< radial clearance [m]
  constexpr double depth      = 30e-6;   ///< d₀ of the imprint [m]
  constexpr double pocket_dir = -pi / 2; ///< the pocket's axis, bushing frame [rad]

  /** The bore imprinted by the pin pressed @p depth deep along ψ = −π/2 (file comment). */
  Profile
  imprinted_bore(const double d0, const unsigned int n = 360)
  {
    std::vector<double> r(n);
    for (unsigned int k = 0; k < n; ++k)
      r[k] = R1 + std::max(0.0, (clearance + d0) * std::cos(two_pi * k / n - pocket_dir) - clearance);
    return Profile::from_samples(r, "imprinted bore");
  }

  FeForceLawSettings
  table_settings(const unsigned int n_bore, const unsigned int n_levels)
  {
    FeForceLawSettings s;
    s.fe.surface_element_size    = 100e-6;
    s.fe.refined_layer_thickness = 0.2e-3;
    s.fe.outer_radius            = 0.024;
    s.cache                      = false;
    s.min_force                  = 100;
    s.max_force                  = 1e4;
    s.n_levels                   = n_levels;
    s.n_bore_directions          = n_bore;
    s.n_pin_directions           = 8; // the pin is round: one relative angle is built
    return s;
  }

  mbs::Vec2
  ray_direction(const double a)
  {
    return {std::cos(a), std::sin(a)};
  }

  /** The radius along u(@p alpha) at which the rigid overlap is @p delta (bisection, to 1e-15 m). */
  double
  radius_at_overlap(const contact::JointGeometry &g, const double alpha, const double delta)
  {
    const contact::Gap gap(g.bore, g.pin);
    double             lo = 0, hi = 2 * clearance + delta;
    while (hi - lo > 1e-15)
      {
        const double mid                                                               = 0.5 * (lo + hi);
        (gap.evaluate(mid * ray_direction(alpha), 0, 0).penetration < delta ? lo : hi) = mid;
      }
    return 0.5 * (lo + hi);
  }

  /** The force of the bushing on the pin from a displacement-controlled FE solve at @p e. */
  mbs::Vec2
  fe_force(PinBushingModel &model, const mbs::Vec2 &e, const double relative_angle = 0)
  {
    LoadCase lc;
    lc.control            = Control::displacement;
    lc.pin_angle          = relative_angle;
    lc.eccentricity       = {{e.x(), e.y()}};
    const ContactResult r = model.solve(lc, SolverKind::condensed);
    return {-r.resultant[0], -r.resultant[1]};
  }

  contact::ConformalForce
  field_at(const contact::ConformalField &f, const mbs::Vec2 &e, const contact::ConformalMotion *m = nullptr)
  {
    contact::ConformalForce out;
    f.evaluate(e, 0.0, m, true, out);
    return out;
  }

  /** One table of the worn pocket for the suite (24 directions × 6 levels), and its model. */
  class FeConformalTableTest : public ::testing::Test
  {
  protected:
    static void
    SetUpTestSuite()
    {
      geometry       = std::make_unique<contact::JointGeometry>(steel_pair());
      geometry->bore = imprinted_bore(depth);
      model          = std::make_unique<std::shared_ptr<PinBushingModel>>();
      table          = build_conformal_table(*geometry, table_settings(24, 6), build, model.get());
      std::cout << "conformal table of the pocket: " << build.n_solves << " FE solves in " << build.seconds
                << " s (mesh " << build.mesh_seconds << " s, set-up " << build.setup_seconds << " s, solves "
                << build.solve_seconds << " s), " << build.n_failed << " failed, " << build.n_repaired << " repaired\n";
    }
    static void
    TearDownTestSuite()
    {
      table.reset();
      model.reset();
      geometry.reset();
    }

    static inline std::unique_ptr<contact::JointGeometry>           geometry;
    static inline std::unique_ptr<std::shared_ptr<PinBushingModel>> model;
    static inline std::unique_ptr<FeConformalTable>                 table;
    static inline TableBuild                                        build;
  };
} // namespace

// At the nodes the field is the FE solve of the node: the pin centre ρ u(α_i) evaluated
// through the gap (δ = δ_k to the root's 1e-10) and the interpolation (weights 1 and 0),
// against the same displacement-controlled solve on the same model. Relative 1e-9: the
// root's tolerance times the local exponent, far above the solver's round-off.
TEST_F(FeConformalTableTest, NodesReproduceDirectFeSolves)
{
  ASSERT_EQ(build.n_failed, 0u);
  const auto &n = table->nodes();
  ASSERT_EQ(n.n_pin, 1u) << "a round pin needs one relative angle";
  ASSERT_EQ(n.n_bore, 24u);
  const std::size_t K = n.overlaps.size();
  for (unsigned int i = 0; i < n.n_bore; i += 3)
    for (std::size_t k = 0; k < K; k += 2)
      {
        const double    alpha = two_pi * i / n.n_bore;
        const mbs::Vec2 e     = n.radius[i * K + k] * ray_direction(alpha);
        const mbs::Vec2 f_fe  = fe_force(**model, e);
        const auto      f     = field_at(*table, e);
        EXPECT_NEAR(f.overlap, n.overlaps[k], 1e-9 * n.overlaps[k]) << "direction " << i << ", level " << k;
        EXPECT_NEAR((f.force - f_fe).norm() / f_fe.norm(), 0.0, 1e-9) << "direction " << i << ", level " << k;
      }
}

// Between the nodes: at the mid-point of two neighbouring directions (7.5° from both) and
// at the geometric mean of two neighbouring levels, the field against a direct FE solve
// at the same pin centre.
//  - Clear of the pocket (both neighbouring rays on the round part of the bore) the field
//    is smooth and the interpolation error small: 2 % in force, 0.1° in direction
//    (measured 1.2 % at the lowest mid-level, where the local exponent changes most, and
//    0.01°).
//  - In the pocket the force at a given overlap changes across a cell by as much as the
//    conformal bottom and the flank differ (measured: 3.1× between the axis and the ray
//    15° off it), and peaks within ~δ/(ρ sin 19°) of the axis (the overlap is a maximum,
//    with a corner there): a 15° grid cannot see inside the cell. Asserted: the error of
//    the interpolated force is within the change of the FE force between the cell's two
//    rays (what the grid leaves unresolved) plus 2 %, its direction within the change of
//    direction plus 1°. The first-order rigid overlap (contact/gap.h) leaves the FE
//    without contact at the smallest mid-level 7.5° off the axis (its pin meets the
//    flank 0.3 µm later than the linearized gap says); those points are reported, not
//    compared.
TEST_F(FeConformalTableTest, BetweenNodesFollowsDirectFeSolves)
{
  const auto       &n           = table->nodes();
  const std::size_t K           = n.overlaps.size();
  const double      step        = two_pi / n.n_bore;
  double            worst_round = 0, worst_angle = 0, worst_pocket = 0;
  for (unsigned int i = 0; i < n.n_bore; ++i)
    for (std::size_t k = 0; k + 1 < K; k += 2)
      {
        const double    alpha = (i + 0.5) * step;
        const double    delta = std::sqrt(n.overlaps[k] * n.overlaps[k + 1]);
        const mbs::Vec2 e     = radius_at_overlap(*geometry, alpha, delta) * ray_direction(alpha);
        const mbs::Vec2 f_fe  = fe_force(**model, e);
        const auto      f     = field_at(*table, e);
        const double    off   = std::abs(std::remainder(alpha - pocket_dir, two_pi)); // from the pocket's axis
        if (f_fe.norm() == 0)
          {
            std::cout << "  no FE contact " << off * 180 / pi << "° off the axis at δ = " << delta
                      << " m; the field: " << f.force.norm() << " N\n";
            EXPECT_LT(off, 20 * pi / 180) << "only in the pocket";
            continue;
          }
        const double df   = std::abs(f.force.norm() / f_fe.norm() - 1);
        const double dphi = std::abs(std::asin(mbs::cross(f_fe, f.force) / (f_fe.norm() * f.force.norm())));
        if (off > 19.4 * pi / 180 + step) // both rays on the round part of the bore
          {
            EXPECT_LT(df, 0.02) << "α = " << alpha << ", δ = " << delta;
            EXPECT_LT(dphi, 0.1 * pi / 180) << "α = " << alpha << ", δ = " << delta;
            worst_round = std::max(worst_round, df);
            worst_angle = std::max(worst_angle, dphi);
            continue;
          }
        // The FE force on the cell's two rays at the same overlap.
        mbs::Vec2 ends[2];
        for (int side = 0; side < 2; ++side)
          {
            const double a = (i + side) * step;
            ends[side]     = fe_force(**model, radius_at_overlap(*geometry, a, delta) * ray_direction(a));
          }
        const double change = std::abs(std::log(ends[1].norm() / ends[0].norm()));
        const double turn   = std::abs(std::asin(mbs::cross(ends[0], ends[1]) / (ends[0].norm() * ends[1].norm())));
        std::cout << "  " << off * 180 / pi << "° off the axis, δ = " << delta << " m: FE " << f_fe.norm()
                  << " N, field / FE − 1 = " << f.force.norm() / f_fe.norm() - 1 << " (the rays' forces differ by "
                  << std::exp(change) << "×), direction off by " << dphi * 180 / pi << "° (the rays' by "
                  << turn * 180 / pi << "°)\n";
        EXPECT_LT(std::abs(std::log(f.force.norm() / f_fe.norm())), change + 0.02)
          << "α = " << alpha << ", δ = " << delta;
        EXPECT_LT(dphi, turn + pi / 180) << "α = " << alpha << ", δ = " << delta;
        worst_pocket = std::max(worst_pocket, df);
      }
  std::cout << "largest deviation between nodes: " << 100 * worst_round << " % in force and " << worst_angle * 180 / pi
            << "° clear of the pocket, " << 100 * worst_pocket << " % in the pocket\n";
}

// A round pair through the conformal table: the force along e against the round
// force–approach table F(δ) of the same (periodic) model, at the mid-levels of the
// round table (100 N … 10 kN, 8 levels), in two directions. Both are the same FE
// problem, reached by force and by displacement control, each interpolated in its own
// 8 levels (×1.93 apart): 1 % (measured 0.43 %, both interpolation errors together).
// The direction: the periodic mesh is rotation-invariant, the force radial to 0.01°
// (measured 0.004°).
TEST(FeConformalTable, RoundPairAgreesWithTheRoundTable)
{
  const auto                        g = steel_pair();
  const auto                        s = table_settings(4, 8);
  TableBuild                        b1, b2;
  std::shared_ptr<PinBushingModel>  shared;
  const contact::ForceApproachTable round = build_force_approach_table(g, s, b1, &shared);
  const auto                        field = build_conformal_table(g, s, b2, &shared);
  std::cout << "round table " << b1.n_solves << " solves in " << b1.seconds << " s; conformal " << b2.n_solves
            << " solves in " << b2.seconds << " s\n";
  ASSERT_EQ(field->nodes().n_pin, 1u);
  double worst = 0, worst_angle = 0;
  for (const double alpha : {0.3, 2.0})
    for (std::size_t k = 0; k + 1 < round.n_levels(); ++k)
      {
        const double F  = std::sqrt(round.forces()[k] * round.forces()[k + 1]);
        double       lo = 1e-9, hi = 1e-4; // δ of the round table at F
        for (int it = 0; it < 200; ++it)
          (round.evaluate(std::sqrt(lo * hi), 0, 0).force < F ? lo : hi) = std::sqrt(lo * hi);
        const double delta = std::sqrt(lo * hi);
        const auto   f     = field_at(*field, (clearance + delta) * ray_direction(alpha));
        const double d     = f.force.norm() / F - 1;
        const double angle = std::asin(mbs::cross(-ray_direction(alpha), f.force) / f.force.norm());
        EXPECT_NEAR(d, 0, 0.01) << "α = " << alpha << ", F = " << F << " N";
        EXPECT_NEAR(angle, 0, 0.01 * pi / 180) << "α = " << alpha << ", F = " << F << " N";
        worst       = std::max(worst, std::abs(d));
        worst_angle = std::max(worst_angle, std::abs(angle));
      }
  std::cout << "largest deviation: " << 100 * worst << " %, " << worst_angle * 180 / pi << "°\n";
}

// The event value and the force: over pin centres across the onset in every direction,
// overlap() > 0 exactly where the force is > 0. The force is continuous at the smallest
// level δ_0 (C¹ there: the power law of the end slope) and across a direction node (the
// weights are continuous): relative changes over steps of 1e-12 of δ and of 1e-9 rad.
TEST_F(FeConformalTableTest, ForceIsPositiveExactlyWhereTheOverlapIsAndContinuous)
{
  for (int a = 0; a < 72; ++a)
    {
      const double alpha = two_pi * (a + 0.37) / 72;
      const double rho0  = radius_at_overlap(*geometry, alpha, 0.0);
      for (const double step : {-1e-9, -1e-12, 0.0, 1e-12, 1e-9, 1e-7})
        {
          const mbs::Vec2 e = (rho0 + step) * ray_direction(alpha);
          const auto      f = field_at(*table, e);
          EXPECT_EQ(f.overlap > 0, f.force.norm() > 0) << "α = " << alpha << ", step " << step;
          EXPECT_EQ(f.overlap, table->overlap(e, 0.0));
        }
    }
  // A jump where the power law meets the first Hermite segment, or between the weights
  // of two directions, would be of the order of the interpolants' difference (percent);
  // the steps move a continuous force by ~1e-7 of itself (δ by 1e-14 m of ~0.1 µm, and the
  // overlap and β with α by 1e-10 rad): 1e-6.
  const auto  &n      = table->nodes();
  const double delta0 = n.overlaps.front();
  for (const double alpha : {pocket_dir + 0.1, pocket_dir + 0.5, 1.0})
    {
      const double rho = radius_at_overlap(*geometry, alpha, delta0);
      const auto   lo  = field_at(*table, (rho - 1e-14) * ray_direction(alpha)),
                 hi    = field_at(*table, (rho + 1e-14) * ray_direction(alpha));
      EXPECT_LT(lo.overlap, hi.overlap);
      EXPECT_NEAR((hi.force - lo.force).norm() / lo.force.norm(), 0.0, 1e-6) << "across δ_0 at α = " << alpha;
    }
  for (unsigned int i = 0; i < n.n_bore; i += 5)
    {
      const double alpha = two_pi * i / n.n_bore;
      const double rho   = n.radius[i * n.overlaps.size() + 3];
      const auto   lo    = field_at(*table, rho * ray_direction(alpha - 1e-10));
      const auto   hi    = field_at(*table, rho * ray_direction(alpha + 1e-10));
      EXPECT_NEAR((hi.force - lo.force).norm() / lo.force.norm(), 0.0, 1e-6) << "across direction " << i;
    }
}

// The hysteresis (χ = 3(1 − 0.9²)/4, the guard v_min = 1e-4 m/s, δ̇⁻ = 0.1 m/s):
//  - no motion: the damped force is the elastic one;
//  - pressing into the pocket's bottom: larger, and along the normal exactly the L-N law
//    F (1 + χ δ̇/v) of the round part of the bore (a round pair's normal mode is u(α));
//  - leaving: smaller, never tensile;
//  - sliding sideways on the pocket's flank: the damping opposes the motion;
//  - the damping power −(damped − F)·ṽ is ≥ 0 for motions in every direction.
TEST_F(FeConformalTableTest, HysteresisDampsPressingLeavingAndSliding)
{
  contact::ConformalMotion m;
  m.factor           = 3 * (1 - 0.81) / 4;
  m.min_velocity     = 1e-4;
  m.impact_velocity  = 0.1;
  const double delta = std::sqrt(table->nodes().overlaps[2] * table->nodes().overlaps[3]);

  // The pocket's bottom.
  const mbs::Vec2 e     = radius_at_overlap(*geometry, pocket_dir, delta) * ray_direction(pocket_dir);
  const auto      still = field_at(*table, e, &m);
  EXPECT_EQ((still.damped - still.force).norm(), 0.0);
  EXPECT_EQ(still.damping_power, 0.0);
  m.velocity          = 0.01 * ray_direction(pocket_dir);
  const auto pressing = field_at(*table, e, &m);
  EXPECT_GT(pressing.damped.norm(), pressing.force.norm());
  m.velocity         = -0.01 * ray_direction(pocket_dir);
  const auto leaving = field_at(*table, e, &m);
  EXPECT_LT(leaving.damped.norm(), leaving.force.norm());
  EXPECT_GE(leaving.damped.dot(leaving.force), 0.0) << "never tensile";

  // The round side of the bore (opposite the pocket): the normal mode is the L-N law.
  const double    alpha = pocket_dir + pi;
  const mbs::Vec2 r     = radius_at_overlap(*geometry, alpha, delta) * ray_direction(alpha);
  m.velocity            = 0.02 * ray_direction(alpha);
  const auto   round    = field_at(*table, r, &m);
  const double rate = 0.02, v = std::max(m.impact_velocity, rate);
  // D's off-diagonal terms there are of the size of β's derivatives (1e-5: the FE force is
  // radial to round-off on the round part), which move the magnitude at second order.
  EXPECT_NEAR(round.damped.norm(), round.force.norm() * (1 + m.factor * rate / v), 1e-6 * round.force.norm())
    << "L-N along the normal of a round part";

  // Sliding sideways across the pocket's flank, 15° off its axis.
  const double    flank = pocket_dir + 15 * pi / 180;
  const mbs::Vec2 ef    = radius_at_overlap(*geometry, flank, delta) * ray_direction(flank);
  for (const double sign : {-1.0, 1.0})
    {
      m.velocity       = sign * 0.01 * mbs::perp(ray_direction(flank));
      const auto slide = field_at(*table, ef, &m);
      EXPECT_LT((slide.damped - slide.force).dot(m.velocity), 0.0) << "sliding sideways is resisted";
      EXPECT_GT(slide.damping_power, 0.0);
    }
  for (int a = 0; a < 36; ++a)
    for (const double speed : {1e-5, 1e-3, 0.3})
      {
        m.velocity   = speed * ray_direction(two_pi * a / 36);
        const auto f = field_at(*table, ef, &m);
        EXPECT_GE(f.damping_power, 0.0) << "motion " << a << " at " << speed << " m/s";
        EXPECT_NEAR(f.damping_power, -(f.damped - f.force).dot(m.velocity), 1e-12 * f.force.norm() * speed);
        EXPECT_GE(f.damped.dot(f.force), 0.0) << "never tensile";
      }
}

// The potential (the energy balance's): on a node's ray, V at the nodes against a fine
// quadrature of the interpolated field's −F·u from the onset (4,000 midpoints in
// s = ρ − ρ_onset, graded as s ∝ t³ towards the onset, where F ∝ s^n), and its slope
// −dV/dρ against −F·u between the levels (central differences). The node values are the
// piecewise power law of −F·u in s between the levels, exact for a power law: measured
// 0.55 % where ln F bends against ln s (asserted 1.5 %); the slope is the derivative of the Hermite interpolant of ln V
// between levels ×2.2 apart: measured 0.6 % (asserted 2 %).
TEST_F(FeConformalTableTest, PotentialIsTheWorkAlongTheRay)
{
  const auto       &n          = table->nodes();
  const std::size_t K          = n.overlaps.size();
  double            worst_node = 0, worst_slope = 0;
  for (unsigned int i = 0; i < n.n_bore; i += 2)
    {
      const double        alpha = two_pi * i / n.n_bore;
      const mbs::Vec2     u     = ray_direction(alpha);
      const double        onset = n.onset[i], span = n.radius[i * K + K - 1] - onset;
      std::vector<double> work(K, 0.0);
      const int           m = 4000;
      for (int q = 0; q < m; ++q)
        {
          const double t0 = double(q) / m, t1 = double(q + 1) / m, tm = 0.5 * (t0 + t1);
          const double s = span * tm * tm * tm, ds = span * (t1 * t1 * t1 - t0 * t0 * t0);
          const double g = -field_at(*table, (onset + s) * u).force.dot(u);
          for (std::size_t k = 0; k < K; ++k)
            work[k] += onset + s < n.radius[i * K + k] ? g * ds : 0.0;
        }
      for (std::size_t k = 1; k < K; ++k) // level 0 holds few quadrature cells of its own
        {
          const double V = table->node_potential(0, i, k);
          EXPECT_NEAR(V / work[k], 1.0, 0.015) << "direction " << i << ", level " << k;
          worst_node = std::max(worst_node, std::abs(V / work[k] - 1));
        }
      for (std::size_t k = 0; k + 1 < K; ++k)
        {
          const double rho = 0.5 * (n.radius[i * K + k] + n.radius[i * K + k + 1]);
          const double h   = 1e-4 * (n.radius[i * K + k + 1] - n.radius[i * K + k]);
          const double slope =
            (field_at(*table, (rho + h) * u).potential - field_at(*table, (rho - h) * u).potential) / (2 * h);
          const double along = -field_at(*table, rho * u).force.dot(u);
          EXPECT_NEAR(slope / along, 1.0, 0.02) << "direction " << i << ", between levels " << k << " and " << k + 1;
          worst_slope = std::max(worst_slope, std::abs(slope / along - 1));
        }
    }
  std::cout << "potential: nodes off the fine quadrature by " << 100 * worst_node << " %, slope off the force by "
            << 100 * worst_slope << " %\n";
}

// The law: a joint of the conformal form (use_conformal(true)) with worn profiles gets the
// conformal table as its field, and the deepest-point form the force–approach table; a
// round pair keeps its round table either way (no field); switching the form rebuilds
// only for worn profiles; a second build of the same geometry comes from the cache.
TEST(FeConformalTable, LawBuildsWhatTheFormNeeds)
{
  const std::string cache = wearlink::testing::fresh_directory("fe_conformal_cache");
  ::setenv("WEARLINK_CACHE_DIR", cache.c_str(), 1);
  auto s    = table_settings(4, 4);
  s.cache   = true;
  auto worn = steel_pair();
  worn.bore = imprinted_bore(depth);

  FeNormalForceLaw law(s);
  law.use_conformal(true);
  law.update_geometry(steel_pair());
  EXPECT_EQ(law.conformal_field(), nullptr) << "a round pair has no field";
  EXPECT_EQ(law.report().at("table_kind").get<std::string>(), "force-approach");
  law.update_geometry(worn);
  ASSERT_NE(law.conformal_field(), nullptr);
  const Json j = law.report();
  EXPECT_EQ(j.at("table_kind").get<std::string>(), "conformal");
  EXPECT_EQ(j.at("table_fe_solves").get<unsigned int>(), 16u) << "4 directions × 4 levels, one relative angle";
  EXPECT_EQ(j.at("table_builds").get<unsigned int>(), 2u);
  law.use_conformal(false);
  EXPECT_EQ(law.conformal_field(), nullptr);
  EXPECT_EQ(law.report().at("table_kind").get<std::string>(), "force-approach");
  EXPECT_EQ(law.report().at("table_builds").get<unsigned int>(), 3u);
  law.use_conformal(false);
  EXPECT_EQ(law.report().at("table_builds").get<unsigned int>(), 3u) << "the same form: nothing rebuilt";

  FeNormalForceLaw again(s);
  again.use_conformal(true);
  again.update_geometry(worn);
  ASSERT_NE(again.conformal_field(), nullptr);
  EXPECT_TRUE(again.report().at("table_from_cache").get<bool>());
  contact::ConformalForce a, b;
  const mbs::Vec2         e = (clearance + depth + 1e-6) * ray_direction(pocket_dir + 0.2);
  law.use_conformal(true);
  law.conformal_field()->evaluate(e, 0, nullptr, false, a);
  again.conformal_field()->evaluate(e, 0, nullptr, false, b);
  EXPECT_EQ(a.force, b.force) << "the cached table is the table";
  ::unsetenv("WEARLINK_CACHE_DIR");
}

// The joint and the law together: a clearance joint of the conformal form with worn
// profiles uses the fe law's conformal table as its field; set to the deepest-point form
// it has no field and the law has rebuilt its force–approach table.
TEST(FeConformalTable, JointUsesTheLawsOwnField)
{
  contact::ClearanceJointDescription d;
  d.name                         = "J";
  d.pin_body                     = 0;
  d.geometry                     = steel_pair();
  d.geometry.bore                = imprinted_bore(depth);
  d.clearance_form               = contact::ClearanceForm::conformal;
  auto                    law    = std::make_unique<FeNormalForceLaw>(table_settings(4, 4));
  auto                   *fe_law = law.get();
  contact::ClearanceJoint joint(d, std::move(law), nullptr);
  ASSERT_NE(joint.conformal_field(), nullptr);
  EXPECT_EQ(joint.conformal_field(), fe_law->conformal_field()) << "the law's own field, not the foundation";
  joint.set_clearance_form(contact::ClearanceForm::deepest_point);
  EXPECT_EQ(joint.conformal_field(), nullptr);
  EXPECT_EQ(fe_law->report().at("table_kind").get<std::string>(), "force-approach");
  EXPECT_EQ(fe_law->report().at("table_builds").get<unsigned int>(), 2u) << "one table per form, nothing else";
}

// A loaded joint that turns rigidly (both bodies and the pin centre about the bore centre,
// ω = 2 rad/s) does no work and keeps its energy: the field's force acts on the line
// through the pin centre, and the bushing receives its moment −e × F about the bore
// centre. Pin centre 11° off the pocket's axis, 27 µm out: |F| ~ 15 kN along a line
// that misses the bore centre by ~0.04 mm (e × F ~ 0.6 N m). The power is round-off of
// products of ~1e4 N and ~1e-3 m/s: 1e-9 W; V to round-off.
TEST_F(FeConformalTableTest, RigidRotationOfALoadedJointDoesNoWork)
{
  contact::ClearanceJointDescription d;
  d.name         = "J";
  d.bushing_body = 0;
  d.pin_body     = 1;
  d.geometry     = *geometry;
  contact::ClearanceJoint joint(d, std::make_unique<FeNormalForceLaw>(table_settings(24, 6)), nullptr);
  joint.set_mode(true, 0.1);
  const double alpha = pocket_dir + 0.2, rho = clearance + depth - 3e-6, omega = 2;
  double       energy[2];
  for (int turn = 0; turn < 2; ++turn)
    {
      const double          theta_b = 0.7 * turn;
      const mbs::Vec2       e       = rho * ray_direction(alpha + theta_b);
      const double          q[6]    = {0, 0, theta_b, e.x(), e.y(), theta_b + 0.3};
      const double          v[6]    = {0, 0, omega, -omega * e.y(), omega * e.x(), omega};
      const mbs::StateView  s(q, v);
      double                g[6] = {0, 0, 0, 0, 0, 0};
      mbs::ForceAccumulator out;
      out.g = g;
      joint.add_forces(0, s, out);
      double power = 0;
      for (int i = 0; i < 6; ++i)
        power += g[i] * v[i];
      ASSERT_GT(std::hypot(g[3], g[4]), 1e3) << "the joint must be loaded";
      EXPECT_GT(std::abs(g[2]), 0.1) << "the bushing receives the force's moment";
      EXPECT_NEAR(power, 0, 1e-9) << "turned by " << theta_b << " rad";
      EXPECT_NEAR(out.damping_power, 0, 1e-12) << "no relative motion, no hysteresis";
      energy[turn] = joint.potential_energy(s);
    }
  EXPECT_NEAR(energy[1], energy[0], 1e-12 * energy[0]);
}
