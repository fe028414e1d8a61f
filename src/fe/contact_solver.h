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
//     whose multiplier of the equality constraint is U. It works on the contact window
//     only: the candidates whose initial gap is below a threshold that the elastic
//     deformation cannot bridge (checked against the solution and widened when it is not
//     enough; outside it the gaps stay open).
//     The window's columns of A are gathered once per state; the Cholesky factor of the
//     active block is kept in an order that puts the arc's edges last (distance from the
//     first point of contact), so that an iteration, which changes the active set at the
//     edges, re-factors only the rows after the first change (LAPACK, i.e. OpenBLAS on
//     Debian). Where the iteration cycles (worn, conforming pairs) a monotone primal
//     active-set method (Lawson–Hanson) finishes from a feasible point.
//   - ReferenceContactSolver: the same active-set iteration on the full FE system of
//     both bodies (deal.II step-41 style): the active contact conditions g_i = 0 are
//     affine constraints between the pin node and the bore nodes, the core is tied to
//     one master node loaded by P, and every iteration re-factors the constrained
//     system; λ_i are the residual forces. It sees every candidate.
#pragma once

#include "fe/boundary_compliance.h"
#include "fe/contact_kinematics.h"
#include "fe/elasticity_problem.h"

#include <deal.II/base/tensor.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <cmath>
#include <memory>
#include <vector>

namespace wearlink::fe
{
  /** Result of one load state (per position of the kinematics it was solved on). */
  struct ContactSolution
  {
    std::vector<double>  lambda;          ///< normal force per position [N/m]
    dealii::Tensor<1, 2> pin_translation; ///< U, bushing frame [m] (from the pose the solver was given)
    /** The translation from the last linearization's pose: gap = g0 − n·U_last + A λ there [m]. */
    dealii::Tensor<1, 2> last_translation;
    dealii::Tensor<1, 2> resultant; ///< Σ λ_i n_i, bushing frame [N/m]
    std::vector<double>  gap;       ///< final gap per position [m]
    /** The active positions at the end (for a warm start of the same state). */
    std::vector<unsigned int> active;
    unsigned int              iterations = 0;
    unsigned int              n_active   = 0;
    bool                      monotone   = false; ///< the condensed solver's monotone phase was needed
    /** Full displacement field (reference solver only; empty otherwise). */
    dealii::Vector<double> displacement;
  };

  namespace condensed_detail
  {
    class WindowCompliance;
    class ActiveFactor;
    struct WindowState;
    struct Workspace;
  } // namespace condensed_detail

  /** Linearizations of one load state at most (the last one is accepted). */
  constexpr unsigned int max_relinearizations = 12;

  /** Smallest distance between neighbouring pin candidates along the surface [m]. */
  double
  candidate_spacing(const ElasticityProblem &problem);

  /**
   * True when the pin has moved by @p U since the pose its contact pairing was computed
   * at by more than a quarter of the candidate @p spacing: then it is paired anew
   * (refresh_gaps() keeps the pairing for smaller moves).
   */
  inline bool
  pairing_outdated(const dealii::Tensor<1, 2> &U, const double spacing)
  {
    return U.norm() > 0.25 * spacing;
  }

  /**
   * True when a converged linearization ended farther than 2 % of the candidate
   * @p spacing across the load (unit direction @p d) from the pose its pairing was
   * computed at: the state is then paired once more at the solution and solved again,
   * so that the accepted pairing (which bore points the pin's forces act on) is that of
   * the solution whatever the path. On a worn, conformal pocket the pressure depends on
   * it: at 1 kN on a 32 µm worn bore (25 µm elements), pairings 1.5 µm apart across the
   * load gave peaks 9 % apart for pin positions 6 nm apart; paired at the solutions,
   * 0.6 %. A move along the load (the elastic approach that the start's estimate
   * missed) shifts the points the rays meet far less and does not count.
   */
  inline bool
  pairing_off_the_solution(const dealii::Tensor<1, 2> &U, const dealii::Tensor<1, 2> &d, const double spacing)
  {
    const double across = U[0] * d[1] - U[1] * d[0];
    return std::abs(across) > 0.02 * spacing;
  }

