// SPDX-License-Identifier: LGPL-2.1-or-later
// The sub-commands of the wearlink program; one file each in app/commands/.
#pragma once

#include "app/command_line.h"

#include <vector>

namespace wearlink::app
{
  /** The table of sub-commands, in the order `wearlink --help` lists them. */
  const std::vector<Command> &
  commands();
} // namespace wearlink::app
