// SPDX-License-Identifier: LGPL-2.1-or-later
// Benchmark: `wearlink sweep` of 8 members of the nine-bar with clearance joints A and B
// (params/nine_bar_clearance.prm, 10 crank cycles each, radial clearance of A from 0.1 to
// 0.8 mm), run serially and then with `mpirun -np 2`, in the same process one after the
// other. Prints both wall times (the whole command, MPI start-up included), the speed-up
// and the parallel efficiency T_serial / (2 T_2), and checks that both runs wrote the
// same bifurcation.csv. Asserts nothing about time: the machine's two cores may be
// shared with other work, which the printed figures then include.
#include "base/json.h"
#include "io/json_file.h"
#include "support/test_support.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

namespace
{
  double
  run(const std::string &command)
  {
    const auto start  = std::chrono::steady_clock::now();
    const int  status = std::system(command.c_str());
    if (status != 0)
      {
        std::fprintf(stderr, "command failed (%d): %s\n", status, command.c_str());
        std::exit(1);
      }
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  std::string
  read(const std::string &path)
  {
    std::ifstream     in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
} // namespace

int
main()
{
  const std::string dir  = wearlink::testing::fresh_directory("bench_sweep");
  const std::string args = " sweep " + wearlink::testing::source_path("params/nine_bar_clearance.prm") +
                           " --parameter 'Joint A/Clearance/Radial clearance' --values 1e-4:8e-4:8"
                           " --set 'Simulation/End time=5' --set 'Analyses/Transient=1' --quiet";
  const std::string bin    = WEARLINK_BINARY;
  const double      serial = run(bin + args + " --output " + dir + "/serial > " + dir + "/serial.log 2>&1");
  const double mpi  = run(std::string(WEARLINK_MPIRUN) + " -np 2 --oversubscribe " + bin + args + " --output " + dir +
                         "/mpi > " + dir + "/mpi.log 2>&1");
  const bool   same = read(dir + "/serial/bifurcation.csv") == read(dir + "/mpi/bifurcation.csv");
  std::printf("wearlink sweep, nine-bar with clearance joints, 8 members x 10 crank cycles\n");
  std::printf("%-28s %10s\n", "run", "wall [s]");
  std::printf("%-28s %10.2f\n", "serial (1 rank)", serial);
  std::printf("%-28s %10.2f\n", "mpirun -np 2", mpi);
  std::printf("speed-up %.2f, parallel efficiency %.0f %% (T_serial / (2 T_2)); identical bifurcation.csv: %s\n",
              serial / mpi,
              100.0 * serial / (2.0 * mpi),
              same ? "yes" : "NO");
  // Where the time went: member times per rank (from sweep.json) show the load balance;
  // the machine's load during the run shows how much of the two cores was ours.
  for (const char *run : {"serial", "mpi"})
    {
      const wearlink::Json j       = wearlink::io::read_json_file(dir + "/" + run + "/sweep.json");
      double               busy[2] = {0.0, 0.0};
      for (std::size_t k = 0; k < j.at("members").size(); ++k)
        {
          const auto &m = j.at("members")[k];
          busy[static_cast<int>(wearlink::json_number(m.at("rank"))) % 2] += wearlink::json_number(m.at("wall_time_s"));
        }
      std::printf("%-8s sum of member times per rank: rank 0 %.2f s, rank 1 %.2f s; command wall %.2f s\n",
                  run,
                  busy[0],
                  busy[1],
                  wearlink::json_number(j.at("wall_time_s")));
    }
  double load[3] = {0, 0, 0};
  if (std::FILE *f = std::fopen("/proc/loadavg", "r"))
    {
      if (std::fscanf(f, "%lf %lf %lf", &load[0], &load[1], &load[2]) != 3)
        load[0] = -1;
      std::fclose(f);
    }
  std::printf("load average at the end (1 min): %.2f on %ld cores\n", load[0], sysconf(_SC_NPROCESSORS_ONLN));
  return same ? 0 : 1;
}
