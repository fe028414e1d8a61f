// SPDX-License-Identifier: LGPL-2.1-or-later
#include "mbs/assembly.h"

#include "base/exceptions.h"

#include <Eigen/QR>

#include <sstream>

namespace wearlink::mbs
{
  namespace
  {
    /** Φ, Φq, Φt of the mechanism's constraints followed by the extra ones. */
    struct AllConstraints
    {
      const Mechanism                                &mechanism;
      const std::vector<std::unique_ptr<Constraint>> &extra;

      unsigned int
      n_rows() const
      {
        unsigned int m = mechanism.n_constraint_equations();
        for (const auto &c : extra)
          m += c->n_equations();
        return m;
      }

      /** Name of the constraint owning row @p row. */
      std::string
      name_of_row(unsigned int row) const
      {
        const auto &cs = mechanism.get_constraints();
        for (unsigned int c = 0; c < cs.size(); ++c)
          if (row < mechanism.constraint_row(c) + cs[c]->n_equations())
            return cs[c]->name;
        row -= mechanism.n_constraint_equations();
        for (const auto &c : extra)
          {
            if (row < c->n_equations())
              return c->name;
            row -= c->n_equations();
          }
        return "?";
      }

      void
      evaluate(double                 t,
               const Eigen::VectorXd &q,
               const Eigen::VectorXd &v,
               Eigen::VectorXd       &phi,
               Eigen::MatrixXd       &jac,
               Eigen::VectorXd       &phi_t) const
      {
        Eigen::VectorXd p0, pt0, g0;
        Eigen::MatrixXd j0;
        mechanism.evaluate_constraints(t, q.data(), v.data(), p0, j0, pt0, g0);
        const unsigned int m0 = mechanism.n_constraint_equations();
        const unsigned int m  = n_rows();
        const unsigned int n  = mechanism.n_coordinates();
        phi.setZero(m);
        phi_t.setZero(m);
        jac.setZero(m, n);
        phi.head(m0)    = p0;
        phi_t.head(m0)  = pt0;
        jac.topRows(m0) = j0;
        const StateView s(q.data(), v.data());
        ConstraintRows  r;
        unsigned int    row = m0;
        for (const auto &c : extra)
          {
            c->evaluate(t, s, r);
            for (unsigned int k = 0; k < r.n; ++k, ++row)
              {
                phi[row]   = r.phi[k];
                phi_t[row] = r.phi_t[k];
                for (unsigned int d = 0; d < 3; ++d)
                  {
                    if (c->body_i != ground)
                      jac(row, 3 * c->body_i + d) += r.jac_i[k][d];
                    jac(row, 3 * c->body_j + d) += r.jac_j[k][d];
                  }
              }
          }
      }
    };
  } // namespace

  namespace
  {
    /**
     * Newton's method on Φ(q, t) = 0 of @p all from @p q (minimum-norm steps, backtracking
     * on ‖Φ‖); leaves Φ, Φq, Φt at the result in @p phi, @p jac, @p phi_t.
     */
    AssemblyResult
    solve_positions(const AllConstraints  &all,
                    const double           t,
                    const AssemblyOptions &options,
                    Eigen::VectorXd       &q,
                    const Eigen::VectorXd &v,
                    Eigen::VectorXd       &phi,
                    Eigen::MatrixXd       &jac,
                    Eigen::VectorXd       &phi_t)
    {
      AssemblyResult result;
      all.evaluate(t, q, v, phi, jac, phi_t);
      double residual = phi.size() > 0 ? phi.cwiseAbs().maxCoeff() : 0.0;
      while (residual > options.tolerance && result.iterations < options.max_iterations)
        {
          ++result.iterations;
          const Eigen::VectorXd dq = jac.completeOrthogonalDecomposition().solve(-phi);
          // Backtracking: accept the largest step 2^-k that reduces the residual.
          double          step = 1.0;
          Eigen::VectorXd trial;
          double          trial_residual = residual;
          for (unsigned int k = 0; k < 30; ++k, step *= 0.5)
            {
              trial = q + step * dq;
              Eigen::VectorXd p, pt;
              Eigen::MatrixXd j;
              all.evaluate(t, trial, v, p, j, pt);
              trial_residual = p.cwiseAbs().maxCoeff();
              if (trial_residual < residual)
                break;
            }
          if (!(trial_residual < residual))
            break; // no descent: stuck at a local minimum of ‖Φ‖
          q = trial;
          all.evaluate(t, q, v, phi, jac, phi_t);
          residual = phi.cwiseAbs().maxCoeff();
        }
      result.residual = residual;
      return result;
    }

