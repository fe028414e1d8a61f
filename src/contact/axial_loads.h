// SPDX-License-Identifier: LGPL-2.1-or-later
// The axial load of sliced joints over a run (doc/models.md §1.8): per slice the time
// mean of its normal force, and per joint the edge load — the moment of the slices'
// forces about the in-plane axes through the bushing's mid-plane, M = |Σ z_i f_i| — and
// the axial position of the resultant, z_R = ∫ Σ z_i F_i dt / ∫ Σ F_i dt. The planar
// model carries the slices' sum; what they do along the pin is reported here.
#pragma once

#include "base/json.h"
#include "contact/clearance_joint.h"

#include <string>
#include <vector>

namespace wearlink::contact
{
  class AxialLoads
  {
  public:
    /** The sliced joints among @p joints (the mechanism's clearance joints, in order). */
    explicit AxialLoads(const std::vector<ClearanceJoint *> &joints);

    /** True if a joint of the scene is sliced. */
    bool
    any() const
    {
      return !groups.empty();
    }

    /**
     * Add one accepted step of duration @p h [s] whose end state gave @p diagnostics
     * (one per clearance joint, in the order the constructor was given them).
     */
    void
    record(const std::vector<JointDiagnostics> &diagnostics, double h);

    /**
     * Per sliced joint: slices, positions_m, mean_normal_force_N, force_share (of the sum),
     * edge_to_mean_force (the largest slice's mean force over the slices' mean),
     * resultant_position_m, mean_edge_moment_N_m (of the mean forces), max_edge_moment_N_m;
     * with a bending pin also largest_pin_deflection_m (at the recorded steps) and
     * pin_solve_failures (states where the deflection was not found to its tolerance).
     */
    Json
    json() const;

  private:
    struct Group
    {
      std::string               joint;
      std::vector<unsigned int> members; ///< indices into the joints given
      std::vector<double>       positions, force_time;
      double                    moment_time = 0, duration = 0, max_moment = 0;
      const ElasticPin         *pin        = nullptr; ///< the bending pin, or nullptr
      double                    deflection = 0;       ///< its largest [m]
    };
    std::vector<Group> groups;
  };
} // namespace wearlink::contact
