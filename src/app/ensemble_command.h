// SPDX-License-Identifier: LGPL-2.1-or-later
// The options --ensemble N, --seed S, --perturbation RAD of `run` and `life`, and the
// part of those commands that runs an ensemble (workflows/ensemble/ensemble.h): MPI for the
// command, the output folder held by rank 0, the members, the printed table.
#pragma once

#include "app/command_line.h"
#include "base/output_directory.h"
#include "workflows/ensemble/ensemble.h"

#include <string>
#include <vector>

namespace wearlink::app
{
  /** The option specs of an ensemble (to add to a command's). */
  std::vector<OptionSpec>
  ensemble_options();

  /** The request of @p a (members 0 without --ensemble); InputError for a bad value. */
  workflows::EnsembleRequest
  ensemble_request(const ParsedArguments &a);

  /**
   * Run the ensemble of command @p command ("run", "life") of the scene @p file with the
   * arguments @p a, its members run by @p run, writing @p member_files in each member's
   * folder. Initialises MPI for the command; returns the exit status (3 if every member
   * failed).
   */
  int
  run_ensemble_command(const std::string          &command,
                       const std::string          &file,
                       const ParsedArguments      &a,
                       const workflows::MemberRun &run,
                       const RunFiles             &member_files);
} // namespace wearlink::app
