// SPDX-License-Identifier: LGPL-2.1-or-later
// Reading a JSON file written by wearlink (a run's summary.json, say) back.
#pragma once

#include "base/json.h"

#include <string>

namespace wearlink::io
{
  /**
   * Read and parse the JSON file @p path. An InputError naming the file (and, for
   * malformed text, the byte offset and what was expected) if it cannot be read or
   * parsed.
   */
  Json
  read_json_file(const std::string &path);
} // namespace wearlink::io
