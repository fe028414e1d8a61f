// SPDX-License-Identifier: LGPL-2.1-or-later
// The linearly implicit Rosenbrock-W method ROS34PW2 (Rang & Angermann, BIT Numer. Math.
// 45 (2005) 761–787), four stages
//   (I − hγW) k_i = h f(t + α_i h, y + Σ_{j<i} α_ij k_j) + h W Σ_{j<i} γ_ij k_j,
//   y₁ = y + Σ b_i k_i,   ŷ₁ = y + Σ b̂_i k_i (order 2, for the error estimate),
// with γ = 0.4358665215: order 3 for *any* matrix W (a W-method), L-stable when W is the
// Jacobian. A non-autonomous system is taken in its autonomous form with W's column of
// ∂f/∂t set to zero, which a W-method allows.
//
// W comes from the system's stiff directions (OdeSystem::stiff_directions). For a
// second-order system y = [q | q̇ | z] with q' = q̇ (n coordinates) and z quantities that
// only follow (energy accumulators: nothing depends on them),
//   W = [[0, I, 0], [Σ_k u^q_k w_kᵀ, Σ_k u^v_k w_kᵀ, 0], [Σ_k z^q_k w_kᵀ, Σ_k z^v_k w_kᵀ, 0]],
// w_k the directions and u_k (z_k) the change of the accelerations q̈ (of z') per unit of
// w_k·q (u^q, z^q) or of w_k·q̇ (u^v, z^v), by a one-sided difference along
// d_k = w_k/|w_k|²: one right-hand side per direction and kind, a handful per contact.
// (The z rows matter: z' = the power dissipated in a sticking friction ramp varies as
// fast as the stiff mode, and without them the stage values of that power would be
// integrated explicitly.) The linear solves (I − hγW) x = b reduce to a rank-r update
// of the identity (Woodbury):
//   c = b_q̇ + g Σ_pos u^q_k (w_k·b_q),  x_q̇ = c + C (I_r − R C)⁻¹ R c,  x_q = b_q + g x_q̇,
//   x_z = b_z + g Σ_k z_k (w_k·x_(q̇ or q)),   g = hγ,  C = [g u^v, g² u^q],
//   R = [w_velocity; w_position],
// a few r × r operations per stage and nothing of the size of the system.
// W is rebuilt at a restart, after a rejected step that used an older W, and every few
// accepted steps; between rebuilds the method keeps its order (W-method), only its
// damping of the stiff modes follows the older W.
// Dense output: cubic Hermite from (y, f) at both ends of the step; f at the new point
// is evaluated anyway, as the next step's first stage.
#include "base/exceptions.h"
#include "mbs/adaptive_runge_kutta.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace wearlink::mbs
{
  namespace
  {
    namespace ros34pw2
    {
      constexpr double gamma = 4.3586652150845900e-1;
      constexpr double a21   = 8.7173304301691801e-1;
      constexpr double a31 = 8.4457060015369423e-1, a32 = -1.1299064236484185e-1;
      constexpr double a43 = 1.0;
      constexpr double g21 = -8.7173304301691801e-1;
      constexpr double g31 = -9.0338057013044082e-1, g32 = 5.4180672388095326e-2;
      constexpr double g41 = 2.4212380706095346e-1, g42 = -1.2232505839045147e0, g43 = 5.4526025533510214e-1;
      constexpr double c2 = a21, c3 = a31 + a32, c4 = a43;
      constexpr double b1 = 2.4212380706095346e-1, b2 = -1.2232505839045147e0, b3 = 1.5452602553351020e0,
                       b4  = 4.3586652150845900e-1;
      constexpr double bh1 = 3.7810903145819369e-1, bh2 = -9.6042292212423178e-2, bh3 = 0.5,
                       bh4 = 2.1793326075422950e-1;
    } // namespace ros34pw2

    /** Accepted steps between two rebuilds of W. */
    constexpr int max_jacobian_age = 2;

    class RosenbrockW : public AdaptiveRungeKutta
    {
    public:
      // I controller for the embedded order 2 (exponent 1/3); growth ≤ 6, shrink ≤ 5.
      RosenbrockW(OdeSystem &system, const IntegratorSettings &settings)
        : AdaptiveRungeKutta(system, settings, Controller{1.0 / 3.0, 0.0, 0.2, 6.0}, 3)
        , n(system.n_second_order())
        , n_follow(static_cast<Eigen::Index>(system.size()) - 2 * n)
      {
        if (n == 0)
          throw InputError("ros34pw2 needs a second-order system (positions and velocities); this one is not.");
        const unsigned int size = system.size();
        for (auto *v : {&k1, &k2, &k3, &k4, &stage, &stage_f, &rhs, &wk, &y_new, &f_new, &err})
          v->setZero(size);
      }

      void
      reset(const double time, const Eigen::VectorXd &state) override
      {
        Integrator::reset(time, state);
        jacobian_valid = false;
      }

      void
      restarted() override
      {
        jacobian_valid = false;
      }

      double
      probe_stiff_rate() override
      {
        build_jacobian();
        return rate;
      }

      /** h·ρ with ρ the fastest rate of the stiff directions at the last W. */
      double
      stiffness_indicator() const override
      {
        return last_step * rate;
      }

    protected:
      double
      attempt(const double hs, const double /*t_new*/) override
      {
        // A retry after a rejection rebuilds a W that was made at an earlier point.
        if (!jacobian_valid || jacobian_age >= max_jacobian_age || (retrying && jacobian_age > 0))
          build_jacobian();
        retrying = true; // until accept()
        factor(hs);
        stages(hs);
        return error_norm(err, y_new);
      }

      void
      accept(const double hs, const double t_new) override
      {
        evaluate(t_new, y_new, f_new);
        advance(t_new, y_new, f_new);
        last_step = hs;
        retrying  = false;
        ++jacobian_age;
      }

      void
      interpolate(const double s, double *out) const override
      {
        hermite_interpolate(s, t - t_prev, y_prev, f_prev, y, f, out);
      }

      const char *
      method_name() const override
      {
        return "ros34pw2";
      }

    private:
      /** Whether a column of W answers a change of w·q̇ or of w·q. */
      enum class Kind
      {
        velocity,
        position
      };

      /** The four stages of a trial step of @p hs; y₁ in y_new, its error estimate in err. */
      void
      stages(const double hs)
      {
        using namespace ros34pw2;
        solve_stage(hs, f, {}, k1);
        stage = y + a21 * k1;
        evaluate(t + c2 * hs, stage, stage_f);
        wk = g21 * k1;
        solve_stage(hs, stage_f, wk, k2);
        stage = y + a31 * k1 + a32 * k2;
        evaluate(t + c3 * hs, stage, stage_f);
        wk = g31 * k1 + g32 * k2;
        solve_stage(hs, stage_f, wk, k3);
        stage = y + a43 * k3;
        evaluate(t + c4 * hs, stage, stage_f);
        wk = g41 * k1 + g42 * k2 + g43 * k3;
        solve_stage(hs, stage_f, wk, k4);
        y_new = y + b1 * k1 + b2 * k2 + b3 * k3 + b4 * k4;
        err   = (b1 - bh1) * k1 + (b2 - bh2) * k2 + (b3 - bh3) * k3 + (b4 - bh4) * k4;
      }

      /** k = (I − hγW)⁻¹ (h F + h W Σγ_ij k_j); @p coupled is Σγ_ij k_j (empty: none). */
      void
      solve_stage(const double hs, const Eigen::VectorXd &stage_rhs, const Eigen::VectorXd &coupled, Eigen::VectorXd &k)
      {
        rhs = hs * stage_rhs;
        if (coupled.size() > 0)
          add_w_times(hs, coupled, rhs);
        k = rhs;
        solve(k);
      }

      /** w_k·q̇ or w_k·q of @p x for column @p k. */
      double
      projection(const Eigen::Index k, const Eigen::VectorXd &x) const
      {
        return kinds[static_cast<std::size_t>(k)] == Kind::velocity ? rows.row(k).dot(x.segment(n, n)) :
                                                                      rows.row(k).dot(x.head(n));
      }

      /** out += s · W x. */
      void
      add_w_times(const double s, const Eigen::VectorXd &x, Eigen::VectorXd &out) const
      {
        out.head(n) += s * x.segment(n, n);
        for (Eigen::Index k = 0; k < columns.cols(); ++k)
          {
            const double wx = s * projection(k, x);
            out.segment(n, n) += wx * columns.col(k);
            out.tail(n_follow) += wx * follow_columns.col(k);
          }
      }

      /** Factor I_r − R C for the step @p hs (C scaled by g = hγ or g²). */
      void
      factor(const double hs)
      {
        g                 = hs * ros34pw2::gamma;
        const auto      r = static_cast<Eigen::Index>(kinds.size());
        Eigen::MatrixXd m = Eigen::MatrixXd::Identity(r, r);
        for (Eigen::Index k = 0; k < r; ++k)
          m.col(k) -= scale(k) * projected.col(k);
        if (r > 0)
          lu.compute(m);
      }

      double
      scale(const Eigen::Index k) const
      {
        return kinds[static_cast<std::size_t>(k)] == Kind::velocity ? g : g * g;
      }

      /** x ← (I − hγW)⁻¹ x (Woodbury on the coordinates; the accumulators pass). */
      void
      solve(Eigen::VectorXd &x) const
      {
        const auto r = static_cast<Eigen::Index>(kinds.size());
        auto       q = x.head(n);
        auto       v = x.segment(n, n);
        for (Eigen::Index k = 0; k < r; ++k)
          if (kinds[static_cast<std::size_t>(k)] == Kind::position)
            v += (g * rows.row(k).dot(q)) * columns.col(k);
        if (r > 0)
          {
            Eigen::VectorXd rc = rows * v;
            rc                 = lu.solve(rc);
            for (Eigen::Index k = 0; k < r; ++k)
              v += (scale(k) * rc[k]) * columns.col(k);
          }
        q += g * v;
        for (Eigen::Index k = 0; k < r; ++k)
          x.tail(n_follow) += (g * projection(k, x)) * follow_columns.col(k);
      }

      /** W at the current point: the stiff directions and the accelerations' change along them. */
      void
      build_jacobian()
      {
        system.stiff_directions(t, y.data(), directions);
        kinds.clear();
        std::vector<std::pair<std::size_t, Kind>> order;
        for (std::size_t d = 0; d < directions.size(); ++d)
          {
            if (directions[d].velocity)
              order.emplace_back(d, Kind::velocity);
            if (directions[d].position)
              order.emplace_back(d, Kind::position);
          }
        const auto r = static_cast<Eigen::Index>(order.size());
        rows.resize(r, n);
        columns.resize(n, r);
        follow_columns.resize(n_follow, r);
        for (Eigen::Index k = 0; k < r; ++k)
          {
            const auto &[d, kind] = order[static_cast<std::size_t>(k)];
            difference_column(k, directions[d], kind);
          }
        projected = rows * columns;
        rate      = 0;
        for (Eigen::Index k = 0; k < r; ++k)
          {
            const double p = std::abs(projected(k, k));
            rate           = std::max(rate, kinds[static_cast<std::size_t>(k)] == Kind::velocity ? p : std::sqrt(p));
          }
        jacobian_valid = true;
        jacobian_age   = 0;
      }

      /** Column @p k of W: the accelerations' change per unit of w·q or w·q̇ along d = w/|w|². */
      void
      difference_column(const Eigen::Index k, const StiffDirection &dir, const Kind kind)
      {
        const double       step   = kind == Kind::velocity ? dir.velocity_step : dir.position_step;
        const Eigen::Index offset = kind == Kind::velocity ? n : 0;
        stage                     = y;
        stage.segment(offset, n) += (step / dir.w.squaredNorm()) * dir.w;
        evaluate(t, stage, stage_f);
        columns.col(k)        = (stage_f.segment(n, n) - f.segment(n, n)) / step;
        follow_columns.col(k) = (stage_f.tail(n_follow) - f.tail(n_follow)) / step;
        rows.row(k)           = dir.w.transpose();
        kinds.push_back(kind);
      }

      const Eigen::Index                   n;        ///< coordinates q
      const Eigen::Index                   n_follow; ///< the quantities z after q and q̇
      std::vector<StiffDirection>          directions;
      std::vector<Kind>                    kinds;
      Eigen::MatrixXd                      rows, columns, follow_columns, projected;
      Eigen::PartialPivLU<Eigen::MatrixXd> lu;
      double                               g = 0, rate = 0, last_step = 0;
      bool                                 jacobian_valid = false;
      bool                                 retrying       = false;
      int                                  jacobian_age   = 0;
      Eigen::VectorXd                      k1, k2, k3, k4, stage, stage_f, rhs, wk, y_new, f_new, err;
    };
  } // namespace

  std::unique_ptr<AdaptiveRungeKutta>
  make_ros34pw2(OdeSystem &system, const IntegratorSettings &settings)
  {
    return std::make_unique<RosenbrockW>(system, settings);
  }
} // namespace wearlink::mbs
