// SPDX-License-Identifier: LGPL-2.1-or-later
#include "base/exceptions.h"
#include "mbs/adaptive_runge_kutta.h"
#include "mbs/integrator.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace wearlink::mbs
{
  IntegratorType
  parse_integrator_type(const std::string &name)
  {
    if (name == "rk4")
      return IntegratorType::rk4;
    if (name == "dopri5")
      return IntegratorType::dopri5;
    if (name == "dop853")
      return IntegratorType::dop853;
    if (name == "ros34pw2")
      return IntegratorType::ros34pw2;
    if (name == "dopri5-stiff")
      return IntegratorType::dopri5_stiff;
    throw InputError("Unknown integrator '" + name + "'; valid are " + integrator_names() + ".");
  }

  std::string
  integrator_names()
  {
    return "rk4|dopri5|dop853|ros34pw2|dopri5-stiff";
  }

  std::string
  integrator_name(const IntegratorType type)
  {
    switch (type)
      {
        case IntegratorType::rk4:
          return "rk4";
        case IntegratorType::dopri5:
          return "dopri5";
        case IntegratorType::dop853:
          return "dop853";
        case IntegratorType::ros34pw2:
          return "ros34pw2";
        case IntegratorType::dopri5_stiff:
          return "dopri5-stiff";
      }
    throw InputError("Unknown integrator type.");
  }

  void
  hermite_interpolate(const double           s,
                      const double           h,
                      const Eigen::VectorXd &y0,
                      const Eigen::VectorXd &f0,
                      const Eigen::VectorXd &y1,
                      const Eigen::VectorXd &f1,
                      double                *out)
  {
    const double h00 = (1 + 2 * s) * (1 - s) * (1 - s);
    const double h10 = s * (1 - s) * (1 - s);
    const double h01 = s * s * (3 - 2 * s);
    const double h11 = s * s * (s - 1);
    for (Eigen::Index i = 0; i < y0.size(); ++i)
      out[i] = h00 * y0[i] + h10 * h * f0[i] + h01 * y1[i] + h11 * h * f1[i];
  }

  Integrator::Integrator(OdeSystem &system, const IntegratorSettings &settings)
    : system(system)
    , settings(settings)
  {
    const unsigned int n = system.size();
    y.setZero(n);
    y_prev.setZero(n);
    f.setZero(n);
    f_prev.setZero(n);
  }

  void
  Integrator::evaluate(double time, const Eigen::VectorXd &state, Eigen::VectorXd &derivative)
  {
    ++n_evaluations;
    system.rhs(time, state.data(), derivative.data());
  }

  void
  Integrator::reset(double time, const Eigen::VectorXd &state)
  {
    evaluate(time, state, f);
    start_at(time, state, f);
  }

  void
  Integrator::end_step_at(const double t_end, const double t_start, const Eigen::VectorXd &y_start)
  {
    reset(t_start, y_start);
    step(t_end);
  }

  void
  Integrator::start_at(const double time, const Eigen::VectorXd &state, const Eigen::VectorXd &derivative)
  {
    t      = time;
    t_prev = time;
    y      = state;
    y_prev = state;
    f      = derivative;
    f_prev = derivative;
  }

  namespace
  {
    // ------------------------------------------------------------------------------
    // Classical Runge–Kutta, fixed step.
    class RK4 : public Integrator
    {
    public:
      RK4(OdeSystem &system, const IntegratorSettings &settings)
        : Integrator(system, settings)
      {
        const unsigned int n = system.size();
        k2.setZero(n);
        k3.setZero(n);
        k4.setZero(n);
        tmp.setZero(n);
      }

      void
      step(double t_limit) override
      {
        const double h = std::min(settings.time_step, t_limit - t);
        if (!(h > 0))
          throw NumericalError("rk4: no time left to step (t = " + std::to_string(t) + " s).");
        y_prev = y;
        f_prev = f;
        t_prev = t;
        tmp    = y + 0.5 * h * f;
        evaluate(t + 0.5 * h, tmp, k2);
        tmp = y + 0.5 * h * k2;
        evaluate(t + 0.5 * h, tmp, k3);
        tmp = y + h * k3;
        evaluate(t + h, tmp, k4);
        y += (h / 6.0) * (f + 2 * k2 + 2 * k3 + k4);
        // Land exactly on t_limit when the last step is shortened.
        t = (t_limit - t <= settings.time_step) ? t_limit : t + h;
        evaluate(t, y, f);
        if (!y.allFinite())
          {
            std::ostringstream os;
            os << "rk4: the state became non-finite at t = " << t << " s; the step " << settings.time_step
               << " s is too large for this contact stiffness (use a smaller step or "
                  "Integrator/Method = dopri5).";
            throw NumericalError(os.str());
          }
        ++n_accepted;
      }

      void
      dense_output(double time, double *out) const override
      {
        const double h = t - t_prev;
        if (h <= 0)
          {
            for (Eigen::Index i = 0; i < y.size(); ++i)
              out[i] = y[i];
            return;
          }
        hermite_interpolate((time - t_prev) / h, h, y_prev, f_prev, y, f, out);
      }

    private:
      Eigen::VectorXd k2, k3, k4, tmp;
    };

    // ------------------------------------------------------------------------------
    // Dormand–Prince 5(4).
    namespace dp
    {
      constexpr double c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;
      constexpr double a21 = 1.0 / 5;
      constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
      constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
      constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561, a54 = -212.0 / 729;
      constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247, a64 = 49.0 / 176,
                       a65 = -5103.0 / 18656;
      constexpr double a71 = 35.0 / 384, a73 = 500.0 / 1113, a74 = 125.0 / 192, a75 = -2187.0 / 6784, a76 = 11.0 / 84;
      constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920, e5 = -17253.0 / 339200, e6 = 22.0 / 525,
                       e7 = -1.0 / 40;
      constexpr double d1 = -12715105075.0 / 11282082432, d3 = 87487479700.0 / 32700410799,
                       d4 = -10690763975.0 / 1880347072, d5 = 701980252875.0 / 199316789632,
                       d6 = -1453857185.0 / 822651844, d7 = 69997945.0 / 29380423;
    } // namespace dp

    class DormandPrince : public AdaptiveRungeKutta
    {
    public:
      // PI control as in Hairer's dopri5: β = 0.04, growth ≤ 10, shrink ≤ 5 per step.
      DormandPrince(OdeSystem &system, const IntegratorSettings &settings)
        : AdaptiveRungeKutta(system, settings, Controller{0.2 - 0.75 * 0.04, 0.04, 0.2, 10.0}, 5)
      {
        const unsigned int n = system.size();
        for (auto *v : {&k2, &k3, &k4, &k5, &k6, &k7, &tmp, &y6, &err, &r2, &r3, &r4, &r5})
          v->setZero(n);
      }

      /**
       * Hairer's estimate (dopri5 code, Solving ODE I §IV.2): stages 6 and 7 are both
       * at t + h, so ρ ≈ ‖k7 − k6‖ / ‖y7 − y6‖ approximates the Jacobian's dominant
       * eigenvalue magnitude; dopri5's stability boundary on the negative real axis is
       * near h·ρ = 3.3.
       */
      double
      stiffness_indicator() const override
      {
        return last_stiffness;
      }

    protected:
      double
      attempt(const double hs, const double t_new) override
      {
        stages(hs, t_new);
        err = hs * (dp::e1 * f + dp::e3 * k3 + dp::e4 * k4 + dp::e5 * k5 + dp::e6 * k6 + dp::e7 * k7);
        return error_norm(err, tmp);
      }

      void
      accept(const double hs, const double t_new) override
      {
        prepare_dense_output(hs);
        last_stiffness = stiffness_estimate(hs);
        advance(t_new, tmp, k7);
      }

      /**
       * With `interpolate_events`: the point at @p t_end from the step's continuous
       * extension (order 4, the order of the error estimate that accepted the step)
       * rather than a second step to it — one right-hand side (f at the new point)
       * instead of a step's six or more, at an error up to the tolerance's instead of
       * the much smaller one of the propagated fifth-order solution (doc/performance.md,
       * "Where an event ends the step"). The extension keeps describing the whole step,
       * so output sampled inside it is unchanged.
       */
      void
      end_step_at(const double t_end, const double t_start, const Eigen::VectorXd &y_start) override
      {
        if (!settings.interpolate_events)
          return Integrator::end_step_at(t_end, t_start, y_start);
        dense_output(t_end, tmp.data());
        evaluate(t_end, tmp, k2);
        t = t_end;
        y = tmp;
        f = k2;
      }

      const char *
      method_name() const override
      {
        return "dopri5";
      }

      void
      interpolate(const double s, double *out) const override
      {
        const double s1 = 1 - s;
        for (Eigen::Index i = 0; i < y.size(); ++i)
          out[i] = y_prev[i] + s * (r2[i] + s1 * (r3[i] + s * (r4[i] + s1 * r5[i])));
      }

    private:
      /** The seven stages from (t, y, f); the 5th-order solution lands in tmp, f there in k7. */
      void
      stages(const double hs, const double t_new)
      {
        using namespace dp;
        tmp = y + hs * a21 * f;
        evaluate(t + c2 * hs, tmp, k2);
        tmp = y + hs * (a31 * f + a32 * k2);
        evaluate(t + c3 * hs, tmp, k3);
        tmp = y + hs * (a41 * f + a42 * k2 + a43 * k3);
        evaluate(t + c4 * hs, tmp, k4);
        tmp = y + hs * (a51 * f + a52 * k2 + a53 * k3 + a54 * k4);
        evaluate(t + c5 * hs, tmp, k5);
        y6 = y + hs * (a61 * f + a62 * k2 + a63 * k3 + a64 * k4 + a65 * k5);
        evaluate(t + hs, y6, k6);
        tmp = y + hs * (a71 * f + a73 * k3 + a74 * k4 + a75 * k5 + a76 * k6);
        evaluate(t_new, tmp, k7);
      }

      /** h‖k7 − k6‖/‖y7 − y6‖ over the error-controlled components (not the accumulators). */
      double
      stiffness_estimate(const double hs) const
      {
        double df = 0, dy = 0;
        for (Eigen::Index i = 0; i < y.size(); ++i)
          if (tolerance[i] > 0)
            {
              df += (k7[i] - k6[i]) * (k7[i] - k6[i]);
              dy += (tmp[i] - y6[i]) * (tmp[i] - y6[i]);
            }
        return dy > 0 ? hs * std::sqrt(df / dy) : 0.0;
      }

      /** Coefficients of the continuous extension of order 4 (before advance()). */
      void
      prepare_dense_output(const double hs)
      {
        using namespace dp;
        r2 = tmp - y;
        r3 = hs * f - r2;
        r4 = r2 - hs * k7 - r3;
        r5 = hs * (d1 * f + d3 * k3 + d4 * k4 + d5 * k5 + d6 * k6 + d7 * k7);
      }

      Eigen::VectorXd k2, k3, k4, k5, k6, k7, tmp, y6, err, r2, r3, r4, r5;
      double          last_stiffness = 0;
    };
  } // namespace

  std::unique_ptr<AdaptiveRungeKutta>
  make_dopri5(OdeSystem &system, const IntegratorSettings &settings)
  {
    return std::make_unique<DormandPrince>(system, settings);
  }

  std::unique_ptr<Integrator>
  make_integrator(OdeSystem &system, const IntegratorSettings &settings)
  {
    switch (settings.type)
      {
        case IntegratorType::rk4:
          return std::make_unique<RK4>(system, settings);
        case IntegratorType::dopri5:
          return std::make_unique<DormandPrince>(system, settings);
        case IntegratorType::dop853:
          return make_dop853(system, settings);
        case IntegratorType::ros34pw2:
          return make_ros34pw2(system, settings);
        case IntegratorType::dopri5_stiff:
          return make_dopri5_stiff(system, settings);
      }
    throw InputError("Unknown integrator type.");
  }
} // namespace wearlink::mbs
