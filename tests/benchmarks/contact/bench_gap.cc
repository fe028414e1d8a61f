// SPDX-License-Identifier: LGPL-2.1-or-later
// Benchmark: the exact gap of worn profiles (contact/gap.h), evaluated as the dynamics of
// a wear scene evaluate it, on the worn bores and pins that nine_bar_wear.prm leaves
// after 50,000 revolutions (meshes/worn/, 360 samples each). 400,000 evaluations per
// joint: the eccentricity in 2,000 directions, its magnitude c + 20 … 60 µm (the pin
// pressed into the worn pocket or onto its flank; c = min bore − max pin radius),
// body angles turned by 0.37 and −0.11 rad per round. Prints the mean time per
// evaluation (the best of 5 rounds, so that other load on the machine does not count),
// the mean penetration and a checksum of all of them (a change that is meant to give
// the same minima must print the same checksum). Asserts nothing.
//   usage: bench_gap DIRECTORY_WITH_nine_bar_{A,B}_{bore,pin}.csv
#include "contact/gap.h"
#include "io/profile_file.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

using namespace wearlink;

int
main(int argc, char **argv)
{
  if (argc != 2)
    {
      std::fprintf(stderr, "usage: bench_gap DIRECTORY (with nine_bar_A_bore.csv etc.)\n");
      return 1;
    }
  const std::string dir = argv[1];
  constexpr double  pi  = 3.14159265358979323846;
  std::printf("joint  evaluations  best [us/eval]  mean penetration [um]  checksum\n");
  for (const char *joint : {"A", "B"})
    {
      const Profile      bore = io::read_profile_csv(dir + "/nine_bar_" + joint + "_bore.csv");
      const Profile      pin  = io::read_profile_csv(dir + "/nine_bar_" + joint + "_pin.csv");
      const contact::Gap gap(bore, pin);
      const double       c    = bore.min_radius() - pin.max_radius();
      double             best = 1e300, sum = 0;
      long               n = 0;
      for (int round = 0; round < 5; ++round)
        {
          sum          = 0;
          n            = 0;
          const auto t = std::chrono::steady_clock::now();
          for (int rep = 0; rep < 200; ++rep)
            for (int k = 0; k < 2000; ++k)
              {
                const double phi = 2 * pi * k / 2000, tb = 0.37 * rep, tp = -0.11 * rep;
                const double e = c + 20e-6 + 40e-6 * ((k * 7) % 13) / 13.0;
                sum += gap.evaluate(mbs::Vec2(e * std::cos(phi), e * std::sin(phi)), tb, tp).penetration;
                ++n;
              }
          best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count());
        }
      std::printf("%5s  %11ld  %14.3f  %21.4f  %.17g\n", joint, n, 1e6 * best / n, 1e6 * sum / n, sum);
    }
  return 0;
}
