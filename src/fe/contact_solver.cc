// SPDX-License-Identifier: LGPL-2.1-or-later
// The active-set rules both solvers share, the reference solver, and the approach
// estimate; the condensed solver is in condensed_contact_solver.cc.
#include "fe/contact_solver.h"

#include "base/effect_ledger.h"
#include "base/exceptions.h"
#include "base/numbers.h"
#include "fe/active_set_rules.h"
#include "fe/boundary_ids.h"

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/petsc_solver.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparse_direct.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <set>

namespace wearlink::fe
{
  using namespace dealii;

  namespace
  {
  } // namespace


  namespace active_set
  {
    std::vector<unsigned int>
    update(const std::vector<unsigned int>     &active,
           const std::vector<double>           &lambda,
           const std::vector<double>           &gap,
           double                               tolerance,
           std::set<std::vector<unsigned int>> &history)
    {
      std::vector<char> is_active(gap.size(), 0);
      for (const auto i : active)
        is_active[i] = 1;
      // A force this close to zero is zero (round-off of the active system): it must not
      // leave while a neighbour penetrates, or a load along one candidate's normal, which
      // that candidate carries alone, makes the two-candidate rule cycle.
      double lambda_tolerance = 0;
      for (const auto i : active)
        lambda_tolerance = std::max(lambda_tolerance, 1e-10 * std::abs(lambda[i]));
      std::vector<unsigned int> next;
      unsigned int              worst_lambda = 0, worst_gap = 0;
      double                    min_lambda = -lambda_tolerance, min_gap = -tolerance;
      for (unsigned int i = 0; i < gap.size(); ++i)
        {
          if (is_active[i])
            {
              if (lambda[i] >= -lambda_tolerance)
                next.push_back(i);
              else if (lambda[i] < min_lambda)
                {
                  min_lambda   = lambda[i];
                  worst_lambda = i;
                }
            }
          else if (gap[i] < -tolerance)
            {
              next.push_back(i);
              if (gap[i] < min_gap)
                {
                  min_gap   = gap[i];
                  worst_gap = i;
                }
            }
        }
      // next is sorted: the loop above visits the positions in increasing order.
      if (next != active && history.count(next))
        {
          // Cycling: correct one kind of violation only — drop every tensile candidate
          // if there are any, otherwise add every penetrating one. If that set was seen
          // too, correct the single worst violation (monotone, but one at a time).
          std::vector<unsigned int> partial;
          const bool                tensile = min_lambda < -lambda_tolerance;
          for (const auto i : active)
            if (!tensile || lambda[i] >= -lambda_tolerance)
              partial.push_back(i);
          if (!tensile)
            for (unsigned int i = 0; i < gap.size(); ++i)
              if (!is_active[i] && gap[i] < -tolerance)
                partial.push_back(i);
          std::sort(partial.begin(), partial.end());
          next = partial;
          if (next == active || history.count(next))
            {
              next = active;
              if (tensile)
                next.erase(std::find(next.begin(), next.end(), worst_lambda));
              else if (min_gap < -tolerance)
                next.insert(std::upper_bound(next.begin(), next.end(), worst_gap), worst_gap);
            }
        }
      history.insert(active);
      return next;
    }

    void
    ensure_two_active(std::vector<unsigned int>               &active,
                      const std::vector<double>               &gap_estimate,
                      const std::vector<dealii::Tensor<1, 2>> &normal,
                      const dealii::Tensor<1, 2>              &load)
    {
      const auto cross = [](const dealii::Tensor<1, 2> &a, const dealii::Tensor<1, 2> &b) {
        return a[0] * b[1] - a[1] * b[0];
      };
      while (active.size() < 2 && active.size() < gap_estimate.size())
        {
          unsigned int best = 0, best_bracketing = 0;
          double       g = std::numeric_limits<double>::max(), g_bracketing = g;
          for (unsigned int j = 0; j < gap_estimate.size(); ++j)
            {
              if (std::find(active.begin(), active.end(), j) != active.end())
                continue;
              if (gap_estimate[j] < g)
                {
                  g    = gap_estimate[j];
                  best = j;
                }
              if (active.size() == 1 && gap_estimate[j] < g_bracketing)
                {
                  const auto  &ni = normal[active[0]];
                  const auto  &nj = normal[j];
                  const double d  = cross(ni, nj);
                  if (d != 0.0 && cross(load, nj) / d >= 0.0 && cross(ni, load) / d >= 0.0)
                    {
                      g_bracketing    = gap_estimate[j];
                      best_bracketing = j;
                    }
                }
            }
          const unsigned int add = g_bracketing < std::numeric_limits<double>::max() ? best_bracketing : best;
          active.insert(std::upper_bound(active.begin(), active.end(), add), add);
        }
    }

