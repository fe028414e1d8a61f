// SPDX-License-Identifier: LGPL-2.1-or-later
#include "fe/boundary_compliance.h"

#include "base/effect_ledger.h"
#include "base/exceptions.h"
#include "base/numbers.h"
#include "fe/blas_threads.h"
#include "fe/boundary_ids.h"

#include <Eigen/CholmodSupport>
#include <Eigen/Sparse>
#include <deal.II/base/parallel.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>

namespace wearlink::fe
{
  using namespace dealii;

  struct BoundaryCompliance::Factorization
  {
    /** Eigen's supernodal LLT with its CHOLMOD factor in reach (Workspace::solve()). */
    struct Llt : Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>>
    {
      cholmod_factor *
      factor() const
      {
        return m_cholmodFactor;
      }
    };
    Eigen::SparseMatrix<double> matrix;
    Llt                         llt;
  };

  // CHOLMOD solves with one factor from several threads when each has a workspace (a
  // cholmod_common) of its own: the solve only reads the factor.
  struct BoundaryCompliance::Workspace
  {
    Workspace()
    {
      cholmod_start(&common);
    }
    ~Workspace()
    {
      cholmod_finish(&common);
    }
    Workspace(const Workspace &) = delete;
    Workspace &
    operator=(const Workspace &) = delete;

    /** K⁻¹ rhs with the factor of @p f; through Eigen's own workspace without one (@p w null). */
    static Eigen::MatrixXd
    solve(Workspace *w, const Factorization &f, Eigen::MatrixXd &rhs)
    {
      if (w == nullptr)
        return f.llt.solve(rhs);
      cholmod_dense  b = Eigen::viewAsCholmod(rhs);
      cholmod_dense *x = cholmod_solve(CHOLMOD_A, f.llt.factor(), &b, &w->common);
      if (x == nullptr)
        throw NumericalError("CHOLMOD failed to solve with the clamped stiffness factor (out of memory?).");
      Eigen::MatrixXd u = Eigen::Map<const Eigen::MatrixXd>(static_cast<const double *>(x->x), rhs.rows(), rhs.cols());
      cholmod_free_dense(&x, &w->common);
      return u;
    }

    cholmod_common common;
  };

  namespace
  {
    /** Per DoF: 1 if it belongs to a pin cell, 0 for the bushing. */
    std::vector<char>
    pin_dofs(const ElasticityProblem &problem)
    {
      std::vector<char>             is_pin(problem.dof_handler.n_dofs(), 0);
      std::vector<global_dof_index> dofs(problem.fe.n_dofs_per_cell());
      for (const auto &cell : problem.dof_handler.active_cell_iterators())
        if (cell->material_id() == material_ids::pin)
          {
            cell->get_dof_indices(dofs);
            for (const auto d : dofs)
              is_pin[d] = 1;
          }
      return is_pin;
    }

    /** Factor the lower triangle of K on the DoFs with reduced index ≥ 0 and body @p body. */
    void
    factor_body(const SparseMatrix<double>                               &K,
                const std::vector<long>                                  &reduced_index,
                const std::vector<char>                                  &is_pin,
                const char                                                body,
                const long                                                n_free,
                Eigen::SparseMatrix<double>                              &matrix,
                Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>> &llt)
    {
      std::vector<Eigen::Triplet<double>> entries;
      for (types::global_dof_index row = 0; row < K.m(); ++row)
        {
          const long r = reduced_index[row];
          if (r < 0 || is_pin[row] != body)
            continue;
          for (auto e = K.begin(row); e != K.end(row); ++e)
            {
              const long c = reduced_index[e->column()];
              if (c >= 0 && c <= r)
                entries.emplace_back(r, c, e->value());
            }
        }
      matrix.resize(n_free, n_free);
      matrix.setFromTriplets(entries.begin(), entries.end());
      llt.compute(matrix);
      if (llt.info() != Eigen::Success)
        throw NumericalError("The clamped stiffness matrix of the pin–bushing mesh is not positive "
                             "definite (CHOLMOD failed): check the mesh (inverted elements?) and "
                             "the materials.");
    }

