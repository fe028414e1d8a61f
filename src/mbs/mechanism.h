// SPDX-License-Identifier: LGPL-2.1-or-later
// A planar rigid multibody system in Cartesian coordinates q = (x_i, y_i, θ_i) per body
// (doc/models.md §2): bodies, kinematic constraints, force elements and gravity, and the
// Baumgarte-stabilized equations of motion (seed eq. 27)
//
//     [ M   Φqᵀ ] [ q̈ ]   [ g                       ]
//     [ Φq  0   ] [ λ  ] = [ γ − 2α Φ̇ − β² Φ         ],   Φ̇ = Φq q̇ + Φt.
//
// M is diagonal (m, m, J per body), so the saddle-point system is solved through its
// Schur complement S = Φq M⁻¹ Φqᵀ (small, symmetric positive definite while the
// constraints are independent):
//     S λ = Φq M⁻¹ g − γ̂,    q̈ = M⁻¹ (g − Φqᵀ λ).
// S is assembled from the per-body blocks of Φq (each constraint touches at most two
// bodies), which keeps the right-hand side at a few microseconds for the nine-bar.
#pragma once

#include "mbs/constraint.h"
#include "mbs/force_element.h"
#include "mbs/types.h"

#include <Eigen/Core>
#include <Eigen/LU>

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace wearlink::mbs
{
  struct Body
  {
    std::string name;
    double      mass    = 0;                  ///< [kg]
    double      inertia = 0;                  ///< about the centre of mass [kg m²]
    Vec2        initial_position{0, 0};       ///< guess for assembly [m]
    double      initial_angle = 0;            ///< guess for assembly [rad]
    Vec2        initial_velocity{0, 0};       ///< projected onto the constraints [m/s]
    double      initial_angular_velocity = 0; ///< [rad/s]
  };

  /** Power terms of one right-hand-side evaluation, for the energy balance. */
  struct PowerTerms
  {
    double constraint = 0; ///< −q̇ᵀ Φqᵀ λ: work rate of constraint reactions (drivers) [W]
    double damping    = 0; ///< dissipated by contact damping [W]
    double friction   = 0; ///< dissipated by friction [W]
  };

  class Mechanism
  {
  public:
    /** Add a body; returns its index. */
    int
    add_body(const Body &body);
    void
    add_constraint(std::unique_ptr<Constraint> c);
    /** The mechanism owns its force elements; returns a non-owning pointer. */
    ForceElement *
    add_force_element(std::unique_ptr<ForceElement> f);

    void
    set_gravity(const Vec2 &g)
    {
      gravity = g;
    }
    void
    set_baumgarte(double alpha, double beta)
    {
      baumgarte_alpha = alpha;
      baumgarte_beta  = beta;
    }

    /** Index of the body called @p name, ground (−1) for "ground", −2 if unknown. */
    int
    body_index(const std::string &name) const;

    unsigned int
    n_bodies() const
    {
      return static_cast<unsigned int>(bodies.size());
    }
    unsigned int
    n_coordinates() const
    {
      return 3 * n_bodies();
    }
    unsigned int
    n_constraint_equations() const
    {
      return n_equations;
    }
    const std::vector<Body> &
    get_bodies() const
    {
      return bodies;
    }
    const std::vector<std::unique_ptr<Constraint>> &
    get_constraints() const
    {
      return constraints;
    }
    const std::vector<std::unique_ptr<ForceElement>> &
    get_force_elements() const
    {
      return force_elements;
    }
    /** First row of constraint @p c in Φ. */
    unsigned int
    constraint_row(unsigned int c) const
    {
      return row_offset[c];
    }
    const Vec2 &
    get_gravity() const
    {
      return gravity;
    }

    /** Finish set-up (row offsets, Schur-complement sparsity, workspace). */
    void
    finalize();

    /**
     * Φ, Φq (dense m × n), Φt and γ at (t, q, v). Used by assembly and tests; the
     * right-hand side uses the block form internally.
     */
    void
    evaluate_constraints(double           t,
                         const double    *q,
                         const double    *v,
                         Eigen::VectorXd &phi,
                         Eigen::MatrixXd &jacobian,
                         Eigen::VectorXd &phi_t,
                         Eigen::VectorXd &gamma) const;

    /**
     * Accelerations q̈ [n] and multipliers λ [m] at (t, q, v); @p power receives the
     * energy-rate terms. Throws NumericalError if Φq loses rank (lock-up).
     */
    void
    accelerations(double t, const double *q, const double *v, double *a, PowerTerms &power);

    /** max |Φ| of the last accelerations() call [m for position rows, rad for angles]. */
    double
    last_constraint_violation() const;

    /** λ of the last accelerations() call (reactions, driver torques). */
    const Eigen::VectorXd &
    multipliers() const
    {
      return lambda;
    }

    /** ½ q̇ᵀ M q̇ [J]. */
    double
    kinetic_energy(const double *v) const;
    /** The potential energy of force element @p f at state @p s [J], as a caller supplies it. */
    using ElementPotential = std::function<double(const ForceElement &f, const StateView &s)>;

    /**
     * Gravity plus force-element potentials [J], summed in that order. @p trig: the
     * bodies' (cos θ, sin θ) from body_trig(), if the caller has them (else each rotation
     * computes its own). @p element_potential, if given, is asked for each element's
     * potential instead of ForceElement::potential_energy(): a caller that evaluated some
     * elements at this state already passes their energies on.
     */
    double
    potential_energy(const double           *q,
                     const double           *v,
                     const double           *trig              = nullptr,
                     const ElementPotential &element_potential = {}) const;

    /** True if the last evaluation that held contacts was at (@p q, @p v) (their forces are from there). */
    bool
    held_forces_at(const double *q, const double *v) const;

    /** Count of right-hand-side evaluations since construction. */
    long
    n_evaluations() const
    {
      return evaluations;
    }

  private:
    // The steps of accelerations(), in order (each works on the workspace below).
    /** g: gravity and the force elements' forces; their damping and friction power. */
    void
    apply_forces(double t, const StateView &s, PowerTerms &power);
    /** rhs = Φq M⁻¹ g − γ̂ with Baumgarte's γ̂ = γ − 2αΦ̇ − β²Φ. */
    void
    assemble_constraint_rhs(const double *v);
    /** S = Φq M⁻¹ Φqᵀ from the per-body blocks (lower triangle, envelope only). */
    void
    assemble_schur_complement();
    // The steps of finalize().
    /** Row offsets of the constraints, M⁻¹, and which constraints touch each body. */
    void
    index_rows_and_bodies();
    /** The permutation of S (reverse Cuthill–McKee) and its envelope. */
    void
    order_schur_rows();
    /** The constant part of S and the products that complete it (schur_entries, …). */
    void
    plan_schur_assembly();
    /** Every constraint's rows at q = 0, q̇ = 0, t = 0 (where its constant entries are read). */
    void
    evaluate_rows_at_rest();
    /** S = L D Lᵀ in place (D on the diagonal); NumericalError naming @p t if Φq lost rank. */
    void
    factor_schur_complement(double t);
    /** The NumericalError of a singular S (Φq lost rank) at time @p t. */
    [[noreturn]] void
    throw_rank_loss(double t) const;
    /** λ = S⁻¹ rhs (two triangular solves in the permuted order). */
    void
    solve_multipliers();
    /** q̈ = M⁻¹ (g − Φqᵀ λ) and the reaction power −q̇ᵀ Φqᵀ λ. */
    void
    constrained_accelerations(const double *v, double *a, PowerTerms &power) const;
    /**
     * With held contacts (held_contacts.cc): their normal forces from their acceleration
     * rows, then q̈, λ and the power terms with those forces applied. False if no
     * element holds its contact (nothing done).
     */
    bool
    solve_held_contacts(const StateView &s, const double *v, double *a, PowerTerms &power);
    /**
     * The response of q̈ to the generalized force @p g (S factored) into @p out, λ's into
     * `lambda`; returns the response's reaction power −q̇ᵀ Φqᵀ λ_g.
     */
    double
    acceleration_response(const double *v, const std::vector<double> &g, std::vector<double> &out);

    std::vector<Body>                          bodies;
    std::vector<std::unique_ptr<Constraint>>   constraints;
    std::vector<std::unique_ptr<ForceElement>> force_elements;
    Vec2                                       gravity{0, 0};
    double                                     baumgarte_alpha = 5;
    double                                     baumgarte_beta  = 5;

    // Set up by finalize().
    unsigned int              n_equations = 0;
    std::vector<unsigned int> row_offset;
    std::vector<double>       inverse_mass; // per coordinate
    /** For each body, the constraints touching it and on which side (0: i, 1: j). */
    std::vector<std::vector<std::pair<unsigned int, unsigned int>>> body_constraints;

    // Workspace (no allocation in accelerations()).
    std::vector<ConstraintRows> rows;
    /**
     * S = Φq M⁻¹ Φqᵀ in a permuted order (reverse Cuthill–McKee on the coupling graph of
     * the constraint rows), lower triangle, row-major m × m, factored in place. Only the
     * envelope (columns first_column[i]..i of row i) is ever non-zero, so assembly,
     * factorization and solves skip everything outside it.
     */
    std::vector<double>       schur;
    std::vector<unsigned int> permuted;     ///< row r of Φ sits at position permuted[r] in S
    std::vector<unsigned int> first_column; ///< envelope start per permuted row
    /**
     * The assembly of S, planned once by finalize() (the pointers are into `rows` and
     * `inverse_mass`, which are never resized afterwards): every envelope entry starts
     * from its constant part; a ThetaTerm adds w a_θ b_θ of two rows whose position
     * entries are constants (folded into the constant part); a FullTerm adds
     * Σ_d a[d] w[d] b[d] over the three entries of one body.
     */
    struct SchurEntry
    {
      std::size_t target; ///< flat index into `schur`
      double      constant;
    };
    struct ThetaTerm
    {
      std::size_t   target;
      const double *a, *b;
      double        w;
    };
    struct FullTerm
    {
      std::size_t   target;
      const double *a, *b, *w;
    };
    std::vector<SchurEntry> schur_entries; ///< every envelope entry, in memory order
    std::vector<ThetaTerm>  theta_terms;
    std::vector<FullTerm>   full_terms;
    Eigen::VectorXd         rhs, lambda, forces;
    /** Held contacts' workspace: the elements, their rows, the responses of q̈ to them. */
    std::vector<const ForceElement *>    held_elements;
    std::vector<HeldContact>             held;
    std::vector<std::vector<double>>     held_response;
    std::vector<Eigen::VectorXd>         held_lambda;
    std::vector<double>                  held_reaction_power;
    std::vector<double>                  held_state; ///< (q, v) of the last evaluation with held contacts
    Eigen::VectorXd                      held_lambda_base, forces_backup, held_fixed, held_force, held_rhs;
    Eigen::MatrixXd                      held_coupling;
    Eigen::PartialPivLU<Eigen::MatrixXd> held_lu;
    std::vector<double>                  scaled_forces; ///< M⁻¹ g
    std::vector<double>                  trig;          ///< cos θ, sin θ per body
    std::vector<double>                  work; ///< factorization scratch, then the permuted right-hand side / solution
    std::vector<double>                  inverse_pivot; ///< 1 / D_ii of the last factorization

    long evaluations = 0;
  };
} // namespace wearlink::mbs
