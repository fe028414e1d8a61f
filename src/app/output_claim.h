// SPDX-License-Identifier: LGPL-2.1-or-later
// How a command takes its output folder (base/output_directory.h), the same for every
// command that writes one: the folder is locked while the command lasts (a second
// command into it is refused with the holder's pid, exit status 2), temporary files of a
// killed command are removed, and the files of an earlier run (the file names the
// command writes) are refused unless --overwrite (or, for `run`, --resume). A folder the
// claim created is removed again if the command leaves it empty (bad input).
#pragma once

#include "base/output_directory.h"

#include <memory>
#include <string>

namespace wearlink::app
{
  struct ParsedArguments;

  /**
   * The paragraph of a command's --help on its output folder (lock, earlier files,
   * --overwrite), for the commands whose claim refuses earlier files.
   */
  extern const char *const output_folder_help;

  /** An output folder to claim: where, what the command writes, and what to say. */
  struct OutputClaim
  {
    std::string directory;
    RunFiles    files; ///< the names the command writes (--overwrite removes only these)
    EarlierRun  earlier = EarlierRun::refuse;
    std::string advice; ///< ends the refusal of an earlier run's files
    bool        quiet = false;
  };

  /**
   * The claim of @p directory for a command that writes @p files: EarlierRun from
   * --overwrite in @p a (else refuse), the advice "Add --overwrite to replace them, or
   * choose another --output directory.", quiet from --quiet.
   */
  OutputClaim
  output_claim(const std::string &directory, const RunFiles &files, const ParsedArguments &a);

  /**
   * Claim the folder (see the top of this file); reports on stderr, unless quiet, the
   * temporary files and earlier files removed. InputError if it is in use or holds an
   * earlier run's files (refuse), IoError if it cannot be created or locked.
   */
  std::unique_ptr<OutputDirectory>
  claim_output_directory(const OutputClaim &claim);

  /**
   * The same for a command that may run on several MPI ranks (MPI_COMM_WORLD, MPI
   * initialised): rank 0 claims the folder (it writes the outputs), every other rank
   * receives its refusal and throws the same error, so that all ranks stop alike.
   * Returns nullptr on the other ranks.
   */
  std::unique_ptr<OutputDirectory>
  claim_output_directory_on_root(const OutputClaim &claim);
} // namespace wearlink::app
