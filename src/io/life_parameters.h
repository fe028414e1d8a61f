// SPDX-License-Identifier: LGPL-2.1-or-later
// The entries of a scene's `subsection Life` (the stop criteria of `wearlink life`,
// analysis/life_criteria.h): declaration with units, bounds and defaults (every
// criterion off), parsing and the checks against the built scene. That at least one
// criterion is on is checked by the life command (check_life_criteria), not here: a
// plain run or wear run ignores the section.
#pragma once

#include "analysis/life_criteria.h"

#include <deal.II/base/parameter_handler.h>

namespace wearlink::io
{
  struct Scene;

  /** Declare `subsection Life` (called by the scene reader). */
  void
  declare_life(dealii::ParameterHandler &prm);

  /**
   * Read `subsection Life` of @p scene (built: its bodies exist) from @p prm. InputError
   * naming the file, the entry and the allowed range for a value that is not finite or
   * a response body that is not a body of the scene.
   */
  analysis::LifeSettings
  parse_life(dealii::ParameterHandler &prm, const Scene &scene);

  /**
   * For `wearlink life`: InputError naming the file and every criterion entry with its
   * unit and range unless @p scene switches on at least one criterion and wears.
   */
  void
  check_life_criteria(const Scene &scene);
} // namespace wearlink::io
