// SPDX-License-Identifier: LGPL-2.1-or-later
// The entries of a scene's `subsection Analyses`: declaration (with units and allowed
// values), reading, and the checks against what the scene holds (its clearance joints,
// bodies and time span; the scene reader adds the driving period a Poincaré section needs).
#pragma once

#include "analysis/analyses_settings.h"

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace wearlink::analysis
{
  /** What the Analyses entries are checked against: the scene being read. */
  struct AnalysedScene
  {
    std::string              file;             ///< for messages
    std::vector<std::string> clearance_joints; ///< names, in the scene's order
    std::vector<std::string> bodies;           ///< names of the moving bodies
    double                   start_time = 0;   ///< [s]
    double                   end_time   = 0;   ///< [s]
  };

  /** Declare `subsection Analyses` (called by the scene reader). */
  void
  declare_analyses(dealii::ParameterHandler &prm);

  /**
   * Read `subsection Analyses` of @p scene from @p prm and check it: listed joints must
   * be clearance joints, bodies must exist, the run must be long enough for the samples
   * asked for. InputError naming the entry otherwise.
   */
  AnalysesSettings
  read_analyses(dealii::ParameterHandler &prm, const AnalysedScene &scene);

  /**
   * Parse "CHANNEL: BEFORE AFTER, ..." (e.g. "A_ex_m: 0.041 0.076, B_ex_m: 0.030 0.052").
   * InputError if malformed, its message prefixed with "@p where: " unless @p where is
   * empty (then it is the bare reason, for a caller that names the entry itself).
   */
  std::vector<PublishedExponents>
  parse_published_exponents(const std::string &text, const std::string &where);
} // namespace wearlink::analysis
