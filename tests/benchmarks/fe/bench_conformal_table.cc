// SPDX-License-Identifier: LGPL-2.1-or-later
// Benchmark (label benchmark): what the grid of the fe law's conformal table
// (fe/fe_conformal_table.h) resolves on the nine-bar's worn joint A (meshes/worn/, the
// profiles after 50,000 revolutions; 25 µm elements, the FE wear scene's mesh, meshed
// round and carried to the worn profiles as the scene's kept mesh is). Against direct
// displacement-controlled FE solves at pin positions every 2.5° over ±40° about the
// bore's pocket (184°), at five overlaps (0.06 … 8 µm) and five relative angles that
// are no table node, it prints the rms and largest relative error of the force vector
// (points carrying more than 30 N), per overlap and over all, for several grids
// (directions × relative angles × levels) and their build times, and for comparison the
// 8 × 8 force–approach table applied along the deepest point and the elastic foundation
// calibrated to the FE round pair (contact/conformal_contact.h). The figures quoted in
// the declarations of 'Table bore/pin directions', params/nine_bar_wear_fe.prm and
// doc/models.md §1.7 come from here. Asserts only that the tables build.
#include "base/numbers.h"
#include "contact/conformal_contact.h"
#include "contact/gap.h"
#include "fe/fe_conformal_table.h"
#include "fe/fe_normal_force_law.h"
#include "fe/model_pool.h"
#include "fe/pin_bushing_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <string>

using namespace wearlink;
using namespace wearlink::fe;

namespace
{
  using numbers::pi;

  Profile
  worn_profile(const std::string &name)
  {
    std::ifstream       in(std::string(WEARLINK_SOURCE_DIR) + "/meshes/worn/" + name);
    std::string         line;
    std::vector<double> r;
    while (std::getline(in, line))
      if (!line.empty() && line[0] != '#' && line[0] != 'a')
        r.push_back(std::stod(line.substr(line.find(',') + 1)));
    return Profile::from_samples(r, name);
  }

  mbs::Vec2
  towards(const double angle)
  {
    return {std::cos(angle), std::sin(angle)};
  }

  /** The radius along u(@p alpha) at which the rigid overlap is @p delta (bisection). */
  double
  radius_for_overlap(const contact::Gap &gap, const double alpha, const double theta, const double delta)
  {
    double lo = 0, hi = 2e-3;
    while (hi - lo > 1e-15)
      {
        const double mid                                                             = 0.5 * (lo + hi);
        (gap.evaluate(mid * towards(alpha), 0, theta).penetration < delta ? lo : hi) = mid;
      }
    return 0.5 * (lo + hi);
  }

  /** Squared relative errors per overlap, for one way of computing the force. */
  struct Errors
  {
    std::map<double, double> sum, largest;
    std::map<double, int>    count;
    void
    add(const double delta, const double error)
    {
      sum[delta] += error * error;
      largest[delta] = std::max(largest[delta], error);
      ++count[delta];
    }
    void
    print(const std::string &what) const
    {
      double total = 0;
      int    n     = 0;
      std::printf("  %-34s", what.c_str());
      for (const auto &[delta, s] : sum)
        {
          std::printf("  %5.2f µm: %5.1f %% (%5.0f %%)",
                      delta * 1e6,
                      100 * std::sqrt(s / count.at(delta)),
                      100 * largest.at(delta));
          total += s;
          n += count.at(delta);
        }
      std::printf("  all: %5.1f %%\n", 100 * std::sqrt(total / n));
    }
  };
} // namespace

