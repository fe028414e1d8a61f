// SPDX-License-Identifier: LGPL-2.1-or-later
#include "base/exceptions.h"

#include <ostream>

namespace wearlink
{
  Error::Error(std::string message)
    : text(std::move(message))
  {
  }

  void
  Error::print_info(std::ostream &out) const
  {
    out << text << '\n';
  }
} // namespace wearlink
