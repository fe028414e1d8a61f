// SPDX-License-Identifier: LGPL-2.1-or-later
// Cost of the condensed (production) contact solver against the reference solver at the
// default FE mesh (FeSettings defaults: both surfaces refined all around at 25 µm, as a
// wear loop with a rotating load needs), for the load states of params/pin_bushing.prm
// (100 N … 100 kN along −y), measured in one run:
//   setup      mesh + assembly (both), + factorization + the influence columns the load
//              states need (condensed), + the full influence matrix of every candidate
//   per state  mean wall time per load state (condensed: after the columns exist)
// and their ratio. Targets: condensed ≥ 100× faster than the reference and
// under 1 ms per load state. Only the agreement of the two solvers is asserted.
#include "fe_test_support.h"

#include <gtest/gtest.h>

#include <chrono>
#include <iomanip>
#include <iostream>

using namespace wearlink;
using namespace wearlink::fe;
using namespace wearlink::fe::testing;

TEST(FeBenchmark, CondensedVersusReferenceAtDefaultMesh)
{
  const auto geometry = steel_pair();
  FeSettings settings; // defaults
  settings.outer_radius = 0.024;
  PinBushingModel model(geometry, settings, mesh_file("benchmark"));
  const auto     &st = model.statistics();
  const auto      t0 = std::chrono::steady_clock::now();
  model.prepare_condensed();
  const double factor = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  const std::vector<double>  loads = {100, 1000, 10000, 100000};
  std::vector<ContactResult> cold, warm, ref;
  for (const double F : loads)
    cold.push_back(model.solve(load_minus_y(F), SolverKind::condensed));
  const double columns_needed = model.compliance_time();
  const auto   n_columns      = model.n_compliance_solves();
  for (const double F : loads)
    warm.push_back(model.solve(load_minus_y(F), SolverKind::condensed));
  // Repeat the warm pass a few times for a stable per-state figure.
  const int           repeats = 20;
  std::vector<double> warm_time(loads.size(), 0.0);
  for (int rep = 0; rep < repeats; ++rep)
    for (std::size_t k = 0; k < loads.size(); ++k)
      warm_time[k] += model.solve(load_minus_y(loads[k]), SolverKind::condensed).solve_time / repeats;
  for (const double F : loads)
    ref.push_back(model.solve(load_minus_y(F), SolverKind::reference));

  const auto t1 = std::chrono::steady_clock::now();
  model.precompute_compliance();
  const double all_columns =
    columns_needed + std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();

  const double common = st.mesh_time + st.assembly_time;
  std::cout << std::setprecision(4) << "default mesh: " << st.mesh.n_quadrilaterals << " quadrilaterals, " << st.n_dofs
            << " DoFs, " << st.n_pin_candidates << " pin + " << st.n_bore_candidates << " bore candidates\n"
            << "setup: mesh " << st.mesh_time << " s + assembly " << st.assembly_time
            << " s; condensed + factorization " << factor << " s + influence columns for these loads " << columns_needed
            << " s (" << n_columns << " back substitutions) = " << common + factor + columns_needed
            << " s; full influence matrix " << all_columns << " s; reference " << common << " s\n"
            << "  load [N]  active  condensed [ms]  reference [ms]  ratio   max|Δp|/p_peak\n";
  double mean_c = 0, mean_r = 0;
  for (std::size_t k = 0; k < loads.size(); ++k)
    {
      double diff = 0;
      for (std::size_t i = 0; i < warm[k].pressure.size(); ++i)
        diff = std::max(diff, std::abs(warm[k].pressure[i] - ref[k].pressure[i]));
      diff /= ref[k].peak_pressure;
      mean_c += warm_time[k] / loads.size();
      mean_r += ref[k].solve_time / loads.size();
      std::cout << std::setw(10) << loads[k] << std::setw(8) << warm[k].n_active << std::setw(16) << warm_time[k] * 1e3
                << std::setw(16) << ref[k].solve_time * 1e3 << std::setw(9) << ref[k].solve_time / warm_time[k]
                << std::setw(14) << diff << "\n";
      EXPECT_LT(diff, 1e-6);
      EXPECT_LT(warm[k].equilibrium_relative_residual, 1e-6);
      EXPECT_LT(ref[k].equilibrium_relative_residual, 1e-6);
    }
  std::cout << "mean per load state: condensed " << mean_c * 1e3 << " ms, reference " << mean_r * 1e3 << " ms, ratio "
            << mean_r / mean_c << "\n";
}

// The full influence matrices of a worn pair (not periodic: every column is computed) at
// the default mesh: what a worn contact-law table (8 × 8 directions all around) needs
// after every re-mesh of the FE wear scene. Prints the wall time of precompute_compliance()
// and the back substitutions; asserts only that every candidate got its column.
TEST(FeBenchmark, FullInfluenceMatrixOfAWornPair)
{
  const auto geometry = dented_pair(30e-6, 10e-6);
  FeSettings settings; // defaults: 25 µm all around
  settings.outer_radius = 0.024;
  PinBushingModel model(geometry, settings, mesh_file("benchmark_worn"));
  model.prepare_condensed();
  const auto &st = model.statistics();
  const auto  t0 = std::chrono::steady_clock::now();
  model.precompute_compliance();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cout << "worn pair, default mesh: " << st.n_dofs << " DoFs, " << st.n_pin_candidates << " pin + "
            << st.n_bore_candidates << " bore candidates; full influence matrices " << seconds << " s wall, "
            << model.n_compliance_solves() << " back substitutions\n";
  EXPECT_EQ(model.n_compliance_solves(), st.n_pin_candidates + 2 * st.n_bore_candidates);
}