    [[noreturn]] void
    not_converged(const char *solver, unsigned int iterations)
    {
      throw NumericalError(std::string("The ") + solver + " contact solver did not converge in " +
                           std::to_string(iterations) +
                           " active-set iterations. Raise 'Maximum active-set iterations' or "
                           "refine the contact surfaces ('Surface element size').");
    }
  } // namespace active_set


  double
  candidate_spacing(const ElasticityProblem &problem)
  {
    const auto &nodes = problem.pin_nodes;
    double      h     = std::numeric_limits<double>::max();
    for (unsigned int i = 0; i < nodes.size(); ++i)
      h = std::min(h, (nodes[(i + 1) % nodes.size()].point - nodes[i].point).norm());
    return h;
  }


  double
  smallest_pin_radius(const ElasticityProblem &problem)
  {
    double r = std::numeric_limits<double>::max();
    for (const auto &n : problem.pin_nodes)
      r = std::min(r, n.point.norm());
    return r;
  }


  double
  predicted_approach(const double load_per_length, const double effective_modulus, const double radial_clearance)
  {
    const double scale = load_per_length / (numbers::pi * effective_modulus);
    const double log_term =
      std::log(4 * numbers::pi * effective_modulus * std::max(radial_clearance, 0.0) / load_per_length) - 1;
    return scale * std::max(0.9 * log_term, 0.1);
  }


  std::vector<unsigned int>
  initial_active_set(const ContactKinematics &kinematics,
                     bool                     force_control,
                     const Tensor<1, 2>      &load,
                     double                   effective_modulus)
  {
    const double              load_per_length = load.norm();
    std::vector<unsigned int> active;
    const double              tol = kinematics.tolerance;
    for (unsigned int i = 0; i < kinematics.g0.size(); ++i)
      if (kinematics.g0[i] < -tol)
        active.push_back(i);
    if (force_control)
      {
        const double g_min    = *std::min_element(kinematics.g0.begin(), kinematics.g0.end());
        const double approach = 2 * load_per_length / (numbers::pi * effective_modulus);
        for (unsigned int i = 0; i < kinematics.g0.size(); ++i)
          if (kinematics.g0[i] <= g_min + std::max(tol, approach) &&
              std::find(active.begin(), active.end(), i) == active.end())
            active.push_back(i);
        std::sort(active.begin(), active.end());
        active_set::ensure_two_active(active, kinematics.g0, kinematics.normal, load);
      }
    return active;
  }


  namespace
  {
    /**
     * The distributed solve of the reference solver (see solve_constrained()): METIS
     * partitions (subdomain ids, DoFs numbered subdomain-wise), each rank assembling its
     * own cells through the constraints, MUMPS on the PETSc matrix, the solution
     * gathered on every rank.
     */
    Vector<double>
    solve_distributed(const ElasticityProblem               &problem,
                      const AffineConstraints<double>       &constraints,
                      const std::array<global_dof_index, 2> &load_dofs,
                      const Tensor<1, 2>                    &load)
    {
      const MPI_Comm         comm  = MPI_COMM_WORLD;
      const unsigned int     rank  = Utilities::MPI::this_mpi_process(comm);
      const auto             owned = DoFTools::locally_owned_dofs_per_subdomain(problem.dof_handler)[rank];
      DynamicSparsityPattern dsp(problem.dof_handler.n_dofs());
      DoFTools::make_sparsity_pattern(problem.dof_handler, dsp, constraints, false);
      PETScWrappers::MPI::SparseMatrix matrix;
      matrix.reinit(owned, owned, dsp, comm);
      PETScWrappers::MPI::Vector rhs(owned, comm), solution(owned, comm);

      FEValues<2>                   fe_values(problem.fe, problem.quadrature(), update_gradients | update_JxW_values);
      const unsigned int            dofs_per_cell = problem.fe.n_dofs_per_cell();
      FullMatrix<double>            cell_matrix(dofs_per_cell, dofs_per_cell);
      Vector<double>                cell_rhs(dofs_per_cell);
      std::vector<global_dof_index> dof_indices(dofs_per_cell);
      for (const auto &cell : problem.dof_handler.active_cell_iterators())
        if (cell->subdomain_id() == rank)
          {
            problem.cell_stiffness(cell, fe_values, cell_matrix);
            cell_rhs = 0;
            cell->get_dof_indices(dof_indices);
            constraints.distribute_local_to_global(cell_matrix, cell_rhs, dof_indices, matrix, rhs);
          }
      for (unsigned int d = 0; d < 2; ++d)
        if (owned.is_element(load_dofs[d]))
          rhs(load_dofs[d]) += load[d];
      matrix.compress(VectorOperation::add);
      rhs.compress(VectorOperation::add);

      SolverControl                    control(1, 0);
      PETScWrappers::SparseDirectMUMPS mumps(control, comm);
      mumps.solve(matrix, solution, rhs);
      Vector<double> u(solution);
      constraints.distribute(u);
      return u;
    }
  } // namespace


