// SPDX-License-Identifier: LGPL-2.1-or-later
// The file names `wearlink run` writes into its output folder (plain and wear runs),
// which --overwrite removes; `wearlink life` writes the same and a few more.
#pragma once

#include "base/output_directory.h"

namespace wearlink::app
{
  /** The names of `wearlink run --help`'s list of files and sub-folders. */
  RunFiles
  run_files();
} // namespace wearlink::app
