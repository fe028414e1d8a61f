// SPDX-License-Identifier: LGPL-2.1-or-later
#include "base/exceptions.h"
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
    throw InputError("Unknown integrator '" + name + "'; valid are " + integrator_names() + ".");
  }

  std::string
  integrator_names()
  {
    return "rk4|dopri5";
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
    t      = time;
    t_prev = time;
    y      = state;
    y_prev = state;
    evaluate(t, y, f);
    f_prev = f;
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
        const double s   = (time - t_prev) / h;
        const double h00 = (1 + 2 * s) * (1 - s) * (1 - s);
        const double h10 = s * (1 - s) * (1 - s);
        const double h01 = s * s * (3 - 2 * s);
        const double h11 = s * s * (s - 1);
        for (Eigen::Index i = 0; i < y.size(); ++i)
          out[i] = h00 * y_prev[i] + h10 * h * f_prev[i] + h01 * y[i] + h11 * h * f[i];
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

    class DormandPrince : public Integrator
    {
    public:
      DormandPrince(OdeSystem &system, const IntegratorSettings &settings)
        : Integrator(system, settings)
      {
        const unsigned int n = system.size();
        for (auto *v : {&k2, &k3, &k4, &k5, &k6, &k7, &tmp, &err, &r2, &r3, &r4, &r5})
          v->setZero(n);
        tolerance.resize(n);
        for (unsigned int i = 0; i < n; ++i)
          tolerance[i] = i < settings.absolute_tolerance.size() ? settings.absolute_tolerance[i] : 1e-9;
        h = settings.initial_step;
      }

      void
      step(double t_limit) override
      {
        if (!(h > 0))
          h = initial_step_size();
        bool last_rejected = false;
        while (true)
          {
            double hs = std::min({h, settings.max_step, t_limit - t});
            if (!(hs > 0))
              throw NumericalError("dopri5: no time left to step (t = " + std::to_string(t) + " s).");
            if (hs < settings.min_step && hs < t_limit - t)
              {
                std::ostringstream os;
                os << "dopri5: the step size fell to " << hs << " s at t = " << t << " s (minimum " << settings.min_step
                   << " s); the error tolerance cannot be met there. Loosen "
                      "Integrator/Relative tolerance or look for a singular position.";
                throw NumericalError(os.str());
              }
            using namespace dp;
            tmp = y + hs * a21 * f;
            evaluate(t + c2 * hs, tmp, k2);
            tmp = y + hs * (a31 * f + a32 * k2);
            evaluate(t + c3 * hs, tmp, k3);
            tmp = y + hs * (a41 * f + a42 * k2 + a43 * k3);
            evaluate(t + c4 * hs, tmp, k4);
            tmp = y + hs * (a51 * f + a52 * k2 + a53 * k3 + a54 * k4);
            evaluate(t + c5 * hs, tmp, k5);
            tmp = y + hs * (a61 * f + a62 * k2 + a63 * k3 + a64 * k4 + a65 * k5);
            evaluate(t + hs, tmp, k6);
            tmp                = y + hs * (a71 * f + a73 * k3 + a74 * k4 + a75 * k5 + a76 * k6);
            const double t_new = (hs >= t_limit - t) ? t_limit : t + hs;
            evaluate(t_new, tmp, k7);
            err = hs * (e1 * f + e3 * k3 + e4 * k4 + e5 * k5 + e6 * k6 + e7 * k7);

            double       sum          = 0;
            unsigned int n_controlled = 0;
            for (Eigen::Index i = 0; i < y.size(); ++i)
              if (tolerance[i] > 0)
                {
                  const double sc =
                    tolerance[i] + settings.relative_tolerance * std::max(std::abs(y[i]), std::abs(tmp[i]));
                  const double r = err[i] / sc;
                  sum += r * r;
                  ++n_controlled;
                }
            double error_norm = std::sqrt(sum / std::max(1u, n_controlled));
            if (!std::isfinite(error_norm))
              error_norm = 1e10; // a blown-up trial step is rejected and shrunk

            // PI step-size control (Hairer's dopri5: β = 0.04).
            constexpr double beta = 0.04, safe = 0.9, fac_min = 0.2, fac_max = 10.0;
            const double     expo  = 0.2 - 0.75 * beta;
            const double     fac11 = std::pow(error_norm, expo);
            if (error_norm <= 1.0)
              {
                double fac   = fac11 / std::pow(fac_old, beta);
                fac          = std::max(1.0 / fac_max, std::min(1.0 / fac_min, fac / safe));
                double h_new = hs / fac;
                if (last_rejected)
                  h_new = std::min(h_new, hs);
                fac_old = std::max(error_norm, 1e-4);

                // Dense-output coefficients (continuous extension of order 4).
                r2 = tmp - y;
                r3 = hs * f - r2;
                r4 = r2 - hs * k7 - r3;
                r5 = hs * (d1 * f + d3 * k3 + d4 * k4 + d5 * k5 + d6 * k6 + d7 * k7);

                y_prev = y;
                f_prev = f;
                t_prev = t;
                y      = tmp;
                f      = k7;
                t      = t_new;
                // A step shortened to land on t_limit (an event or the end time) says
                // little about the next one: keep the earlier proposal if it was larger.
                const bool truncated = hs < std::min(h, settings.max_step);
                h                    = truncated ? std::max(h, h_new) : h_new;
                ++n_accepted;
                return;
              }
            ++n_rejected;
            last_rejected = true;
            h             = hs / std::min(1.0 / fac_min, fac11 / safe);
          }
      }

      void
      dense_output(double time, double *out) const override
      {
        const double hs = t - t_prev;
        if (hs <= 0)
          {
            for (Eigen::Index i = 0; i < y.size(); ++i)
              out[i] = y[i];
            return;
          }
        const double s  = (time - t_prev) / hs;
        const double s1 = 1 - s;
        for (Eigen::Index i = 0; i < y.size(); ++i)
          out[i] = y_prev[i] + s * (r2[i] + s1 * (r3[i] + s * (r4[i] + s1 * r5[i])));
      }

    private:
      /** Hairer's starting-step heuristic (Solving ODE I, §II.4). */
      double
      initial_step_size()
      {
        double       d0 = 0, d1 = 0;
        unsigned int n_controlled = 0;
        for (Eigen::Index i = 0; i < y.size(); ++i)
          if (tolerance[i] > 0)
            {
              const double sc = tolerance[i] + settings.relative_tolerance * std::abs(y[i]);
              d0 += (y[i] / sc) * (y[i] / sc);
              d1 += (f[i] / sc) * (f[i] / sc);
              ++n_controlled;
            }
        d0        = std::sqrt(d0 / std::max(1u, n_controlled));
        d1        = std::sqrt(d1 / std::max(1u, n_controlled));
        double h0 = (d0 < 1e-5 || d1 < 1e-5) ? 1e-6 : 0.01 * d0 / d1;
        h0        = std::min(h0, settings.max_step);
        tmp       = y + h0 * f;
        evaluate(t + h0, tmp, k2);
        double d2 = 0;
        for (Eigen::Index i = 0; i < y.size(); ++i)
          if (tolerance[i] > 0)
            {
              const double sc = tolerance[i] + settings.relative_tolerance * std::abs(y[i]);
              d2 += ((k2[i] - f[i]) / sc) * ((k2[i] - f[i]) / sc);
            }
        d2 = std::sqrt(d2 / std::max(1u, n_controlled)) / h0;
        const double h1 =
          std::max(d1, d2) <= 1e-15 ? std::max(1e-6, h0 * 1e-3) : std::pow(0.01 / std::max(d1, d2), 0.2);
        return std::min({100 * h0, h1, settings.max_step});
      }

      Eigen::VectorXd     k2, k3, k4, k5, k6, k7, tmp, err, r2, r3, r4, r5;
      std::vector<double> tolerance;
      double              h       = 0;
      double              fac_old = 1e-4;
    };
  } // namespace

  std::unique_ptr<Integrator>
  make_integrator(OdeSystem &system, const IntegratorSettings &settings)
  {
    switch (settings.type)
      {
        case IntegratorType::rk4:
          return std::make_unique<RK4>(system, settings);
        case IntegratorType::dopri5:
          return std::make_unique<DormandPrince>(system, settings);
      }
    throw InputError("Unknown integrator type.");
  }
} // namespace wearlink::mbs
