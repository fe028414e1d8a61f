// SPDX-License-Identifier: LGPL-2.1-or-later
// The condensed (boundary) compliance of the two bodies at their contact candidates.
//
// Both bodies are clamped where they are held: the pin at its rigid core (its elastic
// displacement is measured relative to the core, which translates with the unknown pin
// displacement), the bushing at its outer edge. The clamped stiffness matrix is SPD and
// block diagonal (the bodies do not touch in the mesh); it is factored once per mesh
// (see below). A column of the compliance is one forward/backward
// substitution:
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
//
// Factorization: the clamped DoFs are removed and the SPD remainder is factored by
// CHOLMOD's supernodal Cholesky (through Eigen's CholmodSupport). A missing column is
// computed together with up to block_size − 1 missing neighbours along the surface
// (candidates are sorted by angle, and a contact zone is contiguous), as one
// multi-right-hand-side solve: the supernodal triangular solves then run as BLAS-3
// and cost a fraction of one solve per column (measured in the FE benchmark).
#pragma once

#include "fe/elasticity_problem.h"

#include <deal.II/lac/vector.h>

#include <memory>
#include <vector>

namespace wearlink::fe
{
  class BoundaryCompliance
  {
  public:
    /** Clamp core and outer edge and factor @p problem's stiffness matrix. */
    explicit BoundaryCompliance(const ElasticityProblem &problem);
    ~BoundaryCompliance();

    /** Columns computed per multi-right-hand-side solve (pin; bore uses half). */
    static constexpr unsigned int block_size = 32;

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

    /** max_i |pin_column(j)[i]| [m per N/m], computed once per column. */
    double
    pin_column_bound(unsigned int j);

    /**
     * Largest displacement of any bore node for a unit force at bore candidate @p c in
     * any direction, bounded by |u_x| + |u_y| of the responses to unit x and y forces
     * [m per N/m], computed once per column.
     */
    double
    bore_column_bound(unsigned int c);

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
    /** Solve for the unit loads of the given candidates and fill their columns. */
    void
    compute_pin_block(unsigned int j);
    void
    compute_bore_block(unsigned int c);

    struct Factorization; // CHOLMOD through Eigen (kept out of this header)

    const ElasticityProblem       &problem;
    std::unique_ptr<Factorization> factorization;
    /** Row of each DoF in the reduced (unclamped) system, −1 for clamped DoFs. */
    std::vector<long>                reduced_index;
    std::vector<std::vector<double>> pin_columns;
    std::vector<std::vector<double>> bore_columns;
    std::vector<double>              pin_bounds;  ///< NaN until computed
    std::vector<double>              bore_bounds; ///< NaN until computed
    unsigned long                    n_solves           = 0;
    double                           seconds_in_columns = 0;
  };
} // namespace wearlink::fe