  ReferenceContactSolver::ReferenceContactSolver(const ElasticityProblem &problem,
                                                 unsigned int             max_iterations,
                                                 bool                     distributed)
    : problem(problem)
    , max_iterations(max_iterations)
    , distributed(distributed)
  {
  }


  // Serial: copy K into a pattern with room for the constraints' couplings, condense,
  // factor with UMFPACK. Distributed: every rank assembles the cells of its METIS
  // partition through the constraints into a PETSc matrix (rows of its own DoFs) and
  // MUMPS factors the distributed system; the solution is gathered on every rank.
  Vector<double>
  ReferenceContactSolver::solve_constrained(const AffineConstraints<double>       &constraints,
                                            const std::array<global_dof_index, 2> &load_dofs,
                                            const Tensor<1, 2>                    &load) const
  {
    const auto n = problem.dof_handler.n_dofs();
    EffectLedger::instance().add_resource("factorizations");
    if (!distributed)
      {
        const auto            &K = problem.stiffness_matrix;
        DynamicSparsityPattern dsp(n);
        for (types::global_dof_index row = 0; row < n; ++row)
          for (auto e = problem.sparsity_pattern.begin(row); e != problem.sparsity_pattern.end(row); ++e)
            dsp.add(row, e->column());
        constraints.condense(dsp);
        SparsityPattern pattern;
        pattern.copy_from(dsp);
        SparseMatrix<double> matrix(pattern);
        for (types::global_dof_index row = 0; row < n; ++row)
          for (auto e = K.begin(row); e != K.end(row); ++e)
            matrix.add(row, e->column(), e->value());
        Vector<double> rhs(n);
        rhs(load_dofs[0]) += load[0];
        rhs(load_dofs[1]) += load[1];
        constraints.condense(matrix, rhs);
        SparseDirectUMFPACK direct;
        direct.initialize(matrix);
        Vector<double> u = rhs;
        direct.solve(u);
        constraints.distribute(u);
        return u;
      }
    return solve_distributed(problem, constraints, load_dofs, load);
  }


  // The reference: semismooth Newton (primal–dual active set) on the full FE system of
  // both bodies, in the spirit of deal.II's step-41. For the current active set every
  // active pin candidate i gets the affine constraint
  //     ν_i · u_i = g0_i + n_i · Σ_a w_a u_a        (gap closed; ν_i pin frame),
  // solved for the DoF of its larger normal component; the core DoFs are tied to one
  // core node (force control: loaded by P in the pin frame) or fixed (displacement
  // control); the bushing's outer edge is fixed. The constrained system is condensed
  // and factored with UMFPACK; λ_i = −ν_i · (K u)_i are the reaction forces of the
  // unconstrained operator, and the gaps follow from u.
  namespace
  {
    /**
     * The constraints of one active set of the reference solver: the outer edge
     * clamped; the pin core rigid (displacement control: clamped; force control: tied
     * to its first node, which carries the load); for each active candidate the normal
     * gap closed, ν·u_pin − Σ w n·u_bore = g0, written on the pin DoF of the larger
     * normal component.
     */
    void
    active_set_constraints(const ElasticityProblem         &problem,
                           const ContactKinematics         &kin,
                           const std::vector<unsigned int> &active,
                           const bool                       force_control,
                           AffineConstraints<double>       &constraints)
    {
      const auto &pin  = problem.pin_nodes;
      const auto &bore = problem.bore_nodes;
      const auto &core = problem.core_nodes;
      for (const auto d : problem.outer_dofs)
        constraints.add_line(d);
      for (unsigned int c = 0; c < core.size(); ++c)
        for (unsigned int d = 0; d < 2; ++d)
          if (!force_control)
            constraints.add_line(core[c][d]);
          else if (c > 0)
            {
              constraints.add_line(core[c][d]);
              constraints.add_entry(core[c][d], core[0][d], 1.0);
            }
      for (const auto i : active)
        {
          const auto        &nu    = pin[i].normal;
          const auto        &nb    = kin.normal[i];
          const unsigned int comp  = std::abs(nu[0]) >= std::abs(nu[1]) ? 0 : 1;
          const unsigned int other = 1 - comp;
          const auto         dof   = pin[i].dofs[comp];
          constraints.add_line(dof);
          constraints.add_entry(dof, pin[i].dofs[other], -nu[other] / nu[comp]);
          for (unsigned int a = 0; a < kin.n_masters[i]; ++a)
            {
              const auto  &b = bore[kin.masters[i][a]];
              const double w = kin.weights[i][a] / nu[comp];
              if (w != 0)
                {
                  constraints.add_entry(dof, b.dofs[0], w * nb[0]);
                  constraints.add_entry(dof, b.dofs[1], w * nb[1]);
                }
            }
          constraints.set_inhomogeneity(dof, kin.g0[i] / nu[comp]);
        }
      constraints.close();
    }
  } // namespace

