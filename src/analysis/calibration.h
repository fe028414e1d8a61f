// SPDX-License-Identifier: LGPL-2.1-or-later
// Calibration of wear coefficients from measured mass losses: the root finding and the
// interval, as pure functions of a forward model (workflows/wear/calibration.h supplies the
// wear runs).
//
// Each measured surface s (a joint's pin or bushing) has an Archard coefficient k_s
// [m³/(N m)] and a measured mass loss m_s [mg]. The forward model maps all coefficients
// at once to the predicted mass losses m_pred,s(k) (one wear run: the surfaces share the
// dynamics, so a coefficient of one surface acts on the others, but weakly). The wear
// volume is nearly proportional to k (Archard), not exactly: the worn gap feeds back on
// the dynamics. In x = log k the residual
//     f_s(x) = log m_pred,s(k) − log m_s
// is therefore nearly linear with slope ≈ 1. The iteration (fit_coefficients):
//  - run 0 at the prior k0; run 1 at the linear rescale k1 = k0 · m_s / m_pred,s(k0)
//    (the step with slope 1);
//  - then a regression secant per surface: the slope S_s = d log m / d log k is the
//    least-squares slope of f_s over all the surface's runs so far (a secant through two
//    runs when there are two; with more, the noise of the chaotic dynamics averages out
//    instead of entering the step), clamped to [0.2, 5] (a non-finite or non-positive
//    slope is taken as 1); x_new = x_last − f_last / S_s. Once runs on both sides of the
//    root exist (f < 0 and f > 0; m_pred grows with k), a step leaving that bracket is
//    replaced by the bracket's midpoint (bisection in log k);
//  - a surface whose relative residual |m_pred/m − 1| is below the tolerance keeps its k;
//    the loop stops when every surface is below it (converged), or when every surface is
//    below it or bracketed within the tolerance in log k (located: the root lies between
//    two runs closer than the tolerance, and further runs would only sample the chaotic
//    scatter, which a non-monotone m_pred(k) shows), or after the maximum number of runs.
//    The run kept is the one with the smallest largest relative residual.
// The dynamics are chaotic: one run is one sample, so m_pred(k) carries a scatter of a
// few per cent for multi-iteration wear runs, and a tolerance below it is reached by
// chance only; the final correction by the ensemble mean (corrected_coefficient) and the
// interval take care of that.
//
// The interval (coefficient_interval): with the measurement's 1σ uncertainty σ_m [mg],
// the chaos term σ_c [mg] and the local sensitivity S = d log m / d log k,
//     σ_log k = sqrt((σ_m / m)² + (σ_c / m_pred)²) / |S|,
//     95 % interval = [k exp(−1.96 σ_log k), k exp(+1.96 σ_log k)],
// first-order propagation in log k (a relative error of the mass maps to a relative
// error of k divided by S), normal errors. The caller chooses σ_c; the workflow's
// (workflows/wear/calibration.h) is σ_c = s sqrt(1 + 1/N) for an ensemble of N runs with
// sample std s: the measured test is itself one sample of the chaotic wear (it scatters
// about the mean by s) and the ensemble's mean is known to s/√N.
#pragma once

#include <functional>
#include <vector>

namespace wearlink::analysis
{
  /** One forward run of one surface: log k and the residual f = log m_pred − log m. */
  struct SecantPoint
  {
    double log_k    = 0;
    double residual = 0;
  };

  /** The knobs of the iteration. */
  struct SecantSettings
  {
    double       tolerance = 1e-3; ///< on |m_pred/m − 1| of every surface [-]
    unsigned int max_runs  = 10;   ///< forward runs at most (the first at k0 included)
    double       min_slope = 0.2;  ///< clamp of d log m / d log k [-]
    double       max_slope = 5;
    double       max_step  = 4.6; ///< largest step in log k (a factor 100) [-]
  };

  /**
   * d log m / d log k of @p points: the least-squares slope of residual on log k over the
   * points with distinct log k (1 with fewer than two, or if their log k span less than
   * 1e-6), clamped to [settings.min_slope, settings.max_slope]; non-finite or ≤ 0: 1.
   */
  double
  log_slope(const std::vector<SecantPoint> &points, const SecantSettings &settings);

  /**
   * The next log k of one surface from its runs @p points (the last one the newest): the
   * regression-secant step from the last run, kept inside the bracket of runs on both
   * sides of the root (bisection otherwise), at most settings.max_step long. Unchanged
   * if the last relative residual is below the tolerance.
   */
  double
  next_log_k(const std::vector<SecantPoint> &points, const SecantSettings &settings);

  /**
   * The width in log k of the narrowest bracket of @p points' root: hi − lo for the
   * largest log k with a residual < 0 and the smallest with a residual > 0, if lo < hi;
   * otherwise (no bracket, or runs that contradict a rising m_pred) infinity.
   */
  double
  bracket_width(const std::vector<SecantPoint> &points);

  /** The predicted mass losses [mg] of the surfaces at the coefficients k [m³/(N m)]. */
  using ForwardModel = std::function<std::vector<double>(const std::vector<double> &k)>;

  /** What fit_coefficients found. */
  struct CoefficientFit
  {
    std::vector<double>                   k;         ///< of the run kept [m³/(N m)]
    std::vector<double>                   predicted; ///< its mass losses [mg]
    std::vector<double>                   slope;     ///< d log m / d log k per surface [-]
    std::vector<std::vector<SecantPoint>> history;   ///< per surface, every run
    unsigned int                          runs      = 0;
    bool                                  converged = false; ///< every surface below the tolerance
    bool located = false; ///< every surface below the tolerance or bracketed within it in log k
  };

  /**
   * Solve m_pred,s(k) = @p measured_s [mg] for every surface from the prior @p k0 (see
   * the top of this file). @p forward must return one positive mass loss per surface
   * (a surface that does not wear cannot be calibrated: std::invalid_argument, which the
   * caller words). @p after_run, if given, is called after every run with its index,
   * the coefficients and the predictions (progress).
   */
  CoefficientFit
  fit_coefficients(
    const ForwardModel                                                                                &forward,
    const std::vector<double>                                                                         &k0,
    const std::vector<double>                                                                         &measured,
    const SecantSettings                                                                              &settings,
    const std::function<void(unsigned int, const std::vector<double> &, const std::vector<double> &)> &after_run = {});

  /**
   * The coefficient at which the mean prediction meets the measurement, from a run at
   * @p k whose ensemble mean is @p predicted_mean [mg], through the local slope @p slope:
   * k (measured / predicted_mean)^(1 / slope) (one more secant step, on the mean).
   */
  double
  corrected_coefficient(double k, double measured, double predicted_mean, double slope);

  /** A coefficient's 95 % interval and the standard deviation of its logarithm. */
  struct CoefficientInterval
  {
    double sigma_log_k = 0; ///< [-]
    double low         = 0; ///< [m³/(N m)]
    double high        = 0;
  };

  /**
   * The 95 % interval of @p k (see the top of this file) from the measured mass loss
   * @p measured with its 1σ @p sigma_measured, the predicted mean @p predicted with its
   * 1σ @p sigma_predicted [mg each], and the slope d log m / d log k.
   */
  CoefficientInterval
  coefficient_interval(double k,
                       double measured,
                       double sigma_measured,
                       double predicted,
                       double sigma_predicted,
                       double slope);
} // namespace wearlink::analysis
