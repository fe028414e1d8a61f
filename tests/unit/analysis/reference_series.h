// SPDX-License-Identifier: LGPL-2.1-or-later
// Reference series for the Lyapunov tests, generated inside the tests (doc/models.md §6.3):
// the Lorenz (sigma 10, rho 28, beta 8/3) and Rössler (a = b = 0.2, c = 5.7) flows
// integrated with classical fourth-order Runge-Kutta, the Hénon map (a 1.4, b 0.3), a
// sine and the Van der Pol limit cycle. Each generator discards a transient so the
// series lies on the attractor, and returns one coordinate sampled every `dt`.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace wearlink::testing
{
  using State3 = std::array<double, 3>;

  /** One classical RK4 step of x' = f(x) with step h. */
  template <class F>
  State3
  rk4_step(const F &f, const State3 &x, const double h)
  {
    auto axpy = [](const State3 &a, const double s, const State3 &b) {
      return State3{{a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2]}};
    };
    const State3 k1 = f(x);
    const State3 k2 = f(axpy(x, 0.5 * h, k1));
    const State3 k3 = f(axpy(x, 0.5 * h, k2));
    const State3 k4 = f(axpy(x, h, k3));
    State3       out;
    for (int i = 0; i < 3; ++i)
      out[i] = x[i] + h / 6.0 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
    return out;
  }

  /**
   * Coordinate @p component of a flow, @p n samples every @p dt, integrated with
   * @p substeps RK4 steps per sample after a transient of @p transient time units.
   */
  template <class F>
  std::vector<double>
  sample_flow(const F           &f,
              State3             x,
              const double       dt,
              const std::size_t  n,
              const unsigned int substeps,
              const double       transient,
              const unsigned int component = 0)
  {
    const double h = dt / substeps;
    for (double t = 0; t < transient; t += h)
      x = rk4_step(f, x, h);
    std::vector<double> out(n);
    for (std::size_t i = 0; i < n; ++i)
      {
        out[i] = x[component];
        for (unsigned int s = 0; s < substeps; ++s)
          x = rk4_step(f, x, h);
      }
    return out;
  }

  /** Lorenz x(t), sigma 10, rho 28, beta 8/3; LLE 0.906 per time unit. */
  inline std::vector<double>
  lorenz_x(const std::size_t n, const double dt = 0.01)
  {
    const auto f = [](const State3 &s) {
      return State3{{10.0 * (s[1] - s[0]), s[0] * (28.0 - s[2]) - s[1], s[0] * s[1] - 8.0 / 3.0 * s[2]}};
    };
    return sample_flow(f, {{1.0, 1.0, 1.0}}, dt, n, 2, 50.0);
  }

  /** Rössler x(t), a = b = 0.2, c = 5.7; LLE about 0.071 per time unit. */
  inline std::vector<double>
  roessler_x(const std::size_t n, const double dt = 0.1)
  {
    const auto f = [](const State3 &s) {
      return State3{{-s[1] - s[2], s[0] + 0.2 * s[1], 0.2 + s[2] * (s[0] - 5.7)}};
    };
    return sample_flow(f, {{1.0, 1.0, 0.0}}, dt, n, 4, 500.0);
  }

  /** Van der Pol x(t), x'' - mu (1 - x^2) x' + x = 0: a limit cycle, LLE 0. */
  inline std::vector<double>
  van_der_pol_x(const std::size_t n, const double dt = 0.05, const double mu = 1.0)
  {
    const auto f = [mu](const State3 &s) {
      return State3{{s[1], mu * (1 - s[0] * s[0]) * s[1] - s[0], 0.0}};
    };
    return sample_flow(f, {{2.0, 0.0, 0.0}}, dt, n, 4, 200.0);
  }

  /** Hénon x_n, a 1.4, b 0.3; LLE 0.420 per iteration. */
  inline std::vector<double>
  henon_x(const std::size_t n)
  {
    double x = 0.1, y = 0.1;
    for (int k = 0; k < 1000; ++k)
      {
        const double xn = 1.0 - 1.4 * x * x + y;
        y               = 0.3 * x;
        x               = xn;
      }
    std::vector<double> out(n);
    for (std::size_t k = 0; k < n; ++k)
      {
        out[k]          = x;
        const double xn = 1.0 - 1.4 * x * x + y;
        y               = 0.3 * x;
        x               = xn;
      }
    return out;
  }

  /** sin(2 pi t / period) sampled every dt. */
  inline std::vector<double>
  sine(const std::size_t n, const double dt, const double period)
  {
    std::vector<double> out(n);
    for (std::size_t i = 0; i < n; ++i)
      out[i] = std::sin(2.0 * 3.14159265358979323846 * i * dt / period);
    return out;
  }
} // namespace wearlink::testing
