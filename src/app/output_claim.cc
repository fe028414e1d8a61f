// SPDX-License-Identifier: LGPL-2.1-or-later
#include "app/output_claim.h"

#include "app/command_line.h"
#include "base/exceptions.h"

#include <deal.II/base/mpi.h>

#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <iostream>
#include <utility>

namespace wearlink::app
{
  const char *const output_folder_help =
    R"(The output directory is locked while the command runs (a second command into it is
refused with the first one's pid); one that holds the files of an earlier run (the
names listed above) is refused unless --overwrite, which removes those files first.
)";

  OutputClaim
  output_claim(const std::string &directory, const RunFiles &files, const ParsedArguments &a)
  {
    OutputClaim c;
    c.directory = directory;
    c.files     = files;
    c.earlier   = a.has("--overwrite") ? EarlierRun::overwrite : EarlierRun::refuse;
    c.advice    = "Add --overwrite to replace them, or choose another --output directory.";
    c.quiet     = a.has("--quiet");
    return c;
  }

  std::unique_ptr<OutputDirectory>
  claim_output_directory(const OutputClaim &claim)
  {
    const std::string &dir     = claim.directory;
    auto               claimed = std::make_unique<OutputDirectory>(dir, claim.earlier, claim.files, claim.advice);
    if (!claim.quiet && !claimed->removed_partials().empty())
      std::cerr << "[wearlink] removed " << claimed->removed_partials().size() << " temporary file(s) left in " << dir
                << " by a run that was killed\n";
    if (!claim.quiet && !claimed->removed_files().empty())
      std::cerr << "[wearlink] --overwrite: removed " << claimed->removed_files().size()
                << " file(s) of the earlier run in " << dir << "\n";
    return claimed;
  }

  std::unique_ptr<OutputDirectory>
  claim_output_directory_on_root(const OutputClaim &claim)
  {
    const MPI_Comm comm = MPI_COMM_WORLD;
    if (dealii::Utilities::MPI::n_mpi_processes(comm) == 1)
      return claim_output_directory(claim);
    // Rank 0's outcome for everyone: 0 claimed, 2 InputError, 4 IoError, and the message.
    std::pair<int, std::string>      outcome{0, ""};
    std::unique_ptr<OutputDirectory> claimed;
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      try
        {
          claimed = claim_output_directory(claim);
        }
      catch (const InputError &e)
        {
          outcome = {2, e.message()};
        }
      catch (const IoError &e)
        {
          outcome = {4, e.message()};
        }
    outcome = dealii::Utilities::MPI::broadcast(comm, outcome, 0);
    if (outcome.first == 2)
      throw InputError(outcome.second);
    if (outcome.first == 4)
      throw IoError(outcome.second);
    return claimed;
  }
} // namespace wearlink::app
