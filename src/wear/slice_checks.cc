// SPDX-License-Identifier: LGPL-2.1-or-later
#include "wear/slice_checks.h"

#include "base/text.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace wearlink::wear
{
  namespace
  {
    /**
     * The largest increment over the approach that still wears in: measured on the
     * misaligned journal of tests/scenes/slices_test.cc, a ratio of 1.0 flattens the axial
     * load monotonically and 3.8 throws it from edge to edge.
     */
    constexpr double increment_limit = 2;

    /** One sliced joint's slices: their wear histories and their joints. */
    struct Slices
    {
      std::vector<const JointWearState *>          states;
      std::vector<const contact::ClearanceJoint *> joints;
    };

    /** The largest ratio of a slice's depth increment to the slices' approach over the iterations. */
    double
    largest_ratio(const Slices &s, std::size_t &at)
    {
      const auto  *first    = s.joints.front();
      const double exponent = first->normal_force_law().exponent();
      double       largest  = 0;
      if (!(std::isfinite(exponent) && exponent > 0))
        return largest; // a tabulated law: no power law to invert
      for (std::size_t k = 0; k < s.states.front()->history.size(); ++k)
        {
          double force = 0, increment = 0;
          for (const auto *js : s.states)
            {
              const auto &r = js->history[k];
              const auto *p = k > 0 ? &js->history[k - 1] : nullptr;
              force += r.mean_normal_force;
              increment = std::max(increment,
                                   r.max_depth_bore - (p ? p->max_depth_bore : 0.0) + r.max_depth_pin -
                                     (p ? p->max_depth_pin : 0.0));
            }
          const double approach = std::pow(force / s.states.size() / first->stiffness(), 1 / exponent);
          if (approach > 0 && increment / approach > largest)
            {
              largest = increment / approach;
              at      = k + 1;
            }
        }
      return largest;
    }
  } // namespace

  void
  check_axial_increments(const WearState                              &state,
                         const std::vector<contact::ClearanceJoint *> &joints,
                         ValidityWarnings                             &warnings)
  {
    std::map<std::string, Slices> sliced;
    for (const auto &js : state.joints)
      for (const auto *j : joints)
        if (j->name() == js.name && j->get_description().slice.count > 1 && !js.history.empty())
          {
            auto &s = sliced[j->get_description().slice.joint];
            s.states.push_back(&js);
            s.joints.push_back(j);
          }
    for (const auto &[joint, s] : sliced)
      {
        std::size_t  iteration = 0;
        const double ratio     = largest_ratio(s, iteration);
        warnings.check(
          {"joint " + joint +
             ": largest depth increment of a slice in one iteration over the "
             "slices' elastic approach",
           ratio,
           increment_limit,
           "",
           "twice the approach under the slices' mean force (largest in iteration " + std::to_string(iteration) + ")",
           "the axial load moves between the slices from one iteration to the next instead of "
           "wearing in (the iterations take the feedback explicitly); lower Wear/Extrapolation "
           "factor, or use Extrapolation = adaptive with a Maximum depth increment below the "
           "approach (doc/models.md §1.8)"});
      }
  }
} // namespace wearlink::wear
