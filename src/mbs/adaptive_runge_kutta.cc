// SPDX-License-Identifier: LGPL-2.1-or-later
#include "mbs/adaptive_runge_kutta.h"

#include "base/exceptions.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace wearlink::mbs
{
  AdaptiveRungeKutta::AdaptiveRungeKutta(OdeSystem                &system,
                                         const IntegratorSettings &settings,
                                         const Controller         &controller,
                                         const int                 order)
    : Integrator(system, settings)
    , h(settings.initial_step)
    , controller(controller)
    , order(order)
  {
    const unsigned int n = system.size();
    tolerance.resize(n);
    for (unsigned int i = 0; i < n; ++i)
      tolerance[i] = i < settings.absolute_tolerance.size() ? settings.absolute_tolerance[i] : 1e-9;
  }

  void
  AdaptiveRungeKutta::step(const double t_limit)
  {
    if (!(h > 0))
      h = initial_step_size();
    bool last_rejected = false;
    while (true)
      {
        const double hs    = trial_step(t_limit, method_name());
        const double t_new = (hs >= t_limit - t) ? t_limit : t + hs;
        if (control(attempt(hs, t_new), hs, last_rejected))
          {
            accept(hs, t_new);
            return;
          }
      }
  }

  void
  AdaptiveRungeKutta::take_over(const double           t_now,
                                const Eigen::VectorXd &y_now,
                                const Eigen::VectorXd &f_now,
                                const double           h_proposal)
  {
    start_at(t_now, y_now, f_now);
    h = h_proposal;
    restarted();
  }

  void
  AdaptiveRungeKutta::dense_output(const double time, double *out) const
  {
    if (!(t > t_prev))
      {
        for (Eigen::Index i = 0; i < y.size(); ++i)
          out[i] = y[i];
        return;
      }
    // The extension belongs to the whole step [t_prev, step_end], also after
    // end_step_at() moved the current point to an event inside it.
    interpolate((time - t_prev) / (step_end - t_prev), out);
  }

  namespace
  {
    /** A relative tolerance at least this large is loose already [-] (see trial_step). */
    constexpr double loose_relative_tolerance = 1e-2;
  } // namespace

  double
  AdaptiveRungeKutta::trial_step(const double t_limit, const char *method) const
  {
    const double hs = std::min({h, settings.max_step, t_limit - t});
    if (!(hs > 0))
      throw NumericalError(std::string(method) + ": no time left to step (t = " + std::to_string(t) + " s).");
    if (hs < settings.min_step && hs < t_limit - t)
      {
        std::ostringstream os;
        os << method << ": the step size fell to " << hs << " s at t = " << t << " s (minimum " << settings.min_step
           << " s); the error tolerance cannot be met there. ";
        // A relative tolerance of 1 % or more is loose already: more would not help, and
        // the error of a state near zero is measured against its absolute tolerance.
        if (settings.relative_tolerance < loose_relative_tolerance)
          os << "Loosen Integrator/Relative tolerance (now " << settings.relative_tolerance
             << ") or look for a singular position.";
        else
          os << "Integrator/Relative tolerance is " << settings.relative_tolerance
             << " already, so loosening it will not help: look for a singular position (the joint geometry, the "
                "drivers) or a contact stiffer than any step can follow (the elastic moduli), or loosen the "
                "absolute Integrator/Position tolerance and Velocity tolerance.";
        throw NumericalError(os.str());
      }
    return hs;
  }

  double
  AdaptiveRungeKutta::error_sum(const Eigen::VectorXd &e,
                                const Eigen::VectorXd &y_new,
                                unsigned int          &n_controlled) const
  {
    double sum   = 0;
    n_controlled = 0;
    for (Eigen::Index i = 0; i < y.size(); ++i)
      if (tolerance[i] > 0)
        {
          const double sc = tolerance[i] + settings.relative_tolerance * std::max(std::abs(y[i]), std::abs(y_new[i]));
          const double r  = e[i] / sc;
          sum += r * r;
          ++n_controlled;
        }
    return sum;
  }

  double
  AdaptiveRungeKutta::error_norm(const Eigen::VectorXd &e, const Eigen::VectorXd &y_new) const
  {
    unsigned int n_controlled = 0;
    const double sum          = error_sum(e, y_new, n_controlled);
    return std::sqrt(sum / std::max(1u, n_controlled));
  }

  bool
  AdaptiveRungeKutta::control(double err, const double hs, bool &last_rejected)
  {
    if (!std::isfinite(err))
      err = 1e10; // a blown-up trial step is rejected and shrunk
    const Controller &c     = controller;
    const double      fac11 = std::pow(err, c.expo);
    if (err > 1.0)
      {
        ++n_rejected;
        last_rejected = true;
        h             = hs / std::min(1.0 / c.fac_min, fac11 / c.safe);
        return false;
      }
    double fac   = fac11 / std::pow(fac_old, c.beta);
    fac          = std::max(1.0 / c.fac_max, std::min(1.0 / c.fac_min, fac / c.safe));
    double h_new = hs / fac;
    if (last_rejected)
      h_new = std::min(h_new, hs);
    fac_old = std::max(err, 1e-4);
    // A step shortened to land on t_limit (an event or the end time) says little about
    // the next one: keep the earlier proposal if it was larger.
    const bool truncated = hs < std::min(h, settings.max_step);
    h                    = truncated ? std::max(h, h_new) : h_new;
    ++n_accepted;
    return true;
  }

  void
  AdaptiveRungeKutta::advance(const double t_new, const Eigen::VectorXd &y_new, const Eigen::VectorXd &f_new)
  {
    y_prev   = y;
    f_prev   = f;
    t_prev   = t;
    step_end = t_new;
    y        = y_new;
    f        = f_new;
    t        = t_new;
  }

  double
  AdaptiveRungeKutta::initial_step_size()
  {
    Eigen::VectorXd scratch_y(y.size()), scratch_f(y.size());
    const double    rtol = settings.relative_tolerance;
    double          d0 = 0, d1 = 0;
    unsigned int    n_controlled = 0;
    for (Eigen::Index i = 0; i < y.size(); ++i)
      if (tolerance[i] > 0)
        {
          const double sc = tolerance[i] + rtol * std::abs(y[i]);
          d0 += (y[i] / sc) * (y[i] / sc);
          d1 += (f[i] / sc) * (f[i] / sc);
          ++n_controlled;
        }
    d0        = std::sqrt(d0 / std::max(1u, n_controlled));
    d1        = std::sqrt(d1 / std::max(1u, n_controlled));
    double h0 = (d0 < 1e-5 || d1 < 1e-5) ? 1e-6 : 0.01 * d0 / d1;
    h0        = std::min(h0, settings.max_step);
    scratch_y = y + h0 * f;
    evaluate(t + h0, scratch_y, scratch_f);
    double d2 = 0;
    for (Eigen::Index i = 0; i < y.size(); ++i)
      if (tolerance[i] > 0)
        {
          const double sc = tolerance[i] + rtol * std::abs(y[i]);
          d2 += ((scratch_f[i] - f[i]) / sc) * ((scratch_f[i] - f[i]) / sc);
        }
    d2              = std::sqrt(d2 / std::max(1u, n_controlled)) / h0;
    const double dm = std::max(d1, d2);
    const double h1 = dm <= 1e-15 ? std::max(1e-6, h0 * 1e-3) : std::pow(0.01 / dm, 1.0 / order);
    return std::min({100 * h0, h1, settings.max_step});
  }
} // namespace wearlink::mbs
