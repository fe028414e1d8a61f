// SPDX-License-Identifier: LGPL-2.1-or-later
#include "base/validity_warnings.h"

#include "base/text.h"

namespace wearlink
{
  std::string
  ValidityWarning::text() const
  {
    const std::string u = unit.empty() ? "" : " " + unit;
    std::string t = quantity + " " + format_number(value, 3) + u + " exceeds its limit " + format_number(limit, 3) + u;
    if (!why_limit.empty())
      t += " (" + why_limit + ")";
    if (!meaning.empty())
      t += ": " + meaning;
    return t;
  }

  void
  ValidityWarnings::check(const ValidityWarning &w)
  {
    if (!(w.value > w.limit))
      return;
    for (auto &known : list)
      if (known.quantity == w.quantity)
        {
          if (w.value > known.value)
            known = w;
          return;
        }
    list.push_back(w);
  }

  void
  ValidityWarnings::merge(const ValidityWarnings &other)
  {
    for (const auto &w : other.list)
      check(w);
  }

  Json
  ValidityWarnings::json() const
  {
    Json a = Json::array();
    for (const auto &w : list)
      a.push_back(w.text());
    return a;
  }

  void
  ValidityWarnings::print(std::ostream &out) const
  {
    for (const auto &w : list)
      out << "[wearlink] warning: " << w.text() << '\n';
  }
} // namespace wearlink
