// SPDX-License-Identifier: LGPL-2.1-or-later
// The entries of a scene's `subsection Analyses`: declaration (with units and allowed
// values), parsing and cross-checks against the built scene, and the driving period the
// sections and comparisons use.
#pragma once

#include "analysis/analyses_settings.h"

#include <deal.II/base/parameter_handler.h>

namespace wearlink::io
{
  struct Scene;

  /** Declare `subsection Analyses` (called by the scene reader). */
  void
  declare_analyses(dealii::ParameterHandler &prm);

  /**
   * Read `subsection Analyses` of @p scene (already built: joints and bodies exist) from
   * @p prm and check it: listed joints must be clearance joints, bodies must exist, a
   * Poincaré section needs a driving period. InputError naming the entry otherwise.
   */
  analysis::AnalysesSettings
  parse_analyses(dealii::ParameterHandler &prm, const Scene &scene);

  /**
   * Parse "CHANNEL: BEFORE AFTER, ..." (e.g. "A_ex_m: 0.041 0.076, B_ex_m: 0.030 0.052").
   * InputError if malformed, its message prefixed with "@p where: " unless @p where is
   * empty (then it is the bare reason, for a caller that names the entry itself).
   */
  std::vector<analysis::PublishedExponents>
  parse_published_exponents(const std::string &text, const std::string &where);
} // namespace wearlink::io
