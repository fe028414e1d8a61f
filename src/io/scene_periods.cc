// SPDX-License-Identifier: LGPL-2.1-or-later
#include "io/scene_periods.h"

#include "base/exceptions.h"
#include "base/numbers.h"
#include "base/text.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace wearlink::io
{
  namespace
  {
    /** Relative difference below which two driver speeds are the same [-]. */
    constexpr double same_speed = 1e-12;
  } // namespace

  namespace
  {
    /** The driving period of @p scene under @p s [s], or why there is none. */
    struct PeriodFinding
    {
      double      period = 0.0;
      std::string problem; ///< empty if period is valid
    };

    PeriodFinding
    find_driving_period(const Scene &scene, const analysis::AnalysesSettings &s)
    {
      PeriodFinding f;
      f.period = s.given_driving_period;
      if (!(f.period > 0.0))
        {
          std::vector<double> speeds;
          std::string         names;
          for (const auto d : scene.drivers)
            {
              const auto        &driver = *scene.mechanism->get_constraints()[d];
              const std::string &name   = driver.name;
              const double       omega  = driver.rate();
              names += (names.empty() ? "" : ", ") + name + " " + format_number(omega) + " rad/s";
              if (omega != 0.0)
                speeds.push_back(std::abs(omega));
            }
          if (speeds.empty())
            {
              f.problem = "In " + scene.file +
                          ", the driving period is needed (Poincaré sections, sweeps, wear cycles) but the "
                          "scene has no turning angle driver" +
                          (names.empty() ? std::string() : " (" + names + ")") +
                          ". Set 'Analyses/Driving period' (s), or for a wear run 'Wear/Cycle period' (s).";
              return f;
            }
          for (const double w : speeds)
            if (std::abs(w - speeds.front()) > same_speed * speeds.front())
              {
                f.problem = "In " + scene.file + ", the angle drivers turn at different rates (" + names +
                            "), so their common period is not obvious. Set 'Analyses/Driving period' (s) to "
                            "it (for a wear run: 'Wear/Cycle period').";
                return f;
              }
          f.period = numbers::two_pi / speeds.front();
        }
      if (!(s.section_phase < f.period))
        f.problem = "In " + scene.file + ", 'Analyses/Section phase' is " + format_number(s.section_phase, 6) +
                    " s; it must be smaller than the driving period (" + format_number(f.period, 6) + " s).";
      return f;
    }

  } // namespace

  double
  driving_period(const Scene &scene, const analysis::AnalysesSettings &s)
  {
    const auto f = find_driving_period(scene, s);
    if (!f.problem.empty())
      throw InputError(f.problem);
    return f.period;
  }

  double
  driving_period(const Scene &scene)
  {
    return driving_period(scene, scene.analyses);
  }

  double
  driving_period_if_known(const Scene &scene)
  {
    const auto f = find_driving_period(scene, scene.analyses);
    return f.problem.empty() ? f.period : 0.0;
  }


  double
  cycle_period(const Scene &scene)
  {
    if (scene.wear_loop.cycle_period > 0)
      return scene.wear_loop.cycle_period;
    return driving_period(scene);
  }

  void
  check_cycle_period(const Scene &scene, ValidityWarnings &warnings)
  {
    const double cycle   = scene.wear_loop.cycle_period;
    const double driving = driving_period_if_known(scene);
    if (scene.wear.empty() || !(cycle > 0) || !(driving > 0))
      return;
    const double ratio = cycle / driving;
    const double whole = std::max(1.0, std::round(ratio));
    warnings.check({"Wear/Cycle period: distance from a whole number of driving periods",
                    std::abs(ratio - whole),
                    1e-3,
                    "periods",
                    "Cycle period " + format_number(cycle, 6) + " s is " + format_number(ratio, 6) +
                      " driving periods of " + format_number(driving, 6) + " s",
                    "each wear cycle covers another part of the revolution, and the wear per cycle is that of a "
                    "fraction of a revolution; set Cycle period = 0 (the driving period) or a whole number of "
                    "driving periods"});
  }

  int
  response_body(const Scene &scene)
  {
    const auto &name = scene.wear_loop.response_body;
    const auto &mech = *scene.mechanism;
    if (name.empty())
      return static_cast<int>(mech.n_bodies()) - 1;
    for (unsigned int i = 0; i < mech.n_bodies(); ++i)
      if (mech.get_bodies()[i].name == name)
        return static_cast<int>(i);
    throw InputError("In " + scene.file + ", 'Wear/Response body' is '" + name +
                     "', which is not one of Mechanism/Bodies.");
  }

} // namespace wearlink::io