  ContactSolution
  ReferenceContactSolver::solve(const ContactKinematics &kin, bool force_control, const Tensor<1, 2> &load) const
  {
    const auto        &K         = problem.stiffness_matrix;
    const auto        &pin       = problem.pin_nodes;
    const auto        &bore      = problem.bore_nodes;
    const auto        &core      = problem.core_nodes;
    const unsigned int m         = pin.size();
    const auto         n         = problem.dof_handler.n_dofs();
    const double       tolerance = kin.tolerance;
    const Tensor<1, 2> P_pin     = rotate(load, -kin.relative_angle);
    AssertThrow(kin.candidates.size() == m,
                ExcMessage("The reference contact solver needs the kinematics of every candidate."));

    std::vector<unsigned int> active = initial_active_set(kin, force_control, load, problem.effective_modulus());
    std::set<std::vector<unsigned int>> history;
    ContactSolution                     sol;
    std::vector<double>                 lambda(m), gap(m);
    Vector<double>                      u(n), residual(n);
    bool                                converged = false;
    for (unsigned int iteration = 1; iteration <= max_iterations; ++iteration)
      {
        sol.iterations = iteration;
        AffineConstraints<double> constraints;
        active_set_constraints(problem, kin, active, force_control, constraints);

        u = solve_constrained(constraints, core[0], force_control ? P_pin : Tensor<1, 2>());

        K.vmult(residual, u);
        for (unsigned int i = 0; i < m; ++i)
          {
            const auto &nu = pin[i].normal;
            lambda[i]      = -(nu[0] * residual(pin[i].dofs[0]) + nu[1] * residual(pin[i].dofs[1]));
            double g       = kin.g0[i] - (nu[0] * u(pin[i].dofs[0]) + nu[1] * u(pin[i].dofs[1]));
            for (unsigned int a = 0; a < kin.n_masters[i]; ++a)
              {
                const auto &b = bore[kin.masters[i][a]];
                g += kin.weights[i][a] * (kin.normal[i][0] * u(b.dofs[0]) + kin.normal[i][1] * u(b.dofs[1]));
              }
            gap[i] = g;
          }
        auto next = active_set::update(active, lambda, gap, tolerance, history);
        if (force_control)
          active_set::ensure_two_active(next, gap, kin.normal, load);
        if (next == active)
          {
            converged = true;
            break;
          }
        active = next;
      }
    if (!converged)
      active_set::not_converged("reference", max_iterations);

    std::vector<char> is_active(m, 0);
    for (const auto i : active)
      is_active[i] = 1;
    for (unsigned int i = 0; i < m; ++i)
      if (!is_active[i])
        lambda[i] = 0;
    sol.active   = active;
    sol.lambda   = lambda;
    sol.gap      = gap;
    sol.n_active = active.size();
    if (force_control)
      {
        Tensor<1, 2> U_pin;
        U_pin[0]            = u(core[0][0]);
        U_pin[1]            = u(core[0][1]);
        sol.pin_translation = rotate(U_pin, kin.relative_angle);
      }
    for (unsigned int i = 0; i < m; ++i)
      sol.resultant += lambda[i] * kin.normal[i];
    sol.displacement = u;
    return sol;
  }
} // namespace wearlink::fe
