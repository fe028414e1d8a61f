// SPDX-License-Identifier: LGPL-2.1-or-later
// What `wearlink sweep` does: run one scene per value of one scene entry and draw the
// bifurcation diagram, the Poincaré points of one channel against the parameter
// (doc/architecture.md §7: MPI for parameter sweeps). Member i runs on rank i mod N
// (round-robin: neighbouring values, which tend to cost alike, land on different
// ranks); each rank serialises its results and rank 0 gathers them. The computation of
// a member does not depend on the rank or on which members ran before it in the same
// process, so the diagram is the same for any number of ranks.
//
// A member whose value is invalid (outside the entry's pattern) or makes the scene
// impossible (a mechanism that cannot be assembled, a numerical failure) is reported
// with its message and the sweep goes on: this is the one place besides main() that
// catches, because one bad value must not sink a sweep.
//
// Only rank 0 writes, each file atomically (temporary name, then rename):
//   bifurcation.csv   member, parameter value, section index, time, channel value
//   members.csv       member, parameter value, status, number of points, message
//   bifurcation.png   the diagram
//   sweep.json        the command, timings per member and rank, statuses
// The two CSV files hold no timings or ranks, so serial and MPI runs give equal files.
#pragma once

#include "base/parameters.h"

#include <string>
#include <vector>

namespace wearlink::workflows
{
  struct SweepRequest
  {
    std::string         file;      ///< the scene
    std::string         parameter; ///< "Section/Entry"
    std::vector<double> values;    ///< one member each
    std::string         channel;   ///< empty: the first clearance joint's e_x
    ParameterOverrides  overrides; ///< --set, applied to every member
    std::string         output_directory;
    bool                quiet = false; ///< no line per member
  };

  /**
   * Run the sweep on the ranks of MPI_COMM_WORLD (MPI must be initialised; one rank is
   * a serial sweep). Returns the exit status: 3 if every member failed, else 0.
   * InputError (on every rank alike) for a bad scene, parameter or channel.
   */
  int
  run_sweep(const SweepRequest &request);
} // namespace wearlink::workflows
