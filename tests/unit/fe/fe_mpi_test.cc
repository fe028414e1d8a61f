// SPDX-License-Identifier: LGPL-2.1-or-later
// The reference contact solver distributed over MPI (`mpirun -np 2 wearlink contact`):
// METIS partitions, each rank assembling its cells into a PETSc matrix, MUMPS. It solves
// the same discrete problem as the serial run (UMFPACK on one process), so the nodal
// pressures must agree to the round-off of two different direct solvers on a system
// with condition number ~1e8: 1e-8 of the peak pressure. Two load states, one in the
// Hertz regime (1 kN) and one with a wide arc (10 kN), on a coarse mesh (100 µm).
#include "io/json_file.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace
{
  /** Pressure column of a pressure_<k>_<solver>.csv file. */
  std::vector<double>
  pressures(const std::string &file)
  {
    std::ifstream       in(file);
    std::vector<double> p;
    std::string         line;
    while (std::getline(in, line))
      {
        if (line.empty() || line[0] == '#' || line[0] == 'p')
          continue;
        p.push_back(std::stod(line.substr(line.rfind(',') + 1)));
      }
    return p;
  }
} // namespace

TEST(FeMpi, DistributedReferenceSolverGivesTheSerialAnswer)
{
  // Open MPI refuses to start as root unless told that this is intended (CI is root).
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  const std::string              dir         = wearlink::testing::fresh_directory("fe_mpi");
  const std::vector<std::string> args        = {"contact",
                                                wearlink::testing::source_path("params/pin_bushing.prm"),
                                                "--set",
                                                "FE model/Surface element size=1e-4",
                                                "--set",
                                                "FE model/Solvers=reference",
                                                "--set",
                                                "Output/Write VTU=false",
                                                "--set",
                                                "Loads/Load magnitudes=1000, 10000"};
  auto                           serial_args = args;
  serial_args.insert(serial_args.end(), {"--output", dir + "/serial"});
  auto parallel_args = args;
  parallel_args.insert(parallel_args.end(), {"--output", dir + "/mpi"});

  const auto serial = wearlink::testing::run_wearlink(serial_args);
  ASSERT_EQ(serial.exit_status, 0) << serial.output;
  const auto parallel = wearlink::testing::run_wearlink_mpi(2, parallel_args);
  ASSERT_EQ(parallel.exit_status, 0) << parallel.output;
  EXPECT_NE(parallel.output.find("distributed over 2 MPI ranks"), std::string::npos) << parallel.output;

  const auto summary = wearlink::io::read_json_file(dir + "/mpi/summary.json");
  EXPECT_EQ(wearlink::json_number(summary.at("mpi_ranks")), 2);
  for (const int k : {0, 1})
    {
      const auto a = pressures(dir + "/serial/pressure_" + std::to_string(k) + "_reference.csv");
      const auto b = pressures(dir + "/mpi/pressure_" + std::to_string(k) + "_reference.csv");
      ASSERT_EQ(a.size(), b.size());
      ASSERT_GT(a.size(), 10u);
      double peak = 0, diff = 0;
      for (std::size_t i = 0; i < a.size(); ++i)
        {
          peak = std::max(peak, a[i]);
          diff = std::max(diff, std::abs(a[i] - b[i]));
        }
      std::cout << "load state " << k << ": max |p_serial − p_mpi| / p_peak = " << diff / peak << " (peak "
                << peak / 1e6 << " MPa)\n";
      EXPECT_GT(peak, 1e7);
      EXPECT_LT(diff / peak, 1e-8);
    }
}
