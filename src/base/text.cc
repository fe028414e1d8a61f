// SPDX-License-Identifier: LGPL-2.1-or-later
#include "base/text.h"

#include <iomanip>
#include <sstream>

namespace wearlink
{
  std::string
  trim(const std::string &s, const std::string &blanks)
  {
    const auto first = s.find_first_not_of(blanks);
    if (first == std::string::npos)
      return "";
    return s.substr(first, s.find_last_not_of(blanks) - first + 1);
  }

  std::string
  format_number(const double value, const int significant_digits)
  {
    std::ostringstream os;
    os << std::setprecision(significant_digits) << value;
    return os.str();
  }
} // namespace wearlink
