// SPDX-License-Identifier: LGPL-2.1-or-later
// Held contacts in the right-hand side (force_element.h, HeldContact; doc/models.md §1.6).
// The equations of motion are linear in the applied forces once S = Φq M⁻¹ Φqᵀ is factored,
// so with the contacts' normal forces F_k unknown,
//   q̈ = q̈₀ + Σ_k F_k r_k,   r_k = q̈(g + g_k) − q̈(g),
// q̈₀ the accelerations without them and r_k the response to contact k's unit force (one
// more solve with the factored S each). Each held row w_k·q̈ + c_k = −2b δ̇_k − b²(δ_k −
// δ_s(F_k)) then gives the small system
//   Σ_j (w_k·r_j) F_j = −c_k − w_k·q̈₀ − 2b δ̇_k − b² δ_k + b² δ_s(F_k),
// nonlinear only through δ_s(F) = (F/K)^(1/e), whose weight b² dδ_s/dF is ~10⁻³ of w·r at
// the contact forces of a mechanism: a few fixed-point sweeps converge to round-off. The
// forces are then applied and q̈, λ and the reaction power computed once more with them.
// Energy: the contact's elastic part K δᵉ stays in the potential energy; what the held
// force differs from it by, (F − K δᵉ) δ̇, is counted as damping, as the hysteresis of
// the compliant laws is; friction F_t = (F_t/F) F dissipates −F_t v_t.
#include "mbs/mechanism.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace wearlink::mbs
{
  namespace
  {
    /** Baumgarte's rate b of the held rows [1/s]: slow beside a contact mode (~10⁴/s). */
    constexpr double hold_rate = 1e3;
    /** Fixed-point sweeps on δ_s(F). */
    constexpr int fixed_point_sweeps = 3;

    double
    quasi_static_penetration(const HeldContact &h, const double force)
    {
      return force > 0 ? std::pow(force / h.stiffness, 1.0 / h.exponent) : 0.0;
    }
  } // namespace

  bool
  Mechanism::held_forces_at(const double *q, const double *v) const
  {
    const unsigned int nc = n_coordinates();
    if (held_state.size() != 2 * nc)
      return false;
    return std::equal(q, q + nc, held_state.begin()) && std::equal(v, v + nc, held_state.begin() + nc);
  }

  double
  Mechanism::acceleration_response(const double *v, const std::vector<double> &g, std::vector<double> &out)
  {
    // λ_g = S⁻¹ Φq M⁻¹ g (no γ: the response is linear), then M⁻¹ (g − Φqᵀ λ_g).
    const unsigned int nc = n_coordinates();
    for (unsigned int i = 0; i < nc; ++i)
      scaled_forces[i] = inverse_mass[i] * g[i];
    for (unsigned int c = 0; c < constraints.size(); ++c)
      {
        const auto   &con = *constraints[c];
        const auto   &r   = rows[c];
        const double *gj  = scaled_forces.data() + 3 * con.body_j;
        const double *gi  = con.body_i != ground ? scaled_forces.data() + 3 * con.body_i : nullptr;
        for (unsigned int k = 0; k < r.n; ++k)
          {
            const double *J   = r.jac_j[k];
            double        jmg = J[0] * gj[0] + J[1] * gj[1] + J[2] * gj[2];
            if (gi)
              jmg += r.jac_i[k][0] * gi[0] + r.jac_i[k][1] * gi[1] + r.jac_i[k][2] * gi[2];
            rhs[row_offset[c] + k] = jmg;
          }
      }
    solve_multipliers();
    std::swap(forces_backup, forces);
    for (unsigned int i = 0; i < nc; ++i)
      forces[i] = g[i];
    PowerTerms reaction;
    constrained_accelerations(v, out.data(), reaction);
    std::swap(forces_backup, forces);
    return reaction.constraint;
  }

  bool
  Mechanism::solve_held_contacts(const StateView &s, const double *v, double *a, PowerTerms &power)
  {
    held_elements.clear();
    for (const auto &f : force_elements)
      if (f->holds_contact())
        held_elements.push_back(f.get());
    if (held_elements.empty())
      return false;
    const unsigned int nc = n_coordinates();
    const auto         m  = static_cast<Eigen::Index>(held_elements.size());
    if (held.size() < held_elements.size())
      {
        held.resize(held_elements.size());
        held_response.resize(held_elements.size());
        held_lambda.resize(held_elements.size());
        held_reaction_power.resize(held_elements.size());
      }
    // Without the held forces first (λ of the caller's solve), then each response.
    constrained_accelerations(v, a, power);
    held_lambda_base = lambda;
    forces_backup.resize(nc);
    for (Eigen::Index k = 0; k < m; ++k)
      {
        HeldContact &h = held[k];
        h.w.assign(nc, 0.0);
        h.g.assign(nc, 0.0);
        held_response[k].resize(nc);
        held_elements[k]->held_contact(s, h);
        held_reaction_power[k] = acceleration_response(v, h.g, held_response[k]);
        held_lambda[k]         = lambda;
      }
    // The rows' matrix and the right-hand side without δ_s.
    held_coupling.resize(m, m);
    held_fixed.resize(m);
    held_force.setZero(m);
    for (Eigen::Index k = 0; k < m; ++k)
      {
        const HeldContact &h  = held[k];
        double             wa = 0;
        for (unsigned int i = 0; i < nc; ++i)
          wa += h.w[i] * a[i];
        held_fixed[k] = -h.convective - wa - 2 * hold_rate * h.rate - hold_rate * hold_rate * h.penetration;
        for (Eigen::Index j = 0; j < m; ++j)
          {
            double wr = 0;
            for (unsigned int i = 0; i < nc; ++i)
              wr += h.w[i] * held_response[j][i];
            held_coupling(k, j) = wr;
          }
      }
    held_lu.compute(held_coupling);
    for (int sweep = 0; sweep < fixed_point_sweeps; ++sweep)
      {
        held_rhs = held_fixed;
        for (Eigen::Index k = 0; k < m; ++k)
          held_rhs[k] += hold_rate * hold_rate * quasi_static_penetration(held[k], held_force[k]);
        held_force = held_lu.solve(held_rhs);
      }
    // The forces applied, by linearity: q̈, λ and the reaction power −q̇ᵀ Φqᵀ λ.
    lambda = held_lambda_base;
    for (Eigen::Index k = 0; k < m; ++k)
      {
        const double f = held_force[k];
        lambda += f * held_lambda[k];
        for (unsigned int i = 0; i < nc; ++i)
          a[i] += f * held_response[k][i];
        power.constraint += f * held_reaction_power[k];
      }
    for (Eigen::Index k = 0; k < m; ++k)
      {
        const HeldContact &h       = held[k];
        const double       elastic = h.stiffness * std::pow(std::max(h.penetration, 0.0), h.exponent);
        power.damping += (held_force[k] - elastic) * h.rate;
        power.friction += -h.friction_per_force * held_force[k] * h.sliding_velocity;
        held_elements[k]->set_held_force(held_force[k]);
      }
    return true;
  }
} // namespace wearlink::mbs
