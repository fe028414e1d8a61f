// SPDX-License-Identifier: LGPL-2.1-or-later
#include "base/timings.h"

#include <utility>

namespace wearlink
{
  PhaseTimings &
  PhaseTimings::operator+=(const PhaseTimings &o)
  {
    dynamics += o.dynamics;
    meshing += o.meshing;
    fe_setup += o.fe_setup;
    fe_compliance += o.fe_compliance;
    pressure_evaluation += o.pressure_evaluation;
    contact_law_tables += o.contact_law_tables;
    wear_bookkeeping += o.wear_bookkeeping;
    outputs += o.outputs;
    before_after_dynamics += o.before_after_dynamics;
    total += o.total;
    return *this;
  }

  Json
  PhaseTimings::to_json() const
  {
    Json t                     = Json::object();
    t["before/after dynamics"] = before_after_dynamics;
    t["contact-law tables"]    = contact_law_tables;
    t["dynamics"]              = dynamics;
    t["fe compliance"]         = fe_compliance;
    t["fe set-up"]             = fe_setup;
    t["meshing"]               = meshing;
    t["outputs"]               = outputs;
    t["pressure evaluation"]   = pressure_evaluation;
    t["total"]                 = total;
    t["wear bookkeeping"]      = wear_bookkeeping;
    return t;
  }

  bool
  PhaseTimings::from_json(const Json &j, PhaseTimings &out)
  {
    PhaseTimings                            t;
    const std::pair<const char *, double *> fields[] = {{"before/after dynamics", &t.before_after_dynamics},
                                                        {"contact-law tables", &t.contact_law_tables},
                                                        {"dynamics", &t.dynamics},
                                                        {"fe compliance", &t.fe_compliance},
                                                        {"fe set-up", &t.fe_setup},
                                                        {"meshing", &t.meshing},
                                                        {"outputs", &t.outputs},
                                                        {"pressure evaluation", &t.pressure_evaluation},
                                                        {"total", &t.total},
                                                        {"wear bookkeeping", &t.wear_bookkeeping}};
    if (!j.is_object())
      return false;
    for (const auto &[key, value] : fields)
      {
        if (!j.contains(key) || !j.at(key).is_number())
          return false;
        *value = j.at(key).get<double>();
      }
    out = t;
    return true;
  }
} // namespace wearlink