    /**
     * S if rotating @p nodes by one of @p sectors sectors maps node i onto node i + S
     * (positions and normals to 1e-9 of the radius), else 0.
     */
    unsigned int
    sector_size(const std::vector<SurfaceNode> &nodes, const unsigned int sectors)
    {
      const unsigned int m = nodes.size();
      if (sectors < 2 || m % sectors != 0)
        return 0;
      const unsigned int S = m / sectors;
      const double       a = numbers::two_pi / sectors, c = std::cos(a), s = std::sin(a);
      for (unsigned int i = 0; i < m; ++i)
        {
          const auto  &p = nodes[i], &q = nodes[(i + S) % m];
          const double tol = 1e-9 * p.point.norm();
          if (std::hypot(c * p.point[0] - s * p.point[1] - q.point[0], s * p.point[0] + c * p.point[1] - q.point[1]) >
                tol ||
              std::hypot(c * p.normal[0] - s * p.normal[1] - q.normal[0],
                         s * p.normal[0] + c * p.normal[1] - q.normal[1]) > 1e-9)
            return 0;
        }
      return S;
    }
  } // namespace


  // Homogeneous Dirichlet conditions on the core and the outer edge: those DoFs are
  // removed from the system (a load that vanishes there gives a displacement that
  // vanishes there), and each body's SPD remainder is factored once.
  BoundaryCompliance::BoundaryCompliance(const ElasticityProblem &problem,
                                         const unsigned int       pin_sectors,
                                         const unsigned int       bore_sectors)
    : problem(problem)
    , pin_factor(std::make_unique<Factorization>())
    , ring_factor(std::make_unique<Factorization>())
    , pin_columns(problem.pin_nodes.size())
    , bore_columns(problem.bore_nodes.size())
    , pin_sector_size(sector_size(problem.pin_nodes, pin_sectors))
    , bore_sector_size(sector_size(problem.bore_nodes, bore_sectors))
  {
    if (bore_sector_size > 0)
      for (unsigned int k = 0; k < bore_sectors; ++k)
        sector_rotations.push_back(
          {{std::cos(numbers::two_pi * k / bore_sectors), std::sin(numbers::two_pi * k / bore_sectors)}});
    const auto        n      = problem.dof_handler.n_dofs();
    const auto        is_pin = pin_dofs(problem);
    std::vector<char> clamped(n, 0);
    for (const auto &c : problem.core_nodes)
      clamped[c[0]] = clamped[c[1]] = 1;
    for (const auto d : problem.outer_dofs)
      clamped[d] = 1;
    reduced_index.assign(n, -1);
    long n_pin = 0, n_ring = 0;
    for (types::global_dof_index d = 0; d < n; ++d)
      if (!clamped[d])
        reduced_index[d] = is_pin[d] ? n_pin++ : n_ring++;
    // The two bodies' factorizations are independent: one task each (each CHOLMOD
    // factor has its own workspace) where the BLAS allows several threads.
    const auto factor = [&](const unsigned int begin, const unsigned int end) {
      for (unsigned int body = begin; body < end; ++body) // 0: the pin, 1: the ring
        {
          Factorization &f = body == 0 ? *pin_factor : *ring_factor;
          factor_body(problem.stiffness_matrix,
                      reduced_index,
                      is_pin,
                      body == 0,
                      body == 0 ? n_pin : n_ring,
                      f.matrix,
                      f.llt);
        }
    };
    if (blas_is_thread_safe())
      parallel::apply_to_subranges(0u, 2u, factor, 1);
    else
      factor(0, 2);
    EffectLedger::instance().add_resource("factorizations", 2);
  }


  BoundaryCompliance::~BoundaryCompliance() = default;


