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

    /** The criteria's limits: entry, bounds and meaning. */
    void
    declare_criteria(dealii::ParameterHandler &prm)
    {
      declare(prm,
              "Maximum wear depth",
              "0",
              P::Double(0, 0.1),
              "Stop criterion of `wearlink life`: the largest envelope depth of any surface (pin or "
              "bore) of any wearing joint — the largest running median of the depth over the "
              "joint's contact width (2b of the Hertz strip at the first iteration's peak force), so "
              "a one-area spike does not reach it and a pocket as wide as the contact does — 0 … "
              "0.1 m (a wear depth beyond 10 cm is no joint's); 0: off.",
              "m");
      declare(prm,
              "Radial clearance growth",
              "0",
              P::Double(0, 0.1),
              "Stop criterion: the growth of a joint's radial clearance, the envelope depth of its "
              "bore plus that of its pin (see Maximum wear depth; they face each other once per "
              "relative revolution), 0 … 0.1 m; 0: off.",
              "m");
      declare(prm,
              "Pin mass loss",
              "0",
              P::Double(0, 1e9),
              "Stop criterion: the mass worn off a joint's pin (worn volume × Pin density), 0 … 1e9 "
              "mg (1 t); 0: off.",
              "mg");
      declare(prm,
              "Bushing mass loss",
              "0",
              P::Double(0, 1e9),
              "Stop criterion: the mass worn off a joint's bushing, 0 … 1e9 mg; 0: off.",
              "mg");
      declare(prm,
              "Response rise",
              "0",
              P::Double(0, 1e4),
              "Stop criterion: the rise of the response measure — the mean over Response cycles of "
              "the per-cycle peak acceleration magnitude of Response body, over every accepted "
              "integrator step, in a run from the initial assembly with the current profiles after "
              "one settling cycle, measured after every wear iteration — over its value with the "
              "fresh profiles, 0 … 1e4 %; 0: off (and no response runs). The measure scatters, so "
              "the criterion is decided on a trend fitted through all measurements — a line, a step "
              "or a ramp, chosen by BIC: reached when the lower 95 % confidence bound of the "
              "trend's rise is at the limit, located where the trend crosses it, with the 95 % "
              "interval of that crossing (profile likelihood; see Response tolerance); an "
              "undecided criterion is never the life, unless it is reached and its whole interval "
              "lies before every reached wear criterion.",
              "%");
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
    s.max_wear_depth     = r.get_double("Maximum wear depth");
    s.clearance_growth   = r.get_double("Radial clearance growth");
    s.pin_mass_loss      = r.get_double("Pin mass loss");
    s.bushing_mass_loss  = r.get_double("Bushing mass loss");
    s.response_rise      = r.get_double("Response rise");
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
