// SPDX-License-Identifier: LGPL-2.1-or-later
// The FE contact model against an independent solution of the same continuum problem
// (exact_kernel_contact.h: exact Fourier kernels of the two rings, no FE): the steel
// pair of params/pin_bushing.prm (R1 = 12 mm, R2 = 11.5 mm, rigid pin core 0.4 R2,
// ring clamped at 24 mm, L = 10 mm) at 100 N, 1 kN, 10 kN and 100 kN along −y.
// The target: the peak pressure and the contact half-angle within 1 % at all four
// loads. Checked on the production mesh (FeSettings defaults: both surfaces at 25 µm
// all around) and printed with the approach.
#include "exact_kernel_contact.h"
#include "fe_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <iostream>

using namespace wearlink;
using namespace wearlink::fe;
using namespace wearlink::fe::testing;

TEST(FeValidation, AgainstTheExactKernelSolutionAtFourLoads)
{
  const auto geometry = steel_pair();
  FeSettings settings; // the production mesh
  settings.outer_radius = 0.024;
  PinBushingModel                   model(geometry, settings, mesh_file("exact_kernel"));
  const validation::ExactKernelPair pair; // the same pair (its defaults)
  std::cout
    << "  load [N]  peak FE / exact [MPa]      (err %)   half-angle FE / exact [deg] (err %)  approach FE / exact [µm]\n";
  for (const double F : {1e2, 1e3, 1e4, 1e5})
    {
      const auto   fe          = model.solve(load_minus_y(F), SolverKind::condensed);
      const auto   exact       = validation::solve_exact_kernel_contact(pair, F, -pi / 2);
      const double e_p         = fe.peak_pressure / exact.peak_pressure - 1;
      const double e_a         = fe.half_angle / exact.half_angle - 1;
      const double fe_approach = -fe.pin_displacement[1] - (R1 - R2);
      std::cout << std::setw(10) << F << std::fixed << std::setprecision(3) << std::setw(11) << fe.peak_pressure / 1e6
                << " / " << std::setw(9) << exact.peak_pressure / 1e6 << " (" << std::setw(6) << 100 * e_p << ")"
                << std::setprecision(4) << std::setw(12) << fe.half_angle * 180 / pi << " / " << std::setw(8)
                << exact.half_angle * 180 / pi << " (" << std::setw(6) << std::setprecision(3) << 100 * e_a << ")"
                << std::setw(12) << fe_approach * 1e6 << " / " << exact.approach * 1e6 << "\n"
                << std::defaultfloat;
      EXPECT_LT(std::abs(e_p), 0.01) << F << " N";
      EXPECT_LT(std::abs(e_a), 0.01) << F << " N";
    }
}
