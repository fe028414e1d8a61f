// SPDX-License-Identifier: LGPL-2.1-or-later
// The condensed contact solver works on a contact window (contact_solver.h): the
// candidates whose initial gap is below a threshold, accepted when the threshold
// exceeds the pin translation plus 0.25 × the largest elastic opening of the gap. That
// rests on a measured property: outside the contact the elastic deformation closes a
// gap by at most a small fraction (≈ 0.055) of the opening it makes at the contact.
// Checked here with every candidate in the window, on a round pair and on a worn dent
// (30 µm bore, 10 µm pin), 10 N … 100 kN, three load directions: (1) that fraction
// stays below 0.125 (half the margin the rule assumes); (2) the production window gives
// the same pressures as the whole-surface solve.
#include "fe/boundary_compliance.h"
#include "fe/contact_solver.h"
#include "fe/pin_bushing_mesher.h"
#include "fe_test_support.h"
#include "io/profile_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

using namespace wearlink;
using namespace wearlink::fe;
using namespace wearlink::fe::testing;

namespace
{
  /** The elastic part A λ of the gap at window position q [m]. */
  double
  elastic_part(const ContactKinematics &kin, const ContactSolution &sol, const unsigned int q)
  {
    return sol.gap[q] - kin.g0[q] + kin.normal[q] * sol.last_translation;
  }
} // namespace

TEST(FeContactWindow, ElasticClosingOutsideTheContactIsSmallAndTheWindowHoldsEveryContact)
{
  for (const bool dented : {false, true})
    {
      const auto        g = dented ? dented_pair(30e-6, 10e-6) : steel_pair();
      MeshSpecification spec;
      spec.core_radius          = 0.4 * g.pin.min_radius();
      spec.outer_radius         = 0.024;
      spec.surface_element_size = 100e-6;
      spec.max_element_size     = 1.5e-3;
      spec.size_growth          = 0.3;
      spec.layer_thickness      = 0.2e-3;
      const std::string msh     = mesh_file(dented ? "window_dented" : "window_round");
      write_pin_bushing_mesh(g.bore, g.pin, spec, msh);
      ElasticityProblem problem(msh, 1, 0, g.pin_material, g.bushing, g.pin, g.bore);
      problem.run();
      BoundaryCompliance     compliance(problem);
      CondensedContactSolver solver(problem, compliance, 100, 30);
      for (const double F : {10.0, 1e3, 1e5})
        for (const double direction : {-pi / 2, -pi / 2 + 0.3, 0.0})
          {
            dealii::Tensor<1, 2> P;
            P[0]               = F / L * std::cos(direction);
            P[1]               = F / L * std::sin(direction);
            const double delta = predicted_approach(F / L, problem.effective_modulus(), R1 - R2);
            PinPose      pose;
            pose.bore         = &g.bore;
            pose.eccentricity = (g.bore.radius(direction) - g.pin.radius(direction) + delta) * P / P.norm();
            ContactKinematics window, all;
            const auto        a = solver.solve(pose, true, P, delta, window);
            const auto        b = solver.solve(pose, true, P, 1.0, all); // every candidate
            ASSERT_EQ(all.candidates.size(), problem.pin_nodes.size());
            double opening = 0, closing = 0;
            for (unsigned int q = 0; q < all.candidates.size(); ++q)
              if (b.lambda[q] > 0)
                opening = std::max(opening, elastic_part(all, b, q));
              else
                closing = std::min(closing, elastic_part(all, b, q));
            EXPECT_GT(closing, -0.125 * opening) << F << " N, direction " << direction << ", dented " << dented;
            // Same pressures: every force of the whole-surface solve within 1e-9 of its peak.
            double peak = 0, difference = 0;
            for (unsigned int q = 0; q < all.candidates.size(); ++q)
              peak = std::max(peak, b.lambda[q]);
            for (unsigned int q = 0; q < all.candidates.size(); ++q)
              {
                const auto   it = std::lower_bound(window.candidates.begin(), window.candidates.end(), q);
                const double in =
                  it != window.candidates.end() && *it == q ? a.lambda[it - window.candidates.begin()] : 0;
                difference = std::max(difference, std::abs(in - b.lambda[q]));
              }
            EXPECT_LT(difference, 1e-9 * peak) << F << " N, direction " << direction << ", dented " << dented;
            EXPECT_LT(window.candidates.size(), all.candidates.size() / 2) << "the window is the point";
            if (direction == 0.0)
              std::cout << (dented ? "dented" : "round") << ", " << F << " N: window " << window.candidates.size()
                        << " of " << all.candidates.size() << " candidates, " << a.n_active
                        << " active; elastic closing outside ≥ " << -closing / opening << " × the opening\n";
          }
    }
}

// A worn pair from a wear run (data/jagged_worn_*.csv: 0.2 mm elements, bores worn
// ~50 µm with kinks between neighbouring samples) under the 87 N load state on which the
// condensed solver's active set cycled: the first window's nine candidates all had
// normals on one side of the load, so no λ ≥ 0 in it could balance the load. The window
// is widened until its normals bracket the load (load_bracketing_window()); then the
// condensed solve equals the whole-surface reference, and balances the load.
TEST(FeContactWindow, BracketsTheLoadOnAJaggedWornBore)
{
  const std::string dir = std::string(WEARLINK_SOURCE_DIR) + "/tests/unit/fe/data/";
  auto              g   = steel_pair();
  g.bore                = io::read_profile_csv(dir + "jagged_worn_bore.csv", 360);
  g.pin                 = io::read_profile_csv(dir + "jagged_worn_pin.csv", 360);
  FeSettings s;
  s.surface_element_size    = 2e-4;
  s.refined_layer_thickness = 0.1e-3;
  s.outer_radius            = 0.024;
  PinBushingModel model(g, s, mesh_file("jagged_worn"));
  LoadCase        lc;
  lc.bushing_angle = 0.6226649469383595;
  lc.pin_angle     = 449.81100440093189;
  lc.load          = {{78.10359582365588, 39.241158796993744}};
  ContactResult condensed;
  ASSERT_NO_THROW(condensed = model.solve(lc, SolverKind::condensed, "", true));
  const ContactResult reference = model.solve(lc, SolverKind::reference);
  EXPECT_LT(condensed.equilibrium_relative_residual, 1e-8);
  ASSERT_EQ(condensed.pressure.size(), reference.pressure.size());
  for (std::size_t i = 0; i < reference.pressure.size(); ++i)
    EXPECT_NEAR(condensed.pressure[i], reference.pressure[i], 1e-9 * reference.peak_pressure) << "node " << i;
  EXPECT_NEAR(condensed.half_angle, reference.half_angle, 1e-9);
}