TEST(ConformalTableBenchmark, GridsOnTheNineBarsWornJointA)
{
  contact::JointGeometry g;
  g.bore         = worn_profile("nine_bar_A_bore.csv");
  g.pin          = worn_profile("nine_bar_A_pin.csv");
  g.axial_length = 0.01;
  g.bushing      = {207e9, 0.3};
  g.pin_material = {207e9, 0.3};
  FeForceLawSettings s;
  s.fe.remesh_depth = 2;
  s.cache           = false;
  s.min_force       = 10;
  s.max_force       = 2e4;
  auto round        = g;
  round.bore        = Profile::round(0.012, 360);
  round.pin         = Profile::round(0.0115, 360);
  const auto kept   = shared_model(round, s.fe); // the scene's mesh: of the round pair

  // The references: direct FE solves, today's table along the deepest point, the foundation.
  const contact::Gap gap(g.bore, g.pin);
  struct Point
  {
    mbs::Vec2 e;
    double    theta, delta;
    mbs::Vec2 fe;
  };
  std::vector<Point> points;
  use_profiles(*kept, g);
  for (const double theta : {0.2, 1.1, 2.3, 3.9, 5.5})
    for (const double delta : {0.0641e-6, 0.215e-6, 0.723e-6, 2.43e-6, 8.15e-6})
      for (double off = -40; off <= 40; off += 2.5)
        {
          const double alpha = (184 + off) * pi / 180;
          Point        p{radius_for_overlap(gap, alpha, theta, delta) * towards(alpha), theta, delta, {0, 0}};
          LoadCase     lc;
          lc.control            = Control::displacement;
          lc.pin_angle          = theta;
          lc.eccentricity       = {{p.e.x(), p.e.y()}};
          const ContactResult r = kept->solve(lc, SolverKind::condensed);
          p.fe                  = {-r.resultant[0], -r.resultant[1]};
          if (p.fe.norm() > 30)
            points.push_back(p);
        }
  std::printf("%zu pin positions carrying more than 30 N\n", points.size());

  auto s_old              = s;
  s_old.n_bore_directions = s_old.n_pin_directions = 8;
  s_old.n_levels                                   = 12;
  TableBuild                        b_old, b_round;
  const contact::ForceApproachTable old         = build_force_approach_table(g, s_old, b_old);
  const contact::ForceApproachTable round_table = build_force_approach_table(round, s_old, b_round);
  const double                      c_nominal   = g.bore.mean_radius() - g.pin.mean_radius();
  const contact::OverlapFoundation  foundation(
    g.bore,
    g.pin,
    g.axial_length,
    g.bore.mean_radius(),
    contact::Foundation::of_curve([&](double d) { return round_table.evaluate(d, 0, 0).force; },
                                  c_nominal,
                                  g.bore.mean_radius(),
                                  g.axial_length,
                                  1e-12,
                                  std::max(1e-6, c_nominal),
                                  161),
    4);
  Errors e_old, e_foundation;
  for (const auto &p : points)
    {
      const auto      gr = gap.evaluate(p.e, 0, p.theta);
      const mbs::Vec2 f  = -old.evaluate(p.delta, gr.angle(), gr.angle() - p.theta).force * gr.normal;
      e_old.add(p.delta, (f - p.fe).norm() / p.fe.norm());
      contact::ConformalForce cf;
      foundation.evaluate(p.e, p.theta, nullptr, false, cf);
      e_foundation.add(p.delta, (cf.force - p.fe).norm() / p.fe.norm());
    }
  std::printf("rms (largest) relative error of the force vector against direct FE solves:\n");
  e_old.print("force–approach table 8 × 8 × 12");
  e_foundation.print("foundation of the FE round pair");

  const unsigned int grids[][3] = {{24, 4, 8}, {32, 4, 8}, {48, 4, 8}, {72, 4, 8}, {48, 2, 8}, {48, 8, 8}, {48, 4, 12}};
  for (const auto &grid : grids)
    {
      s.n_bore_directions = grid[0];
      s.n_pin_directions  = grid[1];
      s.n_levels          = grid[2];
      TableBuild b;
      const auto table = build_conformal_table(g, s, b);
      ASSERT_NE(table, nullptr);
      use_profiles(*kept, g);
      Errors errors;
      for (const auto &p : points)
        {
          contact::ConformalForce cf;
          table->evaluate(p.e, p.theta, nullptr, false, cf);
          errors.add(p.delta, (cf.force - p.fe).norm() / p.fe.norm());
        }
      char name[80];
      std::snprintf(name, sizeof name, "conformal %u × %u × %u (%.2f s)", grid[0], grid[1], grid[2], b.seconds);
      errors.print(name);
    }
}