    /** The least change of @p v with Φq v = −Φt; the largest remaining residual. */
    double
    project_velocities(const Eigen::MatrixXd &jac, const Eigen::VectorXd &phi_t, Eigen::VectorXd &v)
    {
      if (jac.rows() == 0)
        return 0;
      v += jac.completeOrthogonalDecomposition().solve(-(jac * v + phi_t));
      return (jac * v + phi_t).cwiseAbs().maxCoeff();
    }
  } // namespace

  AssemblyResult
  assemble(const Mechanism                                &mechanism,
           double                                          t0,
           const std::vector<std::unique_ptr<Constraint>> &extra,
           const AssemblyOptions                          &options,
           Eigen::VectorXd                                &q,
           Eigen::VectorXd                                &v)
  {
    const AllConstraints all{mechanism, extra};
    const unsigned int   n = mechanism.n_coordinates();
    q.resize(n);
    v.resize(n);
    const auto &bodies = mechanism.get_bodies();
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        q[3 * b]     = bodies[b].initial_position.x();
        q[3 * b + 1] = bodies[b].initial_position.y();
        q[3 * b + 2] = bodies[b].initial_angle;
        v[3 * b]     = bodies[b].initial_velocity.x();
        v[3 * b + 1] = bodies[b].initial_velocity.y();
        v[3 * b + 2] = bodies[b].initial_angular_velocity;
      }

    Eigen::VectorXd      phi, phi_t;
    Eigen::MatrixXd      jac;
    const AssemblyResult result = solve_positions(all, t0, options, q, v, phi, jac, phi_t);
    if (!(result.residual <= options.tolerance))
      {
        Eigen::Index worst = 0;
        phi.cwiseAbs().maxCoeff(&worst);
        std::ostringstream os;
        os << "The mechanism cannot be assembled at t = " << t0 << " s: after " << result.iterations
           << " Newton iterations the largest constraint residual is " << result.residual << " (in joint '"
           << all.name_of_row(static_cast<unsigned int>(worst)) << "'); allowed is " << options.tolerance
           << ". Check the link lengths and attachment points (Joint */Point on body 1|2), "
              "or move the initial guesses (Body */Initial position, Initial angle) "
              "closer to the intended assembly branch.";
        throw InputError(os.str());
      }

    // Velocities: minimum change of the guess that satisfies Φq q̇ = −Φt.
    const double vres = project_velocities(jac, phi_t, v);
    if (!(vres <= 1e-8 * (1 + v.cwiseAbs().maxCoeff())))
      {
        std::ostringstream os;
        os << "The initial velocities cannot satisfy the constraints at t = " << t0 << " s (residual " << vres
           << "): the mechanism is at a singular position. Start from another time or "
              "initial pose.";
        throw InputError(os.str());
      }
    return result;
  }

  AssemblyResult
  carry(const Mechanism                                &mechanism,
        const double                                    t,
        const std::vector<std::unique_ptr<Constraint>> &extra,
        const AssemblyOptions                          &options,
        Eigen::VectorXd                                &q,
        Eigen::VectorXd                                &v)
  {
    Eigen::VectorXd      phi, phi_t;
    Eigen::MatrixXd      jac;
    const AssemblyResult result = solve_positions(AllConstraints{mechanism, extra}, t, options, q, v, phi, jac, phi_t);
    if (!(result.residual <= options.tolerance))
      throw NumericalError("The state could not be carried onto the worn profiles at t = " + std::to_string(t) +
                           " s: the constraints' residual stays at " + std::to_string(result.residual) + " after " +
                           std::to_string(result.iterations) + " Newton iterations.");
    const std::vector<std::unique_ptr<Constraint>> none;
    AllConstraints{mechanism, none}.evaluate(t, q, v, phi, jac, phi_t);
    project_velocities(jac, phi_t, v);
    return result;
  }
} // namespace wearlink::mbs
