// SPDX-License-Identifier: LGPL-2.1-or-later
// Helpers shared by the test executables.
#pragma once

#include "base/json.h"

#include <cstddef>
#include <functional>
#include <map>
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
   * Run the wearlink executable with every file it writes limited to @p bytes
   * (RLIMIT_FSIZE): a write beyond fails with EFBIG as one on a full disk fails with
   * ENOSPC — an injected write failure that needs no special file system.
   */
  ProgramResult
  run_wearlink_with_file_size_limit(std::size_t bytes, const std::vector<std::string> &args);

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

  /** The temporary files (".NAME.partial-PID...") in @p dir, recursively. */
  std::vector<std::string>
  partial_files_in(const std::string &dir);

  /** The content of @p path ("" if it cannot be read). */
  std::string
  file_content(const std::string &path);

  /** Every file of @p dir (recursively, relative path → content), to see that nothing changed. */
  std::map<std::string, std::string>
  directory_snapshot(const std::string &dir);

  /**
   * A wear checkpoint's text (wear/wear_state.h) with its header's payload length and
   * CRC-32 made to match its payload again: a checkpoint edited on purpose, to reach
   * the checks behind the checksum.
   */
  std::string
  reseal_checkpoint(const std::string &text);

  /**
   * Start the wearlink executable with @p args in the background (output into
   * @p log_file; SIGHUP at its default, as from a terminal); returns its pid.
   */
  int
  start_wearlink(const std::vector<std::string> &args, const std::string &log_file);

  /** Wait for @p pid; its exit status, or 128 + the signal that ended it. */
  int
  wait_for(int pid);

  /** @p a followed by @p b (scene overrides added to a list). */
  std::vector<std::string>
  with(std::vector<std::string> a, const std::vector<std::string> &b);

  /**
   * The @p p quantile of @p v by linear interpolation between the order statistics
   * (Hyndman & Fan's type 7), written here independently of the library's.
   */
  double
  type7(std::vector<double> v, double p);
} // namespace wearlink::testing