  /** The smallest radius of the meshed pin surface (its candidates) [m]. */
  double
  smallest_pin_radius(const ElasticityProblem &problem);

  /**
   * True when the pin translation @p U of a linearization is small enough to stop
   * re-linearizing: |U| < 2e-4 R (R = smallest_pin_radius()). The gap is linearized as g0 − n·U;
   * the exact change of a ray's length is −(ν·U)/(ν·n), ν the bore normal where it
   * lands, which differs by less than 2 % of |U| on the contact arcs of interest.
   */
  inline bool
  relinearization_done(const dealii::Tensor<1, 2> &U, const double pin_radius)
  {
    return U.norm() < 2e-4 * pin_radius;
  }

  /**
   * An estimate of the elastic approach of a conforming pin–bore pair under the load per
   * unit length @p load_per_length [N/m]: Johnson's cylinder in a cylindrical hole,
   * δ = 0.9 P/(πE*) [ln(4πE*ΔR/P) − 1] (the factor: the rigid pin core and the clamped
   * ring of the FE model make it stiffer than two unbounded bodies; within 10 % of the FE
   * approach from 100 N to 100 kN on the steel pair of params/pin_bushing.prm), and at
   * least 0.1 P/(πE*). Deterministic, so that a load state's path through the
   * kinematic updates does not depend on what was solved before.
   */
  double
  predicted_approach(double load_per_length, double effective_modulus, double radial_clearance);

  /**
   * Where the condensed solver's time goes, summed over its load states [s]: gathering
   * the window's compliance columns (the bore and pin columns themselves excluded when
   * they are computed on first use), factoring the active block, the products of the
   * gathered columns with the multipliers (the gaps), and the triangular substitutions
   * with the factor; `total` is the whole of CondensedContactSolver::solve().
   */
  struct CondensedTimings
  {
    double        total = 0, gather = 0, factorization = 0, gaps = 0, substitutions = 0;
    unsigned long solves = 0;
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
    ~CondensedContactSolver();

    /**
     * One load state about @p pose, on its contact window (compute_window_kinematics):
     * the window first reaches half of @p closure_estimate [m] (the elastic approach
     * expected), and is widened and the state solved again if the solution's elastic
     * deformation could close a gap outside it (see the .cc). Under force control the
     * gaps are refreshed about the translated pin (refresh_gaps()) until the
     * translation of the last linearization is below relinearization_done(); the
     * solution's pin_translation is the total from @p pose. @p kinematics receives the
     * window's kinematics (its gaps those of the last linearization).
     * @param force_control true: U unknown with Σ λ n = @p load [N/m, bushing frame];
     *        false: U = 0 (the eccentricity of @p pose is the given one).
     */
    ContactSolution
    solve(const PinPose              &pose,
          bool                        force_control,
          const dealii::Tensor<1, 2> &load,
          double                      closure_estimate,
          ContactKinematics          &kinematics);

    /**
     * Displacement field of both bodies for a solution (one back substitution with the
     * contact forces, plus the pin's translation): what the reference solver computes
     * directly, for VTU output.
     */
    dealii::Vector<double>
    displacement_field(const ContactKinematics &kinematics, const ContactSolution &solution) const;

    /** The time of the load states solved so far, by phase. */
    const CondensedTimings &
    timings() const;

    /**
     * Gap opened per unit force per length at each pin candidate by the surfaces' wear
     * during the load state [m²/N] (indexed by pin node; empty: none): the diagonal the
     * sequential wear update adds to the compliance, c / ∫N_i ds for a wear compliance
     * c [m/Pa] (so that A λ includes the worn depth c p_i and the state is solved at the
     * end of its own wear: backward Euler). Set before solve(); clear after.
     */
    void
    set_wear_diagonal(std::vector<double> diagonal)
    {
      wear_diagonal = std::move(diagonal);
    }

