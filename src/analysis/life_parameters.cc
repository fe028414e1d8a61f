// SPDX-License-Identifier: LGPL-2.1-or-later
#include "analysis/life_parameters.h"

#include "base/exceptions.h"
#include "base/parameters.h"

#include <algorithm>

namespace wearlink::analysis
{
  namespace
  {
    namespace P = dealii::Patterns;

    /** The criteria's limits, one entry per row of the criteria table. */
    void
    declare_criteria(dealii::ParameterHandler &prm)
    {
      for (const auto &row : criteria_table())
        declare(prm, row.entry, "0", P::Double(0, row.upper), row.meaning, row.unit);
    }

    /** The response measure, the tolerance and the run's bounds. */
    void
    declare_settings(dealii::ParameterHandler &prm)
    {
      declare(prm,
              "Response body",
              "",
              P::Anything(),
              "Body of the Response rise criterion; empty: Wear/Response body (itself defaulting to "
              "the last body).",
              "none");
      declare(prm,
              "Response cycles",
              "3",
              P::Integer(1, 1000),
              "Driving cycles averaged by the response measure (after one settling cycle), 1 … 1000. "
              "The per-cycle peaks of a clearance mechanism scatter by tens of percent: more cycles, "
              "a steadier measure, at 1 + this many cycles of dynamics per wear iteration.",
              "cycles");
      declare(prm,
              "Response tolerance",
              "0.5",
              P::Double(1e-3, 100),
              "The Response rise criterion counts as decided only if the 95 % interval of its "
              "crossing (the revolutions where the confidence band of the response trend crosses "
              "the limit) is at most this fraction of the crossing's revolutions wide; 1e-3 … 100. "
              "A reached criterion with a wider interval is reported as undecided (with its "
              "interval) and is not the life. Default 0.5: the crossing known to about ±25 %.",
              "none");
      declare(prm,
              "Tolerance",
              "0.02",
              P::Double(1e-6, 0.5),
              "The wear iteration that crosses a wear criterion (depth, clearance growth, mass "
              "loss) represents at most this fraction of the revolutions at its end, so each such "
              "life is located within Tolerance × life (the bracket in summary.json); 1e-6 … 0.5. "
              "Smaller: one more, shorter iteration near each crossing.",
              "none");
      declare(prm,
              "Maximum revolutions",
              "1e9",
              P::Double(1, 1e15),
              "A life run ends here at the latest (criteria not reached by then are reported as "
              "not reached), 1 … 1e15 revolutions.",
              "cycles");
      declare(prm,
              "Maximum iterations",
              "1000",
              P::Integer(1, 100000),
              "A life run ends after this many wear iterations at the latest (it replaces Wear/Number "
              "of iterations for `wearlink life`), 1 … 1e5.",
              "none");
    }
  } // namespace

  void
  declare_life(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Life");
    declare_criteria(prm);
    declare_settings(prm);
    prm.leave_subsection();
  }

  LifeSettings
  read_life(dealii::ParameterHandler &prm, const std::string &file, const std::vector<std::string> &bodies)
  {
    LifeSettings    s;
    ParameterReader r(prm, file);
    r.enter("Life");
    for (const auto &row : criteria_table())
      s.limits.push_back(r.get_double(row.entry));
    s.response_body      = r.get("Response body");
    s.response_cycles    = static_cast<unsigned int>(r.get_integer("Response cycles"));
    s.response_tolerance = r.get_double("Response tolerance");
    s.tolerance          = r.get_double("Tolerance");
    s.max_revolutions    = r.get_double("Maximum revolutions");
    s.max_iterations     = static_cast<unsigned int>(r.get_integer("Maximum iterations"));
    if (!s.response_body.empty())
      {
        if (std::find(bodies.begin(), bodies.end(), s.response_body) == bodies.end())
          r.fail("Response body", "it must be a body of the scene (Mechanism/Bodies)");
      }
    r.leave();
    return s;
  }

} // namespace wearlink::analysis
