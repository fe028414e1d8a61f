// SPDX-License-Identifier: LGPL-2.1-or-later
// The entries of a scene's `subsection Uncertainty`: the uncertain inputs of an
// ensemble (analysis/input_distributions.h) and the seed of their sampling.
//
//   subsection Uncertainty
//     set Inputs = Joint A/Clearance/archard/Pin wear coefficient: lognormal(4.6e-14, 0.3); (\)
//                  Joint A/Clearance/modified-coulomb/Friction coefficient: uniform(0.1, 0.2)
//     set Seed   = 1
//   end
//
// (a long list continues on the next line after a trailing backslash, shown as (\)).
// Inputs is a list separated by ';', each "ENTRY PATH: DISTRIBUTION(PARAMETERS)" with
// parameters in the entry's own unit:
//   normal(mean, std)                         std > 0
//   lognormal(median, sigma_log)              ln x normal with mean ln(median) and
//                                             standard deviation sigma_log [-]; median > 0,
//                                             sigma_log > 0 (0.3: a factor e^0.3 = 1.35
//                                             per σ)
//   uniform(low, high)                        low < high
//   truncated normal(mean, std, low, high)    the normal (mean, std) restricted to
//                                             [low, high], low < high
// The entry must be a declared entry of the scene with a numeric value, in a part the
// scene uses (not the subsection of a law it did not choose), and listed once. Only
// `--ensemble` samples the inputs; a single run uses the scene's own values.
#pragma once

#include "analysis/input_distributions.h"

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace wearlink::analysis
{
  /** Declare `subsection Uncertainty` (called by the scene reader, io/scene_declarations.cc). */
  void
  declare_uncertainty(dealii::ParameterHandler &prm);

  /**
   * One distribution from its text, e.g. "lognormal(4.6e-14, 0.3)". InputError naming
   * the family, the parameter and the allowed range (the caller adds the file and entry).
   */
  InputDistribution
  parse_distribution(const std::string &text);

  /**
   * Read `subsection Uncertainty` of the scene @p file from @p prm (parsed, overrides
   * applied). @p inactive_prefixes are the entry-path prefixes of the parts the scene
   * does not use. InputError naming the file, `Uncertainty/Inputs`, the input, what is
   * allowed and what to do.
   */
  UncertaintySettings
  read_uncertainty(dealii::ParameterHandler       &prm,
                   const std::string              &file,
                   const std::vector<std::string> &inactive_prefixes);

  /** The syntax of an input as a user writes it, for messages and documentation. */
  std::string
  uncertainty_syntax();
} // namespace wearlink::analysis
