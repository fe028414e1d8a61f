// SPDX-License-Identifier: LGPL-2.1-or-later
#include "fe/boundary_compliance.h"

#include "base/effect_ledger.h"
#include "base/exceptions.h"

#include <Eigen/CholmodSupport>
#include <Eigen/Sparse>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace wearlink::fe
{
  using namespace dealii;

  struct BoundaryCompliance::Factorization
  {
    Eigen::SparseMatrix<double>                              matrix;
    Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>> llt;
  };

  // Homogeneous Dirichlet conditions on the core and the outer edge: those DoFs are
  // removed from the system (a load that vanishes there gives a displacement that
  // vanishes there), and the SPD remainder is factored once.
  BoundaryCompliance::BoundaryCompliance(const ElasticityProblem &problem)
    : problem(problem)
    , factorization(std::make_unique<Factorization>())
    , pin_columns(problem.pin_nodes.size())
    , bore_columns(problem.bore_nodes.size())
    , pin_bounds(problem.pin_nodes.size(), std::numeric_limits<double>::quiet_NaN())
    , bore_bounds(problem.bore_nodes.size(), std::numeric_limits<double>::quiet_NaN())
  {
    const auto n = problem.dof_handler.n_dofs();
    reduced_index.assign(n, 0);
    for (const auto &c : problem.core_nodes)
      reduced_index[c[0]] = reduced_index[c[1]] = -1;
    for (const auto d : problem.outer_dofs)
      reduced_index[d] = -1;
    long n_free = 0;
    for (auto &r : reduced_index)
      if (r == 0)
        r = n_free++;

    // Lower triangle of the reduced matrix (CHOLMOD reads one triangle).
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(problem.stiffness_matrix.n_nonzero_elements() / 2 + n);
    const auto &K = problem.stiffness_matrix;
    for (types::global_dof_index row = 0; row < n; ++row)
      {
        const long r = reduced_index[row];
        if (r < 0)
          continue;
        for (auto e = K.begin(row); e != K.end(row); ++e)
          {
            const long c = reduced_index[e->column()];
            if (c >= 0 && c <= r)
              entries.emplace_back(r, c, e->value());
          }
      }
    auto &f = *factorization;
    f.matrix.resize(n_free, n_free);
    f.matrix.setFromTriplets(entries.begin(), entries.end());
    f.llt.compute(f.matrix);
    if (f.llt.info() != Eigen::Success)
      throw NumericalError("The clamped stiffness matrix of the pin–bushing mesh is not positive "
                           "definite (CHOLMOD failed): check the mesh (inverted elements?) and "
                           "the materials.");
    EffectLedger::instance().add_resource("factorizations");
  }


  BoundaryCompliance::~BoundaryCompliance() = default;


  namespace
  {
    /**
     * Up to @p block missing columns around @p j along the (periodic) candidate list:
     * j first, then alternately its neighbours on either side.
     */
    template <typename Columns>
    std::vector<unsigned int>
    missing_neighbours(const Columns &columns, unsigned int j, unsigned int block)
    {
      const unsigned int        n = columns.size();
      std::vector<unsigned int> chosen{j};
      for (unsigned int d = 1; chosen.size() < block && 2 * d <= n; ++d)
        for (const unsigned int k : {(j + d) % n, (j + n - d) % n})
          if (chosen.size() < block && columns[k].empty() && std::find(chosen.begin(), chosen.end(), k) == chosen.end())
            chosen.push_back(k);
      return chosen;
    }
  } // namespace


  void
  BoundaryCompliance::compute_pin_block(unsigned int j)
  {
    const auto         start  = std::chrono::steady_clock::now();
    const auto        &nodes  = problem.pin_nodes;
    const auto         chosen = missing_neighbours(pin_columns, j, block_size);
    const unsigned int b      = chosen.size();
    Eigen::MatrixXd    rhs    = Eigen::MatrixXd::Zero(factorization->matrix.rows(), b);
    for (unsigned int s = 0; s < b; ++s)
      for (unsigned int d = 0; d < 2; ++d)
        rhs(reduced_index[nodes[chosen[s]].dofs[d]], s) = nodes[chosen[s]].normal[d];
    const Eigen::MatrixXd u = factorization->llt.solve(rhs);
    n_solves += b;
    for (unsigned int s = 0; s < b; ++s)
      {
        auto &column = pin_columns[chosen[s]];
        column.resize(nodes.size());
        for (unsigned int i = 0; i < nodes.size(); ++i)
          column[i] = nodes[i].normal[0] * u(reduced_index[nodes[i].dofs[0]], s) +
                      nodes[i].normal[1] * u(reduced_index[nodes[i].dofs[1]], s);
      }
    seconds_in_columns += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }


  void
  BoundaryCompliance::compute_bore_block(unsigned int c)
  {
    const auto         start  = std::chrono::steady_clock::now();
    const auto        &nodes  = problem.bore_nodes;
    const unsigned int n      = nodes.size();
    const auto         chosen = missing_neighbours(bore_columns, c, block_size / 2);
    const unsigned int b      = chosen.size();
    Eigen::MatrixXd    rhs    = Eigen::MatrixXd::Zero(factorization->matrix.rows(), 2 * b);
    for (unsigned int s = 0; s < b; ++s)
      for (unsigned int d = 0; d < 2; ++d)
        rhs(reduced_index[nodes[chosen[s]].dofs[d]], 2 * s + d) = 1;
    const Eigen::MatrixXd u = factorization->llt.solve(rhs);
    n_solves += 2 * b;
    for (unsigned int s = 0; s < b; ++s)
      {
        auto &column = bore_columns[chosen[s]];
        column.resize(4 * n);
        for (unsigned int d = 0; d < 2; ++d)
          for (unsigned int a = 0; a < n; ++a)
            {
              column[2 * n * d + 2 * a]     = u(reduced_index[nodes[a].dofs[0]], 2 * s + d);
              column[2 * n * d + 2 * a + 1] = u(reduced_index[nodes[a].dofs[1]], 2 * s + d);
            }
      }
    seconds_in_columns += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }


  const std::vector<double> &
  BoundaryCompliance::pin_column(unsigned int j)
  {
    if (pin_columns[j].empty())
      compute_pin_block(j);
    return pin_columns[j];
  }


  const std::vector<double> &
  BoundaryCompliance::bore_column(unsigned int c)
  {
    if (bore_columns[c].empty())
      compute_bore_block(c);
    return bore_columns[c];
  }


  double
  BoundaryCompliance::pin_column_bound(const unsigned int j)
  {
    if (std::isnan(pin_bounds[j]))
      {
        double b = 0;
        for (const double v : pin_column(j))
          b = std::max(b, std::abs(v));
        pin_bounds[j] = b;
      }
    return pin_bounds[j];
  }


  double
  BoundaryCompliance::bore_column_bound(const unsigned int c)
  {
    if (std::isnan(bore_bounds[c]))
      {
        const auto        &col = bore_column(c);
        const unsigned int q   = bore_columns.size();
        double             b   = 0;
        for (unsigned int n = 0; n < q; ++n)
          b = std::max(b,
                       std::hypot(col[2 * n], col[2 * n + 1]) + std::hypot(col[2 * q + 2 * n], col[2 * q + 2 * n + 1]));
        bore_bounds[c] = b;
      }
    return bore_bounds[c];
  }


  void
  BoundaryCompliance::solve_clamped(Vector<double> &rhs_and_solution) const
  {
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(factorization->matrix.rows());
    for (std::size_t i = 0; i < reduced_index.size(); ++i)
      if (reduced_index[i] >= 0)
        rhs(reduced_index[i]) = rhs_and_solution(i);
    const Eigen::VectorXd u = factorization->llt.solve(rhs);
    for (std::size_t i = 0; i < reduced_index.size(); ++i)
      rhs_and_solution(i) = reduced_index[i] >= 0 ? u(reduced_index[i]) : 0.0;
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
