// SPDX-License-Identifier: LGPL-2.1-or-later
#include "mbs/mechanism.h"

#include "base/exceptions.h"
#include "mbs/body_trig.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace wearlink::mbs
{
  int
  Mechanism::add_body(const Body &body)
  {
    bodies.push_back(body);
    return static_cast<int>(bodies.size()) - 1;
  }

  void
  Mechanism::add_constraint(std::unique_ptr<Constraint> c)
  {
    constraints.push_back(std::move(c));
  }

  ForceElement *
  Mechanism::add_force_element(std::unique_ptr<ForceElement> f)
  {
    force_elements.push_back(std::move(f));
    return force_elements.back().get();
  }

  int
  Mechanism::body_index(const std::string &name) const
  {
    if (name == "ground")
      return ground;
    for (unsigned int b = 0; b < bodies.size(); ++b)
      if (bodies[b].name == name)
        return static_cast<int>(b);
    return -2;
  }

  void
  Mechanism::finalize()
  {
    index_rows_and_bodies();
    order_schur_rows();
    plan_schur_assembly();
    const unsigned int nb = n_bodies();
    rhs.setZero(n_equations);
    lambda.setZero(n_equations);
    forces.setZero(3 * nb);
    scaled_forces.assign(3 * nb, 0.0);
    trig.assign(2 * nb, 0.0);
    work.assign(n_equations, 0.0);
    inverse_pivot.assign(n_equations, 0.0);
  }

  void
  Mechanism::index_rows_and_bodies()
  {
    const unsigned int nb = n_bodies();
    row_offset.resize(constraints.size());
    n_equations = 0;
    for (unsigned int c = 0; c < constraints.size(); ++c)
      {
        row_offset[c] = n_equations;
        n_equations += constraints[c]->n_equations();
      }
    inverse_mass.resize(3 * nb);
    for (unsigned int b = 0; b < nb; ++b)
      {
        inverse_mass[3 * b]     = 1.0 / bodies[b].mass;
        inverse_mass[3 * b + 1] = 1.0 / bodies[b].mass;
        inverse_mass[3 * b + 2] = 1.0 / bodies[b].inertia;
      }
    body_constraints.assign(nb, {});
    for (unsigned int c = 0; c < constraints.size(); ++c)
      {
        if (constraints[c]->body_i != ground)
          body_constraints[constraints[c]->body_i].emplace_back(c, 0);
        if (constraints[c]->body_j != ground)
          body_constraints[constraints[c]->body_j].emplace_back(c, 1);
      }
    rows.resize(constraints.size());
    schur.assign(std::size_t(n_equations) * n_equations, 0.0);
  }

  void
  Mechanism::order_schur_rows()
  {
    // Coupling graph of the constraint rows: two rows are coupled when they share a body.
    const unsigned int                     m = n_equations;
    std::vector<std::vector<unsigned int>> adjacent(m);
    for (const auto &list : body_constraints)
      for (const auto &[c1, s1] : list)
        for (const auto &[c2, s2] : list)
          for (unsigned int k1 = 0; k1 < constraints[c1]->n_equations(); ++k1)
            for (unsigned int k2 = 0; k2 < constraints[c2]->n_equations(); ++k2)
              if (row_offset[c1] + k1 != row_offset[c2] + k2)
                adjacent[row_offset[c1] + k1].push_back(row_offset[c2] + k2);
    for (auto &a : adjacent)
      {
        std::sort(a.begin(), a.end());
        a.erase(std::unique(a.begin(), a.end()), a.end());
      }
    // Reverse Cuthill–McKee: breadth-first from a row of least degree, neighbours by
    // increasing degree, per connected component; then reversed.
    std::vector<unsigned int> order;
    std::vector<bool>         visited(m, false);
    while (order.size() < m)
      {
        unsigned int start = m;
        for (unsigned int r = 0; r < m; ++r)
          if (!visited[r] && (start == m || adjacent[r].size() < adjacent[start].size()))
            start = r;
        visited[start]   = true;
        std::size_t head = order.size();
        order.push_back(start);
        while (head < order.size())
          {
            auto next = adjacent[order[head++]];
            std::sort(next.begin(), next.end(), [&](unsigned int a, unsigned int b) {
              return adjacent[a].size() < adjacent[b].size();
            });
            for (const auto r : next)
              if (!visited[r])
                {
                  visited[r] = true;
                  order.push_back(r);
                }
          }
      }
    std::reverse(order.begin(), order.end());
    permuted.resize(m);
    for (unsigned int p = 0; p < m; ++p)
      permuted[order[p]] = p;
    // Envelope: the first coupled column of each permuted row (fill-in stays inside).
    first_column.resize(m);
    for (unsigned int r = 0; r < m; ++r)
      {
        unsigned int f = permuted[r];
        for (const auto a : adjacent[r])
          f = std::min(f, permuted[a]);
        first_column[permuted[r]] = f;
      }
  }

  void
  Mechanism::plan_schur_assembly()
  {
    // Every pair of constraint rows that share a body contributes Σ_d a_d w_d b_d (their
    // Jacobian entries for that body, w its M⁻¹ diagonal) to the lower triangle of S.
    // Listing the products once removes the index arithmetic and the nested loops from
    // every right-hand side, and the dimensions where both entries are constants (the
    // ±1 and 0 of positions and angles) are summed here, once: what remains per
    // right-hand side is mostly one θ product per pair of revolute rows.
    const unsigned int m = n_equations;
    evaluate_rows_at_rest();
    std::vector<double> constant(std::size_t(m) * m, 0.0);
    theta_terms.clear();
    full_terms.clear();
    for (unsigned int b = 0; b < n_bodies(); ++b)
      for (const auto &[c1, side1] : body_constraints[b])
        for (const auto &[c2, side2] : body_constraints[b])
          for (unsigned int k1 = 0; k1 < constraints[c1]->n_equations(); ++k1)
            for (unsigned int k2 = 0; k2 < constraints[c2]->n_equations(); ++k2)
              {
                const unsigned int row = permuted[row_offset[c1] + k1];
                const unsigned int col = permuted[row_offset[c2] + k2];
                if (col > row)
                  continue;
                const std::size_t   target = std::size_t(row) * m + col;
                const double       *a      = side1 == 0 ? rows[c1].jac_i[k1] : rows[c1].jac_j[k1];
                const double       *bb     = side2 == 0 ? rows[c2].jac_i[k2] : rows[c2].jac_j[k2];
                const double       *w      = &inverse_mass[3 * b];
                const auto          fixed1 = constraints[c1]->constant_jacobian(k1);
                const auto          fixed2 = constraints[c2]->constant_jacobian(k2);
                std::array<bool, 3> fixed;
                for (unsigned int d = 0; d < 3; ++d)
                  fixed[d] = fixed1[d] && fixed2[d];
                if (fixed[0] && fixed[1])
                  {
                    constant[target] += a[0] * w[0] * bb[0] + a[1] * w[1] * bb[1];
                    if (fixed[2])
                      constant[target] += a[2] * w[2] * bb[2];
                    else
                      theta_terms.push_back({target, a + 2, bb + 2, w[2]});
                  }
                else
                  full_terms.push_back({target, a, bb, w});
              }
    // In memory order of the targets, for locality.
    std::stable_sort(theta_terms.begin(), theta_terms.end(), [](const ThetaTerm &x, const ThetaTerm &y) {
      return x.target < y.target;
    });
    std::stable_sort(full_terms.begin(), full_terms.end(), [](const FullTerm &x, const FullTerm &y) {
      return x.target < y.target;
    });
    schur_entries.clear();
    for (unsigned int i = 0; i < m; ++i)
      for (unsigned int j = first_column[i]; j <= i; ++j)
        schur_entries.push_back({std::size_t(i) * m + j, constant[std::size_t(i) * m + j]});
  }

  void
  Mechanism::evaluate_rows_at_rest()
  {
    // The constant Jacobian entries hold at any state: take q = 0, q̇ = 0, t = 0.
    const unsigned int  nb = n_bodies();
    std::vector<double> zero(3 * nb, 0.0), trig_zero(2 * nb, 0.0);
    for (unsigned int b = 0; b < nb; ++b)
      trig_zero[2 * b] = 1.0;
    const StateView s(zero.data(), zero.data(), trig_zero.data());
    for (unsigned int c = 0; c < constraints.size(); ++c)
      constraints[c]->evaluate(0.0, s, rows[c]);
  }

  void
  Mechanism::evaluate_constraints(double           t,
                                  const double    *q,
                                  const double    *v,
                                  Eigen::VectorXd &phi,
                                  Eigen::MatrixXd &jacobian,
                                  Eigen::VectorXd &phi_t,
                                  Eigen::VectorXd &gamma) const
  {
    const StateView s(q, v);
    phi.setZero(n_equations);
    phi_t.setZero(n_equations);
    gamma.setZero(n_equations);
    jacobian.setZero(n_equations, n_coordinates());
    ConstraintRows r;
    for (unsigned int c = 0; c < constraints.size(); ++c)
      {
        const auto &con = *constraints[c];
        con.evaluate(t, s, r);
        for (unsigned int k = 0; k < r.n; ++k)
          {
            const unsigned int row = row_offset[c] + k;
            phi[row]               = r.phi[k];
            phi_t[row]             = r.phi_t[k];
            gamma[row]             = r.gamma[k];
            for (unsigned int d = 0; d < 3; ++d)
              {
                if (con.body_i != ground)
                  jacobian(row, 3 * con.body_i + d) += r.jac_i[k][d];
                jacobian(row, 3 * con.body_j + d) += r.jac_j[k][d];
              }
          }
      }
  }

  void
  Mechanism::accelerations(double t, const double *q, const double *v, double *a, PowerTerms &power)
  {
    ++evaluations;
    body_trig(q, n_bodies(), trig.data());
    const StateView s(q, v, trig.data());
    apply_forces(t, s, power);
    for (unsigned int c = 0; c < constraints.size(); ++c)
      constraints[c]->evaluate(t, s, rows[c]);
    assemble_constraint_rhs(v);
    assemble_schur_complement();
    factor_schur_complement(t);
    solve_multipliers();
    if (solve_held_contacts(s, v, a, power))
      {
        held_state.assign(q, q + n_coordinates());
        held_state.insert(held_state.end(), v, v + n_coordinates());
      }
    else
      constrained_accelerations(v, a, power);
  }

  void
  Mechanism::apply_forces(const double t, const StateView &s, PowerTerms &power)
  {
    const unsigned int nb = n_bodies();
    // Applied forces g: gravity and force elements.
    for (unsigned int b = 0; b < nb; ++b)
      {
        forces[3 * b]     = bodies[b].mass * gravity.x();
        forces[3 * b + 1] = bodies[b].mass * gravity.y();
        forces[3 * b + 2] = 0;
      }
    ForceAccumulator acc;
    acc.g = forces.data();
    for (const auto &f : force_elements)
      f->add_forces(t, s, acc);
    power.damping  = acc.damping_power;
    power.friction = acc.friction_power;
  }

  void
  Mechanism::assemble_constraint_rhs(const double *v)
  {
    // Baumgarte: γ̂ = γ − 2αΦ̇ − β²Φ; rhs = Φq M⁻¹ g − γ̂.
    const unsigned int nc = n_coordinates();
    for (unsigned int i = 0; i < nc; ++i)
      scaled_forces[i] = inverse_mass[i] * forces[i];
    const double two_alpha = 2 * baumgarte_alpha, beta_squared = baumgarte_beta * baumgarte_beta;
    for (unsigned int c = 0; c < constraints.size(); ++c)
      {
        const auto   &con = *constraints[c];
        const auto   &r   = rows[c];
        const double *vj = v + 3 * con.body_j, *gj = scaled_forces.data() + 3 * con.body_j;
        for (unsigned int k = 0; k < r.n; ++k)
          {
            const double *J   = r.jac_j[k];
            double        jv  = r.phi_t[k] + J[0] * vj[0] + J[1] * vj[1] + J[2] * vj[2];
            double        jmg = J[0] * gj[0] + J[1] * gj[1] + J[2] * gj[2];
            if (con.body_i != ground)
              {
                const double *I = r.jac_i[k], *vi = v + 3 * con.body_i, *gi = scaled_forces.data() + 3 * con.body_i;
                jv += I[0] * vi[0] + I[1] * vi[1] + I[2] * vi[2];
                jmg += I[0] * gi[0] + I[1] * gi[1] + I[2] * gi[2];
              }
            rhs[row_offset[c] + k] = jmg - (r.gamma[k] - two_alpha * jv - beta_squared * r.phi[k]);
          }
      }
  }

  void
  Mechanism::assemble_schur_complement()
  {
    // S = Φq M⁻¹ Φqᵀ, lower triangle: the constant part of every envelope entry, then
    // the planned products (plan_schur_assembly).
    double *S = schur.data();
    for (const SchurEntry &e : schur_entries)
      S[e.target] = e.constant;
    for (const ThetaTerm &t : theta_terms)
      S[t.target] += t.w * *t.a * *t.b;
    for (const FullTerm &t : full_terms)
      S[t.target] += t.a[0] * t.w[0] * t.b[0] + t.a[1] * t.w[1] * t.b[1] + t.a[2] * t.w[2] * t.b[2];
  }

  void
  Mechanism::factor_schur_complement(const double t)
  {
    const unsigned int m = n_equations;
    // S = L D Lᵀ (L unit lower triangular) in place within the envelope, row by row; each
    // entry is one contiguous dot product of two rows. S has a few dozen rows at most; a
    // plain envelope factorization beats a blocked dense library one by a wide margin
    // here (callgrind on the nine-bar: Eigen's dynamic LLT spent ~3× the instructions in
    // its blocking and GEMV kernels). LDLᵀ rather than Cholesky: the rows form one chain
    // of dependent pivots, and a square root plus a division per pivot was ~40 % of the
    // factorization's time on that chain (perf); one division per pivot remains.
    // w_j = L_ij D_j of the current row is kept in `work` (scratch until the solve).
    double *L = schur.data();
    double *w = work.data();
    for (unsigned int i = 0; i < m; ++i)
      {
        double            *Li = L + std::size_t(i) * m;
        const unsigned int fi = first_column[i];
        double             d  = Li[i];
        for (unsigned int j = fi; j < i; ++j)
          {
            const double *Lj = L + std::size_t(j) * m;
            double        s  = Li[j];
            for (unsigned int k = std::max(fi, first_column[j]); k < j; ++k)
              s -= w[k] * Lj[k];
            w[j]  = s;
            Li[j] = s * inverse_pivot[j];
            d -= s * Li[j];
          }
        if (!(d > 1e-14 * (1.0 + std::abs(Li[i]))))
          throw_rank_loss(t);
        Li[i]            = d;
        inverse_pivot[i] = 1.0 / d;
      }
  }

  namespace
  {
    /**
     * The body whose mass (or moment of inertia, by @p of) lies furthest from the
     * others', if the bodies' values span more than 1e10: S = Φq M⁻¹ Φqᵀ then mixes
     * terms ten orders of magnitude apart, and its pivots drown in rounding (doubles
     * carry 16 digits). "" otherwise.
     */
    std::string
    disparate_body(const std::vector<Body> &bodies, double Body::*of, const std::string &entry, const char *unit)
    {
      if (bodies.size() < 2)
        return "";
      const auto range =
        std::minmax_element(bodies.begin(), bodies.end(), [of](const Body &x, const Body &y) { return x.*of < y.*of; });
      const Body &lo = *range.first, &hi = *range.second;
      if (!(hi.*of > 1e10 * lo.*of))
        return "";
      // The odd one out: the lightest if the others are near the heaviest, else the heaviest.
      double sum_log = 0;
      for (const auto &b : bodies)
        sum_log += std::log10(b.*of);
      const double       mean_log = sum_log / static_cast<double>(bodies.size());
      const Body        &odd      = mean_log - std::log10(lo.*of) > std::log10(hi.*of) - mean_log ? lo : hi;
      std::ostringstream os;
      os << " The bodies' " << entry << " values span " << std::setprecision(3) << hi.*of / lo.*of << " (Body "
         << odd.name << ": " << odd.*of << " " << unit << "), beyond what double precision can solve with: check 'Body "
         << odd.name << "/" << entry << "'.";
      return os.str();
    }
  } // namespace

  void
  Mechanism::throw_rank_loss(const double t) const
  {
    std::ostringstream os;
    os << "The constraint Jacobian lost rank at t = " << t
       << " s (the mechanism locks up or passes a singular position); the "
          "equations of motion cannot be solved. Check the joint geometry and the "
          "drivers."
       << disparate_body(bodies, &Body::mass, "Mass", "kg")
       << disparate_body(bodies, &Body::inertia, "Moment of inertia", "kg m²");
    throw NumericalError(os.str());
  }

  void
  Mechanism::solve_multipliers()
  {
    const unsigned int m = n_equations;
    const double      *L = schur.data();
    for (unsigned int r = 0; r < m; ++r)
      work[permuted[r]] = rhs[r];
    for (unsigned int i = 0; i < m; ++i) // L y = rhs (unit diagonal)
      {
        const double *Li = L + std::size_t(i) * m;
        double        s  = work[i];
        for (unsigned int k = first_column[i]; k < i; ++k)
          s -= Li[k] * work[k];
        work[i] = s;
      }
    for (unsigned int i = 0; i < m; ++i) // z = D⁻¹ y
      work[i] *= inverse_pivot[i];
    for (unsigned int i = m; i-- > 0;) // Lᵀ λ = z (unit diagonal)
      {
        const double *Li = L + std::size_t(i) * m;
        const double  x  = work[i];
        for (unsigned int k = first_column[i]; k < i; ++k)
          work[k] -= Li[k] * x;
      }
    for (unsigned int r = 0; r < m; ++r)
      lambda[r] = work[permuted[r]];
  }

  void
  Mechanism::constrained_accelerations(const double *v, double *a, PowerTerms &power) const
  {
    const unsigned int nb = n_bodies();
    // q̈ = M⁻¹ (g − Φqᵀ λ), and the reaction power −q̇ᵀ Φqᵀ λ.
    for (unsigned int i = 0; i < 3 * nb; ++i)
      a[i] = forces[i];
    for (unsigned int c = 0; c < constraints.size(); ++c)
      {
        const auto &con = *constraints[c];
        const auto &r   = rows[c];
        double     *aj  = a + 3 * con.body_j;
        double     *ai  = con.body_i != ground ? a + 3 * con.body_i : nullptr;
        for (unsigned int k = 0; k < r.n; ++k)
          {
            const double l = lambda[row_offset[c] + k];
            aj[0] -= r.jac_j[k][0] * l;
            aj[1] -= r.jac_j[k][1] * l;
            aj[2] -= r.jac_j[k][2] * l;
            if (ai)
              {
                ai[0] -= r.jac_i[k][0] * l;
                ai[1] -= r.jac_i[k][1] * l;
                ai[2] -= r.jac_i[k][2] * l;
              }
          }
      }
    double p_reaction = 0;
    for (unsigned int i = 0; i < 3 * nb; ++i)
      {
        p_reaction += v[i] * (a[i] - forces[i]); // = −q̇ᵀ Φqᵀ λ
        a[i] *= inverse_mass[i];
      }
    power.constraint = p_reaction;
  }

  double
  Mechanism::last_constraint_violation() const
  {
    double m = 0;
    for (const auto &r : rows)
      for (unsigned int k = 0; k < r.n; ++k)
        m = std::max(m, std::abs(r.phi[k]));
    return m;
  }

  double
  Mechanism::kinetic_energy(const double *v) const
  {
    double t = 0;
    for (unsigned int b = 0; b < n_bodies(); ++b)
      t += 0.5 * bodies[b].mass * (v[3 * b] * v[3 * b] + v[3 * b + 1] * v[3 * b + 1]) +
           0.5 * bodies[b].inertia * v[3 * b + 2] * v[3 * b + 2];
    return t;
  }

  double
  Mechanism::potential_energy(const double           *q,
                              const double           *v,
                              const double           *trig,
                              const ElementPotential &element_potential) const
  {
    double e = 0;
    for (unsigned int b = 0; b < n_bodies(); ++b)
      e -= bodies[b].mass * (gravity.x() * q[3 * b] + gravity.y() * q[3 * b + 1]);
    const StateView s(q, v, trig);
    for (const auto &f : force_elements)
      e += element_potential ? element_potential(*f, s) : f->potential_energy(s);
    return e;
  }
} // namespace wearlink::mbs
