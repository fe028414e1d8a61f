// SPDX-License-Identifier: LGPL-2.1-or-later
#include "app/output_claim.h"

#include "app/command_line.h"
#include "base/exceptions.h"
#include "workflows/ensemble/ensemble.h"

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
    return workflows::held_on_root([&claim] { return claim_output_directory(claim); });
  }
} // namespace wearlink::app
