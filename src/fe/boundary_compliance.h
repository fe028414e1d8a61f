// SPDX-License-Identifier: LGPL-2.1-or-later
// The condensed (boundary) compliance of the two bodies at their contact candidates.
//
// Both bodies are clamped where they are held: the pin at its rigid core (its elastic
// displacement is measured relative to the core, which translates with the unknown pin
// displacement), the bushing at its outer edge. The clamped stiffness matrix is SPD and
// block diagonal (the bodies do not touch in the mesh); it is factored once per mesh
// with UMFPACK. A column of the compliance is one forward/backward substitution:
//   - pin column j: the displacement, projected on every pin candidate's normal, due to
//     a unit force along the normal ν_j of pin candidate j (pin frame). Normal-to-normal
//     compliance ν_i·C_ij ν_j is invariant under a rigid rotation of the pin, so one
//     factorization serves every relative angle of pin and bushing.
//   - bore column c: the displacement vector at every bore candidate due to a unit force
//     along x and along y at bore candidate c (bushing frame); the force of a pin node
//     on the bore is interpolated onto the bore nodes of the face it meets, along the
//     pin node's normal, so the bore needs full 2×2 blocks.
// Columns are computed on demand and cached: a load state needs only the columns of
// the candidates that are in contact, and a wear cycle re-uses them. precompute_all()
// fills every column (what a benchmark of the full influence matrix measures).
#pragma once

#include "fe/elasticity_problem.h"

#include <deal.II/lac/sparse_direct.h>

#include <memory>
#include <vector>

namespace wearlink::fe
{
  class BoundaryCompliance
  {
  public:
    /** Clamp core and outer edge and factor @p problem's stiffness matrix. */
    explicit BoundaryCompliance(const ElasticityProblem &problem);

    /**
     * ν_i · u_i for all pin candidates i, for a unit normal force on pin candidate
     * @p j [m per N/m].
     */
    const std::vector<double> &
    pin_column(unsigned int j);

    /**
     * Displacements of all bore candidates for unit forces at bore candidate @p c:
     * entries [2a + d] for a force along x, [2 n_bore + 2a + d] along y (d = x, y).
     */
    const std::vector<double> &
    bore_column(unsigned int c);

    /** Fill every column (the full influence matrices). */
    void
    precompute_all();

    /** Solve the clamped system in place (forces in, displacements out). */
    void
    solve_clamped(dealii::Vector<double> &rhs_and_solution) const;

    /** Number of back substitutions so far. */
    unsigned long
    n_back_substitutions() const
    {
      return n_solves;
    }

    /** Wall time spent computing columns so far [s]. */
    double
    column_time() const
    {
      return seconds_in_columns;
    }

  private:
    const ElasticityProblem &           problem;
    dealii::SparseMatrix<double>        clamped_matrix;
    dealii::SparseDirectUMFPACK         factorization;
    std::vector<std::vector<double>>    pin_columns;
    std::vector<std::vector<double>>    bore_columns;
    unsigned long                       n_solves = 0;
    double                              seconds_in_columns = 0;
  };
} // namespace wearlink::fe
