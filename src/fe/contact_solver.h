// SPDX-License-Identifier: LGPL-2.1-or-later
// Frictionless unilateral contact between the pin surface and the bore.
//
// Contact discretization: node-to-segment collocation with the pin as the slave.
// Each support point i of the pin surface is a contact candidate with a scalar normal
// force λ_i ≥ 0 [N per m of axial length] acting along the pin's outward normal n_i:
// −λ_i n_i on the pin node, +λ_i n_i on the bore, interpolated onto the bore nodes of
// the face that the ray x_i + t n_i meets (FE shape functions along that face). The
// initial gap g0_i is that ray's length to the exact bore profile R1*(ψ), with the pin
// placed at its reference eccentricity and relative rotation, so that gaps far below
// the element size (the Hertz approach is ~0.1 µm) are exact and the meshes of the two
// bodies need not match. The linearized gap is
//     g_i = g0_i − n_i·U + n_i·(u_bore(x_i) − w_pin,i),
// with U the pin's rigid translation and w_pin its elastic displacement relative to its
// rigid core. Complementarity: λ_i ≥ 0, g_i ≥ 0, λ_i g_i = 0; force control adds
// Σ λ_i n_i = P (the load per unit length pushing the pin into the bore), displacement
// control fixes U = 0 at the given eccentricity.
// Why this choice: (1) the pin and bore meshes are independent (the relative angle and
// eccentricity change every load state, so no matching mesh can exist); (2) the
// unknowns live on one surface, so the condensed problem has one unknown per pin
// candidate and a compliance that is invariant under the pin's rotation; (3) equilibrium
// Σ λ_i n_i = P holds exactly at the discrete level, and the nodal pressure
// p_i = λ_i / ∫N_i ds converges to the Hertz pressure under refinement. Mortar methods
// would give smoother pressures on coarse meshes but need a segment intersection per
// load state; with a surface element size well below the contact width (what the
// Hertz test asks for anyway) NTS with a fine slave surface is accurate.
//
// Two solvers of exactly the same discrete problem:
//   - CondensedContactSolver (production): the dense compliance A_ij = ∂g_i/∂λ_j on the
//     contact candidates (pin and bore parts from BoundaryCompliance) and a
//     primal–dual active-set method (semismooth Newton for this QP):
//         min ½ λᵀAλ + g0ᵀλ  s.t. λ ≥ 0, Σ λ_i n_i = P,
//     whose multiplier of the equality constraint is U. Each iteration is a small
//     Cholesky solve on the active set. Where it cycles (worn, conforming pairs) a
//     monotone primal active-set method (Lawson–Hanson) finishes from a feasible point.
//   - ReferenceContactSolver: the same active-set iteration on the full FE system of
//     both bodies (deal.II step-41 style): the active contact conditions g_i = 0 are
//     affine constraints between the pin node and the bore nodes, the core is tied to
//     one master node loaded by P, and every iteration re-factors the constrained
//     system; λ_i are the residual forces.
#pragma once

#include "base/profile.h"
#include "fe/boundary_compliance.h"
#include "fe/elasticity_problem.h"

#include <deal.II/base/tensor.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <vector>

namespace wearlink::fe
{
  /** Geometry of one load state: where each pin candidate meets the bore. */
  struct ContactKinematics
  {
    double                                   relative_angle = 0; ///< θ_pin − θ_bushing [rad]
    dealii::Tensor<1, 2>                     eccentricity;       ///< reference pin position, bushing frame [m]
    std::vector<double>                      g0;                 ///< initial gap per pin candidate [m]
    std::vector<dealii::Tensor<1, 2>>        normal;             ///< pin normal, bushing frame
    std::vector<double>                      bore_angle; ///< bushing-frame angle of the contact point on the bore
    std::vector<std::array<unsigned int, 3>> masters;    ///< bore nodes of the face met
    std::vector<std::array<double, 3>>       weights;    ///< their interpolation weights
    std::vector<unsigned char>               n_masters;
  };

  /**
   * Place the pin (its candidates from @p problem) at eccentricity @p eccentricity
   * (bushing frame) and relative rotation @p relative_angle, and cast each candidate's
   * normal ray onto the bore profile @p bore. @p pin_offsets (if given, one per pin
   * candidate) moves each candidate radially by that much [m] before the ray is cast:
   * the difference between the pin's current profile and the meshed one, so that a
   * mesh kept across small wear updates still sees the current gaps (the normals and
   * the compliance stay those of the mesh).
   */
  ContactKinematics
  compute_kinematics(const ElasticityProblem    &problem,
                     const Profile              &bore,
                     double                      relative_angle,
                     const dealii::Tensor<1, 2> &eccentricity,
                     const std::vector<double>  *pin_offsets = nullptr);