    /** Load states that needed the monotone phase (see solve()). */
    unsigned long
    n_monotone_solves() const
    {
      return n_monotone;
    }

  private:
    /**
     * The contact window at @p pose from the threshold @p T [m] on; under force control
     * widened (T raised) until its normals bracket @p load: no λ ≥ 0 on a window whose
     * normals all lie on one side of the load balances it. @p threshold receives the
     * window's threshold [m].
     */
    ContactKinematics
    load_bracketing_window(const PinPose              &pose,
                           bool                        force_control,
                           const dealii::Tensor<1, 2> &load,
                           double                     &T,
                           double                     &threshold) const;

    void
    finish(const ContactKinematics       &kinematics,
           condensed_detail::WindowState &state,
           bool                           force_control,
           const dealii::Tensor<1, 2>    &load,
           ContactSolution               &solution) const;

    /** How the linearizations of one pairing ended (linearize()). */
    enum class PairingEnd
    {
      accepted,
      narrow, ///< the window is too narrow for the solution's deformation
      slid    ///< the pin slid too far from the pairing's pose
    };

    PairingEnd
    linearize(const PinPose                      &paired,
              double                              threshold,
              bool                                force_control,
              const dealii::Tensor<1, 2>         &load,
              ContactKinematics                  &kinematics,
              condensed_detail::WindowCompliance &A,
              condensed_detail::ActiveFactor     &factor,
              condensed_detail::WindowState      &state,
              dealii::Tensor<1, 2>               &U_pair,
              unsigned int                       &updates,
              double                             &widen,
              bool                               &monotone_used);

    void
    solve_exactly(const ContactKinematics            &kinematics,
                  condensed_detail::WindowCompliance &A,
                  condensed_detail::ActiveFactor     &factor,
                  bool                                force_control,
                  const dealii::Tensor<1, 2>         &load,
                  condensed_detail::WindowState      &state,
                  bool                               &monotone_used);

    void
    solve_linearized(const ContactKinematics            &kinematics,
                     condensed_detail::WindowCompliance &A,
                     condensed_detail::ActiveFactor     &factor,
                     bool                                force_control,
                     const dealii::Tensor<1, 2>         &load,
                     bool                                exact,
                     condensed_detail::WindowState      &state,
                     bool                               &monotone_used);

    const ElasticityProblem &problem;
    BoundaryCompliance      &compliance;
    const unsigned int       max_iterations;
    const unsigned int       primal_dual_limit;
    const double             clearance;  ///< mean radial clearance of the meshed surfaces [m]
    const double             pin_radius; ///< smallest radius of the meshed pin surface [m]
    const double             spacing;    ///< candidate_spacing() [m]
    unsigned long            n_monotone = 0;
    /** Memory the load states reuse (gathered columns, factor). */
    std::unique_ptr<condensed_detail::Workspace> workspace;
    std::vector<double>                          wear_diagonal; ///< see set_wear_diagonal()
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

    /** One load state on the kinematics of every candidate (compute_kinematics()). */
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
   * Initial active set of the reference solver. Displacement control: the candidates
   * that overlap. Force control with the load per unit length P (bushing frame): the
   * candidates whose initial gap is within the Hertz approach δ_H = 2P/(π E*) of the
   * smallest one. For a contact of relative radius R*, Hertz's half-width b satisfies
   * b²/(2R*) = 2P/(πE*), so this picks the arc |s| < b about the first point of contact
   * whatever R* is — also on worn, conforming profiles, where it overestimates the arc
   * (the iteration then only removes candidates).
   */
  std::vector<unsigned int>
  initial_active_set(const ContactKinematics    &kinematics,
                     bool                        force_control,
                     const dealii::Tensor<1, 2> &load,
                     double                      effective_modulus);
} // namespace wearlink::fe
