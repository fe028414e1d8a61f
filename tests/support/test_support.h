// SPDX-License-Identifier: LGPL-2.1-or-later
// Helpers shared by the test executables.
#pragma once

#include "base/json.h"

#include <functional>
#include <string>
#include <vector>

namespace wearlink::testing
{
  /** Absolute path of a file in the source tree, e.g. source_path("params/x.prm"). */
  std::string
  source_path(const std::string &relative);

  /** A fresh, empty directory under the build tree's tmp area, unique per test. */
  std::string
  fresh_directory(const std::string &name);

  /** Result of running the wearlink executable. */
  struct ProgramResult
  {
    int         exit_status = -1;
    std::string output; ///< stdout and stderr together
  };

  /** Run the wearlink executable with @p args (each one shell-quoted). */
  ProgramResult
  run_wearlink(const std::vector<std::string> &args);

  /**
   * Run the wearlink executable on @p n_ranks MPI ranks (mpiexec found by CMake's
   * FindMPI, with --oversubscribe so that a 2-core machine can host the ranks).
   */
  ProgramResult
  run_wearlink_mpi(unsigned int n_ranks, const std::vector<std::string> &args);

  /** The message of the InputError that @p f throws, or "(no InputError)". */
  std::string
  input_error_message(const std::function<void()> &f);

  /** Files (recursively) in @p dir. */
  std::vector<std::string>
  files_in(const std::string &dir);
} // namespace wearlink::testing
