// SPDX-License-Identifier: LGPL-2.1-or-later
#include "analysis/calibration.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace wearlink::analysis
{
  double
  log_slope(const std::vector<SecantPoint> &points, const SecantSettings &settings)
  {
    if (points.size() < 2)
      return 1;
    double mx = 0, mf = 0;
    for (const auto &p : points)
      {
        mx += p.log_k;
        mf += p.residual;
      }
    mx /= points.size();
    mf /= points.size();
    double sxx = 0, sxf = 0;
    for (const auto &p : points)
      {
        sxx += (p.log_k - mx) * (p.log_k - mx);
        sxf += (p.log_k - mx) * (p.residual - mf);
      }
    const auto [lo, hi] =
      std::minmax_element(points.begin(), points.end(), [](const auto &a, const auto &b) { return a.log_k < b.log_k; });
    if (hi->log_k - lo->log_k < 1e-6)
      return 1;
    const double s = sxf / sxx;
    if (!std::isfinite(s) || !(s > 0))
      return 1;
    return std::clamp(s, settings.min_slope, settings.max_slope);
  }

  namespace
  {
    /** |m_pred/m − 1| of a residual f = log(m_pred/m). */
    double
    relative_residual(const double f)
    {
      return std::abs(std::expm1(f));
    }
  } // namespace

  namespace
  {
    /** The largest log k of a run below the root and the smallest of a run above it (±inf if none). */
    std::pair<double, double>
    bracket(const std::vector<SecantPoint> &points)
    {
      double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
      for (const auto &p : points)
        {
          if (p.residual < 0)
            lo = std::max(lo, p.log_k);
          else if (p.residual > 0)
            hi = std::min(hi, p.log_k);
        }
      return {lo, hi};
    }
  } // namespace

  double
  next_log_k(const std::vector<SecantPoint> &points, const SecantSettings &settings)
  {
    const SecantPoint &last = points.back();
    if (relative_residual(last.residual) < settings.tolerance)
      return last.log_k;
    const double step = std::clamp(-last.residual / log_slope(points, settings), -settings.max_step, settings.max_step);
    double       x    = last.log_k + step;
    const auto [lo, hi] = bracket(points);
    if (std::isfinite(lo) && std::isfinite(hi) && lo < hi && !(x > lo && x < hi))
      x = 0.5 * (lo + hi);
    return x;
  }

  double
  bracket_width(const std::vector<SecantPoint> &points)
  {
    const auto [lo, hi] = bracket(points);
    return std::isfinite(lo) && std::isfinite(hi) && lo < hi ? hi - lo : std::numeric_limits<double>::infinity();
  }

  namespace
  {
    /** The largest relative residual of run @p r over the surfaces. */
    double
    worst_residual(const CoefficientFit &fit, const std::size_t r)
    {
      double worst = 0;
      for (const auto &h : fit.history)
        worst = std::max(worst, relative_residual(h[r].residual));
      return worst;
    }

    /** The residuals of one run, checked: a surface without wear cannot be calibrated. */
    std::vector<double>
    residuals(const std::vector<double> &predicted, const std::vector<double> &measured)
    {
      if (predicted.size() != measured.size())
        throw std::invalid_argument("the forward model returned " + std::to_string(predicted.size()) +
                                    " mass losses for " + std::to_string(measured.size()) + " surfaces");
      std::vector<double> f(measured.size());
      for (std::size_t s = 0; s < f.size(); ++s)
        {
          if (!(predicted[s] > 0) || !std::isfinite(predicted[s]))
            throw std::invalid_argument("surface " + std::to_string(s) + ": the predicted mass loss " +
                                        std::to_string(predicted[s]) + " mg is not positive");
          f[s] = std::log(predicted[s] / measured[s]);
        }
      return f;
    }
  } // namespace

  CoefficientFit
  fit_coefficients(
    const ForwardModel                                                                                &forward,
    const std::vector<double>                                                                         &k0,
    const std::vector<double>                                                                         &measured,
    const SecantSettings                                                                              &settings,
    const std::function<void(unsigned int, const std::vector<double> &, const std::vector<double> &)> &after_run)
  {
    CoefficientFit fit;
    fit.history.resize(k0.size());
    std::vector<double>              k = k0;
    std::vector<std::vector<double>> ks, predictions;
    while (fit.runs < std::max(1u, settings.max_runs))
      {
        const auto predicted = forward(k);
        const auto f         = residuals(predicted, measured);
        for (std::size_t s = 0; s < k.size(); ++s)
          fit.history[s].push_back({std::log(k[s]), f[s]});
        ks.push_back(k);
        predictions.push_back(predicted);
        if (after_run)
          after_run(fit.runs, k, predicted);
        ++fit.runs;
        fit.converged = worst_residual(fit, fit.runs - 1) < settings.tolerance;
        fit.located   = true;
        for (const auto &h : fit.history)
          fit.located = fit.located && (relative_residual(h.back().residual) < settings.tolerance ||
                                        bracket_width(h) < settings.tolerance);
        if (fit.converged || fit.located)
          break;
        for (std::size_t s = 0; s < k.size(); ++s)
          k[s] = std::exp(next_log_k(fit.history[s], settings));
      }
    std::size_t best = 0;
    for (std::size_t r = 1; r < ks.size(); ++r)
      if (worst_residual(fit, r) < worst_residual(fit, best))
        best = r;
    fit.k         = ks[best];
    fit.predicted = predictions[best];
    for (const auto &h : fit.history)
      fit.slope.push_back(log_slope(h, settings));
    return fit;
  }

  double
  corrected_coefficient(const double k, const double measured, const double predicted_mean, const double slope)
  {
    return k * std::pow(measured / predicted_mean, 1 / slope);
  }

  CoefficientInterval
  coefficient_interval(const double k,
                       const double measured,
                       const double sigma_measured,
                       const double predicted,
                       const double sigma_predicted,
                       const double slope)
  {
    const double rm = sigma_measured / measured, rp = sigma_predicted / predicted;
    const double s = std::sqrt(rm * rm + rp * rp) / std::abs(slope);
    return {s, k * std::exp(-1.96 * s), k * std::exp(1.96 * s)};
  }
} // namespace wearlink::analysis
