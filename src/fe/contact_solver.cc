// SPDX-License-Identifier: LGPL-2.1-or-later
#include "fe/contact_solver.h"

#include "base/effect_ledger.h"
#include "base/exceptions.h"
#include "fe/boundary_ids.h"

#include <Eigen/Dense>
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
#include <iostream>
#include <numeric>
#include <set>
#include <sstream>
#include <unordered_map>

namespace wearlink::fe
{
  using namespace dealii;

  namespace
  {
    constexpr double pi = 3.14159265358979323846;

    Tensor<1, 2>
    rotate(const Tensor<1, 2> &v, double angle)
    {
      const double c = std::cos(angle), s = std::sin(angle);
      Tensor<1, 2> r;
      r[0] = c * v[0] - s * v[1];
      r[1] = s * v[0] + c * v[1];
      return r;
    }

    /** Lagrange basis on p+1 equidistant points of [0, 1], evaluated at @p xi. */
    std::array<double, 3>
    lagrange_weights(unsigned int n_points, double xi)
    {
      std::array<double, 3> w{};
      const unsigned int    p = n_points - 1;
      for (unsigned int k = 0; k < n_points; ++k)
        {
          double v = 1;
          for (unsigned int l = 0; l < n_points; ++l)
            if (l != k)
              v *= (xi - double(l) / p) / (double(k) - double(l)) * p;
          w[k] = v;
        }
      return w;
    }

    /** A gap this small [m] counts as closed: round-off of the gap formula. */
    double
    gap_tolerance(const ContactKinematics &kin)
    {
      double scale = 0;
      for (const double g : kin.g0)
        scale = std::max(scale, std::abs(g));
      return 1e-12 * std::max(scale, 1e-9);
    }

