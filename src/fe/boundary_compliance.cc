// SPDX-License-Identifier: LGPL-2.1-or-later
#include "fe/boundary_compliance.h"

#include "base/effect_ledger.h"

#include <deal.II/numerics/matrix_tools.h>

#include <chrono>
#include <map>

namespace wearlink::fe
{
  using namespace dealii;

  // Homogeneous Dirichlet conditions on the core and the outer edge are imposed by
  // eliminating their rows and columns (the matrix stays symmetric); a right-hand side
  // that vanishes on those DoFs then gives a solution that vanishes there too.
  BoundaryCompliance::BoundaryCompliance(const ElasticityProblem &problem)
    : problem(problem)
    , pin_columns(problem.pin_nodes.size())
    , bore_columns(problem.bore_nodes.size())
  {
    clamped_matrix.reinit(problem.sparsity_pattern);
    clamped_matrix.copy_from(problem.stiffness_matrix);
    std::map<global_dof_index, double> clamped;
    for (const auto &c : problem.core_nodes)
      {
        clamped[c[0]] = 0;
        clamped[c[1]] = 0;
      }
    for (const auto d : problem.outer_dofs)
      clamped[d] = 0;
    Vector<double> solution(problem.dof_handler.n_dofs()), rhs(problem.dof_handler.n_dofs());
    MatrixTools::apply_boundary_values(clamped, clamped_matrix, solution, rhs, true);
    factorization.initialize(clamped_matrix);
    EffectLedger::instance().add_resource("factorizations");
  }


  const std::vector<double> &
  BoundaryCompliance::pin_column(unsigned int j)
  {
    auto &column = pin_columns[j];
    if (column.empty())
      {
        const auto start = std::chrono::steady_clock::now();
        const auto &   nodes = problem.pin_nodes;
        Vector<double> u(problem.dof_handler.n_dofs());
        u(nodes[j].dofs[0]) = nodes[j].normal[0];
        u(nodes[j].dofs[1]) = nodes[j].normal[1];
        factorization.solve(u);
        ++n_solves;
        column.resize(nodes.size());
        for (unsigned int i = 0; i < nodes.size(); ++i)
          column[i] = nodes[i].normal[0] * u(nodes[i].dofs[0]) + nodes[i].normal[1] * u(nodes[i].dofs[1]);
        seconds_in_columns +=
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      }
    return column;
  }


  const std::vector<double> &
  BoundaryCompliance::bore_column(unsigned int c)
  {
    auto &column = bore_columns[c];
    if (column.empty())
      {
        const auto start = std::chrono::steady_clock::now();
        const auto &       nodes = problem.bore_nodes;
        const unsigned int n     = nodes.size();
        column.resize(4 * n);
        for (unsigned int d = 0; d < 2; ++d)
          {
            Vector<double> u(problem.dof_handler.n_dofs());
            u(nodes[c].dofs[d]) = 1;
            factorization.solve(u);
            ++n_solves;
            for (unsigned int a = 0; a < n; ++a)
              {
                column[2 * n * d + 2 * a]     = u(nodes[a].dofs[0]);
                column[2 * n * d + 2 * a + 1] = u(nodes[a].dofs[1]);
              }
          }
        seconds_in_columns +=
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      }
    return column;
  }


  void
  BoundaryCompliance::solve_clamped(Vector<double> &rhs_and_solution) const
  {
    factorization.solve(rhs_and_solution);
  }


  void
  BoundaryCompliance::precompute_all()
  {
    for (unsigned int j = 0; j < pin_columns.size(); ++j)
      pin_column(j);
    for (unsigned int c = 0; c < bore_columns.size(); ++c)
      bore_column(c);
  }
} // namespace wearlink::fe
