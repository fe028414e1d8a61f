// SPDX-License-Identifier: LGPL-2.1-or-later
// The condensed (boundary) compliance of the two bodies at their contact candidates.
//
// Both bodies are clamped where they are held: the pin at its rigid core (its elastic
// displacement is measured relative to the core, which translates with the unknown pin
// displacement), the bushing at its outer edge. The clamped stiffness matrix is SPD and
// block diagonal (the bodies do not touch in the mesh): each body's block is factored
// once per mesh, on its own (a column of one body then touches only its factor). A
// column of the compliance is one forward/backward substitution:
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
// Rotation-invariant bodies (a periodic mesh of K identical sectors,
// fe/pin_bushing_mesher.h): rotating by one sector maps candidate i to i + S (S = the
// candidates per sector, in the angle-sorted order) and the body onto itself, so
// C(i + kS, j + kS) = R_k C(i, j) R_kᵀ (R_k the rotation by k sectors; the identity for
// the pin's normal-to-normal entries). Only the S columns of the first sector are
// computed; a column is handed out as a shifted view of one of them. The bore's 2 × 2
// blocks are stored in the frames of the nodes' sectors (BoreColumn), where
// C'(i + kS, j + kS) = C'(i, j) holds without a rotation. The
// constructor checks the node positions and normals for the rotation symmetry (to 1e-9
// of the radius) and computes every column otherwise.
//
// Factorization: the clamped DoFs are removed and each body's SPD block is factored by
// CHOLMOD's supernodal Cholesky (through Eigen's CholmodSupport). A missing column is
// computed together with up to block_size − 1 missing neighbours along the surface
// (candidates are sorted by angle, and a contact zone is contiguous), as one
// multi-right-hand-side solve: the supernodal triangular solves then run as BLAS-3
// and cost a fraction of one solve per column (measured in the FE benchmark).
#pragma once

#include "fe/elasticity_problem.h"

#include <deal.II/lac/vector.h>

#include <array>
#include <memory>
#include <vector>

namespace wearlink::fe
{
  class BoundaryCompliance
  {
  public:
    /**
     * Clamp core and outer edge and factor @p problem's stiffness matrix per body.
     * @param pin_sectors, bore_sectors the sectors of a periodic mesh of each body
     *        (MeshStatistics; 0: not periodic).
     */
    BoundaryCompliance(const ElasticityProblem &problem, unsigned int pin_sectors = 0, unsigned int bore_sectors = 0);
    ~BoundaryCompliance();

    /** Columns computed per multi-right-hand-side solve (pin; bore uses half). */
    static constexpr unsigned int block_size = 32;

    /**
     * One column of the pin compliance: entry i (ν_i · u_i for a unit normal force on
     * the column's candidate j) [m per N/m] is base[(i + m − shift) mod m].
     */
    struct PinColumn
    {
      const double *base  = nullptr;
      unsigned int  shift = 0;
    };
    PinColumn
    pin_column(unsigned int j);

    /**
     * One column of the bore compliance, in sector frames: the frame of a bore candidate
     * is the x–y frame rotated by its sector's angle (sector_rotation(); the x–y frame
     * itself on a mesh that is not periodic). For a unit force along the x (y) axis of
     * candidate c's frame, the displacement of candidate a in a's frame is
     * (xx, yx) ((xy, yy)) at index a' = (a + q − shift) mod q of the four planar arrays
     * xx = base, yx = base + q, xy = base + 2q, yy = base + 3q [m per N/m]. In these
     * frames the columns of a periodic body are shifted copies of one sector's, with no
     * rotation left to apply per entry.
     */
    struct BoreColumn
    {
      const double *base  = nullptr;
      unsigned int  shift = 0;
    };
    BoreColumn
    bore_column(unsigned int c);

    /** (cos, sin) of the rotation of bore candidate @p a's frame (see BoreColumn). */
    std::array<double, 2>
    sector_rotation(const unsigned int a) const
    {
      return bore_sector_size > 0 ? sector_rotations[a / bore_sector_size] : std::array<double, 2>{{1.0, 0.0}};
    }

    /** True when the pin's (the bore's) columns are rotations of one sector's. */
    bool
    pin_periodic() const
    {
      return pin_sector_size > 0;
    }
    bool
    bore_periodic() const
    {
      return bore_sector_size > 0;
    }

    /**
     * Fill every column (the full influence matrices; one sector's for a periodic body),
     * in the blocks the on-demand path would take, on every core.
     */
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

    struct Factorization; // CHOLMOD through Eigen, one per body (kept out of this header)
    struct Workspace;     // CHOLMOD's workspace of one thread (precompute_all())

    /**
     * Solve for the unit loads of the candidates @p chosen and fill their columns, with
     * the workspace @p w (null: the factorization's own); returns the solves.
     */
    unsigned int
    fill_pin_block(const std::vector<unsigned int> &chosen, Workspace *w);
    unsigned int
    fill_bore_block(const std::vector<unsigned int> &chosen, Workspace *w);

    const ElasticityProblem       &problem;
    std::unique_ptr<Factorization> pin_factor, ring_factor;
    /** Per DoF: its row in its body's reduced (unclamped) system, −1 for clamped DoFs. */
    std::vector<long>                  reduced_index;
    std::vector<std::vector<double>>   pin_columns;
    std::vector<std::vector<double>>   bore_columns;
    unsigned int                       pin_sector_size = 0, bore_sector_size = 0; ///< S per body, 0: not periodic
    std::vector<std::array<double, 2>> sector_rotations;                          ///< (cos, sin) per bore sector
    unsigned long                      n_solves           = 0;
    double                             seconds_in_columns = 0;
  };
} // namespace wearlink::fe