    /**
     * The primal–dual active-set update: an active candidate stays active while its
     * force is compressive; an inactive one becomes active when its gap is negative.
     * If the plain update would revisit an earlier active set (cycling), only the single
     * worst violation is corrected, which makes the iteration monotone.
     */
    std::vector<unsigned int>
    update_active_set(const std::vector<unsigned int>     &active,
                      const std::vector<double>           &lambda,
                      const std::vector<double>           &gap,
                      double                               tolerance,
                      std::set<std::vector<unsigned int>> &history)
    {
      std::vector<char> is_active(gap.size(), 0);
      for (const auto i : active)
        is_active[i] = 1;
      std::vector<unsigned int> next;
      unsigned int              worst_lambda = 0, worst_gap = 0;
      double                    min_lambda = 0, min_gap = -tolerance;
      for (unsigned int i = 0; i < gap.size(); ++i)
        {
          if (is_active[i])
            {
              if (lambda[i] > 0)
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
      std::sort(next.begin(), next.end());
      if (next != active && history.count(next))
        {
          // Cycling: correct one kind of violation only — drop every tensile candidate
          // if there are any, otherwise add every penetrating one. If that set was seen
          // too, correct the single worst violation (monotone, but one at a time).
          std::vector<unsigned int> partial;
          for (const auto i : active)
            if (min_lambda >= 0 || lambda[i] > 0)
              partial.push_back(i);
          if (min_lambda >= 0)
            for (unsigned int i = 0; i < gap.size(); ++i)
              if (!is_active[i] && gap[i] < -tolerance)
                partial.push_back(i);
          std::sort(partial.begin(), partial.end());
          next = partial;
          if (next == active || history.count(next))
            {
              next = active;
              if (min_lambda < 0)
                next.erase(std::find(next.begin(), next.end(), worst_lambda));
              else if (min_gap < -tolerance)
                next.insert(std::upper_bound(next.begin(), next.end(), worst_gap), worst_gap);
            }
        }
      history.insert(active);
      return next;
    }

    /**
     * Force control needs at least two active candidates with different normals: with
     * one, the frictionless pin could slide sideways freely. Add the closest candidates
     * — but the second one on the side of the load: the load P must be a non-negative
     * combination a n_i + b n_j of the two normals, else the pair can only balance it
     * with a tensile force on one of them (a small load whose direction lies between
     * the normals of i and of its other neighbour was carried as +46 N and −45 N on a
     * 0.2 mm mesh, for 1.6 N). Among the candidates that bracket P the one with the
     * smallest gap is taken; if none does, the closest one.
     */
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
  } // namespace


  // The ray from the pin candidate x_i along its normal n_i meets the bore profile
  // r = R1*(ψ) where |x + t n| = R1*(atan2(x + t n)). For a round bore the circle
  // formula is exact; otherwise a few Newton steps on t follow.
  ContactKinematics
  compute_kinematics(const ElasticityProblem   &problem,
                     const Profile             &bore,
                     double                     relative_angle,
                     const Tensor<1, 2>        &eccentricity,
                     const std::vector<double> *pin_offsets)
  {
    const auto        &nodes = problem.pin_nodes;
    const auto        &faces = problem.bore_faces;
    const unsigned int m     = nodes.size();
    const bool         round = bore.is_round();

    ContactKinematics k;
    k.relative_angle = relative_angle;
    k.eccentricity   = eccentricity;
    k.g0.resize(m);
    k.normal.resize(m);
    k.bore_angle.resize(m);
    k.masters.resize(m);
    k.weights.resize(m);
    k.n_masters.resize(m);

    for (unsigned int i = 0; i < m; ++i)
      {
        Tensor<1, 2> point = nodes[i].point;
        if (pin_offsets != nullptr)
          point *= 1 + (*pin_offsets)[i] / point.norm();
        const Tensor<1, 2> x      = eccentricity + rotate(point, relative_angle);
        const Tensor<1, 2> n      = rotate(nodes[i].normal, relative_angle);
        const double       radius = bore.radius(std::atan2(x[1], x[0]));
        const double       b      = x * n;
        double             t      = -b + std::sqrt(std::max(b * b - x * x + radius * radius, 0.0));
        if (!round)
          for (unsigned int it = 0; it < 20; ++it)
            {
              const Tensor<1, 2> y     = x + t * n;
              const double       rho   = y.norm();
              const double       alpha = std::atan2(y[1], y[0]);
              const double       f     = rho - bore.radius(alpha);
              if (std::abs(f) < 1e-14 * rho)
                break;
              const double df = (y * n) / rho - bore.slope(alpha) * (y[0] * n[1] - y[1] * n[0]) / (rho * rho);
              t -= f / df;
            }
        const Tensor<1, 2> y     = x + t * n;
        const double       alpha = std::atan2(y[1], y[0]);
        k.g0[i]                  = t;
        k.normal[i]              = n;
        k.bore_angle[i]          = alpha;

        auto         it = std::upper_bound(faces.begin(), faces.end(), alpha, [](double a, const SurfaceFace &f) {
          return a < f.begin;
        });
        unsigned int f  = it == faces.begin() ? faces.size() - 1 : (it - faces.begin()) - 1;
        double       d  = alpha - faces[f].begin;
        d -= 2 * pi * std::floor(d / (2 * pi));
        if (d > faces[f].span)
          {
            // Between the end of this face and the start of the next (round-off):
            // take the nearer one.
            const unsigned int g  = (f + 1) % faces.size();
            double             dg = alpha - faces[g].begin;
            dg -= 2 * pi * std::round(dg / (2 * pi));
            if (std::abs(dg) < d - faces[f].span)
              {
                f = g;
                d = 0;
              }
            else
              d = faces[f].span;
          }
        const double xi       = std::clamp(d / faces[f].span, 0.0, 1.0);
        const auto   n_points = static_cast<unsigned int>(faces[f].nodes.size());
        const auto   w        = lagrange_weights(n_points, xi);
        k.n_masters[i]        = n_points;
        for (unsigned int a = 0; a < n_points; ++a)
          {
            k.masters[i][a] = faces[f].nodes[a];
            k.weights[i][a] = w[a];
          }
      }
    return k;
  }


  std::vector<unsigned int>
  initial_active_set(const ContactKinematics &kinematics,
                     bool                     force_control,
                     const Tensor<1, 2>      &load,
                     double                   effective_modulus)
  {
    const double              load_per_length = load.norm();
    std::vector<unsigned int> active;
    const double              tol = gap_tolerance(kinematics);
    for (unsigned int i = 0; i < kinematics.g0.size(); ++i)
      if (kinematics.g0[i] < -tol)
        active.push_back(i);
    if (force_control)
      {
        const double g_min    = *std::min_element(kinematics.g0.begin(), kinematics.g0.end());
        const double approach = 2 * load_per_length / (pi * effective_modulus);
        for (unsigned int i = 0; i < kinematics.g0.size(); ++i)
          if (kinematics.g0[i] <= g_min + std::max(tol, approach) &&
              std::find(active.begin(), active.end(), i) == active.end())
            active.push_back(i);
        std::sort(active.begin(), active.end());
        ensure_two_active(active, kinematics.g0, kinematics.normal, load);
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


  CondensedContactSolver::CondensedContactSolver(const ElasticityProblem &problem,
                                                 BoundaryCompliance      &compliance,
                                                 unsigned int             max_iterations,
                                                 unsigned int             primal_dual_limit)
    : problem(problem)
    , compliance(compliance)
    , max_iterations(max_iterations)
    , primal_dual_limit(primal_dual_limit)
  {
  }


  // One load state of the condensed problem. With the active set 𝒜 fixed, the
  // conditions g_𝒜 = 0 and Σ λ n = P form the KKT system
  //     A_𝒜𝒜 λ − N_𝒜ᵀ U = −g0_𝒜,   N_𝒜 λ = P,
  // solved through the Cholesky factor of A_𝒜𝒜 and the 2×2 Schur complement
  namespace
  {
    /**
     * The condensed compliance as one load state of the condensed solver reads it: the
     * normal displacement of the bore at candidate i's contact point for a unit λ_s at
     * candidate s (the force +n_s interpolated onto the bore nodes of the face s
     * meets), either point-wise from the cached bore columns (only the nodes of i's face
     * are touched) or from a whole bore field assembled once per active candidate.
     */
    class ComplianceReader
    {
    public:
      ComplianceReader(const ContactKinematics &kin, BoundaryCompliance &compliance, const unsigned int q)
        : kin(kin)
        , compliance(compliance)
        , q(q)
      {
      }

      /** Bore part of A(i, s), read point by point. */
      double
      bore_normal(const unsigned int i, const unsigned int s) const
      {
        double u = 0;
        for (unsigned int a = 0; a < kin.n_masters[s]; ++a)
          {
            const auto  &col = compliance.bore_column(kin.masters[s][a]);
            const double fx  = kin.weights[s][a] * kin.normal[s][0];
            const double fy  = kin.weights[s][a] * kin.normal[s][1];
            for (unsigned int c = 0; c < kin.n_masters[i]; ++c)
              {
                const unsigned int b  = kin.masters[i][c];
                const double       ux = fx * col[2 * b] + fy * col[2 * q + 2 * b];
                const double       uy = fx * col[2 * b + 1] + fy * col[2 * q + 2 * b + 1];
                u += kin.weights[i][c] * (kin.normal[i][0] * ux + kin.normal[i][1] * uy);
              }
          }
        return u;
      }

      /** The whole bore displacement field of a unit λ_j (cached per solve). */
      const std::vector<double> &
      bore_field(const unsigned int j)
      {
        auto it = bore_fields.find(j);
        if (it != bore_fields.end())
          return it->second;
        std::vector<double> v(2 * q, 0.0);
        for (unsigned int a = 0; a < kin.n_masters[j]; ++a)
          {
            const auto  &col = compliance.bore_column(kin.masters[j][a]);
            const double fx  = kin.weights[j][a] * kin.normal[j][0];
            const double fy  = kin.weights[j][a] * kin.normal[j][1];
            for (unsigned int r = 0; r < 2 * q; ++r)
              v[r] += fx * col[r] + fy * col[2 * q + r];
          }
        return bore_fields.emplace(j, std::move(v)).first->second;
      }

      /** The normal component of a bore @p field at candidate i's contact point. */
      double
      field_normal(const unsigned int i, const std::vector<double> &field) const
      {
        double u = 0;
        for (unsigned int a = 0; a < kin.n_masters[i]; ++a)
          {
            const unsigned int b = kin.masters[i][a];
            u += kin.weights[i][a] * (kin.normal[i][0] * field[2 * b] + kin.normal[i][1] * field[2 * b + 1]);
          }
        return u;
      }

      /** Bound of |elastic gap change| anywhere for a unit λ_s: pin and bore parts. */
      double
      reach(const unsigned int s) const
      {
        double r = compliance.pin_column_bound(s);
        for (unsigned int a = 0; a < kin.n_masters[s]; ++a)
          r += std::abs(kin.weights[s][a]) * compliance.bore_column_bound(kin.masters[s][a]);
        return r;
      }

      /** max over faces of Σ|w| (> 1 only for degree-2 faces), over @p m candidates. */
      double
      max_weight_sum(const unsigned int m) const
      {
        double max_sum = 1.0;
        for (unsigned int i = 0; i < m; ++i)
          {
            double w = 0;
            for (unsigned int a = 0; a < kin.n_masters[i]; ++a)
              w += std::abs(kin.weights[i][a]);
            max_sum = std::max(max_sum, w);
          }
        return max_sum;
      }

      /** The columns of the active candidates (whole bore fields above the threshold). */
      struct Columns
      {
        std::vector<const std::vector<double> *> pin, bore; ///< bore: only with fields
        bool                                     fields = false;
      };
      Columns
      columns(const std::vector<unsigned int> &active, const unsigned int max_pointwise_active)
      {
        const unsigned int k = active.size();
        Columns            c;
        c.fields = k > max_pointwise_active;
        c.pin.resize(k);
        c.bore.assign(k, nullptr);
        for (unsigned int s = 0; s < k; ++s)
          {
            c.pin[s] = &compliance.pin_column(active[s]);
            if (c.fields)
              c.bore[s] = &bore_field(active[s]);
          }
        return c;
      }

    private:
      const ContactKinematics                              &kin;
      BoundaryCompliance                                   &compliance;
      const unsigned int                                    q;
      std::unordered_map<unsigned int, std::vector<double>> bore_fields;
    };

    /**
     * With many active candidates, reading the columns point by point for every pair
     * costs more (scattered reads, k² pairs) than assembling each active candidate's
     * whole bore field once per solve and reading that: measured on the default mesh,
     * point-wise is faster up to ~150 active candidates (0.76 vs 1.4 ms at 1 kN, 45
     * active), whole fields at 393 (63 vs 207 ms at 100 kN).
     */
    constexpr unsigned int max_pointwise_active = 200;

    using ActiveColumns = ComplianceReader::Columns;

    /** The multipliers of the active candidates and the pin translation U. */
    struct ActiveSolution
    {
      Eigen::VectorXd lambda;
      Tensor<1, 2>    U;
    };

    /**
     * Solve the active system: A λ = N U − g0 with, under force control, Nᵀ λ = P
     * (S = Nᵀ A⁻¹ N, U = S⁻¹ (P + Nᵀ A⁻¹ g0)), under displacement control λ = −A⁻¹ g0.
     */
    ActiveSolution
    solve_active_system(const ContactKinematics         &kin,
                        const std::vector<unsigned int> &active,
                        const ActiveColumns             &cols,
                        ComplianceReader                &reader,
                        const bool                       force_control,
                        const Tensor<1, 2>              &load)
    {
      const unsigned int k = active.size();
      Eigen::MatrixXd    A(k, k);
      Eigen::MatrixXd    N(k, 2);
      Eigen::VectorXd    g0(k);
      for (unsigned int s = 0; s < k; ++s)
        {
          for (unsigned int r = 0; r < k; ++r)
            A(r, s) = (*cols.pin[s])[active[r]] + (cols.fields ? reader.field_normal(active[r], *cols.bore[s]) :
                                                                 reader.bore_normal(active[r], active[s]));
          N(s, 0) = kin.normal[active[s]][0];
          N(s, 1) = kin.normal[active[s]][1];
          g0(s)   = kin.g0[active[s]];
        }
      const Eigen::MatrixXd             As = 0.5 * (A + A.transpose());
      const Eigen::LLT<Eigen::MatrixXd> llt(As);
      AssertThrow(llt.info() == Eigen::Success,
                  ExcMessage("The contact compliance on the active set is not positive definite."));
      ActiveSolution out;
      out.U = 0;
      if (force_control)
        {
          const Eigen::MatrixXd Y   = llt.solve(N);
          const Eigen::VectorXd z   = llt.solve(g0);
          const Eigen::Matrix2d S   = N.transpose() * Y;
          const Eigen::Vector2d rhs = Eigen::Vector2d(load[0], load[1]) + N.transpose() * z;
          const Eigen::Vector2d u   = S.fullPivLu().solve(rhs);
          out.U[0]                  = u[0];
          out.U[1]                  = u[1];
          out.lambda                = Y * u - z;
        }
      else
        out.lambda = -llt.solve(g0);
      return out;
    }
    /**
     * The gaps of all @p m candidates, g = g0 − n·U + (pin part + bore part) of A λ.
     * The elastic part is at most E = max Σ|w| · Σ_s |λ_s| reach(s) anywhere, so a
     * candidate whose rigid gap g0 − n·U exceeds E + tolerance cannot penetrate: its
     * gap is only bounded from below (g0 − n·U − E) and its columns are never read. At
     * 1 kN on the default mesh this leaves a few dozen of the 2,888 candidates to
     * evaluate.
     */
    void
    candidate_gaps(const ContactKinematics         &kin,
                   const std::vector<unsigned int> &active,
                   const ActiveColumns             &cols,
                   ComplianceReader                &reader,
                   const Eigen::VectorXd           &lambda_active,
                   const std::vector<double>       &lambda,
                   const Tensor<1, 2>              &U,
                   const double                     max_weight_sum,
                   const double                     tolerance,
                   std::vector<double>             &gap)
    {
      const unsigned int k = active.size();
      double             E = 0;
      for (unsigned int s = 0; s < k; ++s)
        E += std::abs(lambda_active[s]) * reader.reach(active[s]);
      E *= max_weight_sum;
      std::vector<double> bore_total;
      if (cols.fields)
        {
          bore_total.assign(cols.bore.empty() ? 0 : cols.bore[0]->size(), 0.0);
          for (unsigned int s = 0; s < k; ++s)
            for (unsigned int r = 0; r < bore_total.size(); ++r)
              bore_total[r] += lambda_active[s] * (*cols.bore[s])[r];
        }
      for (unsigned int i = 0; i < gap.size(); ++i)
        {
          const double rigid = kin.g0[i] - kin.normal[i] * U;
          if (rigid > E + tolerance && lambda[i] == 0.0)
            {
              gap[i] = rigid - E;
              continue;
            }
          double g = rigid;
          if (cols.fields)
            {
              g += reader.field_normal(i, bore_total);
              for (unsigned int s = 0; s < k; ++s)
                g += (*cols.pin[s])[i] * lambda_active[s];
            }
          else
            for (unsigned int s = 0; s < k; ++s)
              g += ((*cols.pin[s])[i] + reader.bore_normal(i, active[s])) * lambda_active[s];
          gap[i] = g;
        }
    }

    /**
     * A feasible start of the monotone phase: λ ≥ 0 with Σ λ n = P (force control) on the
     * two candidates of ensure_two_active (closest, and the one bracketing P with it),
     * or λ = 0 (displacement control). Returns the candidates that carry it.
     */
    std::vector<unsigned int>
    feasible_start(const ContactKinematics &kin,
                   const bool               force_control,
                   const Tensor<1, 2>      &load,
                   std::vector<double>     &lambda)
    {
      std::fill(lambda.begin(), lambda.end(), 0.0);
      std::vector<unsigned int> pair;
      if (!force_control)
        return pair;
      ensure_two_active(pair, kin.g0, kin.normal, load);
      if (pair.size() < 2)
        return pair;
      const auto  &a = kin.normal[pair[0]], &b = kin.normal[pair[1]];
      const double d = a[0] * b[1] - a[1] * b[0];
      if (d == 0.0)
        return pair;
      // Clipped at 0 when the pair does not bracket the load (then the start is not
      // quite feasible; the first full step restores the balance).
      lambda[pair[0]] = std::max(0.0, (load[0] * b[1] - load[1] * b[0]) / d);
      lambda[pair[1]] = std::max(0.0, (a[0] * load[1] - a[1] * load[0]) / d);
      return pair;
    }

    /**
     * The monotone (Lawson–Hanson type) step of the primal active-set method from the
     * feasible λ towards the minimizer @p x of the current active set: the longest step
     * α ∈ [0, 1) that keeps λ ≥ 0; the candidates whose force reaches zero leave the
     * set. Returns α, or 1 (changing nothing) if @p x is feasible itself.
     */
    double
    step_back_to_feasible(std::vector<unsigned int> &active, const Eigen::VectorXd &x, std::vector<double> &lambda)
    {
      double       alpha   = 1;
      unsigned int blocker = active.size();
      for (unsigned int s = 0; s < active.size(); ++s)
        if (x[s] <= 0)
          {
            const double l = lambda[active[s]];
            const double a = l > 0 ? l / (l - x[s]) : 0.0;
            if (blocker == active.size() || a < alpha)
              {
                alpha   = a;
                blocker = s;
              }
          }
      if (blocker == active.size())
        return 1;
      if (alpha == 0)
        {
          // Degenerate: candidates at zero force that the minimizer wants tensile leave;
          // the point does not move, and the others (at zero too, but wanted compressive)
          // stay.
          std::vector<unsigned int> kept;
          for (unsigned int s = 0; s < active.size(); ++s)
            if (lambda[active[s]] > 0 || x[s] > 0)
              kept.push_back(active[s]);
          active = kept;
          return 0;
        }
      double max_lambda = 0;
      for (unsigned int s = 0; s < active.size(); ++s)
        {
          double &l = lambda[active[s]];
          l += alpha * (x[s] - l);
          max_lambda = std::max(max_lambda, l);
        }
      lambda[active[blocker]] = 0;
      std::vector<unsigned int> kept;
      for (const auto i : active)
        if (lambda[i] > 1e-14 * max_lambda)
          kept.push_back(i);
        else
          lambda[i] = 0;
      active = kept;
      return alpha;
    }

    /** The penetrating candidates outside the active set, the worst first. */
    std::vector<unsigned int>
    penetrating(const std::vector<double> &lambda, const std::vector<double> &gap, const double tolerance)
    {
      std::vector<unsigned int> out;
      for (unsigned int i = 0; i < gap.size(); ++i)
        if (lambda[i] == 0.0 && gap[i] < -tolerance)
          out.push_back(i);
      std::stable_sort(out.begin(), out.end(), [&](unsigned int a, unsigned int b) { return gap[a] < gap[b]; });
      return out;
    }

    /**
     * The monotone primal active-set method (see CondensedContactSolver::solve); true
     * when it ends within @p max_iterations (counted in @p iterations), with the final
     * set in @p active.
     */
    bool
    monotone_active_set(const ContactKinematics   &kin,
                        ComplianceReader          &reader,
                        const bool                 force_control,
                        const Tensor<1, 2>        &load,
                        const unsigned int         max_iterations,
                        std::vector<unsigned int> &active,
                        std::vector<double>       &lambda,
                        std::vector<double>       &gap,
                        Tensor<1, 2>              &U,
                        unsigned int              &iterations)
    {
      const double tolerance      = gap_tolerance(kin);
      const double max_weight_sum = reader.max_weight_sum(lambda.size());
      // From the feasible pair alone: a start from the primal–dual iteration's last set
      // (bloated where it cycled) cost one step back per surplus candidate (measured:
      // ~100 steps to end at 2 active on a worn pair).
      active = feasible_start(kin, force_control, load, lambda);
      std::sort(active.begin(), active.end());
      // A candidate that joins and is dropped again at once without the point moving
      // (round-off at a penetration near the tolerance) is blocked until the point
      // moves; violations left only at blocked candidates below 1 nm count as solved.
      const unsigned int m = lambda.size();
      std::vector<char>  blocked(m, 0);
      unsigned int       joined = m;
      for (unsigned int it = 0; it < max_iterations; ++it, ++iterations)
        {
          if (force_control)
            ensure_two_active(active, kin.g0, kin.normal, load);
          const ActiveColumns cols  = reader.columns(active, max_pointwise_active);
          const auto          x     = solve_active_system(kin, active, cols, reader, force_control, load);
          const double        alpha = step_back_to_feasible(active, x.lambda, lambda);
          if (alpha == 0 && joined < m && !std::binary_search(active.begin(), active.end(), joined))
            blocked[joined] = 1;
          else if ((alpha > 0 && alpha < 1) || (alpha == 1 && joined < m)) // the point moved
            std::fill(blocked.begin(), blocked.end(), 0);
          joined = m;
          if (alpha < 1)
            continue;
          for (unsigned int s = 0; s < active.size(); ++s)
            lambda[active[s]] = x.lambda[s];
          U = x.U;
          candidate_gaps(kin, active, cols, reader, x.lambda, lambda, U, max_weight_sum, tolerance, gap);
          double worst_blocked = 0;
          for (const auto i : penetrating(lambda, gap, tolerance))
            if (!blocked[i])
              {
                joined = i;
                break;
              }
            else
              worst_blocked = std::min(worst_blocked, gap[i]);
          if (joined == m)
            return worst_blocked > -1e-9;
          active.insert(std::upper_bound(active.begin(), active.end(), joined), joined);
        }
      return false;
    }
  } // namespace

  // S = N A⁻¹ Nᵀ: U = S⁻¹ (P + N A⁻¹ g0), λ = A⁻¹ (Nᵀ U − g0). The gaps of all
  // candidates then follow from the cached compliance columns of the active ones, and
  // the active set is updated until it repeats. The last active set warm-starts the
  // next load state (consecutive states of a mechanism are close).
  // This primal–dual iteration is fast but may cycle on worn, conforming profiles
  // (hundreds of candidates switching at once); when it revisits an active set, or
  // after primal_dual_limit iterations, a monotone primal active-set method takes over from a feasible point:
  // λ stays ≥ 0 and balances the load, the objective ½λᵀAλ + g0ᵀλ never increases and
  // drops at every step that is not degenerate, so no active set repeats and the
  // iteration ends (Lawson–Hanson: the worst penetrating candidate joins, one at a
  // time, which keeps the step non-degenerate; batches of all penetrating candidates
  // were tried and cost long chains of one-by-one removals on worn pairs).
  ContactSolution
  CondensedContactSolver::solve(const ContactKinematics &kin, bool force_control, const Tensor<1, 2> &load)
  {
    const unsigned int m         = problem.pin_nodes.size();
    const double       tolerance = gap_tolerance(kin);

    // Warm start from the previous load state's active set when the load is close to
    // it (consecutive states of a mechanism cycle); otherwise start from the first
    // touching candidates, as the reference solver does.
    const bool warm = force_control && !previous_active.empty() && (load - previous_load).norm() <= 0.25 * load.norm();
    std::vector<unsigned int> active =
      warm ? previous_active : initial_active_set(kin, force_control, load, problem.effective_modulus());
    if (force_control)
      ensure_two_active(active, kin.g0, kin.normal, load);

    ComplianceReader                    reader(kin, compliance, problem.bore_nodes.size());
    const double                        max_weight_sum = reader.max_weight_sum(m);
    ContactSolution                     sol;
    std::vector<double>                 lambda(m, 0.0), gap(m, 0.0);
    std::set<std::vector<unsigned int>> history;
    Tensor<1, 2>                        U;
    bool                                converged = false;
    for (unsigned int iteration = 1; iteration <= std::min(max_iterations, primal_dual_limit); ++iteration)
      {
        sol.iterations           = iteration;
        const ActiveColumns cols = reader.columns(active, max_pointwise_active);
        const auto          x    = solve_active_system(kin, active, cols, reader, force_control, load);
        U                        = x.U;
        std::fill(lambda.begin(), lambda.end(), 0.0);
        for (unsigned int s = 0; s < active.size(); ++s)
          lambda[active[s]] = x.lambda[s];
        candidate_gaps(kin, active, cols, reader, x.lambda, lambda, U, max_weight_sum, tolerance, gap);
        auto next = update_active_set(active, lambda, gap, tolerance, history);
        if (force_control)
          ensure_two_active(next, gap, kin.normal, load);
        if (next == active)
          {
            converged = true;
            break;
          }
        if (history.count(next) != 0 || iteration >= primal_dual_limit)
          break; // cycling, or slow: the monotone method takes over
        active = next;
      }
    if (!converged)
      {
        ++n_monotone;
        sol.monotone = true;
        converged    = monotone_active_set(kin,
                                        reader,
                                        force_control,
                                        load,
                                        10 * max_iterations,
                                        active,
                                        lambda,
                                        gap,
                                        U,
                                        sol.iterations);
      }
    if (!converged)
      not_converged("condensed", sol.iterations);

    previous_active     = active;
    previous_load       = load;
    sol.lambda          = lambda;
    sol.gap             = gap;
    sol.pin_translation = U;
    sol.n_active        = active.size();
    for (unsigned int i = 0; i < m; ++i)
      sol.resultant += lambda[i] * kin.normal[i];
    return sol;
  }

  // The displacement field for a condensed solution: the contact forces −λ_i ν_i on
  // the pin and +λ_i n_i (interpolated) on the bore, one solve with the clamped
  // factorization, plus the pin's rigid translation U (in the pin frame) on its DoFs.
  Vector<double>
  CondensedContactSolver::displacement_field(const ContactKinematics &kin, const ContactSolution &sol) const
  {
    Vector<double> u(problem.dof_handler.n_dofs());
    for (unsigned int i = 0; i < problem.pin_nodes.size(); ++i)
      if (sol.lambda[i] != 0)
        {
          const auto &node = problem.pin_nodes[i];
          u(node.dofs[0]) -= sol.lambda[i] * node.normal[0];
          u(node.dofs[1]) -= sol.lambda[i] * node.normal[1];
          for (unsigned int a = 0; a < kin.n_masters[i]; ++a)
            {
              const auto &b = problem.bore_nodes[kin.masters[i][a]];
              u(b.dofs[0]) += sol.lambda[i] * kin.weights[i][a] * kin.normal[i][0];
              u(b.dofs[1]) += sol.lambda[i] * kin.weights[i][a] * kin.normal[i][1];
            }
        }
    compliance.solve_clamped(u);
    const Tensor<1, 2>            U_pin = rotate(sol.pin_translation, -kin.relative_angle);
    std::vector<char>             done(u.size(), 0);
    std::vector<global_dof_index> dofs(problem.fe.n_dofs_per_cell());
    for (const auto &cell : problem.dof_handler.active_cell_iterators())
      if (cell->material_id() == material_ids::pin)
        {
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            if (!done[dofs[i]])
              {
                done[dofs[i]] = 1;
                u(dofs[i]) += U_pin[problem.fe.system_to_component_index(i).first];
              }
        }
    return u;
  }


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
    const double       tolerance = gap_tolerance(kin);
    const Tensor<1, 2> P_pin     = rotate(load, -kin.relative_angle);

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
        auto next = update_active_set(active, lambda, gap, tolerance, history);
        if (force_control)
          ensure_two_active(next, gap, kin.normal, load);
        if (next == active)
          {
            converged = true;
            break;
          }
        active = next;
      }
    if (!converged)
      not_converged("reference", max_iterations);

    std::vector<char> is_active(m, 0);
    for (const auto i : active)
      is_active[i] = 1;
    for (unsigned int i = 0; i < m; ++i)
      if (!is_active[i])
        lambda[i] = 0;
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
