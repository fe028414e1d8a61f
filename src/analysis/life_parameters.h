// SPDX-License-Identifier: LGPL-2.1-or-later
// The entries of a scene's `subsection Life` (the stop criteria of `wearlink life`,
// analysis/life_criteria.h): declaration with units, bounds and defaults (every
// criterion off) and reading, checked against the scene's bodies. That at least one
// criterion is on is checked by the life run (workflows::check_life_criteria), not here:
// a plain run or wear run ignores the section.
#pragma once

#include "analysis/life_criteria.h"

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace wearlink::analysis
{
  /** Declare `subsection Life` (called by the scene reader). */
  void
  declare_life(dealii::ParameterHandler &prm);

  /**
   * Read `subsection Life` of the scene @p file from @p prm. InputError naming the file,
   * the entry and the allowed range for a value that is not finite or a response body
   * that is not one of @p bodies (the scene's moving bodies).
   */
  LifeSettings
  read_life(dealii::ParameterHandler &prm, const std::string &file, const std::vector<std::string> &bodies);
} // namespace wearlink::analysis