  /** Result of one load state. */
  struct ContactSolution
  {
    std::vector<double>  lambda;          ///< normal force per pin candidate [N/m]
    dealii::Tensor<1, 2> pin_translation; ///< U, bushing frame [m]
    dealii::Tensor<1, 2> resultant;       ///< Σ λ_i n_i, bushing frame [N/m]
    /**
     * Final gap per pin candidate [m]. Condensed solver: exact for the candidates within
     * reach of the contact (see CondensedContactSolver::solve), a lower bound for the
     * others (still far above the tolerance).
     */
    std::vector<double> gap;
    unsigned int        iterations = 0;
    unsigned int        n_active   = 0;
    bool                monotone   = false; ///< the condensed solver's monotone phase was needed
    /** Full displacement field (reference solver only; empty otherwise). */
    dealii::Vector<double> displacement;
  };

  class CondensedContactSolver
  {
  public:
    /**
     * @param primal_dual_limit primal–dual iterations before the monotone method takes
     *        over (0: the monotone method alone; see solve()).
     */
    CondensedContactSolver(const ElasticityProblem &problem,
                           BoundaryCompliance      &compliance,
                           unsigned int             max_iterations,
                           unsigned int             primal_dual_limit = 30);

    /**
     * @param force_control true: U unknown with Σ λ n = @p load [N/m, bushing frame];
     *        false: U = 0 (the eccentricity of @p kinematics is the given one).
     */
    ContactSolution
    solve(const ContactKinematics &kinematics, bool force_control, const dealii::Tensor<1, 2> &load);

    /**
     * Displacement field of both bodies for a solution (one back substitution with the
     * contact forces, plus the pin's translation): what the reference solver computes
     * directly, for VTU output.
     */
    dealii::Vector<double>
    displacement_field(const ContactKinematics &kinematics, const ContactSolution &solution) const;

    /** Load states that needed the monotone phase (see solve()). */
    unsigned long
    n_monotone_solves() const
    {
      return n_monotone;
    }

  private:
    const ElasticityProblem  &problem;
    BoundaryCompliance       &compliance;
    const unsigned int        max_iterations;
    const unsigned int        primal_dual_limit;
    unsigned long             n_monotone = 0;
    std::vector<unsigned int> previous_active;
    dealii::Tensor<1, 2>      previous_load;
  };

  class ReferenceContactSolver
  {
  public:
    /**
     * @param distributed assemble and solve each constrained system over the MPI ranks
     *        of MPI_COMM_WORLD: every rank holds the (replicated) mesh, partitioned
     *        with METIS (ElasticityProblem with n_partitions = number of ranks), and
     *        assembles the cells of its partition into a PETSc matrix that MUMPS
     *        factors in parallel (deal.II step-17 style). The active-set decisions are
     *        made on the gathered solution, identically on every rank.
     */
    ReferenceContactSolver(const ElasticityProblem &problem, unsigned int max_iterations, bool distributed = false);

    ContactSolution
    solve(const ContactKinematics &kinematics, bool force_control, const dealii::Tensor<1, 2> &load) const;

  private:
    /** Solve K u = f under @p constraints; f = @p load at the DoFs @p load_dofs. */
    dealii::Vector<double>
    solve_constrained(const dealii::AffineConstraints<double> &constraints,
                      const std::array<global_dof_index, 2>   &load_dofs,
                      const dealii::Tensor<1, 2>              &load) const;

    const ElasticityProblem &problem;
    const unsigned int       max_iterations;
    const bool               distributed;
  };

  /**
   * Initial active set shared by both solvers (so that they take the same path).
   * Displacement control: the candidates that overlap. Force control with the load per
   * unit length P (bushing frame): the candidates whose initial gap is within the Hertz approach
   * δ_H = 2P/(π E*) of the smallest one. For a contact of relative radius R*, Hertz's
   * half-width b satisfies b²/(2R*) = 2P/(πE*), so this picks the arc |s| < b about the
   * first point of contact whatever R* is — also on worn, conforming profiles, where it
   * overestimates the arc (the iteration then only removes candidates). Starting from
   * the one or two closest candidates instead lets the pin slide sideways in the first
   * iteration and costs ~20 iterations at 1 kN (measured), each touching new columns.
   */
  std::vector<unsigned int>
  initial_active_set(const ContactKinematics    &kinematics,
                     bool                        force_control,
                     const dealii::Tensor<1, 2> &load,
                     double                      effective_modulus);
} // namespace wearlink::fe
