// SPDX-License-Identifier: LGPL-2.1-or-later
// The trend of a noisy response measure against revolutions, as one of three models fitted
// by least squares, and the 95 % statements the response criterion of a life run is decided
// on (analysis/life_criteria.h says how it is decided).
//
// The models, each a fresh level a [m/s²] plus a rise β w(N) along a regressor w of the
// revolutions N, linear in (a, β) once its change points are fixed:
//   line  w = N                                    2 parameters (a, β);
//   step  w = 0 up to τ, 1 after it                3 (a, β, τ): the level a jumps to a + β;
//   ramp  w = clamp(N − τ₁, 0, τ₂ − τ₁)            4 (a, β, τ₁, τ₂): the fresh level up to τ₁,
//                                                  a straight rise to τ₂, then a plateau.
// The ramp has three segments because that is the shape measured on the nine-bar: flat to
// ~10,000 revolutions, a rise, a plateau from ~35,000 on. A two-segment ramp from 0 to a
// plateau must put its fresh level under the first measurements to follow the rise, and
// a rise relative to a fresh level fitted too low is a rise too large too early; the ramp
// from 0 (τ₁ = 0) and a ramp still rising at the last measurement are not excluded, they
// are the ends of the ramp's range. Admissible change points: at least one measurement
// before the change (the fresh one may be alone), at least two after it (one measurement
// alone does not make a level, it may be an outlier): a step's τ between measurements k and
// k + 1 for k = 0 … n − 3, a ramp's τ₁ in the gap of measurements j, j + 1 and τ₂ in the
// gap k, k + 1 with j < k ≤ n − 3 (at least one measurement on the rise).
//
// Fitting (least squares, the change points by profile): a step's residual sum of squares
// RSS is constant while τ stays in a gap between measurements, so the step is fitted at
// every admissible gap and the best is kept; its jump is drawn in the middle of its gap.
// The ramp is continuous in (τ₁, τ₂): within a pair of gaps it is the linear model of the
// fresh level a before, a line e + c N on the rise and a plateau d after, with
// τ₁ = (a − e)/c, τ₂ = (d − e)/c; the convex least-squares problem on the cone of
// (a, e, c, d) whose τ₁, τ₂ lie in their gaps has its minimum at the unconstrained one or
// on a face (τ₁ or τ₂ at an end of its gap, a problem of the same kind in one change point
// fewer), so the minimum over every pair of gaps is exact, without iteration.
//
// The choice among the models: the Bayesian information criterion
//   BIC = n ln(RSS/n) + p ln n      (p: the parameters, change points included),
// the smallest wins. The three are not nested (a step is no line, a ramp with its plateau
// no line either), so no F-test between pairs applies, and with a change point the F
// statistic has no F distribution anyway (the change point is not identified under the
// simpler model). BIC charges ln n ≈ 3 per parameter at n ≈ 20, more than AIC's 2: a
// change point found by searching all gaps gains more than a regular parameter does, and
// a criterion decided on a spurious change is what must not happen. The BIC weights
// exp(−BIC/2) / Σ exp(−BIC/2) are reported beside it.
//
// 95 % statements, by profile likelihood with the residual variance s² = RSS/(n − p) of
// the model: a value of a quantity of the model is admitted if the best fit that has it
// exceeds the model's RSS by at most s² F(0.95; 1, n − p) (= t(0.975, n − p)² s²). With the
// change points fixed the quantity is a ratio of linear combinations of (a, β) and this is
// Fieller's interval (for the line, with no change point, exactly the line's statements of
// analysis/life_criteria.h); with the change points free, it is the union over the change
// points whose own RSS leaves room, of Fieller's sets with the room left,
//   K = s² F − (RSS(τ) − RSS_min).
// The unions are taken over every admissible gap of a step and over 9 × 9 change points
// spread over each pair of gaps of a ramp (the ends included) and its best one. The
// quantities:
//   the rise at N,  r(N) = 100 β w(N) / a [%];
//   the crossing of the limit ℓ, the first N with r(N) ≥ ℓ: a line's ℓ a / β; a ramp's
//     τ₁ + ℓ a / β if that is ≤ τ₂ (else its plateau stays below the limit); a step's τ if
//     its jump reaches the limit (β ≥ ℓ a).
// A step's τ is not a regular parameter: the likelihood ratio of a jump's position tends
// to twice the largest value of a two-sided random walk with drift, whose distribution
// function at c is (1 − e^(−c/2))² for a small jump (χ²₁'s 3.84 covers 73 %), so the
// crossing of a step admits its gaps with the critical value 7.35 (the 95 % point of that
// law; conservative for a large jump, whose gap is then known) instead of 3.84, scaled by
// F(0.95; 1, n − 3)/3.84 for the estimated variance as F is for χ².
// A ramp's crossing τ₁ + ℓ a/β lies a short way up its rise, so its uncertainty is mostly
// that of the start τ₁, a kink between measurements whose likelihood ratio approaches χ²₁
// only slowly: with the one-parameter value the set covered 92 % of 400 synthetic ramps
// (σ 10 % and 17 % of the fresh level, 19 measurements). The crossing's set is therefore
// the projection of the joint 95 % set of the crossing and the start, with the critical
// value 2 s² F(0.95; 2, n − 4) (Scheffé's for two parameters), which covers at least as
// often as that joint set does.
#pragma once

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace wearlink::analysis
{
  /** A 95 % confidence interval; NaN bounds where it is not bounded. */
  struct Interval
  {
    double low  = std::numeric_limits<double>::quiet_NaN();
    double high = std::numeric_limits<double>::quiet_NaN();

    bool
    bounded() const;
  };

  /**
   * The least-squares fit y = a + β w of measures y against a regressor w, and what its
   * normal-theory statements about (a, β) need. The statements take the critical value
   * k = (room in the RSS) of the set: t(0.975, n − 2)² s² for a plain line.
   */
  struct RegressorFit
  {
    double      a      = std::numeric_limits<double>::quiet_NaN(); ///< the level at w = 0 [m/s²]
    double      beta   = std::numeric_limits<double>::quiet_NaN(); ///< [m/s² per unit of w]
    double      rss    = std::numeric_limits<double>::quiet_NaN(); ///< Σ residual² [(m/s²)²]
    double      w_mean = std::numeric_limits<double>::quiet_NaN(); ///< w̄
    double      sww    = std::numeric_limits<double>::quiet_NaN(); ///< Σ (w_i − w̄)²
    std::size_t n      = 0;

    /**
     * The band g ± √(k q) of g = β w − ℓ a at @p w for the limit ratio @p l (ℓ, a fraction),
     * q = ℓ²/n + (w + ℓ w̄)²/Sww: the values of g admitted with room @p k.
     */
    Interval
    excess(double w, double l, double k) const;

    /**
     * Fieller's set of the ratio ρ = β w / a at @p w with room @p k: the ρ with
     * (β w − ρ a)² ≤ k (ρ²/n + (w + ρ w̄)²/Sww); bounded if a is significant, else NaN.
     */
    Interval
    ratio(double w, double k) const;

    /**
     * The hull of the w in [@p w_low, @p w_high] at which β w = ℓ a is admitted with room
     * @p k (the w where the rise reaches ℓ); NaN if none; a bound infinite where the set
     * is unbounded.
     */
    Interval
    crossing(double l, double k, double w_low, double w_high) const;
  };

  /** The least-squares fit of @p y against @p w (NaN coefficients if w has no spread). */
  RegressorFit
  fit_regressor(const std::vector<double> &w, const std::vector<double> &y);

  /** The families of the trend (see the file comment). */
  enum class TrendFamily
  {
    line,
    step,
    ramp
  };

  /** "line", "step", "ramp". */
  std::string
  family_name(TrendFamily family);

  /** A model of one family at given change points, with its fit. */
  struct TrendModel
  {
    TrendFamily family = TrendFamily::line;
    double      tau1 =
      std::numeric_limits<double>::quiet_NaN(); ///< step: end of the gap before; ramp: start of the rise [rev]
    double tau2 =
      std::numeric_limits<double>::quiet_NaN(); ///< step: start of the gap after; ramp: end of the rise [rev]
    RegressorFit fit;
    unsigned int parameters = 2;                                        ///< p: 2, 3, 4
    double       bic        = std::numeric_limits<double>::quiet_NaN(); ///< n ln(RSS/n) + p ln n

    /** w(N) (a step jumps in the middle of its gap). */
    double
    regressor(double revolutions) const;
    /** The fitted measure a + β w(N) [m/s²]. */
    double
    value(double revolutions) const;
    /** The fitted rise over the fresh level, 100 β w(N)/a [%]. */
    double
    rise(double revolutions) const;
    /** The first revolutions at which the fitted rise reaches @p limit [%] (NaN if it does not). */
    double
    crossing(double limit) const;
  };

  /**
   * The three models of the finite measures against distinct revolutions (the rows as
   * analysis::response_trend takes them), the one chosen by BIC, and the 95 % statements of
   * each (see the file comment). A family needs p + 2 measurements (two degrees of freedom
   * left); with fewer it is not fitted.
   */
  class ResponseModels
  {
  public:
    ResponseModels(const std::vector<double> &revolutions, const std::vector<double> &measures, std::size_t count);

    std::size_t
    points() const
    {
      return x.size();
    }
    /** True if @p family was fitted. */
    bool
    has(TrendFamily family) const;
    /** The fitted model of @p family (has(family)). */
    const TrendModel &
    model(TrendFamily family) const;
    /** The family with the smallest BIC (the line without any fit: then nothing holds). */
    TrendFamily
    chosen() const;
    /** exp(−BIC/2) of @p family over the sum of the fitted ones [-]. */
    double
    weight(TrendFamily family) const;
    /** s = √(RSS/(n − p)) of @p family [m/s²]. */
    double
    residual_std(TrendFamily family) const;

    /**
     * The 95 % set of the rise at @p revolutions [%] under @p family: the hull of Fieller's
     * sets over its admitted change points (NaN bounds where one is unbounded).
     */
    Interval
    rise_interval(TrendFamily family, double revolutions) const;
    /**
     * The admitted values of g = β w(N) − ℓ a at @p revolutions for the limit @p limit [%]:
     * low = the smallest lower bound over the admitted change points, high the largest upper
     * one. Only the signs compare across change points: low ≥ 0 ⇔ the rise is at or above
     * the limit at 95 %, high < 0 ⇔ below it. NaN without a fit.
     */
    Interval
    excess_band(TrendFamily family, double revolutions, double limit) const;
    /**
     * The 95 % interval of the crossing of @p limit [%] under @p family (the hull of the
     * admitted crossings, see the file comment): NaN bounds if it is not bounded or empty.
     */
    Interval
    crossing_interval(TrendFamily family, double limit) const;

  private:
    /** A model at admitted change points and the room K its RSS leaves. */
    struct Admitted
    {
      TrendModel model;
      double     room = 0;
    };

    /** The candidates of @p family whose RSS leaves room under the critical value @p critical. */
    std::vector<Admitted>
    admitted(TrendFamily family, double critical) const;
    /** s² F(0.95; 1, n − p) of @p family [(m/s²)²]; NaN without a degree of freedom. */
    double
    critical(TrendFamily family) const;
    /**
     * The critical value of the crossing's set of @p family: critical() for a line, a
     * step's scaled by 7.35/3.84 (its jump's position), a ramp's 2 s² F(0.95; 2, n − 4) (the
     * crossing and the start of the rise jointly, see the file comment) [(m/s²)²].
     */
    double
    crossing_critical(TrendFamily family) const;

    std::vector<double>                  x, y;
    std::vector<TrendModel>              fitted;     ///< the best of each fitted family
    std::vector<std::vector<TrendModel>> candidates; ///< per fitted family: its models at the change points sampled
  };
} // namespace wearlink::analysis
