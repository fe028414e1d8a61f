// SPDX-License-Identifier: LGPL-2.1-or-later
// JSON values for run summaries, ledgers and checkpoint metadata: nlohmann-json's
// ordered_json, so that objects keep their insertion order (a summary reads top-down).
// nlohmann writes non-finite numbers as null (JSON has no NaN), so a broken run is
// visible; json_number() reads such a null back as NaN. Files are read by
// io/json_file.h.
#pragma once

#include <nlohmann/json.hpp>

namespace wearlink
{
  using Json = nlohmann::ordered_json;

  /**
   * The number in @p value; null (how a non-finite number is written) reads as NaN.
   * Throws nlohmann::json::type_error if @p value is neither a number nor null.
   */
  double
  json_number(const Json &value);
} // namespace wearlink
