// SPDX-License-Identifier: LGPL-2.1-or-later
#include "base/json.h"

#include <limits>

namespace wearlink
{
  double
  json_number(const Json &value)
  {
    if (value.is_null())
      return std::numeric_limits<double>::quiet_NaN();
    return value.get<double>();
  }
} // namespace wearlink
