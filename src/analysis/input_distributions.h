// SPDX-License-Identifier: LGPL-2.1-or-later
// Uncertain inputs of a scene and the values an ensemble member draws for them.
//
// An uncertain input is a numeric scene entry ("Joint A/Clearance/Friction coefficient")
// with a distribution (InputDistribution, analysis/sensitivity.h: normal, lognormal,
// uniform, truncated normal). Member k of an ensemble takes point k of the
// d-dimensional Sobol sequence (d inputs), digitally shifted by the scene's seed, and
// maps coordinate i through the inverse CDF of input i. The values depend on the seed,
// the inputs and k only: not on the number of members nor on the MPI rank that runs
// member k. A low-discrepancy sequence covers the inputs' joint distribution more
// evenly than independent random draws, so that a few members already span it.
//
// A Saltelli design (sensitivity.h, for Sobol indices) instead takes design point k of
// SaltelliDesign(inputs, N / (d + 2), 0, seed): N must then be a multiple of d + 2.
#pragma once

#include "analysis/sensitivity.h"

#include <cstdint>
#include <string>
#include <vector>

namespace wearlink::analysis
{
  /** One uncertain scene entry and its distribution (in the entry's own unit). */
  struct UncertainInput
  {
    std::string       entry; ///< full entry path, "Section/Sub/Entry"
    InputDistribution distribution;
  };

  /** A scene's `subsection Uncertainty`: the inputs (none: a plain ensemble) and the seed. */
  struct UncertaintySettings
  {
    std::vector<UncertainInput> inputs;
    /** Seed of the digital shift of the Sobol points (0: the unshifted sequence). */
    std::uint64_t seed = 1;
  };

  /** How the members' input values are laid out. */
  enum class InputSampling
  {
    sobol,   ///< member k: Sobol point k (any N; rank correlations)
    saltelli ///< member k: point k of a Saltelli design of N / (d + 2) base rows (Sobol indices)
  };

  /**
   * The input values of member @p k of @p n_members (one per input, in order) under
   * @p settings. With InputSampling::sobol @p n_members is not used (the values do not
   * depend on it); with saltelli it must be a multiple of d + 2 (InputError otherwise).
   */
  std::vector<double>
  member_inputs(const UncertaintySettings &settings, InputSampling sampling, std::uint64_t n_members, std::uint64_t k);

  /** The Saltelli design of @p n_members members (n_members a multiple of d + 2; InputError otherwise). */
  SaltelliDesign
  member_design(const UncertaintySettings &settings, std::uint64_t n_members);
} // namespace wearlink::analysis