  namespace
  {
    /**
     * Up to @p block columns around @p j that are @p missing, among the first @p n
     * entries of the (periodic) candidate list: j first, then alternately its neighbours
     * on either side.
     */
    template <typename Missing>
    std::vector<unsigned int>
    missing_neighbours(const Missing &missing, const unsigned int n, const unsigned int j, const unsigned int block)
    {
      std::vector<unsigned int> chosen{j};
      for (unsigned int d = 1; chosen.size() < block && 2 * d <= n; ++d)
        for (const unsigned int k : {(j + d) % n, (j + n - d) % n})
          if (chosen.size() < block && missing(k) && std::find(chosen.begin(), chosen.end(), k) == chosen.end())
            chosen.push_back(k);
      return chosen;
    }

    /** The blocks (missing_neighbours()) that compute every missing one of the first @p n @p columns. */
    std::vector<std::vector<unsigned int>>
    plan_blocks(const std::vector<std::vector<double>> &columns, const unsigned int n, const unsigned int block)
    {
      std::vector<char> planned(n, 0);
      const auto        missing = [&](const unsigned int k) {
        return columns[k].empty() && !planned[k];
      };
      std::vector<std::vector<unsigned int>> blocks;
      for (unsigned int j = 0; j < n; ++j)
        if (missing(j))
          {
            blocks.push_back(missing_neighbours(missing, n, j, block));
            for (const auto k : blocks.back())
              planned[k] = 1;
          }
      return blocks;
    }
  } // namespace


  void
  BoundaryCompliance::compute_pin_block(const unsigned int j)
  {
    const auto         start   = std::chrono::steady_clock::now();
    const unsigned int n       = pin_sector_size > 0 ? pin_sector_size : problem.pin_nodes.size();
    const auto         missing = [&](const unsigned int k) {
      return pin_columns[k].empty();
    };
    n_solves += fill_pin_block(missing_neighbours(missing, n, j, block_size), nullptr);
    seconds_in_columns += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }


  unsigned int
  BoundaryCompliance::fill_pin_block(const std::vector<unsigned int> &chosen, Workspace *w)
  {
    const auto        &nodes = problem.pin_nodes;
    const unsigned int b     = chosen.size();
    Eigen::MatrixXd    rhs   = Eigen::MatrixXd::Zero(pin_factor->matrix.rows(), b);
    for (unsigned int s = 0; s < b; ++s)
      for (unsigned int d = 0; d < 2; ++d)
        rhs(reduced_index[nodes[chosen[s]].dofs[d]], s) = nodes[chosen[s]].normal[d];
    const Eigen::MatrixXd u = Workspace::solve(w, *pin_factor, rhs);
    for (unsigned int s = 0; s < b; ++s)
      {
        auto &column = pin_columns[chosen[s]];
        column.resize(nodes.size());
        for (unsigned int i = 0; i < nodes.size(); ++i)
          column[i] = nodes[i].normal[0] * u(reduced_index[nodes[i].dofs[0]], s) +
                      nodes[i].normal[1] * u(reduced_index[nodes[i].dofs[1]], s);
      }
    return b;
  }


  void
  BoundaryCompliance::compute_bore_block(const unsigned int c)
  {
    const auto         start   = std::chrono::steady_clock::now();
    const unsigned int q       = problem.bore_nodes.size();
    const auto         missing = [&](const unsigned int k) {
      return bore_columns[k].empty();
    };
    n_solves +=
      fill_bore_block(missing_neighbours(missing, bore_sector_size > 0 ? bore_sector_size : q, c, block_size / 2),
                      nullptr);
    seconds_in_columns += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }


