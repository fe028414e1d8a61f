// SPDX-License-Identifier: LGPL-2.1-or-later
// The uncertain inputs of an ensemble (a scene's `subsection Uncertainty`,
// io/uncertainty_parameters.h): each member's sampled values as --set overrides on top
// of its initial-angle perturbation, their check before anything runs, and the
// sensitivities of the headline figures to them.
//
// Member k's values come from analysis::member_inputs (Sobol point k, or point k of a
// Saltelli design with --sensitivity saltelli), so they depend on the seed, the inputs
// and k only: the same on any number of MPI ranks. summary.json gains `uncertainty`
// (seed, sampling, the inputs and their distributions), each member's `inputs` (entry →
// value), and `sensitivity`: for the headline figures — per wearing joint the pin's and
// bushing's worn volume, largest depth and mass loss; for life, life_revolutions and each
// criterion's revolutions — either first-order and total Sobol indices with bootstrap
// 95 % intervals (a Saltelli design of at least 64 base rows) or Spearman rank
// correlations with Fisher-z 95 % intervals (any other ensemble; for a smaller Saltelli
// design over its A and B rows), `method` saying which (analysis/sensitivity.h).
#pragma once

#include "base/json.h"
#include "base/parameters.h"
#include "io/scene.h"
#include "workflows/ensemble/ensemble.h"

#include <map>
#include <string>
#include <vector>

namespace wearlink::workflows
{
  /**
   * @p member (member @p k's overrides, its angle shifts already in) with the values of
   * @p scene's uncertain inputs for member @p k of @p request; the values by entry into
   * @p values if given. An uncertain 'Joint <d>/Angle offset' of an angle driver keeps
   * the driver's shift (@p shifts [rad] by driver name) on top of its sampled value.
   */
  ParameterOverrides
  with_uncertain_inputs(const io::Scene                     &scene,
                        const ParameterOverrides            &member,
                        const EnsembleRequest               &request,
                        unsigned int                         k,
                        const std::map<std::string, double> &shifts,
                        std::map<std::string, double>       *values = nullptr);

  /**
   * Before any member runs: every member's scene, with its sampled values, must read
   * (values within each entry's allowed range, a clearance below half the bore, …);
   * otherwise an InputError naming the scene file, the entry, the member's value, its
   * distribution, the reader's objection and what to do. Also checks the member count of
   * a Saltelli design. Nothing to check without uncertain inputs.
   */
  void
  check_uncertain_members(const EnsembleOptions &options, const io::Scene &base);

  /** summary.json's `uncertainty`: seed, sampling and each input's entry and distribution. */
  Json
  uncertainty_summary(const io::Scene &scene, const EnsembleRequest &request);

  /**
   * summary.json's `sensitivity` of the headline figures of @p statistics (summary.json's
   * `ensemble`) over @p members (run_ensemble's records with their `inputs`).
   */
  Json
  ensemble_sensitivity(const analysis::UncertaintySettings &uncertainty,
                       const EnsembleRequest               &request,
                       const Json                          &statistics,
                       const std::vector<Json>             &members);

  /**
   * The printed lines of a `sensitivity` block: per headline figure and input the rank
   * correlation (or first-order and total index) and its 95 % interval.
   */
  std::string
  sensitivity_table(const Json &sensitivity);

  /** Each life criterion's revolutions over the members that decided it (for life_cdf.png). */
  std::map<std::string, std::vector<double>>
  decided_revolutions(const std::vector<Json> &members);
} // namespace wearlink::workflows
