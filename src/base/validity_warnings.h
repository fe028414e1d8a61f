// SPDX-License-Identifier: LGPL-2.1-or-later
// Warnings about results that leave the validity of their own model: a
// penetration far beyond what a contact law assumes, a constraint violation far above
// the integrator's tolerance, an energy balance off by more than the integrator
// promises, a Hertz half-angle past 90°, a contact-law table evaluated beyond its range.
// The run is not stopped (the result may still be what the user wants to see); each
// warning names the quantity, its value and the limit, goes once to stderr prefixed
// "[wearlink] warning:" and into the `warnings` list of summary.json.
#pragma once

#include "base/json.h"

#include <ostream>
#include <string>
#include <vector>

namespace wearlink
{
  /** One quantity beyond its limit. */
  struct ValidityWarning
  {
    std::string quantity; ///< what, and where: "joint A: largest penetration"
    double      value = 0;
    double      limit = 0;
    std::string unit;      ///< of value and limit ("m", "deg", "" for a ratio or a count)
    std::string why_limit; ///< how the limit is set: "10 % of the radial clearance 5e-4 m"
    std::string meaning;   ///< what it means for the result and what to do

    /** "joint A: largest penetration 1e-3 m exceeds its limit 5e-5 m (why_limit): meaning" */
    std::string
    text() const;
  };

  /** The warnings of one command; a quantity warned about twice keeps its largest value. */
  class ValidityWarnings
  {
  public:
    /** Add @p w if its value exceeds its limit (a NaN value is not a warning). */
    void
    check(const ValidityWarning &w);

    /** Every warning of @p other, merged as by check(). */
    void
    merge(const ValidityWarnings &other);

    bool
    empty() const
    {
      return list.empty();
    }
    const std::vector<ValidityWarning> &
    warnings() const
    {
      return list;
    }

    /** The `warnings` list of summary.json: one string each (always an array). */
    Json
    json() const;

    /** One line per warning: "[wearlink] warning: <text>". */
    void
    print(std::ostream &out) const;

  private:
    std::vector<ValidityWarning> list;
  };
} // namespace wearlink
