// SPDX-License-Identifier: LGPL-2.1-or-later
// The active-set rules that the condensed and the reference contact solver share, so
// that both take the same path through the same discrete problem (contact_solver.h).
// Active sets are sorted lists of positions into the kinematics' arrays.
#pragma once

#include <deal.II/base/tensor.h>

#include <set>
#include <vector>

namespace wearlink::fe::active_set
{
  /**
   * The primal–dual active-set update: an active position stays active while its force
   * is compressive; an inactive one becomes active when its gap is below −tolerance. If
   * the plain update would revisit an earlier active set (cycling), one kind of
   * violation is corrected at a time, down to the single worst one (monotone).
   */
  std::vector<unsigned int>
  update(const std::vector<unsigned int>     &active,
         const std::vector<double>           &lambda,
         const std::vector<double>           &gap,
         double                               tolerance,
         std::set<std::vector<unsigned int>> &history);

  /**
   * Force control needs at least two active positions with different normals: with one,
   * the frictionless pin could slide sideways freely. Add the closest ones (smallest
   * @p gap_estimate) — the second on the side of the load: the load P must be a
   * non-negative combination a n_i + b n_j of the two normals, else the pair can only
   * balance it with a tensile force on one of them (a small load whose direction lies
   * between the normals of i and of its other neighbour was carried as +46 N and −45 N
   * on a 0.2 mm mesh, for 1.6 N). Among the positions that bracket P the one with the
   * smallest gap is taken; if none does, the closest one.
   */
  void
  ensure_two_active(std::vector<unsigned int>               &active,
                    const std::vector<double>               &gap_estimate,
                    const std::vector<dealii::Tensor<1, 2>> &normal,
                    const dealii::Tensor<1, 2>              &load);

  /** NumericalError: @p solver did not converge in @p iterations active-set iterations. */
  [[noreturn]] void
  not_converged(const char *solver, unsigned int iterations);
} // namespace wearlink::fe::active_set
