// SPDX-License-Identifier: LGPL-2.1-or-later
// Initial assembly (doc/models.md §2): positions by Newton's method on Φ(q, t0) = 0 from
// the rough pose the scene gives, velocities from Φq q̇ = −Φt.
//
// The Newton step is the minimum-norm correction Δq = −Φq⁺ Φ (pseudo-inverse through a
// complete orthogonal decomposition), so a mechanism with free coordinates moves as
// little as possible from the guess, and the branch reached is the one nearest the
// guess. A backtracking line search on ‖Φ‖ keeps the iteration from jumping branches.
// Velocities are the guess projected onto the constraint manifold with the same
// minimum-change rule. Clearance joints are assembled as revolutes pinned at their
// initial eccentricity (passed in @p extra).
#pragma once

#include "mbs/mechanism.h"

#include <Eigen/Core>

#include <memory>
#include <vector>

namespace wearlink::mbs
{
  struct AssemblyOptions
  {
    double       tolerance      = 1e-12; ///< max |Φ| accepted [m or rad]
    unsigned int max_iterations = 100;
  };

  struct AssemblyResult
  {
    unsigned int iterations = 0;
    double       residual   = 0; ///< max |Φ| reached
  };

  /**
   * Assemble @p mechanism at time @p t0: returns q (3 per body) and v. Throws an
   * InputError naming the worst joint when no configuration satisfies the constraints
   * near the guess.
   */
  AssemblyResult
  assemble(const Mechanism                                &mechanism,
           double                                          t0,
           const std::vector<std::unique_ptr<Constraint>> &extra,
           const AssemblyOptions                          &options,
           Eigen::VectorXd                                &q,
           Eigen::VectorXd                                &v);

  /**
   * Move a state of the mechanism at time @p t so that it also satisfies @p extra (the
   * least change of @p q that satisfies the mechanism's and the extra constraints, by the
   * same Newton iteration as assemble(), from @p q), and project @p v onto the
   * mechanism's own velocity constraints with the least change (the extra constraints
   * fix positions only: the relative velocities they would pin stay as they were).
   * NumericalError if no such configuration is found near @p q.
   */
  AssemblyResult
  carry(const Mechanism                                &mechanism,
        double                                          t,
        const std::vector<std::unique_ptr<Constraint>> &extra,
        const AssemblyOptions                          &options,
        Eigen::VectorXd                                &q,
        Eigen::VectorXd                                &v);
} // namespace wearlink::mbs