  unsigned int
  BoundaryCompliance::fill_bore_block(const std::vector<unsigned int> &chosen, Workspace *w)
  {
    const auto        &nodes = problem.bore_nodes;
    const unsigned int q     = nodes.size();
    const unsigned int b     = chosen.size();
    Eigen::MatrixXd    rhs   = Eigen::MatrixXd::Zero(ring_factor->matrix.rows(), 2 * b);
    for (unsigned int s = 0; s < b; ++s)
      for (unsigned int d = 0; d < 2; ++d)
        rhs(reduced_index[nodes[chosen[s]].dofs[d]], 2 * s + d) = 1;
    const Eigen::MatrixXd u = Workspace::solve(w, *ring_factor, rhs);
    // The base columns lie in the first sector, whose frame is the x–y frame: only the
    // displacements are turned into the frames of their nodes' sectors.
    for (unsigned int s = 0; s < b; ++s)
      {
        auto &column = bore_columns[chosen[s]];
        column.resize(4 * q);
        for (unsigned int d = 0; d < 2; ++d)
          for (unsigned int a = 0; a < q; ++a)
            {
              const auto   r            = sector_rotation(a);
              const double ux           = u(reduced_index[nodes[a].dofs[0]], 2 * s + d);
              const double uy           = u(reduced_index[nodes[a].dofs[1]], 2 * s + d);
              column[2 * q * d + a]     = r[0] * ux + r[1] * uy;
              column[2 * q * d + q + a] = r[0] * uy - r[1] * ux;
            }
      }
    return 2 * b;
  }


  BoundaryCompliance::PinColumn
  BoundaryCompliance::pin_column(const unsigned int j)
  {
    const unsigned int base = pin_sector_size > 0 ? j % pin_sector_size : j;
    if (pin_columns[base].empty())
      compute_pin_block(base);
    return {pin_columns[base].data(), j - base};
  }


  BoundaryCompliance::BoreColumn
  BoundaryCompliance::bore_column(const unsigned int c)
  {
    const unsigned int base = bore_sector_size > 0 ? c % bore_sector_size : c;
    if (bore_columns[base].empty())
      compute_bore_block(base);
    return {bore_columns[base].data(), c - base};
  }


  void
  BoundaryCompliance::solve_clamped(Vector<double> &rhs_and_solution) const
  {
    const auto        is_pin = pin_dofs(problem);
    Eigen::VectorXd   f_pin  = Eigen::VectorXd::Zero(pin_factor->matrix.rows());
    Eigen::VectorXd   f_ring = Eigen::VectorXd::Zero(ring_factor->matrix.rows());
    const std::size_t n      = reduced_index.size();
    for (std::size_t i = 0; i < n; ++i)
      if (reduced_index[i] >= 0)
        (is_pin[i] ? f_pin : f_ring)(reduced_index[i]) = rhs_and_solution(i);
    const Eigen::VectorXd u_pin  = pin_factor->llt.solve(f_pin);
    const Eigen::VectorXd u_ring = ring_factor->llt.solve(f_ring);
    for (std::size_t i = 0; i < n; ++i)
      rhs_and_solution(i) = reduced_index[i] < 0 ? 0.0 : (is_pin[i] ? u_pin : u_ring)(reduced_index[i]);
  }


  // The blocks are planned first, as the on-demand path would take them, then solved on
  // every core (apply_to_subranges), each thread with a CHOLMOD workspace of its own;
  // a block writes only its own columns, whose slots exist already.
  void
  BoundaryCompliance::precompute_all()
  {
    const auto start = std::chrono::steady_clock::now();
    const auto pin_blocks =
      plan_blocks(pin_columns, pin_sector_size > 0 ? pin_sector_size : pin_columns.size(), block_size);
    const auto bore_blocks =
      plan_blocks(bore_columns, bore_sector_size > 0 ? bore_sector_size : bore_columns.size(), block_size / 2);
    const auto                 n_pin = static_cast<unsigned int>(pin_blocks.size());
    std::atomic<unsigned long> solves{0};
    const auto                 blocks = [&](const unsigned int begin, const unsigned int end) {
      Workspace w;
      for (unsigned int k = begin; k < end; ++k)
        solves += k < n_pin ? fill_pin_block(pin_blocks[k], &w) : fill_bore_block(bore_blocks[k - n_pin], &w);
    };
    const auto n = n_pin + static_cast<unsigned int>(bore_blocks.size());
    if (blas_is_thread_safe())
      parallel::apply_to_subranges(0u, n, blocks, 1);
    else
      blocks(0u, n);
    n_solves += solves;
    seconds_in_columns += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
} // namespace wearlink::fe
